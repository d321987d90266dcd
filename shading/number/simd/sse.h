#pragma once
// The x86-64 target of 128-bit registers (SSE2, the baseline every x86-64 CPU has, and SSE4.1's
// rounding and test where the build's CPU has them): the portable operations (portable.h) on
// vectors of 16 bytes, by their instructions. The wider targets (avx2.h, avx512.h) build on it.

#include <bit>
#include <immintrin.h>

#include "shading/number/simd/portable.h"

namespace qs::simd::isa {

// A vector as the intrinsics' type of the same size, and back.
template <class Native, class V, class Op>
[[gnu::always_inline]] inline V by_register(const V& x, Op op) {
    static_assert(sizeof(V) == sizeof(Native));
    return std::bit_cast<V>(op(std::bit_cast<Native>(x)));
}
template <class Native, class V, class Op>
[[gnu::always_inline]] inline V by_register(const V& a, const V& b, Op op) {
    static_assert(sizeof(V) == sizeof(Native));
    return std::bit_cast<V>(op(std::bit_cast<Native>(a), std::bit_cast<Native>(b)));
}
template <class Native, class V, class Op>
[[gnu::always_inline]] inline V by_register(const V& a, const V& b, const V& c, Op op) {
    static_assert(sizeof(V) == sizeof(Native));
    return std::bit_cast<V>(op(std::bit_cast<Native>(a), std::bit_cast<Native>(b), std::bit_cast<Native>(c)));
}

using Float4 = Vector<float, 4>;
using Double2 = Vector<double, 2>;
using Int4 = Vector<std::int32_t, 4>;

// Rounding control of roundps for each rule, without exceptions.
template <Rounding R>
inline constexpr int kRoundingControl = (R == Rounding::Floor  ? _MM_FROUND_TO_NEG_INF
                                         : R == Rounding::Ceil ? _MM_FROUND_TO_POS_INF
                                         : R == Rounding::Trunc ? _MM_FROUND_TO_ZERO
                                                                : _MM_FROUND_TO_NEAREST_INT) |
                                        _MM_FROUND_NO_EXC;

#if defined(__SSE4_1__)
template <Rounding R>
[[gnu::always_inline]] inline Float4 round(const Float4& x) {
    return by_register<__m128>(x, [](__m128 c) { return _mm_round_ps(c, kRoundingControl<R>); });
}
template <Rounding R>
[[gnu::always_inline]] inline Double2 round(const Double2& x) {
    return by_register<__m128d>(x, [](__m128d c) { return _mm_round_pd(c, kRoundingControl<R>); });
}
template <class V>
    requires(sizeof(V) == 16 && std::is_integral_v<element_t<V>>)
[[gnu::always_inline]] inline bool any(const V& m) {
    const __m128i x = std::bit_cast<__m128i>(m);
    return !_mm_testz_si128(x, x);
}
#endif

[[gnu::always_inline]] inline Float4 sqrt(const Float4& x) {
    return by_register<__m128>(x, [](__m128 c) { return _mm_sqrt_ps(c); });
}
[[gnu::always_inline]] inline Double2 sqrt(const Double2& x) {
    return by_register<__m128d>(x, [](__m128d c) { return _mm_sqrt_pd(c); });
}

template <Extremum E>
[[gnu::always_inline]] inline Float4 extremum_or_second(const Float4& a, const Float4& b) {
    if constexpr (E == Extremum::Min) return by_register<__m128>(a, b, [](__m128 x, __m128 y) { return _mm_min_ps(x, y); });
    else return by_register<__m128>(a, b, [](__m128 x, __m128 y) { return _mm_max_ps(x, y); });
}
template <Extremum E>
[[gnu::always_inline]] inline Double2 extremum_or_second(const Double2& a, const Double2& b) {
    if constexpr (E == Extremum::Min) return by_register<__m128d>(a, b, [](__m128d x, __m128d y) { return _mm_min_pd(x, y); });
    else return by_register<__m128d>(a, b, [](__m128d x, __m128d y) { return _mm_max_pd(x, y); });
}

[[gnu::always_inline]] inline Int4 convert_nearest(const Float4& x) {
    return std::bit_cast<Int4>(_mm_cvtps_epi32(std::bit_cast<__m128>(x)));
}
[[gnu::always_inline]] inline Int4 convert_truncate(const Float4& x) {
    return std::bit_cast<Int4>(_mm_cvttps_epi32(std::bit_cast<__m128>(x)));
}

[[gnu::always_inline]] inline void stream(float* p, const Float4& v) { _mm_stream_ps(p, std::bit_cast<__m128>(v)); }

struct Sse : Portable {
    static constexpr const char* name = "SSE";
    static constexpr std::size_t register_bytes = 16;

    // Asked of the CPU once: the build's target does not say.
    static bool cpu_has_fma() {
        static const bool fma = __builtin_cpu_supports("fma");
        return fma;
    }

    [[gnu::always_inline]] static void streaming_stores_done() { _mm_sfence(); }

    static constexpr bool kControlsDenormals = true;
    [[gnu::always_inline]] static unsigned float_control() { return _mm_getcsr(); }
    [[gnu::always_inline]] static void set_float_control(unsigned control) { _mm_setcsr(control); }
    // MXCSR's flush to zero (bit 15) and denormals are zero (bit 6).
    [[gnu::always_inline]] static unsigned flush_denormals(unsigned control) { return control | 1u << 15 | 1u << 6; }
};

}  // namespace qs::simd::isa
