#pragma once
// Whole-block work: which quads of a block run, and a block's colour stored as
// four framebuffer rows (the lane order is core/block_layout.h's), streamed where they can be.

#include <cstddef>
#include <cstdint>
#include <utility>

#if defined(__AVX__)
#include <immintrin.h>
#endif

#include "core/block_layout.h"
#include "core/cache_lines.h"
#include "core/framebuffer.h"
#include "core/lanes16.h"

namespace qs {

// The quads of a block that run: every quad with at least one covered lane, all four lanes.
inline std::uint32_t running_quads(std::uint32_t covered) {
    std::uint32_t running = 0;
    for (int q = 0; q < kBatchQuads; ++q) running |= ((covered >> (4 * q)) & 0xFu) ? 0xFu << (4 * q) : 0u;
    return running;
}

namespace block_detail {
// __builtin_shufflevector picks from two generic vectors with constant indices: one instruction
// on AVX-512 (vpermt2ps), a few on narrower ISAs.
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
#if defined(__AVX__) && !defined(__AVX512F__)
    // Two registers per channel: the generic shuffles below would be split into scalar moves.
    // Per half h (lanes 8h .. 8h + 7, block rows 2h and 2h + 1): interleave red with green and
    // blue with alpha, gather each pixel's four components, then pair the 128-bit halves into
    // rows. Row 2h holds lanes 8h + {2, 3, 6, 7}, row 2h + 1 lanes 8h + {0, 1, 4, 5} (kLaneAt).
    // Each row's two halves are stored into it as they are: a row made whole in registers first
    // (one shuffle of the two) has no register to live in and was assembled float by float
    // through the stack.
    static_assert(kLaneAt[0][0] == 2 && kLaneAt[0][2] == 6 && kLaneAt[1][0] == 0 && kLaneAt[1][2] == 4 &&
                  kLaneAt[2][0] == 10 && kLaneAt[3][0] == 8);
    for (int h = 0; h < 2; ++h) {
        const __m256 r = _mm256_loadu_ps(rgba[0] + 8 * h), g = _mm256_loadu_ps(rgba[1] + 8 * h);
        const __m256 b = _mm256_loadu_ps(rgba[2] + 8 * h), a = _mm256_loadu_ps(rgba[3] + 8 * h);
        const __m256 rg_low = _mm256_unpacklo_ps(r, g), rg_high = _mm256_unpackhi_ps(r, g);  // r0 g0 r1 g1 | r4 ..
        const __m256 ba_low = _mm256_unpacklo_ps(b, a), ba_high = _mm256_unpackhi_ps(b, a);
        auto row = [](__m256 rg, __m256 ba, lanes16::Floats& out) {
            const __m256 first = _mm256_shuffle_ps(rg, ba, _MM_SHUFFLE(1, 0, 1, 0));   // pixel k, k + 4
            const __m256 second = _mm256_shuffle_ps(rg, ba, _MM_SHUFFLE(3, 2, 3, 2));  // pixel k + 1, k + 5
            float* const to = reinterpret_cast<float*>(&out);
            _mm256_storeu_ps(to, _mm256_permute2f128_ps(first, second, 0x20));
            _mm256_storeu_ps(to + 8, _mm256_permute2f128_ps(first, second, 0x31));
        };
        row(rg_high, ba_high, rows[2 * h]);
        row(rg_low, ba_low, rows[2 * h + 1]);
    }
#else
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
#endif
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
