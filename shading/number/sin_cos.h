#pragma once
// GLSL sin and cos on float as llvmpipe evaluates them, to the bit.
//
// Mesa 22.3's llvmpipe does not call a C library: NIR hands fsin/fcos to gallivm, whose
// lp_build_sin_or_cos (src/gallium/auxiliary/gallivm/lp_bld_arit.c) emits the Cephes single
// precision method as adapted in Julien Pommier's sse_mathfun:
//   1. j = int(|a| 4/pi), truncated (cvttps2dq), then rounded up to even: |a| lies within pi/4
//      of the multiple j pi/4 of pi/2 (j = 0x80000000, the conversion's "indefinite" answer,
//      when |a| 4/pi does not fit an int32).
//   2. r = |a| - j pi/4 with pi/4 split in three floats (Cody-Waite: 0.78515625,
//      2.4187564849853515625e-4, 3.77489497744594108e-8), each step one llvm.fmuladd.
//   3. On r in [-pi/4, pi/4] two minimax polynomials in z = r^2:
//        sin: r + r z ((s0 z + s1) z + s2)            (two fmuladds, the last step fused too)
//        cos: 1 - z/2 + z z ((c0 z + c1) z + c2)      (two fmuladds, the rest rounded apart)
//      chosen by bit 1 of the quadrant j (j - 2 for cos: cos a = sin(a + pi/2)), the sign
//      from bit 2 of j (and a's sign for sin, sin being odd).
//   4. The result clamped to [-1, 1], and NaN for an infinite or NaN a.
// llvm.fmuladd is one rounding on a CPU with FMA (LLVM's JIT targets the host) and two without;
// quadshade fuses exactly where llvmpipe on the same machine does (plane_equation.h, the same rule
// for interpolation). The point is llvmpipe's bits, not accuracy: a hash such as
// fract(sin(x) * 43758.5453) multiplies the last bit of sin by 2^15. Measured against the C
// library's sinf and cosf (glibc; softpipe calls them): within 2^-24 for |a| < 2^22, and no
// accuracy left from 2^25 on, where j pi/4 in float no longer reduces |a| (docs/design.md).
//
// Written once over a float type V and its int32 type I: plain float/int32_t, or GCC vectors of
// them (number/lanes.h's lanes, a register at a time).

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include "shading/number/simd/simd.h"

