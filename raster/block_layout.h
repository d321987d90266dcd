#pragma once
// The 4x4 pixel block: exactly one FragmentBatch of kBatchQuads quads, the unit both the
// rasterizer and the ray caster shade. Lane offsets inside a block in framebuffer coordinates
// (y down): quad-major, quads (0,0) (2,0) (0,2) (2,2), and inside each quad the GL lane order of
// number/lanes.h (lower row first: lanes 0, 1 on the quad's row + 1).

#include <array>
#include <cstdint>
#include <experimental/simd>

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

namespace block_detail {
namespace stdx = std::experimental;
using Row = stdx::simd<float, stdx::simd_abi::deduce_t<float, kBatchLanes>>;

// Row R's float j is channel j % 4 of the pixel at dx = j / 4: a single-source permute of each
// channel, then blends by component, which compile to vector permutes, not 64 scalar moves.
// The channels are read straight from the caller's memory: a copy in a local array first made
// the compiler load it again at an offset, stalling on store forwarding.
template <int R>
[[gnu::always_inline]] inline Row pixel_row(const float* const (&rgba)[4]) {
    auto pick = [](const float* channel) {
        Row v(channel, stdx::element_aligned);
        return Row([&](auto j) { return v[kLaneAt[R][int(j) / 4]]; });
    };
    const Row component([](auto j) { return float(int(j) % 4); });
    Row row = pick(rgba[0]);
    where(component == 1.0f, row) = pick(rgba[1]);
    where(component == 2.0f, row) = pick(rgba[2]);
    where(component == 3.0f, row) = pick(rgba[3]);
    return row;
}
}  // namespace block_detail

// Transposes a block's colour from lane order, one array per channel (`rgba[c][i]` is lane i),
// into four framebuffer rows of four RGBA pixels: rows[r] receives the 16 floats of pixels
// (0..3, r) of the block, y down.
inline void block_to_rows(const float* const (&rgba)[4], float* const (&rows)[kBlock]) {
    using block_detail::pixel_row;
    namespace stdx = std::experimental;
    pixel_row<0>(rgba).copy_to(rows[0], stdx::element_aligned);
    pixel_row<1>(rgba).copy_to(rows[1], stdx::element_aligned);
    pixel_row<2>(rgba).copy_to(rows[2], stdx::element_aligned);
    pixel_row<3>(rgba).copy_to(rows[3], stdx::element_aligned);
}

}  // namespace qs
