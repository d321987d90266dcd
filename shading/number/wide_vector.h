#pragma once
// N values of T held as register-wide GCC vectors: the storage of Lanes, IntLanes and their masks.
//
// Why parts and not one GCC vector of N: a batch holds 16 (or 32) floats, and the CPU's registers
// hold 16 (AVX-512), 8 (AVX2) or 4 (SSE). A GCC vector wider than the registers is lowered piece
// by piece inside an expression, but where it lives in memory (a shader's loop variables, an
// array of them) it has no machine mode and GCC 12 copies it through general registers, element
// by element; it also scalarizes comparisons and `mask ? a : b` on such vectors. Before this,
// std::experimental::simd's fixed_size<16> (what it gives for 16 floats on AVX2) made every + and
// * an out-of-line call once a translation unit of shader instantiations had used up GCC's
// inlining budget. Wide<T, N> is an array of vectors the size of one register, each operation is
// always inlined and applies the compiler's own operator to each part: no calls, every part one
// register (measured in docs/design.md, "The number types are arrays of register-wide GCC
// vectors").
//
// Lanes keep their order: lane i is element i % part_size of part i / part_size, so a 2x2 quad
// (four consecutive lanes) lies in one part wherever a register holds four values or more.

#include <bit>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "shading/number/simd/simd.h"

namespace qs::simd {

#define QS_ALWAYS_INLINE __attribute__((always_inline))

// f(std::integral_constant<int, 0>), ..., f(std::integral_constant<int, P - 1>): unrolled, so
// that each part's index is a constant and the parts stay in registers.
template <int P, class F>
[[gnu::always_inline]] inline void for_each_part(F f) {
    [&]<int... I>(std::integer_sequence<int, I...>) QS_ALWAYS_INLINE {
        (f(std::integral_constant<int, I>{}), ...);
    }(std::make_integer_sequence<int, P>());
}

// The signed integer of T's width: what comparing two T yields, all ones where true.
template <class T>
using mask_bits_t = std::conditional_t<sizeof(T) == 8, std::int64_t, std::int32_t>;

template <class T, int N>
struct Wide {
    using value_type = T;
    static constexpr int lanes = N;
    // Lanes per part: a register's worth, or all N where they fit in less.
    static constexpr int part_size = N < int(register_bytes / sizeof(T)) ? N : int(register_bytes / sizeof(T));
    static constexpr int parts = N / part_size;
    static_assert(parts * part_size == N, "a power-of-two number of lanes");
    using Part = Vector<T, part_size>;

    Part part[parts];

    // One part per register, whatever each operation does to its parts.
    template <class R = Wide, class Op, class... W>
    [[gnu::always_inline]] static R map(Op op, const W&... w) {
        R r;
        for_each_part<parts>([&](auto p) QS_ALWAYS_INLINE { r.part[p] = op(w.part[p]...); });
        return r;
    }

    // x in every lane (as an initializer, which keeps -0.0: `V{} + x` would make it +0.0).
    [[gnu::always_inline]] static Wide splat(T x) {
        Wide r;
        const Part p = simd::splat<Part>(x);
        for_each_part<parts>([&](auto i) QS_ALWAYS_INLINE { r.part[i] = p; });
        return r;
    }
    // Loads and stores part by part, as one unaligned vector access each. Not a memcpy of the
    // whole Wide: that takes its address, and a variable whose address is taken stays in memory,
    // stored on every assignment (a shader loop's variables read back from the stack on each
    // iteration) and copied in halves through general registers.
    typedef T UnalignedPart __attribute__((vector_size(sizeof(Part)), aligned(alignof(T)), may_alias));
    [[gnu::always_inline]] static Wide load(const T* p) {
        Wide r;
        for_each_part<parts>([&](auto i) QS_ALWAYS_INLINE {
            r.part[i] = *reinterpret_cast<const UnalignedPart*>(p + i * part_size);
        });
        return r;
    }
    [[gnu::always_inline]] void store(T* p) const {
        for_each_part<parts>([&](auto i) QS_ALWAYS_INLINE { *reinterpret_cast<UnalignedPart*>(p + i * part_size) = part[i]; });
    }

