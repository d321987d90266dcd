#pragma once
// The SIMD layer: operations on GCC/Clang generic vectors (vector.h) that C++'s operators do
// not cover, each as the instruction the build's CPU has for it. target.h picks the target, one
// file per instruction set (avx512.h, avx2.h, sse.h, portable.h); this header takes a vector
// wider than the target's registers apart into register-sized pieces, applies the target's
// operation to each and puts the results back together, so that callers write one vector of the
// width their algorithm wants (a batch's sixteen lanes, a lookup's eight) whatever the CPU.
// Every operation gives the same bits on every target: where an instruction has an odd result
// (a conversion out of range, minps on NaN), the portable code states it lane by lane.
//
// The number types (number/wide_vector.h, lanes.h), the texture sampler, the renderer core's
// 16-lane batches (core/lanes16.h), the depth buffer and the ray caster's packets are written on
// it: intrinsics and target macros appear nowhere else.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>

#include "shading/number/simd/target.h"
#include "shading/number/simd/vector.h"

namespace qs::simd {

// The widest vector register of the target, in bytes and in floats.
inline constexpr std::size_t register_bytes = Target::register_bytes;
inline constexpr int register_floats = int(register_bytes / sizeof(float));

// The register-sized piece of V (V itself where it is no wider).
template <class V>
inline constexpr int pieces_v = sizeof(V) > register_bytes ? int(sizeof(V) / register_bytes) : 1;
template <class V>
using piece_t = Vector<element_t<V>, size_v<V> / pieces_v<V>>;

// op of each register-sized piece of the arguments (of V's size), as one vector of their
// results (of R's). Unrolled: each piece stays in its register.
template <class R, class V, class Op, class... W>
[[gnu::always_inline]] inline R by_pieces(Op op, const V& v, const W&... w) {
    constexpr int k = pieces_v<V>;
    if constexpr (k == 1) {
        return op(v, w...);
    } else {
        using P = piece_t<V>;
        R r;
        const auto piece = [](const auto& x, int i) __attribute__((always_inline)) {
            P p;
            std::memcpy(&p, reinterpret_cast<const char*>(&x) + i * sizeof(P), sizeof p);
            return p;
        };
        [&]<int... I>(std::integer_sequence<int, I...>) __attribute__((always_inline)) {
            (
                [&](auto i) __attribute__((always_inline)) {
                    const auto out = op(piece(v, i.value), piece(w, i.value)...);
                    std::memcpy(reinterpret_cast<char*>(&r) + i.value * sizeof out, &out, sizeof out);
                }(std::integral_constant<int, I>{}),
                ...);
        }(std::make_integer_sequence<int, k>());
        return r;
    }
}
// The lane bits of a comparison op of each piece, in the order of the lanes.
template <class V, class Op>
[[gnu::always_inline]] inline LaneBits bits_by_pieces(Op op, const V& a, const V& b) {
    constexpr int k = pieces_v<V>;
    if constexpr (k == 1) {
        return op(a, b);
    } else {
        using P = piece_t<V>;
        P x[k], y[k];
        std::memcpy(x, &a, sizeof x), std::memcpy(y, &b, sizeof y);
        LaneBits r = 0;
        for (int i = 0; i < k; ++i) r |= op(x[i], y[i]) << (size_v<P> * i);
        return r;
    }
}

// x in every lane, -0 included (`V{} + x` would add +0 to it: +0 for -0, and an addition the
// compiler cannot leave out, where a broadcast operand of the instruction using it is free).
// Wider than a register, one broadcast register copied (a loop compiled to scalar stores).
template <class V>
[[gnu::always_inline]] inline V splat(element_t<V> x) {
    if constexpr (pieces_v<V> == 1) {
        return [&]<std::size_t... I>(std::index_sequence<I...>) {
            return V{((void)I, x)...};
        }(std::make_index_sequence<std::size_t(size_v<V>)>());
    } else {
        using P = piece_t<V>;
        const P p = splat<P>(x);
        P all[pieces_v<V>];
        for (P& q : all) q = p;
        V r;
        std::memcpy(&r, all, sizeof r);
        return r;
    }
}

// v at p (unaligned), a register-sized piece at a time (a copy of a vector wider than the
// registers went through general registers).
template <class T, class V>
[[gnu::always_inline]] inline void store_pieces(T* p, const V& v) {
    static_assert(sizeof(T) == sizeof(element_t<V>));
    using P = piece_t<V>;
    P parts[pieces_v<V>];
    std::memcpy(parts, &v, sizeof parts);
    for (int i = 0; i < pieces_v<V>; ++i) *reinterpret_cast<Unaligned<P>*>(p + i * size_v<P>) = parts[i];
}

// Rounding to an integer value in the direction R (roundps, roundpd; the library's floor, ceil,
// trunc and nearbyint without SSE4.1: the same values).
template <Rounding R, class V>
[[gnu::always_inline]] inline V round(const V& x) {
    return by_pieces<V>([](const auto& p) __attribute__((always_inline)) { return isa::round<R>(p); }, x);
}

// The correctly rounded square root (sqrtps, sqrtpd).
template <class V>
[[gnu::always_inline]] inline V sqrt(const V& x) {
    return by_pieces<V>([](const auto& p) __attribute__((always_inline)) { return isa::sqrt(p); }, x);
}

// a < b ? a : b (Min) or a > b ? a : b (Max), element by element: b where the two are unordered
// (a NaN), and b where they are equal (+0 and -0 too). Exactly minps/maxps (and their pd forms),
// which GCC makes of the plain ternary, but not of one whose mask another test joins (GLSL's min
// ignores a NaN b) or whose b is a constant: there it kept a compare and a blend.
template <Extremum E, class V>
[[gnu::always_inline]] inline V extremum_or_second(const V& a, const V& b) {
    return by_pieces<V>([](const auto& x, const auto& y) __attribute__((always_inline)) { return isa::extremum_or_second<E>(x, y); }, a, b);
}

// a * b + c for operands whose product a * b is representable: one rounding (FMA) or two then
// give the same bits, so the target decides. With FMA it is one instruction, on a multiply
// pipe, one step shorter than the two; shaders use it only where the product is exact
// (noise/simplex2d.h says why there).
template <class V>
[[gnu::always_inline]] inline V exact_product_add(const V& a, const V& b, const V& c) {
    return by_pieces<V>([](const auto& x, const auto& y, const auto& z) __attribute__((always_inline)) { return isa::exact_product_add(x, y, z); }, a, b, c);
}

// a * b + c rounded once on every lane, as std::fma (one instruction per register with FMA, the
// library's fma lane by lane without).
template <class V>
[[gnu::always_inline]] inline V fma(const V& a, const V& b, const V& c) {
    return by_pieces<V>([](const auto& x, const auto& y, const auto& z) __attribute__((always_inline)) { return isa::fma(x, y, z); }, a, b, c);
}

// Whether any element of an integer vector is non-zero: one test where it is a register,
// without a trip through memory (vptest, vptestmd).
template <class V>
[[gnu::always_inline]] inline bool any(const V& m) {
    return isa::any(m);
}

// cvtps2dq: to nearest even; NaN and out of range give INT_MIN.
template <class V>
[[gnu::always_inline]] inline ints_of_t<V> convert_nearest(const V& x) {
    return by_pieces<ints_of_t<V>>([](const auto& p) __attribute__((always_inline)) { return isa::convert_nearest(p); }, x);
}
// cvttps2dq, cvttpd2dq: toward zero; NaN and out of range give INT_MIN.
template <class V>
[[gnu::always_inline]] inline ints_of_t<V> convert_truncate(const V& x) {
    return by_pieces<ints_of_t<V>>([](const auto& p) __attribute__((always_inline)) { return isa::convert_truncate(p); }, x);
}

// base[index[i]] in lane i: one gather instruction per register where the target has one.
template <class I>
[[gnu::always_inline]] inline like_t<std::uint32_t, I> gather(const std::uint32_t* base, const I& index) {
    return by_pieces<like_t<std::uint32_t, I>>([base](const auto& p) __attribute__((always_inline)) { return isa::gather(base, p); }, index);
}
using isa::gather_into;

// (a b + 2^14) >> 15 on each 16-bit lane, rounded half up (pmulhrsw).
template <class S>
[[gnu::always_inline]] inline S multiply_high_rounded(const S& a, const S& b) {
    return by_pieces<S>([](const auto& x, const auto& y) __attribute__((always_inline)) { return isa::multiply_high_rounded(x, y); }, a, b);
}

// Operations across the lanes of one register, in portable.h's terms: permute, permute_into,
// lookup, blend, select, append.
using isa::append;
using isa::blend;
using isa::lookup;
using isa::permute;
using isa::permute_into;
using isa::select;

// Comparisons as lane bits, bit i for lane i (a < b ordered, a > b and a == b on integers, a <
// b on unsigned integers, (a & b) == 0).
template <class V>
[[gnu::always_inline]] inline LaneBits less_bits(const V& a, const V& b) {
    return bits_by_pieces([](const auto& x, const auto& y) __attribute__((always_inline)) { return isa::less_bits(x, y); }, a, b);
}
template <class V>
[[gnu::always_inline]] inline LaneBits greater_bits(const V& a, const V& b) {
    return bits_by_pieces([](const auto& x, const auto& y) __attribute__((always_inline)) { return isa::greater_bits(x, y); }, a, b);
}
template <class V>
[[gnu::always_inline]] inline LaneBits equal_bits(const V& a, const V& b) {
    return bits_by_pieces([](const auto& x, const auto& y) __attribute__((always_inline)) { return isa::equal_bits(x, y); }, a, b);
}
template <class V>
[[gnu::always_inline]] inline LaneBits less_unsigned_bits(const V& a, const V& b) {
    return bits_by_pieces([](const auto& x, const auto& y) __attribute__((always_inline)) { return isa::less_unsigned_bits(x, y); }, a, b);
}
template <class V>
[[gnu::always_inline]] inline LaneBits none_common_bits(const V& a, const V& b) {
    return bits_by_pieces([](const auto& x, const auto& y) __attribute__((always_inline)) { return isa::none_common_bits(x, y); }, a, b);
}

// The lowest n set bits of `mask` (all of them when it has n or fewer; pdep).
[[gnu::always_inline]] inline std::uint32_t lowest_bits(std::uint32_t mask, int n) {
    return n >= 32 ? mask : Target::deposit_low_bits(n, mask);
}
// The bits of `bits` at the set bits of `mask`, packed from bit 0 up (pext).
[[gnu::always_inline]] inline std::uint32_t compress_bits(std::uint32_t bits, std::uint32_t mask) {
    return Target::extract_bits(bits, mask);
}

// v into memory at p, a whole number of cache lines, past the caches: streaming stores, a
// register at a time, loaded as such from where v lies (a wider vector's pieces taken by
// shuffles were moved through the stack float by float). Only the thread that stored them is
// sure to see them until streaming_stores_done().
template <class V>
[[gnu::always_inline]] inline void stream(float* p, const V& v) {
    using P = piece_t<V>;
    for (int i = 0; i < pieces_v<V>; ++i) {
        isa::stream(p + i * size_v<P>, load<P>(reinterpret_cast<const float*>(&v) + i * size_v<P>));
    }
}
[[gnu::always_inline]] inline void streaming_stores_done() { Target::streaming_stores_done(); }

// The calling thread's float control word, and whether the target can flush denormals in it.
inline constexpr bool kControlsDenormals = Target::kControlsDenormals;
[[gnu::always_inline]] inline unsigned float_control() { return Target::float_control(); }
[[gnu::always_inline]] inline void set_float_control(unsigned control) { Target::set_float_control(control); }
// control with denormals flushed to zero and read as zero.
[[gnu::always_inline]] inline unsigned flush_denormals(unsigned control) { return Target::flush_denormals(control); }

}  // namespace qs::simd
