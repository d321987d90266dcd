#pragma once
// The 4x4 pixel block: exactly one FragmentBatch of kBatchQuads quads, the unit both the
// rasterizer and the ray caster shade (both backends' stores of whole blocks are in
// core/block_rows.h). Lane offsets inside a block in framebuffer coordinates
// (y down): quad-major, quads (0,0) (2,0) (0,2) (2,2), and inside each quad the GL lane order of
// number/lanes.h (lower row first: lanes 0, 1 on the quad's row + 1).

#include <cstdint>

#include "shading/batches.h"

namespace qs {

inline constexpr int kBlock = 4;
static_assert(kBlock * kBlock == kBatchLanes);
inline constexpr int kLaneDx[kBatchLanes] = {0, 1, 0, 1, 2, 3, 2, 3, 0, 1, 0, 1, 2, 3, 2, 3};
inline constexpr int kLaneDy[kBatchLanes] = {1, 1, 0, 0, 1, 1, 0, 0, 3, 3, 2, 2, 3, 3, 2, 2};
inline constexpr std::uint32_t kAllLanes = (1u << kBatchLanes) - 1;

// The inverse: lane of the pixel at (dx, dy) inside its block.
inline constexpr int kLaneAt[kBlock][kBlock] = {{2, 3, 6, 7}, {0, 1, 4, 5}, {10, 11, 14, 15}, {8, 9, 12, 13}};  // [dy][dx]

// The lanes of the block whose top-left pixel is (bx, by) that lie in a width x height image.
inline std::uint32_t lanes_inside(int bx, int by, int width, int height) {
    if (bx >= 0 && by >= 0 && bx + kBlock <= width && by + kBlock <= height) return kAllLanes;
    std::uint32_t inside = 0;
    for (int i = 0; i < kBatchLanes; ++i) {
        const int x = bx + kLaneDx[i], y = by + kLaneDy[i];
        inside |= std::uint32_t(x >= 0 && y >= 0 && x < width && y < height) << i;
    }
    return inside;
}

}  // namespace qs
