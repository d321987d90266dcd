#pragma once
// The registers the texture lookups work in, and the x86 instructions' semantics llvmpipe's
// sampling code compiles to (lp_bld_arit.c, lp_bld_conv.c, lp_bld_pack.c): eight lanes as
// GCC/Clang generic vectors of 256 bits, one AVX2 register each (wider vectors, on a machine
// without AVX-512, live on the stack and ran at half the speed), and the plain lookup sixteen at
// a time in one AVX-512 register where the CPU has one; the conversions, rounding and gathers are
// the SIMD layer's operations (shading/number/simd/simd.h), by those instructions where the
// target has them and lane by lane where it has not (the portable build: the same bits).
//
// Private to the sampler's sources (shading/glsl/texture*.cpp): everything here has internal
// linkage, so each of them compiles and inlines its own copy as one file would.

#include "shading/glsl/texture.h"
#include "shading/number/simd/simd.h"
#include "shading/number/sin_cos.h"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

// 256-bit vectors are passed between the sampler's own functions only (all inlined or internal):
// GCC's note that their calling convention differs with AVX concerns nothing here.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace qs::glsl {

namespace {

// A register of N lanes. Every lookup works in eight: one AVX2 register of floats, llvmpipe's
// vector of two quads, whose per-vector choices the general path follows. The plain lookup has no
// such choice and takes sixteen where the CPU has AVX-512 (one register, half the instructions).
// The helpers below are written over the width; each lane's arithmetic is the same at either.
template <int N>
struct LanesOf {
    using Floats = simd::Vector<float, N>;
    using Ints = simd::Vector<std::int32_t, N>;
    using Uints = simd::Vector<std::uint32_t, N>;
    // The 16-bit halves of the lanes (the 8-bit lerp's pairs).
    using Shorts = simd::Vector<std::int16_t, 2 * N>;
};
template <class V>
constexpr int lanes_in = int(sizeof(V) / sizeof(std::int32_t));
template <class V>
using FloatsLike = typename LanesOf<lanes_in<V>>::Floats;  // the float register as wide as V
template <class V>
using IntsLike = typename LanesOf<lanes_in<V>>::Ints;
template <class V>
using UintsLike = typename LanesOf<lanes_in<V>>::Uints;
template <class V>
using ShortsLike = typename LanesOf<lanes_in<V>>::Shorts;

constexpr int L = 8;
using Floats = LanesOf<L>::Floats;
using Ints = LanesOf<L>::Ints;
using Uints = LanesOf<L>::Uints;

// v in every lane (`Floats{} + v` would turn -0 into +0).
template <class V, class T>
V splat_as(T v) { return simd::splat<V>(v); }
inline Floats splat(float v) { return splat_as<Floats>(v); }
inline Ints splat(std::int32_t v) { return Ints{} + v; }
template <class V>
FloatsLike<V> to_float(const V& v) { return __builtin_convertvector(v, FloatsLike<V>); }
template <class V>
IntsLike<V> bits(const V& v) { return std::bit_cast<IntsLike<V>>(v); }
template <class V>
FloatsLike<V> from_bits(const V& v) { return std::bit_cast<FloatsLike<V>>(v); }
// a + b modulo 2^32, as llvmpipe's integer adds (no undefined overflow).
template <class V>
V wrapping_add(const V& a, const V& b) { return V(UintsLike<V>(a) + UintsLike<V>(b)); }

// SSE semantics: minps/maxps return the second operand when either is NaN.
template <class V>
V minps(const V& a, const V& b) { return a < b ? a : b; }
template <class V>
V maxps(const V& a, const V& b) { return a > b ? a : b; }
template <class V>
V imin(const V& a, const V& b) { return a < b ? a : b; }
template <class V>
V imax(const V& a, const V& b) { return a > b ? a : b; }
// Whether any lane is not zero, without a trip through memory (vptest, vptestmd).
template <class V>
bool any(const V& m) { return simd::any(m); }

// cvtps2dq: round to nearest even (the default MXCSR mode); NaN and out of range give INT_MIN.
template <class V>
IntsLike<V> cvt_rne(const V& v) { return simd::convert_nearest(v); }
// cvttps2dq: toward zero; NaN and out of range give INT_MIN.
template <class V>
IntsLike<V> cvt_trunc(const V& v) { return simd::convert_truncate(v); }
// roundps toward -inf, and to nearest even.
template <class V>
V floor(const V& v) { return simd::round<simd::Rounding::Floor>(v); }
inline Floats round_even(const Floats& v) { return simd::round<simd::Rounding::NearestEven>(v); }
inline Floats abs(const Floats& v) { return from_bits(bits(v) & 0x7fffffff); }

// llvmpipe's lerps are llvm.fmuladd, which its JIT fuses on CPUs with FMA; so do we there
// (llvmpipe_math::host_fuses).
using llvmpipe_math::host_fuses;
// w * (b - a) + a, fused where llvmpipe fuses it.
inline Floats lerp(const Floats& w, const Floats& a, const Floats& b) {
    const Floats d = b - a;
    return host_fuses() ? simd::fma(w, d, a) : w * d + a;
}

// texels[index] for every lane: one gather instruction per register where the ISA has one.
template <class V>
UintsLike<V> gather(const std::uint32_t* texels, const V& index) { return simd::gather(texels, index); }

// llvmpipe's 8-bit lerp (lp_build_lerp with pre-scaled weights, pmulhrsw): weight w in 1/256,
// rounded half up, on 8-bit values: a + ((w (b - a) + 128) >> 8).
//
// On two channels at once: red and blue (or green and alpha) of a lane's texel in the two 16-bit
// halves of its 32-bit lane, as llvmpipe unpacks them, and w in both halves. pmulhrsw computes
// (w (d << 7) + 2^14) >> 15, which is the same; the sum stays in [0, 255], so nothing carries.
template <class S>
S mulhrs(const S& a, const S& b) { return simd::multiply_high_rounded(a, b); }
template <class U>
U lerp8_pairs(const U& w_pairs, const U& a, const U& b) {
    using Shorts = ShortsLike<U>;
    const Shorts d = (Shorts(b) - Shorts(a)) * std::int16_t(128);
    return U(Shorts(a) + mulhrs(Shorts(w_pairs), d));
}
// A weight in both 16-bit halves.
template <class I>
UintsLike<I> pairs(const I& w) { return UintsLike<I>(w) | (UintsLike<I>(w) << 16); }

// Texels split into (red, blue) and (green, alpha) 16-bit pairs, and back to channels.
template <class U>
struct PairsOf {
    U rb, ga;
};
using Pairs = PairsOf<Uints>;
template <class U>
PairsOf<U> split(const U& t) { return {t & 0x00ff00ffu, (t >> 8) & 0x00ff00ffu}; }
template <class U>
PairsOf<U> lerp8(const IntsLike<U>& w, const PairsOf<U>& a, const PairsOf<U>& b) {
    const U w2 = pairs(w);
    return {lerp8_pairs(w2, a.rb, b.rb), lerp8_pairs(w2, a.ga, b.ga)};
}
template <class U>
IntsLike<U> channel(const PairsOf<U>& q, int c) {
    const U& v = (c & 1) ? q.ga : q.rb;
    return IntsLike<U>(c < 2 ? (v & 0xffffu) : (v >> 16));
}

// The unorm8 value q as the shader sees it: q times the float nearest 1/255 (a multiply, not a
// division: lp_build_unsigned_norm_to_float).
template <class I>
FloatsLike<I> unorm(const I& q) { return to_float(q) * float(1.0 / 255.0); }

// Lanes base.. of a lookup's array (as many as V holds), zero past its end; and back.
template <class V = Floats, class T>
V load_lanes(const T* p, int base, int n) {
    V r{};
    if (n == lanes_in<V>) {
        std::memcpy(&r, p + base, sizeof r);
    } else {
        for (int i = 0; i < n; ++i) r[i] = p[base + i];
    }
    return r;
}
template <class F>
void store_lanes(float* p, int base, int n, const F& v) {
    if (n == lanes_in<F>) {
        std::memcpy(p + base, &v, sizeof v);
    } else {
        for (int i = 0; i < n; ++i) p[base + i] = v[i];
    }
}

}  // namespace

}  // namespace qs::glsl
