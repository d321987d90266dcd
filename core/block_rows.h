#pragma once
// Whole-block work: which quads of a block run, and a block's colour stored as
// four framebuffer rows (the lane order is core/block_layout.h's), streamed where they can be.

#include <cstddef>
#include <cstdint>
#include <utility>

#include "core/block_layout.h"
#include "core/cache_lines.h"
#include "core/framebuffer.h"
#include "core/lanes16.h"
#include "shading/number/simd/simd.h"

namespace qs {

// The quads of a block that run: every quad with at least one covered lane, all four lanes.
inline std::uint32_t running_quads(std::uint32_t covered) {
    std::uint32_t running = 0;
    for (int q = 0; q < kBatchQuads; ++q) running |= ((covered >> (4 * q)) & 0xFu) ? 0xFu << (4 * q) : 0u;
    return running;
}

namespace block_detail {
// __builtin_shufflevector picks from two generic vectors with constant indices: one instruction
// where sixteen floats are a register (vpermt2ps on AVX-512), a few on narrower ones.
using lanes16::Floats;

// Lanes 8 h .. 8 h + 7 of x and y interleaved: x(8h), y(8h), x(8h+1), y(8h+1), ...
template <int Half, int... J>
void interleave(const Floats& x, const Floats& y, Floats& out, std::integer_sequence<int, J...>) {
    out = __builtin_shufflevector(x, y, ((J % 2) * 16 + Half * 8 + J / 2)...);
}

// Block row R from the interleaved halves holding its lanes: output float j is component j % 4
// of the pixel at dx = j / 4, lane L = kLaneAt[R][dx]; red and green come from `rg`, blue and
// alpha from `ba`, each at 2 (L mod 8) + component.
template <int R, int... J>
void row(const Floats& rg, const Floats& ba, Floats& out, std::integer_sequence<int, J...>) {
    out = __builtin_shufflevector(
        rg, ba, ((J % 4) < 2 ? 2 * (kLaneAt[R][J / 4] % 8) + J % 4 : 16 + 2 * (kLaneAt[R][J / 4] % 8) + J % 4 - 2)...);
}
}  // namespace block_detail

// Transposes a block's colour from lane order, one array per channel (`rgba[c][i]` is lane i),
// into four framebuffer rows of four RGBA pixels: rows[r] receives the 16 floats of pixels
// (0..3, r) of the block, y down. Eight two-source shuffles: rows 0 and 1 hold lanes 0..7 (the
// upper quads), rows 2 and 3 lanes 8..15.
inline void block_to_rows(const float* const (&rgba)[4], lanes16::Floats (&rows)[kBlock]) {
    if constexpr (simd::register_floats == kBatchLanes / 2) {
        // Two registers per channel: the sixteen-lane shuffles below would be split into scalar
        // moves. Per half h (lanes 8h .. 8h + 7, block rows 2h and 2h + 1): interleave red with
        // green and blue with alpha within each 128-bit half (unpcklps, unpckhps), gather each
        // pixel's four components (shufps), then pair the 128-bit halves into rows (vperm2f128).
        // Row 2h holds lanes 8h + {2, 3, 6, 7}, row 2h + 1 lanes 8h + {0, 1, 4, 5} (kLaneAt).
        // Each row's two halves are stored into it as they are: a row made whole in registers
        // first (one shuffle of the two) has no register to live in and was assembled float by
        // float through the stack.
        static_assert(kLaneAt[0][0] == 2 && kLaneAt[0][2] == 6 && kLaneAt[1][0] == 0 && kLaneAt[1][2] == 4 &&
                      kLaneAt[2][0] == 10 && kLaneAt[3][0] == 8);
        using Eight = simd::Vector<float, 8>;
        for (int h = 0; h < 2; ++h) {
            const Eight r = simd::load<Eight>(rgba[0] + 8 * h), g = simd::load<Eight>(rgba[1] + 8 * h);
            const Eight b = simd::load<Eight>(rgba[2] + 8 * h), a = simd::load<Eight>(rgba[3] + 8 * h);
            const Eight rg_low = __builtin_shufflevector(r, g, 0, 8, 1, 9, 4, 12, 5, 13);  // r0 g0 r1 g1 | r4 ..
            const Eight rg_high = __builtin_shufflevector(r, g, 2, 10, 3, 11, 6, 14, 7, 15);
            const Eight ba_low = __builtin_shufflevector(b, a, 0, 8, 1, 9, 4, 12, 5, 13);
            const Eight ba_high = __builtin_shufflevector(b, a, 2, 10, 3, 11, 6, 14, 7, 15);
            auto row = [](const Eight& rg, const Eight& ba, lanes16::Floats& out) {
                const Eight first = __builtin_shufflevector(rg, ba, 0, 1, 8, 9, 4, 5, 12, 13);    // pixel k, k + 4
                const Eight second = __builtin_shufflevector(rg, ba, 2, 3, 10, 11, 6, 7, 14, 15);  // pixel k + 1, k + 5
                float* const to = reinterpret_cast<float*>(&out);
                simd::store(to, Eight(__builtin_shufflevector(first, second, 0, 1, 2, 3, 8, 9, 10, 11)));
                simd::store(to + 8, Eight(__builtin_shufflevector(first, second, 4, 5, 6, 7, 12, 13, 14, 15)));
            };
            row(rg_high, ba_high, rows[2 * h]);
            row(rg_low, ba_low, rows[2 * h + 1]);
        }
        return;
    }
    using namespace block_detail;
    static_assert(kLaneAt[0][0] < 8 && kLaneAt[1][3] < 8 && kLaneAt[2][0] >= 8 && kLaneAt[3][0] >= 8);
    constexpr auto sixteen = std::make_integer_sequence<int, 16>();
    const Floats r = lanes16::load(rgba[0]), g = lanes16::load(rgba[1]), b = lanes16::load(rgba[2]),
                 a = lanes16::load(rgba[3]);
    Floats rg_low, rg_high, ba_low, ba_high;
    interleave<0>(r, g, rg_low, sixteen);
    interleave<1>(r, g, rg_high, sixteen);
    interleave<0>(b, a, ba_low, sixteen);
    interleave<1>(b, a, ba_high, sixteen);
    row<0>(rg_low, ba_low, rows[0], sixteen);
    row<1>(rg_low, ba_low, rows[1], sixteen);
    row<2>(rg_high, ba_high, rows[2], sixteen);
    row<3>(rg_high, ba_high, rows[3], sixteen);
}

// How a block's rows go to the frame: `Streamed` where nothing writes them again this frame.
enum class RowStores { Cached, Streamed };

// The four rows of the block whose top-left pixel is (bx, by), which lies inside the image, into
// `fb`. Streamed, each is a cache line written past the caches (cache_lines.h) where the frame's
// rows let it start one; else four plain stores.
inline void write_block_rows(Framebuffer& fb, int bx, int by, const lanes16::Floats (&rows)[kBlock], RowStores stores) {
    float* const row = fb.pixel(bx, by);
    const std::size_t pitch = 4 * std::size_t(fb.width);
    if (stores == RowStores::Streamed && starts_cache_line(row) && pitch % (kCacheLine / sizeof(float)) == 0) {
        for (int r = 0; r < kBlock; ++r) stream_line(row + std::size_t(r) * pitch, rows[r]);
    } else {
        for (int r = 0; r < kBlock; ++r) lanes16::store(row + std::size_t(r) * pitch, rows[r]);
    }
}

// The block at (bx, by), which lies inside the image, filled with one colour: `row` is four
// pixels of it (write_block_rows).
inline void fill_block_rows(Framebuffer& fb, int bx, int by, const lanes16::Floats& row, RowStores stores) {
    const lanes16::Floats rows[kBlock] = {row, row, row, row};
    write_block_rows(fb, bx, by, rows, stores);
}

// A whole block's undefined cases into `fb`, which holds them; the block, top-left pixel (bx, by),
// lies inside the image.
inline void store_undefined(Framebuffer& fb, int bx, int by, const ColorBatch& out) {
    for (int i = 0; i < kBatchLanes; ++i) fb.undefined[fb.index(bx + kLaneDx[i], by + kLaneDy[i])] = out.undefined[i];
}

// A whole block's shaded colour into `fb` as four rows (write_block_rows), and with `undefined`
// its lanes' undefined cases; the block, top-left pixel (bx, by), lies inside the image.
inline void store_block(Framebuffer& fb, int bx, int by, const ColorBatch& out, bool undefined, RowStores stores) {
    lanes16::Floats rows[kBlock];
    block_to_rows({out.rgba[0], out.rgba[1], out.rgba[2], out.rgba[3]}, rows);
    write_block_rows(fb, bx, by, rows, stores);
    if (undefined) store_undefined(fb, bx, by, out);
}

}  // namespace qs
