#pragma once
// GCC vectors (`T __attribute__((vector_size(...)))`) of at most one register, the parts of
// simd::Wide (wide_vector.h), and the few operations on them that C++ operators do not cover:
// rounding, square roots, minps/maxps, exact products' additions and any() by the CPU's own
// instructions, and splat.

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace qs::simd {

template <class T, int N>
struct vector_of {
    typedef T type __attribute__((vector_size(N * sizeof(T))));
};
// N values of T as one GCC vector (N = 1 is a vector of one element: the per-pixel numbers).
template <class T, int N>
using Vector = typename vector_of<T, N>::type;

template <class V>
using element_t = std::remove_cvref_t<decltype(std::declval<V>()[0])>;
template <class V>
inline constexpr int size_v = int(sizeof(V) / sizeof(element_t<V>));

// x in every lane (as an initializer, which keeps -0.0: `V{} + x` would make it +0.0).
template <class V>
[[gnu::always_inline]] inline V splat(element_t<V> x) {
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        return V{((void)I, x)...};
    }(std::make_index_sequence<std::size_t(size_v<V>)>());
}

// The widest vector register the build's CPU has, in bytes.
inline constexpr std::size_t register_bytes =
#if defined(__AVX512F__)
    64;
#elif defined(__AVX2__)
    32;
#else
    16;
#endif

// Apply op, a function of the CPU's native vector type Native (__m256, ...), to x of the same size
// (or to a, b and c).
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

// f of each element, for what has no vector instruction (transcendentals: the library's
// functions, element by element, as libstdc++'s simd computes them).
template <class V, class F>
V per_element(const V& x, F f) {
    V r;
    for (int i = 0; i < size_v<V>; ++i) r[i] = f(x[i]);
    return r;
}
template <class V, class F>
V per_element(const V& x, const V& y, F f) {
    V r;
    for (int i = 0; i < size_v<V>; ++i) r[i] = f(x[i], y[i]);
    return r;
}

// Rounding to an integer value in the direction Mode (_MM_FROUND_TO_NEG_INF, ..._POS_INF,
// ..._ZERO, ..._NEAREST_INT), with roundps/roundpd as llvmpipe emits for floor, ceil, trunc and
// roundEven; the library's functions where SSE4.1 is missing (the same values).
enum class Rounding { Floor, Ceil, Trunc, NearestEven };

template <Rounding R, class V>
[[gnu::always_inline]] inline V round(const V& x) {
#if defined(__SSE4_1__)
    [[maybe_unused]] constexpr int mode = (R == Rounding::Floor  ? _MM_FROUND_TO_NEG_INF
                          : R == Rounding::Ceil ? _MM_FROUND_TO_POS_INF
                          : R == Rounding::Trunc ? _MM_FROUND_TO_ZERO
                                                 : _MM_FROUND_TO_NEAREST_INT) |
                         _MM_FROUND_NO_EXC;
    using T [[maybe_unused]] = element_t<V>;
#if defined(__AVX512F__)
    if constexpr (sizeof(V) == 64) {
        if constexpr (std::is_same_v<T, float>) return by_register<__m512>(x, [](__m512 c) { return _mm512_roundscale_ps(c, mode); });
        else return by_register<__m512d>(x, [](__m512d c) { return _mm512_roundscale_pd(c, mode); });
    }
#endif
#if defined(__AVX__)
    if constexpr (sizeof(V) == 32) {
        if constexpr (std::is_same_v<T, float>) return by_register<__m256>(x, [](__m256 c) { return _mm256_round_ps(c, mode); });
        else return by_register<__m256d>(x, [](__m256d c) { return _mm256_round_pd(c, mode); });
    }
#endif
    if constexpr (sizeof(V) == 16) {
        if constexpr (std::is_same_v<T, float>) return by_register<__m128>(x, [](__m128 c) { return _mm_round_ps(c, mode); });
        else return by_register<__m128d>(x, [](__m128d c) { return _mm_round_pd(c, mode); });
    }
#endif
    return per_element(x, [](auto e) {
        if constexpr (R == Rounding::Floor) return std::floor(e);
        else if constexpr (R == Rounding::Ceil) return std::ceil(e);
        else if constexpr (R == Rounding::Trunc) return std::trunc(e);
        else return std::nearbyint(e);  // the rounding mode shading threads never change: to even
    });
}

// The correctly rounded square root (sqrtps/sqrtpd; the library's sqrt, element by element, where
// the vector does not fill registers).
template <class V>
[[gnu::always_inline]] inline V sqrt(const V& x) {
    using T [[maybe_unused]] = element_t<V>;
#if defined(__AVX512F__)
    if constexpr (sizeof(V) == 64) {
        if constexpr (std::is_same_v<T, float>) return by_register<__m512>(x, [](__m512 c) { return _mm512_sqrt_ps(c); });
        else return by_register<__m512d>(x, [](__m512d c) { return _mm512_sqrt_pd(c); });
    }
#endif
#if defined(__AVX__)
    if constexpr (sizeof(V) == 32) {
        if constexpr (std::is_same_v<T, float>) return by_register<__m256>(x, [](__m256 c) { return _mm256_sqrt_ps(c); });
        else return by_register<__m256d>(x, [](__m256d c) { return _mm256_sqrt_pd(c); });
    }
#endif
#if defined(__SSE2__)
    if constexpr (sizeof(V) == 16) {
        if constexpr (std::is_same_v<T, float>) return by_register<__m128>(x, [](__m128 c) { return _mm_sqrt_ps(c); });
        else return by_register<__m128d>(x, [](__m128d c) { return _mm_sqrt_pd(c); });
    }
#endif
    return per_element(x, [](auto e) { return std::sqrt(e); });
}

