#pragma once
// The x86 target of 512-bit registers: AVX-512 F, BW, DQ and VL (Skylake-X, Ice Lake, Zen 4
// and later) on top of avx2.h. The operations on vectors of 64 bytes by their instructions, and
// those that AVX-512 alone has: comparisons straight into lane masks, masked moves, permutes and
// gathers, compress and expand, and the two-register table lookup.

#include "shading/number/simd/avx2.h"

namespace qs::simd::isa {

using Float16 = Vector<float, 16>;
using Double8 = Vector<double, 8>;
using Int16 = Vector<std::int32_t, 16>;
using Long8 = Vector<std::int64_t, 8>;

template <Rounding R>
[[gnu::always_inline]] inline Float16 round(const Float16& x) {
    return by_register<__m512>(x, [](__m512 c) { return _mm512_roundscale_ps(c, kRoundingControl<R>); });
}
template <Rounding R>
[[gnu::always_inline]] inline Double8 round(const Double8& x) {
    return by_register<__m512d>(x, [](__m512d c) { return _mm512_roundscale_pd(c, kRoundingControl<R>); });
}

[[gnu::always_inline]] inline Float16 sqrt(const Float16& x) {
    return by_register<__m512>(x, [](__m512 c) { return _mm512_sqrt_ps(c); });
}
[[gnu::always_inline]] inline Double8 sqrt(const Double8& x) {
    return by_register<__m512d>(x, [](__m512d c) { return _mm512_sqrt_pd(c); });
}

template <Extremum E>
[[gnu::always_inline]] inline Float16 extremum_or_second(const Float16& a, const Float16& b) {
    if constexpr (E == Extremum::Min) return by_register<__m512>(a, b, [](__m512 x, __m512 y) { return _mm512_min_ps(x, y); });
    else return by_register<__m512>(a, b, [](__m512 x, __m512 y) { return _mm512_max_ps(x, y); });
}
template <Extremum E>
[[gnu::always_inline]] inline Double8 extremum_or_second(const Double8& a, const Double8& b) {
    if constexpr (E == Extremum::Min) return by_register<__m512d>(a, b, [](__m512d x, __m512d y) { return _mm512_min_pd(x, y); });
    else return by_register<__m512d>(a, b, [](__m512d x, __m512d y) { return _mm512_max_pd(x, y); });
}

[[gnu::always_inline]] inline Float16 fma(const Float16& a, const Float16& b, const Float16& c) {
    return by_register<__m512>(a, b, c, [](__m512 x, __m512 y, __m512 z) { return _mm512_fmadd_ps(x, y, z); });
}
[[gnu::always_inline]] inline Double8 fma(const Double8& a, const Double8& b, const Double8& c) {
    return by_register<__m512d>(a, b, c, [](__m512d x, __m512d y, __m512d z) { return _mm512_fmadd_pd(x, y, z); });
}
template <class V>
    requires(std::is_floating_point_v<element_t<V>> && sizeof(V) == 64)
[[gnu::always_inline]] inline V exact_product_add(const V& a, const V& b, const V& c) {
    return fma(a, b, c);
}

template <class V>
    requires(sizeof(V) == 64 && std::is_integral_v<element_t<V>>)
[[gnu::always_inline]] inline bool any(const V& m) {
    const __m512i x = std::bit_cast<__m512i>(m);
    return _mm512_test_epi32_mask(x, x) != 0;
}

[[gnu::always_inline]] inline Int16 convert_nearest(const Float16& x) {
    return std::bit_cast<Int16>(_mm512_cvtps_epi32(std::bit_cast<__m512>(x)));
}
[[gnu::always_inline]] inline Int16 convert_truncate(const Float16& x) {
    return std::bit_cast<Int16>(_mm512_cvttps_epi32(std::bit_cast<__m512>(x)));
}
[[gnu::always_inline]] inline Int8 convert_truncate(const Double8& x) {
    return std::bit_cast<Int8>(_mm512_cvttpd_epi32(std::bit_cast<__m512d>(x)));
}

[[gnu::always_inline]] inline Vector<std::uint32_t, 16> gather(const std::uint32_t* base, const Int16& index) {
    return std::bit_cast<Vector<std::uint32_t, 16>>(_mm512_i32gather_epi32(std::bit_cast<__m512i>(index), base, 4));
}
template <class U>
    requires Words<U, 64>
[[gnu::always_inline]] inline U gather_into(const U& src, LaneBits lanes, const std::uint32_t* base, const Int16& index) {
    return std::bit_cast<U>(
        _mm512_mask_i32gather_epi32(std::bit_cast<__m512i>(src), __mmask16(lanes), std::bit_cast<__m512i>(index), base, 4));
}

[[gnu::always_inline]] inline Vector<std::int16_t, 32> multiply_high_rounded(const Vector<std::int16_t, 32>& a,
                                                                           const Vector<std::int16_t, 32>& b) {
    return by_register<__m512i>(a, b, [](__m512i x, __m512i y) { return _mm512_mulhrs_epi16(x, y); });
}

template <class V, class I>
    requires(Words<V, 64> && Words<I, 64>)
[[gnu::always_inline]] inline V permute(const V& table, const I& index) {
    return std::bit_cast<V>(_mm512_permutexvar_epi32(std::bit_cast<__m512i>(index), std::bit_cast<__m512i>(table)));
}
template <class V, class I>
    requires(Words<V, 64> && Words<I, 64>)
[[gnu::always_inline]] inline V permute_into(const V& src, LaneBits lanes, const V& table, const I& index) {
    return std::bit_cast<V>(_mm512_mask_permutexvar_epi32(std::bit_cast<__m512i>(src), __mmask16(lanes),
                                                          std::bit_cast<__m512i>(index), std::bit_cast<__m512i>(table)));
}
template <class I>
    requires Words<I, 64>
[[gnu::always_inline]] inline Float16 lookup(const Float16& low, const Float16& high, const I& index) {
    return std::bit_cast<Float16>(
        _mm512_permutex2var_ps(std::bit_cast<__m512>(low), std::bit_cast<__m512i>(index), std::bit_cast<__m512>(high)));
}
template <class V, class I>
    requires(Words<V, 64> && Words<I, 64>)
[[gnu::always_inline]] inline V lookup(const V& low, const V& high, const I& index) {
    return std::bit_cast<V>(
        _mm512_permutex2var_epi32(std::bit_cast<__m512i>(low), std::bit_cast<__m512i>(index), std::bit_cast<__m512i>(high)));
}

[[gnu::always_inline]] inline Float16 select(LaneBits lanes, const Float16& a, const Float16& b) {
    return std::bit_cast<Float16>(_mm512_mask_mov_ps(std::bit_cast<__m512>(b), __mmask16(lanes), std::bit_cast<__m512>(a)));
}
[[gnu::always_inline]] inline Double8 select(LaneBits lanes, const Double8& a, const Double8& b) {
    return std::bit_cast<Double8>(_mm512_mask_mov_pd(std::bit_cast<__m512d>(b), __mmask8(lanes), std::bit_cast<__m512d>(a)));
}

[[gnu::always_inline]] inline LaneBits less_bits(const Float16& a, const Float16& b) {
    return _mm512_cmp_ps_mask(std::bit_cast<__m512>(a), std::bit_cast<__m512>(b), _CMP_LT_OQ);
}
template <class V>
    requires Words<V, 64>
[[gnu::always_inline]] inline LaneBits equal_bits(const V& a, const V& b) {
    return _mm512_cmpeq_epi32_mask(std::bit_cast<__m512i>(a), std::bit_cast<__m512i>(b));
}
[[gnu::always_inline]] inline LaneBits greater_bits(const Long8& a, const Long8& b) {
    return _mm512_cmpgt_epi64_mask(std::bit_cast<__m512i>(a), std::bit_cast<__m512i>(b));
}
template <class V>
    requires Words<V, 64>
[[gnu::always_inline]] inline LaneBits less_unsigned_bits(const V& a, const V& b) {
    return _mm512_cmplt_epu32_mask(std::bit_cast<__m512i>(a), std::bit_cast<__m512i>(b));
}
template <class V>
    requires Words<V, 64>
[[gnu::always_inline]] inline LaneBits none_common_bits(const V& a, const V& b) {
    return _mm512_testn_epi32_mask(std::bit_cast<__m512i>(a), std::bit_cast<__m512i>(b));
}

template <class V>
    requires Words<V, 64>
[[gnu::always_inline]] inline V append(const V& to, int first, LaneBits lanes, const V& v) {
    const __mmask16 slots = __mmask16(((1u << std::popcount(lanes)) - 1u) << first);
    return std::bit_cast<V>(_mm512_mask_expand_epi32(std::bit_cast<__m512i>(to), slots,
                                                     _mm512_maskz_compress_epi32(__mmask16(lanes), std::bit_cast<__m512i>(v))));
}

[[gnu::always_inline]] inline void stream(float* p, const Float16& v) { _mm512_stream_ps(p, std::bit_cast<__m512>(v)); }

struct Avx512 : Avx2 {
    static constexpr const char* name = "AVX-512";
    static constexpr std::size_t register_bytes = 64;
};

}  // namespace qs::simd::isa
