#pragma once
// GCC vectors (`T __attribute__((vector_size(...)))`), the storage of Lanes, IntLanes and their
// masks, and the few operations on them that C++ operators do not cover.
//
// Why GCC vectors and not std::experimental::simd: a batch holds 16 (or 32) floats. Where the
// CPU's registers hold 16 (AVX-512) libstdc++ gives a native simd whose operations are always
// inlined; where they hold 8 (AVX2) it gives fixed_size<16>, whose operations are ordinary
// functions that GCC 12 stops inlining once a translation unit full of shader instantiations has
// used up its inlining budget (`--param inline-unit-growth`): every + and * became a call, and
// the shaders ran ten times slower on AVX2 than the same code with AVX-512 (measured with
// quadshade-bench-core and -fopt-info-inline-missed; docs/design.md). Operators on GCC vectors
// are the compiler's own: lowered to as many registers as the CPU has, never a call.
//
// by_register applies an operation on the CPU's native vector (__m256, __m128, ...) to each
// register-sized part of a wider GCC vector, halving it with shuffles the compiler removes.

#include <bit>
#include <cmath>
#include <cstddef>
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

// Halves of a vector (shuffles the compiler removes), and two halves joined.
template <class V>
[[gnu::always_inline]] inline auto low_half(const V& x) {
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        return __builtin_shufflevector(x, x, I...);
    }(std::make_index_sequence<std::size_t(size_v<V> / 2)>());
}
template <class V>
[[gnu::always_inline]] inline auto high_half(const V& x) {
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        return __builtin_shufflevector(x, x, (I + size_v<V> / 2)...);
    }(std::make_index_sequence<std::size_t(size_v<V> / 2)>());
}
template <class V>
[[gnu::always_inline]] inline auto join(const V& a, const V& b) {
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        return __builtin_shufflevector(a, b, I...);
    }(std::make_index_sequence<std::size_t(2 * size_v<V>)>());
}

// op applied to register-wide parts of vectors with the same number of lanes, the results
// joined: for what GCC 12 scalarizes on vectors wider than a register. Its comparisons of
// 16-float vectors on AVX2 became sixteen vcomiss/seta pairs, and `mask ? a : b` with a mask held
// in a variable sixteen cmovs; on register-wide parts each is one vcmpps or vblendvps.
template <class Op, class V, class... W>
[[gnu::always_inline]] inline auto lanewise(Op op, const V& x, const W&... y) {
    static_assert(((size_v<W> == size_v<V>) && ...));
    if constexpr (sizeof(V) <= register_bytes && ((sizeof(W) <= register_bytes) && ...)) {
        return op(x, y...);
    } else {
        return join(lanewise(op, low_half(x), low_half(y)...), lanewise(op, high_half(x), high_half(y)...));
    }
}

// Apply op, a function of the CPU's native vector type Native (__m256, ...), to each
// Native-sized part of x.
template <class Native, class V, class Op>
[[gnu::always_inline]] inline V by_register(const V& x, Op op) {
    if constexpr (sizeof(V) == sizeof(Native)) {
        return std::bit_cast<V>(op(std::bit_cast<Native>(x)));
    } else {
        static_assert(sizeof(V) % sizeof(Native) == 0 && size_v<V> % 2 == 0);
        return join(by_register<Native>(low_half(x), op), by_register<Native>(high_half(x), op));
    }
}

// Comparisons into masks (all ones where true, of the width of the compared elements), and
// the choice per lane by a mask.
template <class V>
[[gnu::always_inline]] inline auto less(const V& a, const V& b) {
    return lanewise([](const auto& x, const auto& y) { return x < y; }, a, b);
}
template <class V>
[[gnu::always_inline]] inline auto less_equal(const V& a, const V& b) {
    return lanewise([](const auto& x, const auto& y) { return x <= y; }, a, b);
}
template <class V>
[[gnu::always_inline]] inline auto equal(const V& a, const V& b) {
    return lanewise([](const auto& x, const auto& y) { return x == y; }, a, b);
}
template <class V>
[[gnu::always_inline]] inline auto not_equal(const V& a, const V& b) {
    return lanewise([](const auto& x, const auto& y) { return x != y; }, a, b);
}
template <class M, class V>
[[gnu::always_inline]] inline V select(const M& mask, const V& a, const V& b) {
    return lanewise([](const auto& m, const auto& x, const auto& y) { return m ? x : y; }, mask, a, b);
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
    if constexpr (sizeof(V) % 64 == 0) {
        if constexpr (std::is_same_v<T, float>) return by_register<__m512>(x, [](__m512 c) { return _mm512_roundscale_ps(c, mode); });
        else return by_register<__m512d>(x, [](__m512d c) { return _mm512_roundscale_pd(c, mode); });
    }
#endif
#if defined(__AVX__)
    if constexpr (sizeof(V) % 32 == 0) {
        if constexpr (std::is_same_v<T, float>) return by_register<__m256>(x, [](__m256 c) { return _mm256_round_ps(c, mode); });
        else return by_register<__m256d>(x, [](__m256d c) { return _mm256_round_pd(c, mode); });
    }
#endif
    if constexpr (sizeof(V) % 16 == 0) {
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
    if constexpr (sizeof(V) % 64 == 0) {
        if constexpr (std::is_same_v<T, float>) return by_register<__m512>(x, [](__m512 c) { return _mm512_sqrt_ps(c); });
        else return by_register<__m512d>(x, [](__m512d c) { return _mm512_sqrt_pd(c); });
    }
#endif
#if defined(__AVX__)
    if constexpr (sizeof(V) % 32 == 0) {
        if constexpr (std::is_same_v<T, float>) return by_register<__m256>(x, [](__m256 c) { return _mm256_sqrt_ps(c); });
        else return by_register<__m256d>(x, [](__m256d c) { return _mm256_sqrt_pd(c); });
    }
#endif
#if defined(__SSE2__)
    if constexpr (sizeof(V) % 16 == 0) {
        if constexpr (std::is_same_v<T, float>) return by_register<__m128>(x, [](__m128 c) { return _mm_sqrt_ps(c); });
        else return by_register<__m128d>(x, [](__m128d c) { return _mm_sqrt_pd(c); });
    }
#endif
    return per_element(x, [](auto e) { return std::sqrt(e); });
}

// Whether any element of an integer vector is non-zero: the register-wide parts ORed together
// in registers, then one vptest (testing the parts through memory stalled on the stores).
template <class V>
[[gnu::always_inline]] inline bool any(const V& m) {
    if constexpr (sizeof(V) > register_bytes) {
        return any(low_half(m) | high_half(m));
    } else {
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
}
// m's lanes are all ones or zero: all are set where none of ~m is.
template <class V>
[[gnu::always_inline]] inline bool all_set(const V& m) {
    return !any(~m);
}

}  // namespace qs::simd