namespace qs::llvmpipe_math {

// Whether llvm.fmuladd is fused on this machine: LLVM fuses it when the CPU has FMA.
inline bool host_fuses() { return simd::Target::cpu_has_fma(); }

namespace detail {

template <class V>
inline constexpr bool is_scalar = std::is_same_v<V, float>;

template <class V>
struct IntOf {
    typedef std::int32_t type __attribute__((vector_size(sizeof(V))));
};
template <>
struct IntOf<float> {
    using type = std::int32_t;
};
template <class V>
using Int = typename IntOf<V>::type;

template <class V>
V splat(float x) {
    if constexpr (is_scalar<V>) return x;
    else return V{} + x;
}
template <class V>
Int<V> splat_int(std::int32_t x) {
    if constexpr (is_scalar<V>) return x;
    else return Int<V>{} + x;
}

// a * b + c as llvm.fmuladd: one rounding where the host fuses, two elsewhere.
template <class V>
V fmuladd(V a, V b, V c) {
    if constexpr (is_scalar<V>) {
        return host_fuses() ? std::fma(a, b, c) : a * b + c;
    } else {
        return host_fuses() ? simd::fma(a, b, c) : a * b + c;
    }
}

// cvttps2dq: truncation toward zero, 0x80000000 where the result does not fit (NaN included).
template <class V>
Int<V> truncate_to_int(V x) {
    constexpr float two31 = 2147483648.0f;  // x >= 0 here, or NaN
    if constexpr (is_scalar<V>) {
        return x < two31 ? std::int32_t(x) : INT32_MIN;
    } else {
        const Int<V> fits = x < two31;
        const V in_range = fits ? x : V{};  // converting an out-of-range float is undefined in C++
        return fits ? __builtin_convertvector(in_range, Int<V>) : Int<V>{} + INT32_MIN;
    }
}

template <class V>
V to_float(Int<V> i) {
    if constexpr (is_scalar<V>) return float(i);
    else return __builtin_convertvector(i, V);
}

// mask ? a : b on the bits (mask all ones or zero per lane).
template <class V>
Int<V> select_bits(Int<V> mask, Int<V> a, Int<V> b) {
    return (a & mask) | (b & ~mask);
}

// min(y, 1), then max(y, -1), as minps/maxps: the second operand where y is NaN (huge arguments
// make the polynomials inf - inf), so a NaN becomes 1.
template <class V>
V clamp_unit(V y) {
    y = y < 1.0f ? y : splat<V>(1.0f);
    return y > -1.0f ? y : splat<V>(-1.0f);
}

template <class V, bool Cos>
V sin_or_cos(V a) {
    using I = Int<V>;
    const I bits = std::bit_cast<I>(a);
    const V x = std::bit_cast<V>(bits & 0x7fffffff);  // |a|

    // 1. The octant, rounded up to even: j pi/4 is the multiple of pi/2 nearest |a|.
    const I j_odd = truncate_to_int(x * 1.27323954473516f) + 1;  // 4/pi
    const I j = j_odd & ~1;
    const V y = to_float<V>(j);
    const I q = Cos ? j - 2 : j;

    // 2. |a| - j pi/4, pi/4 in three parts so the first products are exact.
    V r = fmuladd(y, splat<V>(-0.78515625f), x);
    r = fmuladd(y, splat<V>(-2.4187564849853515625e-4f), r);
    r = fmuladd(y, splat<V>(-3.77489497744594108e-8f), r);

    // 3. Both polynomials on [-pi/4, pi/4], in z = r^2.
    const V z = r * r;
    V c = fmuladd(z, splat<V>(2.443315711809948e-5f), splat<V>(-1.388731625493765e-3f));
    c = fmuladd(c, z, splat<V>(4.166664568298827e-2f));
    c = c * z * z;
    c = (c - z * 0.5f) + 1.0f;
    V s = fmuladd(z, splat<V>(-1.9515295891e-4f), splat<V>(8.3321608736e-3f));
    s = fmuladd(s, z, splat<V>(-1.6666654611e-1f));
    s = fmuladd(s * z, r, r);

    // The sine polynomial where bit 1 of the quadrant is clear; the sign from bit 2 (sin: and a's).
    const I use_sin = (q & 2) == 0 ? splat_int<V>(-1) : splat_int<V>(0);
    const I sign = Cos ? (~q & 4) << 29 : (bits ^ (j_odd << 29)) & INT32_MIN;
    const V result = std::bit_cast<V>(select_bits<V>(use_sin, std::bit_cast<I>(s), std::bit_cast<I>(c)) ^ sign);

    // 4. Within [-1, 1]; NaN for an infinite or NaN a (its exponent all ones).
    const I finite = (bits & 0x7f800000) != 0x7f800000 ? splat_int<V>(-1) : splat_int<V>(0);
    return std::bit_cast<V>(select_bits<V>(finite, std::bit_cast<I>(clamp_unit(result)),
                                           std::bit_cast<I>(splat<V>(std::numeric_limits<float>::quiet_NaN()))));
}

}  // namespace detail

// float, or a GCC vector of floats.
template <class V>
V sin(V a) { return detail::sin_or_cos<V, false>(a); }
template <class V>
V cos(V a) { return detail::sin_or_cos<V, true>(a); }

// The floats one register holds in this build. N lanes are evaluated a register at a time: on a
// vector type wider than the registers GCC splits the conversions and selects lane by lane
// (measured: 16 lanes as one 64-byte vector on AVX2 take ten times as long as two of 32 bytes).
inline constexpr int kRegisterFloats = simd::register_floats;

// out[i] = sin(in[i]) (cos with Cos) for N floats.
template <bool Cos, int N>
void sin_or_cos(const float* in, float* out) {
    constexpr int w = N < kRegisterFloats ? N : kRegisterFloats;
    static_assert(N % w == 0 && (w & (w - 1)) == 0);
    typedef float V __attribute__((vector_size(w * sizeof(float))));
    for (int i = 0; i < N; i += w) {
        V a;
        std::memcpy(&a, in + i, sizeof a);
        const V r = detail::sin_or_cos<V, Cos>(a);
        std::memcpy(out + i, &r, sizeof r);
    }
}

}  // namespace qs::llvmpipe_math
