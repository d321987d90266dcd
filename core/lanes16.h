#pragma once
// The rasterizer's per-lane arithmetic on one batch: sixteen floats as a GCC/Clang generic
// vector. One register on AVX-512, several on narrower ISAs; plain IEEE operations lane by lane
// (the build does not contract a * b + c). Written with these instead of loops over arrays, the
// compiler needs no run-time checks that the arrays overlap, and nothing falls back to scalar
// code, whose stores a vector load cannot take straight from the store buffer. Every function
// here is always inlined: where sixteen floats are more than a register (AVX2), a call takes and
// returns them through memory, stored in pieces that a whole load then waits for (an out-of-line
// fma was a third of a constant-colour frame's time on the general path).

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#if defined(__AVX__) || defined(__BMI2__)
#include <immintrin.h>
#endif

#include "shading/batches.h"
#include "shading/number/wide_vector.h"

namespace qs::lanes16 {

typedef float Floats __attribute__((vector_size(kBatchLanes * sizeof(float))));
typedef std::int32_t Ints __attribute__((vector_size(kBatchLanes * sizeof(std::int32_t))));

// v in every lane, -0 included (`Floats{} + v` would add +0 to it: +0 for -0, and an addition
// the compiler cannot leave out, where a broadcast operand of the instruction using it is free).
[[gnu::always_inline]] inline Floats broadcast(float v) {
#if defined(__AVX512F__)
    static_assert(sizeof(Floats) == sizeof(__m512));
    return Floats(_mm512_set1_ps(v));
#elif defined(__AVX__)
    // Two registers of eight (a loop compiled to sixteen scalar stores).
    const __m256 half = _mm256_set1_ps(v);
    const __m256 both[2] = {half, half};
    Floats r;
    std::memcpy(&r, both, sizeof r);
    return r;
#else
    Floats r;
    for (int i = 0; i < kBatchLanes; ++i) r[i] = v;
    return r;
#endif
}

[[gnu::always_inline]] inline Floats load(const float* p) {
    Floats v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
[[gnu::always_inline]] inline Ints load(const int* p) {
    Ints v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
// Sixteen lanes of T (float or int) stored at p.
template <class T, class Lanes>
[[gnu::always_inline]] inline void store_lanes(T* p, const Lanes& v) {
    static_assert(sizeof v == kBatchLanes * sizeof(T));
#if defined(__AVX__) && !defined(__AVX512F__)
    // Two registers of eight, stored as such (a copy of the whole went through general registers).
    __m256i halves[2];
    std::memcpy(halves, &v, sizeof halves);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), halves[0]);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(p + 8), halves[1]);
#else
    std::memcpy(p, &v, sizeof v);
#endif
}
[[gnu::always_inline]] inline void store(float* p, const Floats& v) { store_lanes(p, v); }
[[gnu::always_inline]] inline void store(int* p, const Ints& v) { store_lanes(p, v); }

[[gnu::always_inline]] inline Floats to_float(const Ints& v) { return __builtin_convertvector(v, Floats); }

// a * b + c rounded once on every lane, as std::fma.
[[gnu::always_inline]] inline Floats fma(const Floats& a, const Floats& b, const Floats& c) {
#if defined(__AVX512F__)
    static_assert(sizeof(Floats) == sizeof(__m512));
    return Floats(_mm512_fmadd_ps(__m512(a), __m512(b), __m512(c)));
#elif defined(__FMA__)
    // Two registers of eight (a loop of std::fma compiled to sixteen scalar instructions).
    __m256 x[2], y[2], z[2];
    std::memcpy(x, &a, sizeof x), std::memcpy(y, &b, sizeof y), std::memcpy(z, &c, sizeof z);
    for (int h = 0; h < 2; ++h) x[h] = _mm256_fmadd_ps(x[h], y[h], z[h]);
    Floats r;
    std::memcpy(&r, x, sizeof r);
    return r;
#else
    Floats r;
    for (int i = 0; i < kBatchLanes; ++i) r[i] = std::fma(a[i], b[i], c[i]);
    return r;
#endif
}

// Sixteen floats as register-wide parts (shading/number/wide_vector.h): one AVX-512 register or
// two AVX2 ones, each part a value the compiler keeps in a register. A Floats wider than the
// registers has none: kept across a loop, it is copied through the stack in 16-byte pieces on
// every use. Values a tile's loop reuses are held as these (FragmentInputs::ColumnVaryings).
using Wide = simd::Wide<float, kBatchLanes>;

[[gnu::always_inline]] inline Wide to_wide(const Floats& v) { return Wide::load(reinterpret_cast<const float*>(&v)); }

// fma above on register-wide parts.
[[gnu::always_inline]] inline Wide fma(const Wide& a, const Wide& b, const Wide& c) {
    return Wide::map([](const Wide::Part& x, const Wide::Part& y, const Wide::Part& z) {
#if defined(__AVX512F__)
        if constexpr (sizeof(Wide::Part) == sizeof(__m512)) {
            return simd::by_register<__m512>(x, y, z, [](__m512 p, __m512 q, __m512 r) { return _mm512_fmadd_ps(p, q, r); });
        }
#endif
#if defined(__FMA__)
        if constexpr (sizeof(Wide::Part) == sizeof(__m256)) {
            return simd::by_register<__m256>(x, y, z, [](__m256 p, __m256 q, __m256 r) { return _mm256_fmadd_ps(p, q, r); });
        }
#endif
        Wide::Part r;
        for (int i = 0; i < Wide::part_size; ++i) r[i] = std::fma(x[i], y[i], z[i]);
        return r;
    }, a, b, c);
}

