#pragma once
// The x86 target of 256-bit registers: AVX2 with FMA and BMI2 (Haswell, Zen and later). The
// operations on vectors of 32 bytes by their instructions, the fused multiply-add on 16 bytes
// too, and BMI2's bit deposit and extraction; 16-byte vectors as sse.h.

#include "shading/number/simd/sse.h"

namespace qs::simd::isa {

using Float8 = Vector<float, 8>;
using Double4 = Vector<double, 4>;
using Int8 = Vector<std::int32_t, 8>;
using Uint8 = Vector<std::uint32_t, 8>;
using Long4 = Vector<std::int64_t, 4>;

// Vectors of Bytes bytes of 32-bit integers, signed or not.
template <class V, std::size_t Bytes>
concept Words = sizeof(V) == Bytes && std::is_integral_v<element_t<V>> && sizeof(element_t<V>) == 4;

template <Rounding R>
[[gnu::always_inline]] inline Float8 round(const Float8& x) {
    return by_register<__m256>(x, [](__m256 c) { return _mm256_round_ps(c, kRoundingControl<R>); });
}
template <Rounding R>
[[gnu::always_inline]] inline Double4 round(const Double4& x) {
    return by_register<__m256d>(x, [](__m256d c) { return _mm256_round_pd(c, kRoundingControl<R>); });
}

[[gnu::always_inline]] inline Float8 sqrt(const Float8& x) {
    return by_register<__m256>(x, [](__m256 c) { return _mm256_sqrt_ps(c); });
}
[[gnu::always_inline]] inline Double4 sqrt(const Double4& x) {
    return by_register<__m256d>(x, [](__m256d c) { return _mm256_sqrt_pd(c); });
}

template <Extremum E>
[[gnu::always_inline]] inline Float8 extremum_or_second(const Float8& a, const Float8& b) {
    if constexpr (E == Extremum::Min) return by_register<__m256>(a, b, [](__m256 x, __m256 y) { return _mm256_min_ps(x, y); });
    else return by_register<__m256>(a, b, [](__m256 x, __m256 y) { return _mm256_max_ps(x, y); });
}
template <Extremum E>
[[gnu::always_inline]] inline Double4 extremum_or_second(const Double4& a, const Double4& b) {
    if constexpr (E == Extremum::Min) return by_register<__m256d>(a, b, [](__m256d x, __m256d y) { return _mm256_min_pd(x, y); });
    else return by_register<__m256d>(a, b, [](__m256d x, __m256d y) { return _mm256_max_pd(x, y); });
}

// One instruction, rounded once: what std::fma computes, and what a * b + c computes where the
// product is exact.
[[gnu::always_inline]] inline Float4 fma(const Float4& a, const Float4& b, const Float4& c) {
    return by_register<__m128>(a, b, c, [](__m128 x, __m128 y, __m128 z) { return _mm_fmadd_ps(x, y, z); });
}
[[gnu::always_inline]] inline Double2 fma(const Double2& a, const Double2& b, const Double2& c) {
    return by_register<__m128d>(a, b, c, [](__m128d x, __m128d y, __m128d z) { return _mm_fmadd_pd(x, y, z); });
}
[[gnu::always_inline]] inline Float8 fma(const Float8& a, const Float8& b, const Float8& c) {
    return by_register<__m256>(a, b, c, [](__m256 x, __m256 y, __m256 z) { return _mm256_fmadd_ps(x, y, z); });
}
[[gnu::always_inline]] inline Double4 fma(const Double4& a, const Double4& b, const Double4& c) {
    return by_register<__m256d>(a, b, c, [](__m256d x, __m256d y, __m256d z) { return _mm256_fmadd_pd(x, y, z); });
}
[[gnu::always_inline]] inline float exact_product_add(float a, float b, float c) { return std::fma(a, b, c); }
[[gnu::always_inline]] inline double exact_product_add(double a, double b, double c) { return std::fma(a, b, c); }
template <class V>
    requires(std::is_floating_point_v<element_t<V>> && (sizeof(V) == 16 || sizeof(V) == 32))
[[gnu::always_inline]] inline V exact_product_add(const V& a, const V& b, const V& c) {
    return fma(a, b, c);
}

template <class V>
    requires(sizeof(V) == 32 && std::is_integral_v<element_t<V>>)
[[gnu::always_inline]] inline bool any(const V& m) {
    const __m256i x = std::bit_cast<__m256i>(m);
    return !_mm256_testz_si256(x, x);
}

[[gnu::always_inline]] inline Int8 convert_nearest(const Float8& x) {
    return std::bit_cast<Int8>(_mm256_cvtps_epi32(std::bit_cast<__m256>(x)));
}
[[gnu::always_inline]] inline Int8 convert_truncate(const Float8& x) {
    return std::bit_cast<Int8>(_mm256_cvttps_epi32(std::bit_cast<__m256>(x)));
}
[[gnu::always_inline]] inline Int4 convert_truncate(const Double4& x) {
    return std::bit_cast<Int4>(_mm256_cvttpd_epi32(std::bit_cast<__m256d>(x)));
}

[[gnu::always_inline]] inline Uint8 gather(const std::uint32_t* base, const Int8& index) {
    return std::bit_cast<Uint8>(_mm256_i32gather_epi32(reinterpret_cast<const int*>(base), std::bit_cast<__m256i>(index), 4));
}

[[gnu::always_inline]] inline Vector<std::int16_t, 16> multiply_high_rounded(const Vector<std::int16_t, 16>& a,
                                                                           const Vector<std::int16_t, 16>& b) {
    return by_register<__m256i>(a, b, [](__m256i x, __m256i y) { return _mm256_mulhrs_epi16(x, y); });
}

template <class V, class I>
    requires(Words<V, 32> && Words<I, 32>)
[[gnu::always_inline]] inline V permute(const V& table, const I& index) {
    return std::bit_cast<V>(_mm256_permutevar8x32_epi32(std::bit_cast<__m256i>(table), std::bit_cast<__m256i>(index)));
}
template <unsigned Lanes, class V>
    requires Words<V, 32>
[[gnu::always_inline]] inline V blend(const V& a, const V& b) {
    return by_register<__m256i>(a, b, [](__m256i x, __m256i y) { return _mm256_blend_epi32(x, y, Lanes); });
}

[[gnu::always_inline]] inline LaneBits less_bits(const Float8& a, const Float8& b) {
    return LaneBits(_mm256_movemask_ps(_mm256_cmp_ps(std::bit_cast<__m256>(a), std::bit_cast<__m256>(b), _CMP_LT_OQ)));
}
template <class V>
    requires Words<V, 32>
[[gnu::always_inline]] inline LaneBits equal_bits(const V& a, const V& b) {
    return LaneBits(_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(std::bit_cast<__m256i>(a), std::bit_cast<__m256i>(b)))));
}
[[gnu::always_inline]] inline LaneBits greater_bits(const Long4& a, const Long4& b) {
    return LaneBits(_mm256_movemask_pd(_mm256_castsi256_pd(_mm256_cmpgt_epi64(std::bit_cast<__m256i>(a), std::bit_cast<__m256i>(b)))));
}

[[gnu::always_inline]] inline void stream(float* p, const Float8& v) { _mm256_stream_ps(p, std::bit_cast<__m256>(v)); }

struct Avx2 : Sse {
    static constexpr const char* name = "AVX2";
    static constexpr std::size_t register_bytes = 32;

    [[gnu::always_inline]] static constexpr bool cpu_has_fma() { return true; }

    [[gnu::always_inline]] static std::uint32_t deposit_low_bits(int n, std::uint32_t mask) {
        return _pdep_u32((1u << n) - 1u, mask);
    }
    [[gnu::always_inline]] static std::uint32_t extract_bits(std::uint32_t bits, std::uint32_t mask) {
        return _pext_u32(bits, mask);
    }
};

}  // namespace qs::simd::isa