    [[gnu::always_inline]] T operator[](int i) const { return part[i / part_size][i % part_size]; }

#define QS_WIDE_UNARY(op)                                                               \
    [[gnu::always_inline]] friend Wide operator op(const Wide& a) {                     \
        return map([](const Part& x) QS_ALWAYS_INLINE { return op x; }, a);             \
    }
#define QS_WIDE_BINARY(op)                                                              \
    [[gnu::always_inline]] friend Wide operator op(const Wide& a, const Wide& b) {      \
        return map([](const Part& x, const Part& y) QS_ALWAYS_INLINE { return x op y; }, a, b); \
    }                                                                                   \
    [[gnu::always_inline]] Wide& operator op##=(const Wide& b) { return *this = *this op b; }
    QS_WIDE_UNARY(-)
    QS_WIDE_BINARY(+)
    QS_WIDE_BINARY(-)
    QS_WIDE_BINARY(*)
    QS_WIDE_BINARY(/)
    // Integers only (a float part has no ~, &, |, ^ or shifts; using them does not compile).
    QS_WIDE_UNARY(~)
    QS_WIDE_BINARY(&)
    QS_WIDE_BINARY(|)
    QS_WIDE_BINARY(^)
    QS_WIDE_BINARY(<<)
    QS_WIDE_BINARY(>>)
#undef QS_WIDE_UNARY
#undef QS_WIDE_BINARY
    [[gnu::always_inline]] friend Wide operator<<(const Wide& a, int n) {
        return map([n](const Part& x) QS_ALWAYS_INLINE { return x << n; }, a);
    }
    [[gnu::always_inline]] friend Wide operator>>(const Wide& a, int n) {
        return map([n](const Part& x) QS_ALWAYS_INLINE { return x >> n; }, a);
    }
};

// Comparisons into masks: all ones where true, of the width of the compared values.
template <class T, int N>
using WideMask = Wide<mask_bits_t<T>, N>;

template <class T, int N>
[[gnu::always_inline]] inline WideMask<T, N> less(const Wide<T, N>& a, const Wide<T, N>& b) {
    return Wide<T, N>::template map<WideMask<T, N>>([](const auto& x, const auto& y) QS_ALWAYS_INLINE { return x < y; }, a, b);
}
template <class T, int N>
[[gnu::always_inline]] inline WideMask<T, N> less_equal(const Wide<T, N>& a, const Wide<T, N>& b) {
    return Wide<T, N>::template map<WideMask<T, N>>([](const auto& x, const auto& y) QS_ALWAYS_INLINE { return x <= y; }, a, b);
}
template <class T, int N>
[[gnu::always_inline]] inline WideMask<T, N> equal(const Wide<T, N>& a, const Wide<T, N>& b) {
    return Wide<T, N>::template map<WideMask<T, N>>([](const auto& x, const auto& y) QS_ALWAYS_INLINE { return x == y; }, a, b);
}
template <class T, int N>
[[gnu::always_inline]] inline WideMask<T, N> not_equal(const Wide<T, N>& a, const Wide<T, N>& b) {
    return Wide<T, N>::template map<WideMask<T, N>>([](const auto& x, const auto& y) QS_ALWAYS_INLINE { return x != y; }, a, b);
}
// a where the mask is set, b elsewhere: one blend per part.
template <class T, int N>
[[gnu::always_inline]] inline Wide<T, N> select(const WideMask<T, N>& m, const Wide<T, N>& a, const Wide<T, N>& b) {
    return Wide<T, N>::map([](const auto& k, const auto& x, const auto& y) QS_ALWAYS_INLINE { return k ? x : y; }, m, a, b);
}

// extremum_or_second (simd/simd.h), part by part.
template <Extremum E, class T, int N>
[[gnu::always_inline]] inline Wide<T, N> extremum_or_second(const Wide<T, N>& a, const Wide<T, N>& b) {
    return Wide<T, N>::map([](const auto& x, const auto& y) QS_ALWAYS_INLINE { return simd::extremum_or_second<E>(x, y); }, a, b);
}

// The same lanes' bits as another type of the same width (float <-> int32, int32 <-> uint32).
template <class To, class T, int N>
[[gnu::always_inline]] inline Wide<To, N> bit_cast(const Wide<T, N>& a) {
    static_assert(sizeof(To) == sizeof(T));
    return Wide<T, N>::template map<Wide<To, N>>(
        [](const auto& x) QS_ALWAYS_INLINE { return std::bit_cast<typename Wide<To, N>::Part>(x); }, a);
}

// Each lane converted as C++ converts T to To (__builtin_convertvector): part by part where both
// have the same width, else through one vector of all N lanes (only the double instantiations,
// whose parts hold half as many lanes, go that way).
template <class To, class T, int N>
[[gnu::always_inline]] inline Wide<To, N> convert(const Wide<T, N>& a) {
    if constexpr (std::is_same_v<To, T>) {
        return a;
    } else if constexpr (Wide<To, N>::part_size == Wide<T, N>::part_size) {
        return Wide<T, N>::template map<Wide<To, N>>(
            [](const auto& x) QS_ALWAYS_INLINE { return __builtin_convertvector(x, typename Wide<To, N>::Part); }, a);
    } else {
        return std::bit_cast<Wide<To, N>>(__builtin_convertvector(std::bit_cast<Vector<T, N>>(a), Vector<To, N>));
    }
}

// Lane i takes the value of lane Index{}(i), Index a stateless function object evaluated at
// compile time: one shuffle per part where every lane's source is in its own part (a quad's
// lanes among themselves), else one shuffle of all lanes.
template <class Index, class T, int N>
[[gnu::always_inline]] inline Wide<T, N> permute(const Wide<T, N>& a) {
    using W = Wide<T, N>;
    constexpr bool within_parts = [] {
        for (int i = 0; i < N; ++i)
            if (int(Index{}(std::size_t(i))) / W::part_size != i / W::part_size) return false;
        return true;
    }();
    if constexpr (within_parts) {
        W r;
        for_each_part<W::parts>([&](auto p) QS_ALWAYS_INLINE {
            constexpr int base = decltype(p)::value * W::part_size;
            r.part[p] = [&]<std::size_t... I>(std::index_sequence<I...>) QS_ALWAYS_INLINE {
                return __builtin_shufflevector(a.part[p], a.part[p], (Index{}(base + I) - base)...);
            }(std::make_index_sequence<std::size_t(W::part_size)>());
        });
        return r;
    } else {
        const Vector<T, N> x = std::bit_cast<Vector<T, N>>(a);
        return [&]<std::size_t... I>(std::index_sequence<I...>) {
            return std::bit_cast<W>(__builtin_shufflevector(x, x, Index{}(I)...));
        }(std::make_index_sequence<std::size_t(N)>());
    }
}

template <Rounding R, class T, int N>
[[gnu::always_inline]] inline Wide<T, N> round(const Wide<T, N>& a) {
    return Wide<T, N>::map([](const auto& x) QS_ALWAYS_INLINE { return simd::round<R>(x); }, a);
}
template <class T, int N>
[[gnu::always_inline]] inline Wide<T, N> sqrt(const Wide<T, N>& a) {
    return Wide<T, N>::map([](const auto& x) QS_ALWAYS_INLINE { return simd::sqrt(x); }, a);
}

template <class T, int N>
[[gnu::always_inline]] inline Wide<T, N> exact_product_add(const Wide<T, N>& a, const Wide<T, N>& b, const Wide<T, N>& c) {
    return Wide<T, N>::map([](const auto& x, const auto& y, const auto& z) QS_ALWAYS_INLINE { return simd::exact_product_add(x, y, z); },
                           a, b, c);
}

// Whether any lane of an integer Wide is non-zero: the parts ORed, then one test.
template <class T, int N>
[[gnu::always_inline]] inline bool any(const Wide<T, N>& m) {
    auto bits = m.part[0];
    for_each_part<Wide<T, N>::parts>([&](auto p) QS_ALWAYS_INLINE { bits |= m.part[p]; });
    return simd::any(bits);
}
// m's lanes are all ones or zero: all are set where none of ~m is.
template <class T, int N>
[[gnu::always_inline]] inline bool all_set(const Wide<T, N>& m) {
    return !any(~m);
}

// f of each lane, for what has no vector instruction (transcendentals: the library's functions,
// lane by lane, as libstdc++'s simd computes them).
template <class T, int N, class F>
Wide<T, N> per_element(const Wide<T, N>& x, F f) {
    T v[N];
    x.store(v);
    for (T& e : v) e = f(e);
    return Wide<T, N>::load(v);
}
template <class T, int N, class F>
Wide<T, N> per_element(const Wide<T, N>& x, const Wide<T, N>& y, F f) {
    T a[N], b[N];
    x.store(a);
    y.store(b);
    for (int i = 0; i < N; ++i) a[i] = f(a[i], b[i]);
    return Wide<T, N>::load(a);
}

#undef QS_ALWAYS_INLINE

}  // namespace qs::simd
