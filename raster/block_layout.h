#pragma once
// The 4x4 pixel block: exactly one FragmentBatch of kBatchQuads quads, the unit both the
// rasterizer and the ray caster shade. Lane offsets inside a block in framebuffer coordinates
// (y down): quad-major, quads (0,0) (2,0) (0,2) (2,2), and inside each quad the GL lane order of
// number/lanes.h (lower row first: lanes 0, 1 on the quad's row + 1).

#include <array>
#include <cstdint>

#include "program.h"

namespace qs {

inline constexpr int kBlock = 4;
static_assert(kBlock * kBlock == kBatchLanes);
inline constexpr int kLaneDx[kBatchLanes] = {0, 1, 0, 1, 2, 3, 2, 3, 0, 1, 0, 1, 2, 3, 2, 3};
inline constexpr int kLaneDy[kBatchLanes] = {1, 1, 0, 0, 1, 1, 0, 0, 3, 3, 2, 2, 3, 3, 2, 2};
inline constexpr std::uint32_t kAllLanes = (1u << kBatchLanes) - 1;

// The same offsets as floats, for interpolation.
constexpr std::array<float, kBatchLanes> lane_offsets_as_floats(const int (&v)[kBatchLanes]) {
    std::array<float, kBatchLanes> f{};
    for (int i = 0; i < kBatchLanes; ++i) f[std::size_t(i)] = float(v[i]);
    return f;
}
inline constexpr auto kLaneDxF = lane_offsets_as_floats(kLaneDx);
inline constexpr auto kLaneDyF = lane_offsets_as_floats(kLaneDy);

// The inverse: lane of the pixel at (dx, dy) inside its block.
inline constexpr int kLaneAt[kBlock][kBlock] = {{2, 3, 6, 7}, {0, 1, 4, 5}, {10, 11, 14, 15}, {8, 9, 12, 13}};  // [dy][dx]

// The quads of a block that run: every quad with at least one covered lane, all four lanes.
inline std::uint32_t running_quads(std::uint32_t covered) {
    std::uint32_t running = 0;
    for (int q = 0; q < kBatchQuads; ++q) running |= ((covered >> (4 * q)) & 0xFu) ? 0xFu << (4 * q) : 0u;
    return running;
}

}  // namespace qs