// Sixteen 64-bit integers: the edge functions' values (raster/edge_function.h).
typedef std::int64_t Longs __attribute__((vector_size(kBatchLanes * sizeof(std::int64_t))));

// Lane masks (bit i for lane i) of comparisons, on whole registers: GCC splits a comparison of
// these vectors wider than a register into one scalar comparison per lane.
// a < b
[[gnu::always_inline]] inline std::uint32_t less(const Floats& a, const Floats& b) {
#if defined(__AVX512F__)
    return _mm512_cmp_ps_mask(__m512(a), __m512(b), _CMP_LT_OQ);
#elif defined(__AVX__)
    __m256 x[2], y[2];
    std::memcpy(x, &a, sizeof x), std::memcpy(y, &b, sizeof y);
    std::uint32_t r = 0;
    for (int h = 0; h < 2; ++h) r |= std::uint32_t(_mm256_movemask_ps(_mm256_cmp_ps(x[h], y[h], _CMP_LT_OQ))) << (8 * h);
    return r;
#else
    std::uint32_t r = 0;
    for (int i = 0; i < kBatchLanes; ++i) r |= std::uint32_t(a[i] < b[i]) << i;
    return r;
#endif
}
// a == b
[[gnu::always_inline]] inline std::uint32_t equal(const Ints& a, const Ints& b) {
#if defined(__AVX512F__)
    return _mm512_cmpeq_epi32_mask(__m512i(a), __m512i(b));
#elif defined(__AVX2__)
    __m256i x[2], y[2];
    std::memcpy(x, &a, sizeof x), std::memcpy(y, &b, sizeof y);
    std::uint32_t r = 0;
    for (int h = 0; h < 2; ++h) {
        r |= std::uint32_t(_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(x[h], y[h])))) << (8 * h);
    }
    return r;
#else
    std::uint32_t r = 0;
    for (int i = 0; i < kBatchLanes; ++i) r |= std::uint32_t(a[i] == b[i]) << i;
    return r;
#endif
}
// a + b > 0, a the same for every lane
[[gnu::always_inline]] inline std::uint32_t sum_positive(std::int64_t a, const Longs& b) {
#if defined(__AVX512F__)
    __m512i y[2];
    std::memcpy(y, &b, sizeof y);
    const __m512i x = _mm512_set1_epi64(a);
    return std::uint32_t(_mm512_cmpgt_epi64_mask(_mm512_add_epi64(x, y[0]), _mm512_setzero_si512())) |
           std::uint32_t(_mm512_cmpgt_epi64_mask(_mm512_add_epi64(x, y[1]), _mm512_setzero_si512())) << 8;
#elif defined(__AVX2__)
    __m256i y[4];
    std::memcpy(y, &b, sizeof y);
    const __m256i x = _mm256_set1_epi64x(a);
    std::uint32_t r = 0;
    for (int h = 0; h < 4; ++h) {
        const __m256i positive = _mm256_cmpgt_epi64(_mm256_add_epi64(x, y[h]), _mm256_setzero_si256());
        r |= std::uint32_t(_mm256_movemask_pd(_mm256_castsi256_pd(positive))) << (4 * h);
    }
    return r;
#else
    std::uint32_t r = 0;
    for (int i = 0; i < kBatchLanes; ++i) r |= std::uint32_t(a + b[i] > 0) << i;
    return r;
#endif
}

// `to` with the lanes of v at the set bits of `lanes` packed into its lanes first, first + 1, ...
// (in order; first + popcount(lanes) <= kBatchLanes), its other lanes as they were. Computed in
// registers, so that a batch gathered block by block is stored whole each time and its next
// (whole) load is forwarded from that store: gathered with scalar or variable-length copies, the
// load waited for every older store to reach the cache.
[[gnu::always_inline]] inline Ints append(const Ints& to, int first, std::uint32_t lanes, const Ints& v) {
#if defined(__AVX512F__)
    const __mmask16 slots = __mmask16(((1u << std::popcount(lanes)) - 1u) << first);
    return Ints(_mm512_mask_expand_epi32(__m512i(to), slots, _mm512_maskz_compress_epi32(__mmask16(lanes), __m512i(v))));
#else
    Ints r = to;
    for (std::uint32_t m = lanes; m != 0; m &= m - 1) r[first++] = v[std::countr_zero(m)];
    return r;
#endif
}

// The lowest n set bits of `mask` (all of them when it has n or fewer).
inline std::uint32_t lowest_bits(std::uint32_t mask, int n) {
#if defined(__BMI2__)
    return n >= 32 ? mask : _pdep_u32((1u << n) - 1u, mask);
#else
    std::uint32_t r = 0;
    for (; mask != 0 && n > 0; mask &= mask - 1, --n) r |= mask & -mask;
    return r;
#endif
}

// The bits of `bits` at the set bits of `mask`, packed from bit 0 up (BMI2's pext).
inline std::uint32_t compress_bits(std::uint32_t bits, std::uint32_t mask) {
#if defined(__BMI2__)
    return _pext_u32(bits, mask);
#else
    std::uint32_t r = 0;
    for (int n = 0; mask != 0; mask &= mask - 1, ++n) r |= (bits >> std::countr_zero(mask) & 1u) << n;
    return r;
#endif
}

}  // namespace qs::lanes16
