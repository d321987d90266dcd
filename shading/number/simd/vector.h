#pragma once
// The vocabulary of the SIMD layer (simd.h): GCC/Clang generic vectors of N values of T, the
// register-sized pieces that wider ones are taken apart into, and the names of the rounding and
// extremum rules its operations take. Nothing here depends on the target.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>

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

// The vector of V's size with elements of type T (int32 for a float vector's conversions).
template <class T, class V>
using like_t = Vector<T, int(sizeof(V) / sizeof(T))>;
// int32 lanes, one per element of V (half V's size for a vector of doubles).
template <class V>
using ints_of_t = Vector<std::int32_t, size_v<V>>;

// An unaligned V in memory, which may alias anything: what one vector load or store reads or
// writes (a memcpy of a whole wide vector takes its address, and may be split).
template <class T, std::size_t Bytes>
struct unaligned_of {
    typedef T type __attribute__((vector_size(Bytes), aligned(alignof(T)), may_alias));
};
template <class V>
using Unaligned = typename unaligned_of<element_t<V>, sizeof(V)>::type;

template <class V>
[[gnu::always_inline]] inline V load(const element_t<V>* p) {
    return *reinterpret_cast<const Unaligned<V>*>(p);
}
template <class V>
[[gnu::always_inline]] inline void store(element_t<V>* p, const V& v) {
    *reinterpret_cast<Unaligned<V>*>(p) = v;
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

// Rounding to an integer value, as roundps/roundpd do and llvmpipe emits for floor, ceil, trunc
// and roundEven.
enum class Rounding { Floor, Ceil, Trunc, NearestEven };

// a < b ? a : b (Min) or a > b ? a : b (Max): minps/maxps (simd.h, extremum_or_second).
enum class Extremum { Min, Max };

// Lane masks as bits: bit i for lane i.
using LaneBits = std::uint32_t;

}  // namespace qs::simd