// a < b ? a : b (Min) or a > b ? a : b (Max), element by element: b where the two are unordered
// (a NaN), and b where they are equal (+0 and -0 too). Exactly minps/maxps (and their pd forms),
// which GCC makes of the plain ternary, but not of one whose mask another test joins (GLSL's min
// ignores a NaN b) or whose b is a constant: there it kept a compare and a blend.
enum class Extremum { Min, Max };

template <Extremum E, class V>
[[gnu::always_inline]] inline V extremum_or_second(const V& a, const V& b) {
    using T [[maybe_unused]] = element_t<V>;
    constexpr bool kMin [[maybe_unused]] = E == Extremum::Min;
#if defined(__AVX512F__)
    if constexpr (sizeof(V) == 64) {
        if constexpr (std::is_same_v<T, float>) return by_register<__m512>(a, b, [](__m512 x, __m512 y) { return kMin ? _mm512_min_ps(x, y) : _mm512_max_ps(x, y); });
        else return by_register<__m512d>(a, b, [](__m512d x, __m512d y) { return kMin ? _mm512_min_pd(x, y) : _mm512_max_pd(x, y); });
    }
#endif
#if defined(__AVX__)
    if constexpr (sizeof(V) == 32) {
        if constexpr (std::is_same_v<T, float>) return by_register<__m256>(a, b, [](__m256 x, __m256 y) { return kMin ? _mm256_min_ps(x, y) : _mm256_max_ps(x, y); });
        else return by_register<__m256d>(a, b, [](__m256d x, __m256d y) { return kMin ? _mm256_min_pd(x, y) : _mm256_max_pd(x, y); });
    }
#endif
#if defined(__SSE2__)
    if constexpr (sizeof(V) == 16) {
        if constexpr (std::is_same_v<T, float>) return by_register<__m128>(a, b, [](__m128 x, __m128 y) { return kMin ? _mm_min_ps(x, y) : _mm_max_ps(x, y); });
        else return by_register<__m128d>(a, b, [](__m128d x, __m128d y) { return kMin ? _mm_min_pd(x, y) : _mm_max_pd(x, y); });
    }
#endif
    if constexpr (kMin) {
        return a < b ? a : b;
    } else {
        return a > b ? a : b;
    }
}

// a * b + c for operands whose product a * b is representable: one rounding (FMA) or two then
// give the same bits, so the build's CPU decides. With FMA it is one instruction, on a multiply
// pipe, one step shorter than the two; shaders use it only where the product is exact
// (noise/simplex2d.h says why there).
template <class V>
[[gnu::always_inline]] inline V exact_product_add(const V& a, const V& b, const V& c) {
#if defined(__FMA__)
    using T [[maybe_unused]] = element_t<V>;
#if defined(__AVX512F__)
    if constexpr (sizeof(V) == 64) {
        if constexpr (std::is_same_v<T, float>) return by_register<__m512>(a, b, c, [](__m512 x, __m512 y, __m512 z) { return _mm512_fmadd_ps(x, y, z); });
        else return by_register<__m512d>(a, b, c, [](__m512d x, __m512d y, __m512d z) { return _mm512_fmadd_pd(x, y, z); });
    }
#endif
    if constexpr (sizeof(V) == 32) {
        if constexpr (std::is_same_v<T, float>) return by_register<__m256>(a, b, c, [](__m256 x, __m256 y, __m256 z) { return _mm256_fmadd_ps(x, y, z); });
        else return by_register<__m256d>(a, b, c, [](__m256d x, __m256d y, __m256d z) { return _mm256_fmadd_pd(x, y, z); });
    }
    if constexpr (sizeof(V) == 16) {
        if constexpr (std::is_same_v<T, float>) return by_register<__m128>(a, b, c, [](__m128 x, __m128 y, __m128 z) { return _mm_fmadd_ps(x, y, z); });
        else return by_register<__m128d>(a, b, c, [](__m128d x, __m128d y, __m128d z) { return _mm_fmadd_pd(x, y, z); });
    }
#endif
    return a * b + c;
}

// Whether any element of an integer vector (at most one register wide) is non-zero: one test.
template <class V>
[[gnu::always_inline]] inline bool any(const V& m) {
    static_assert(sizeof(V) <= register_bytes);
#if defined(__AVX512F__)
    if constexpr (sizeof(V) == 64) {
        const __m512i x = std::bit_cast<__m512i>(m);
        return _mm512_test_epi32_mask(x, x) != 0;
    }
#endif
#if defined(__AVX__)
    if constexpr (sizeof(V) == 32) {
        const __m256i x = std::bit_cast<__m256i>(m);
        return !_mm256_testz_si256(x, x);
    }
#endif
#if defined(__SSE4_1__)
    if constexpr (sizeof(V) == 16) {
        const __m128i x = std::bit_cast<__m128i>(m);
        return !_mm_testz_si128(x, x);
    }
#endif
    for (int i = 0; i < size_v<V>; ++i)
        if (m[i]) return true;
    return false;
}

#if defined(__AVX512F__)
// Element i of the 32-entry table (low, high) at index[i], in [0, 32): one vpermt2ps.
[[gnu::always_inline]] inline Vector<float, 16> lookup(const Vector<float, 16>& low, const Vector<float, 16>& high,
                                                       const Vector<std::int32_t, 16>& index) {
    return std::bit_cast<Vector<float, 16>>(_mm512_permutex2var_ps(
        std::bit_cast<__m512>(low), std::bit_cast<__m512i>(index), std::bit_cast<__m512>(high)));
}
#endif
}  // namespace qs::simd
