// The lookups' lanes, as Mesa 22.3's llvmpipe samples GL_RGBA8 2D and 3D textures
// (lp_bld_sample_aos.c, lp_bld_sample_soa.c, lp_bld_sample.c), and glGenerateMipmap as llvmpipe
// makes the levels (util_gen_mipmap, u_blitter.c).
// Every rule here was checked bit for bit against OSMesa (docs/design.md, "Textures").
//
// Eight lanes at a time as GCC/Clang generic vectors of 256 bits, one AVX2 register each (wider
// vectors, on a machine without AVX-512, live on the stack and ran at half the speed), and the
// plain lookup sixteen at a time in one AVX-512 register where the CPU has one; the
// conversions, rounding and gathers llvmpipe's code compiles to are x86 instructions with the
// same rounding and out-of-range results (cvtps2dq, cvttps2dq, roundps, vpgatherdd): the SIMD
// layer's operations (shading/number/simd/simd.h), by those instructions where the target has
// them and lane by lane where it has not (the portable build: the same bits).

#include "shading/glsl/texture.h"
#include "shading/glsl/texture_cube.h"
#include "shading/glsl/texture_queries.h"
#include "shading/glsl/texture_shadow.h"
#include "shading/number/simd/simd.h"
#include "shading/number/sin_cos.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <utility>
#include <string>

// 256-bit vectors are passed between this file's functions only (all inlined or internal): GCC's
// note that their calling convention differs with AVX concerns nothing here.
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
Floats splat(float v) { return splat_as<Floats>(v); }
Ints splat(std::int32_t v) { return Ints{} + v; }
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
Floats round_even(const Floats& v) { return simd::round<simd::Rounding::NearestEven>(v); }
Floats abs(const Floats& v) { return from_bits(bits(v) & 0x7fffffff); }

// llvmpipe's lerps are llvm.fmuladd, which its JIT fuses on CPUs with FMA; so do we there
// (llvmpipe_math::host_fuses).
using llvmpipe_math::host_fuses;
// w * (b - a) + a, fused where llvmpipe fuses it.
Floats lerp(const Floats& w, const Floats& a, const Floats& b) {
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

// ---- level of detail (lp_bld_sample.c, lp_build_lod_selector with the default sampler state) ----

// The biased exponent field minus (127 - bias): floor(log2 x) + bias for normal x
// (lp_build_extract_exponent).
Ints exponent(const Floats& x, int bias) { return ((bits(x) >> 23) & 255) - (127 - bias); }
// lp_build_fast_log2: exponent plus mantissa - 1, piecewise linear and exact at powers of two.
Floats fast_log2(const Floats& x) {
    return to_float(exponent(x, -1)) + from_bits((bits(x) & 0x7fffff) | 0x3f800000);
}

// Per lane: which levels, how much of the second, which filter.
struct LevelChoice {
    Ints level0, level1;  // level1 only read where blend > 0
    Floats blend;         // weight of level1: 0 where none
    Ints linear;          // lanes filtered linearly (-1), the others nearest (0)
};

// lp_build_lod_selector and lp_build_{nearest,linear}_mip_levels with the default sampler state
// (no LOD clamps or sampler bias). `rho2`: the implicit level's squared scale factor; `bias`:
// added to its level; `lod`: an explicit level (rho2 and bias unused). An implicit level takes
// the fast paths (no fraction at all for NEAREST: the exponent trick); a bias or an explicit
// level the general one, which rounds NEAREST's level to even.
LevelChoice choose_levels(const Texture& tex, const Floats* rho2_lanes, const Floats* bias_lanes, const Floats* lod_lanes) {
    const SamplerState& st = tex.sampler;
    // Each field set on its own: `c{}` compiled to a memset through the stack.
    LevelChoice c;
    c.level0 = c.level1 = Ints{};
    c.blend = Floats{};
    const int last = int(tex.levels.size()) - 1;
    if (!rho2_lanes && !lod_lanes) {  // min == mag and no mipmaps: no level of detail at all
        c.linear = splat(st.min == Filter::Linear ? -1 : 0);
        return c;
    }
    Ints positive, ipart{};
    Floats fpart{};
    if (!lod_lanes && !bias_lanes && st.mip != MipFilter::Linear) {
        const Floats rho2 = *rho2_lanes;
        ipart = exponent(rho2, 1) >> 1;  // lp_build_ilog2_sqrt: level k from rho >= sqrt(2) 2^(k-1)
        positive = rho2 > 1.0f;
    } else {
        Floats lod = lod_lanes ? *lod_lanes : fast_log2(*rho2_lanes) * 0.5f;
        if (bias_lanes && !lod_lanes) lod = lod + *bias_lanes;
        positive = lod > 0.0f;
        if (st.mip == MipFilter::Nearest) {
            ipart = cvt_rne(lod);  // the general path rounds to even, 0.5 to level 0
        } else {
            const Floats fl = floor(lod);
            ipart = cvt_trunc(fl);
            fpart = lod - fl;
        }
    }
    if (st.mip == MipFilter::Nearest) {
        c.level0 = c.level1 = imin(imax(ipart, splat(0)), splat(last));
    } else if (st.mip == MipFilter::Linear) {
        const Ints below = ipart < 0, beyond = ipart >= last;
        c.level0 = below ? splat(0) : beyond ? splat(last) : ipart;
        c.level1 = below ? splat(0) : beyond ? splat(last) : ipart + 1;
        c.blend = from_bits(bits(fpart) & ~(below | beyond));
    }
    // Magnified lanes take the magnification filter at level0, unblended.
    const Ints minified = st.min == st.mag ? splat(-1) : positive;
    c.blend = from_bits(bits(c.blend) & minified);
    const Ints min_linear = splat(st.min == Filter::Linear ? -1 : 0), mag_linear = splat(st.mag == Filter::Linear ? -1 : 0);
    c.linear = minified ? min_linear : mag_linear;
    return c;
}

// ---- one level's texels ---------------------------------------------------------------------

// Per lane, a level's size and where its texels start.
struct LevelLanes {
    Ints width, height, depth, offset;
};
LevelLanes level_lanes(const Texture& tex, const Ints& level) {
    LevelLanes r;
    if (tex.levels.size() == 1) {
        const Texture::Level& l = tex.levels[0];
        r.width = splat(l.width), r.height = splat(l.height), r.depth = splat(l.depth), r.offset = Ints{};
        return r;
    }
    r.width = imax(splat(tex.width) >> level, splat(1));  // lp_build_minify
    r.height = imax(splat(tex.height) >> level, splat(1));
    r.depth = imax(splat(tex.depth) >> level, splat(1));
    static_assert(sizeof(Texture::Level) == 4 * sizeof(std::int32_t) && offsetof(Texture::Level, offset) == 12);
    r.offset = Ints(gather(reinterpret_cast<const std::uint32_t*>(tex.levels.data()), level * 4 + 3));
    return r;
}

// Two texels and a weight along one axis: (x0, x1, w) with w in 1/256 (8-bit path) or a float.
template <class F>
struct AxisLanes {
    IntsLike<F> i0, i1, w8;
    F w;
};
using Axis = AxisLanes<Floats>;

// lp_bld_sample_aos.c: the 8-bit fixed-point path, REPEAT and CLAMP_TO_EDGE. Linear filtering
// along one axis (lp_build_sample_wrap_linear_int); the same for s, t and r.
//
// A texel offset (`offset`, or none) is added to the texel coordinate, or, for REPEAT on a size
// that is not a power of two, to the normalised one divided by the size (lp_build_sample_image_linear
// and lp_build_sample_wrap_linear_int).
template <class F>
AxisLanes<F> aos_linear(const F& s, const IntsLike<F>& size, Wrap wrap, bool pot, const IntsLike<F>* offset = nullptr) {
    using Ints = IntsLike<F>;
    AxisLanes<F> a;
    const Ints last = size - 1;
    // Linear: 8 fractional bits of s * size - 0.5, rounded to even.
    Ints u, i0;
    if (wrap == Wrap::Repeat && !pot) {
        const F so = offset ? s + to_float(*offset) / to_float(size) : s;
        const F f = so - floor(so);  // lp_build_coord_repeat_npot_linear_int
        u = wrapping_add(cvt_rne((f * to_float(size)) * 256.0f), Ints{} - 128);
        i0 = u >> 8;
    } else {
        u = wrapping_add(cvt_rne(s * to_float(size << 8)), Ints{} - 128);
        i0 = u >> 8;
        if (offset) i0 = wrapping_add(i0, *offset);
    }
    Ints l0, l1;
    const Ints w = u & 255;
    if (wrap == Wrap::Repeat) {
        if (pot) {
            l0 = i0 & last;
        } else {
            l0 = imin(i0 < 0 ? last : i0, last);
        }
        l1 = l0 != last ? l0 + 1 : Ints{};
    } else {
        l0 = imin(imax(i0, Ints{}), last);
        l1 = ((i0 >= 0) & (i0 < last)) ? l0 + 1 : l0;
    }
    a.i0 = l0, a.i1 = l1, a.w8 = w;
    a.w = to_float(a.w8) * (1.0f / 256.0f);
    return a;
}

// The nearest texel along one axis (lp_build_sample_wrap_nearest_int).
// An offset as aos_linear's (lp_build_sample_image_nearest, lp_build_sample_wrap_nearest_int).
template <class F>
IntsLike<F> aos_nearest(const F& s, const IntsLike<F>& size, Wrap wrap, bool pot, const IntsLike<F>* offset = nullptr) {
    using Ints = IntsLike<F>;
    const Ints last = size - 1;
    if (wrap == Wrap::Repeat && !pot) {
        const F so = offset ? s + to_float(*offset) / to_float(size) : s;
        return cvt_trunc(minps(so - floor(so), splat_as<F>(0x1.fffffep-1f)) * to_float(size));
    }
    Ints i = cvt_trunc(floor(s * to_float(size)));
    if (offset) i = wrapping_add(i, *offset);
    return wrap == Wrap::Repeat ? (i & last) : imin(imax(i, Ints{}), last);
}

// Linear lanes as aos_linear gives them, the others their nearest texel with weight 0 (which
// llvmpipe's lerp returns exactly); each part computed only when some lane needs it.
Axis aos_axis(const Floats& s, const Ints& size, Wrap wrap, bool pot, const Ints& linear, const Ints* offset) {
    const bool some_linear = any(linear), all_linear = !any(~linear);
    Axis a{};
    if (some_linear) a = aos_linear(s, size, wrap, pot, offset);
    if (!all_linear) {
        const Ints n = aos_nearest(s, size, wrap, pot, offset);
        a.i0 = linear ? a.i0 : n;
        a.i1 = linear ? a.i1 : n;
        a.w8 = a.w8 & linear;
        a.w = from_bits(bits(a.w) & linear);
    }
    return a;
}

// lp_build_coord_mirror: |2 (s/2 - round_even(s/2))|, NaN to 0.
Floats mirror(const Floats& s) {
    Floats c = s * 0.5f;
    c = c - round_even(c);
    c = c + c;
    return maxps(abs(c), Floats{});
}

// lp_bld_sample_soa.c: the float path, every wrap mode. `linear`: lanes filtered linearly;
// `weights_only`: the other lanes go through the linear code too, with weights rounded to 0 or
// 1 (llvmpipe's lp_build_sample_mipmap_both when some lane of the vector is linear). A texel
// offset (`offset`, or none) is added to the unnormalised coordinate (REPEAT on a power-of-two
// size, CLAMP_TO_EDGE), or divided by the size to the normalised one (lp_build_sample_wrap_linear,
// lp_build_sample_wrap_nearest).
Axis soa_axis(const Floats& s_in, const Ints& size, Wrap wrap, bool pot, const Ints& linear, const Ints& weights_only,
              const Ints* offset) {
    Axis a{};
    const Ints last = size - 1;
    const Floats fsize = to_float(size);
    const bool normalised_offset = offset && (wrap == Wrap::MirroredRepeat || (wrap == Wrap::Repeat && !pot));
    const Floats s = normalised_offset ? s_in + to_float(*offset) / fsize : s_in;
    Floats c, fl;
    Ints l0, l1;
    switch (wrap) {
        case Wrap::Repeat:
            if (pot) {
                c = s * fsize - 0.5f;
                if (offset) c = c + to_float(*offset);
                fl = floor(c);
                const Ints i = cvt_trunc(fl);
                l0 = i & last;
                l1 = wrapping_add(i, splat(1)) & last;
            } else {
                // lp_build_coord_repeat_npot_linear: an unordered c < 0, so NaN (from a NaN or
                // infinite s) takes the last texel too, as its weight NaN (its colour is NaN).
                c = (s - floor(s)) * fsize - 0.5f;
                fl = floor(c);
                const Ints ordered_nonnegative = c >= 0.0f;
                l0 = ordered_nonnegative ? cvt_trunc(fl) : last;
                l1 = l0 != last ? l0 + 1 : Ints{};
            }
            break;
        case Wrap::ClampToEdge: {
            c = s * fsize;
            if (offset) c = c + to_float(*offset);
            c = (c < fsize ? c : fsize) - 0.5f;
            c = maxps(c, Floats{});
            fl = floor(c);
            const Ints i = cvt_trunc(fl);
            l0 = i;
            l1 = imin(i + 1, last);
            break;
        }
        case Wrap::MirroredRepeat: {
            c = mirror(s) * fsize - 0.5f;
            fl = floor(c);
            const Ints i = cvt_trunc(fl);
            l0 = imax(i, Ints{});
            l1 = imin(i + 1, last);
            break;
        }
    }
    Floats w = c - fl;
    const Ints rounded = weights_only & ~linear;
    w = rounded ? (w > 0.5f ? splat(1.0f) : Floats{}) : w;
    Ints n;
    switch (wrap) {
        case Wrap::Repeat:
            if (pot) {
                n = cvt_trunc(floor(s * fsize));
                if (offset) n = wrapping_add(n, *offset);
                n = n & last;
            } else {
                n = cvt_trunc(minps(s - floor(s), splat(0x1.fffffep-1f)) * fsize);
            }
            break;
        case Wrap::ClampToEdge: {
            Floats cn = s * fsize;
            if (offset) cn = cn + to_float(*offset);
            n = imin(imax(cvt_trunc(cn), Ints{}), last);
            break;
        }
        case Wrap::MirroredRepeat: n = imin(cvt_trunc(mirror(s) * fsize), last); break;
    }
    const Ints through_linear = linear | weights_only;
    a.i0 = through_linear ? l0 : n;
    a.i1 = through_linear ? l1 : n;
    a.w = from_bits(bits(w) & through_linear);
    return a;
}

// The coordinates of a lookup's lanes, and the texture's sizes that are powers of two (llvmpipe
// decides that on the base level: a non-power-of-two base takes the npot code on every level).
template <int Dims>
struct Coords {
    Floats c[Dims];
    const Ints* offset[Dims] = {};  // texel offsets, or none
    const Ints* face = nullptr;     // a cube map's face per lane (its levels hold six faces each), or none
};

// A level's lanes, on each lane's face of a cube map (`face`, or none): the faces of a level
// follow one another, +X first, each width x height texels.
LevelLanes face_level_lanes(const Texture& tex, const Ints& level, const Ints* face) {
    LevelLanes lv = level_lanes(tex, level);
    if (face) lv.offset = lv.offset + *face * lv.width * lv.height;
    return lv;
}
template <int Dims>
struct Axes {
    Axis a[Dims];
};

template <int Dims>
std::array<bool, 3> pot_sizes(const Texture& tex) {
    return {std::has_single_bit(unsigned(tex.width)), std::has_single_bit(unsigned(tex.height)),
            Dims == 3 && std::has_single_bit(unsigned(tex.depth))};
}
inline Wrap wrap_of(const SamplerState& st, int axis) { return axis == 0 ? st.wrap_s : axis == 1 ? st.wrap_t : st.wrap_r; }
inline const Ints& size_of(const LevelLanes& lv, int axis) { return axis == 0 ? lv.width : axis == 1 ? lv.height : lv.depth; }

// The 2^Dims texels of a lookup, k[z][y][x] (one slice in 2D).
template <int Dims>
struct Texels {
    Uints k[Dims == 3 ? 2 : 1][2][2];
};
template <int Dims>
Texels<Dims> fetch_texels(const Texture& tex, const LevelLanes& level, const Axes<Dims>& ax) {
    Texels<Dims> r;
    const std::uint32_t* t = tex.texels.data();
    for (int z = 0; z < (Dims == 3 ? 2 : 1); ++z) {
        Ints slice{};
        if constexpr (Dims == 3) slice = (z ? ax.a[2].i1 : ax.a[2].i0) * level.height;
        const Ints row0 = level.offset + (slice + ax.a[1].i0) * level.width;
        const Ints row1 = level.offset + (slice + ax.a[1].i1) * level.width;
        r.k[z][0][0] = gather(t, row0 + ax.a[0].i0), r.k[z][0][1] = gather(t, row0 + ax.a[0].i1);
        r.k[z][1][0] = gather(t, row1 + ax.a[0].i0), r.k[z][1][1] = gather(t, row1 + ax.a[0].i1);
    }
    return r;
}

// Channel c (0: red) of packed RGBA8 texels.
Ints channel(const Uints& texels, int c) { return Ints((texels >> (8 * c)) & 255u); }

// d(colour)/ds, /dt (and /dr) of the (bi/tri)linear interpolant (texels as floats), for Dual2:
// along each axis, the difference of the two texel planes, weighted by the other axes' weights,
// times the level's size; zero along an axis filtered nearest.
template <int Dims>
void interpolant_gradient(const Texels<Dims>& k, const Axes<Dims>& ax, const LevelLanes& level, int c, Floats (&d)[Dims]) {
    Floats v[2][2][2];
    for (int z = 0; z < (Dims == 3 ? 2 : 1); ++z) {
        for (int y = 0; y < 2; ++y) {
            for (int x = 0; x < 2; ++x) v[z][y][x] = unorm(channel(k.k[z][y][x], c));
        }
    }
    auto weight = [&](int axis, int side) { return side ? ax.a[axis].w : 1.0f - ax.a[axis].w; };
    for (int axis = 0; axis < Dims; ++axis) {
        Floats g{};
        for (int z = 0; z < (Dims == 3 ? 2 : 1); ++z) {
            for (int y = 0; y < 2; ++y) {
                for (int x = 0; x < 2; ++x) {
                    const int side = axis == 0 ? x : axis == 1 ? y : z;
                    if (side == 0) continue;  // each pair once: (side 1) - (side 0)
                    const Floats diff = v[z][y][x] - v[axis == 2 ? 0 : z][axis == 1 ? 0 : y][axis == 0 ? 0 : x];
                    Floats w = splat(1.0f);
                    if (axis != 0) w = w * weight(0, x);
                    if (axis != 1) w = w * weight(1, y);
                    if constexpr (Dims == 3) {
                        if (axis != 2) w = w * weight(2, z);
                    }
                    g = g + w * diff;
                }
            }
        }
        const Ints filtered = ax.a[axis].i0 != ax.a[axis].i1;
        d[axis] = from_bits(bits(g * to_float(size_of(level, axis))) & filtered);
    }
}

struct Sample {
    Floats rgba[4];
    Floats d[3][4];  // d(colour channel)/d(coordinate)
};

// One level, 8-bit path: the filtered texel's channels in (red, blue) and (green, alpha) pairs;
// lp_build_lerp_3d: two bilinear slices, then along r.
template <int Dims>
Pairs aos_level(const Texture& tex, const Coords<Dims>& co, const Ints& level, const Ints& linear, bool gradient,
                Floats (&d)[3][4]) {
    const LevelLanes lv = face_level_lanes(tex, level, co.face);
    const std::array<bool, 3> pot = pot_sizes<Dims>(tex);
    Axes<Dims> ax;
    for (int i = 0; i < Dims; ++i) {
        ax.a[i] = aos_axis(co.c[i], size_of(lv, i), wrap_of(tex.sampler, i), pot[std::size_t(i)], linear, co.offset[i]);
    }
    const Texels<Dims> k = fetch_texels(tex, lv, ax);
    if (gradient) {
        for (int c = 0; c < 4; ++c) {
            Floats g[Dims];
            interpolant_gradient(k, ax, lv, c, g);
            for (int i = 0; i < Dims; ++i) d[i][c] = g[i];
        }
    }
    auto slice = [&](int z) {
        return lerp8(ax.a[1].w8, lerp8(ax.a[0].w8, split(k.k[z][0][0]), split(k.k[z][0][1])),
                     lerp8(ax.a[0].w8, split(k.k[z][1][0]), split(k.k[z][1][1])));
    };
    if constexpr (Dims == 3) {
        return lerp8(ax.a[2].w8, slice(0), slice(1));
    } else {
        return slice(0);
    }
}

// One level, float path.
template <int Dims>
void soa_level(const Texture& tex, const Coords<Dims>& co, const Ints& level, const Ints& linear,
               const Ints& weights_only, bool gradient, Floats (&out)[4], Floats (&d)[3][4]) {
    const LevelLanes lv = face_level_lanes(tex, level, co.face);
    const std::array<bool, 3> pot = pot_sizes<Dims>(tex);
    Axes<Dims> ax;
    for (int i = 0; i < Dims; ++i) {
        ax.a[i] = soa_axis(co.c[i], size_of(lv, i), wrap_of(tex.sampler, i), pot[std::size_t(i)], linear, weights_only,
                           co.offset[i]);
    }
    const Texels<Dims> k = fetch_texels(tex, lv, ax);
    for (int c = 0; c < 4; ++c) {
        auto slice = [&](int z) {
            const Floats r0 = lerp(ax.a[0].w, unorm(channel(k.k[z][0][0], c)), unorm(channel(k.k[z][0][1], c)));
            const Floats r1 = lerp(ax.a[0].w, unorm(channel(k.k[z][1][0], c)), unorm(channel(k.k[z][1][1], c)));
            return lerp(ax.a[1].w, r0, r1);
        };
        if constexpr (Dims == 3) {
            out[c] = lerp(ax.a[2].w, slice(0), slice(1));
        } else {
            out[c] = slice(0);
        }
        if (gradient) {
            Floats g[Dims];
            interpolant_gradient(k, ax, lv, c, g);
            for (int i = 0; i < Dims; ++i) d[i][c] = g[i];
        }
    }
}

// llvmpipe decides per 8-lane vector whether a lookup on the float path with different min and
// mag filters runs its linear code: every lane of a vector where one lane filters linearly. Our
// lanes are one such vector (an OR across them, in three shuffles) when they are quads.
Ints any_per_vector(const Ints& linear, bool quad_vectors) {
    static_assert(L == 8);
    if (!quad_vectors) return linear;
    Ints r = linear | __builtin_shufflevector(linear, linear, 1, 0, 3, 2, 5, 4, 7, 6);
    r |= __builtin_shufflevector(r, r, 2, 3, 0, 1, 6, 7, 4, 5);
    return r | __builtin_shufflevector(r, r, 4, 5, 6, 7, 0, 1, 2, 3);
}

// The 8-bit path (lp_bld_sample_aos.c) when llvmpipe takes it (lp_build_sample_soa_code): every
// wrap REPEAT or CLAMP_TO_EDGE, and min == mag or one level of detail per quad (a bias or an
// explicit level is one per pixel).
template <int Dims>
bool takes_8bit_path(const Texture& tex, bool per_pixel_lod) {
    const SamplerState& st = tex.sampler;
    for (int i = 0; i < Dims; ++i) {
        if (wrap_of(st, i) == Wrap::MirroredRepeat) return false;
    }
    return st.min == st.mag || !per_pixel_lod;
}

template <int Dims>
Sample sample_lanes(const Texture& tex, const Coords<Dims>& co, const Floats* rho2, const Floats* bias, const Floats* lod,
                    bool rho2_per_pixel, bool quad_vectors, bool gradient) {
    const SamplerState& st = tex.sampler;
    const LevelChoice lc = choose_levels(tex, rho2, bias, lod);
    const bool blend = st.mip == MipFilter::Linear && any(bits(lc.blend) != 0);
    Sample out;  // out.d only written (and read) with `gradient`
    if (takes_8bit_path<Dims>(tex, bias || lod || rho2_per_pixel)) {
        // The second level blends in with an 8-bit weight truncated from the fraction
        // (lp_build_sample_mipmap).
        Pairs q = aos_level(tex, co, lc.level0, lc.linear, gradient, out.d);
        if (blend) {
            Floats d1[3][4];
            const Pairs q1 = aos_level(tex, co, lc.level1, lc.linear, gradient, d1);
            q = lerp8(imax(cvt_trunc(lc.blend * 256.0f), Ints{}), q, q1);
            if (gradient) {
                for (int i = 0; i < Dims; ++i) {
                    for (int c = 0; c < 4; ++c) out.d[i][c] += lc.blend * (d1[i][c] - out.d[i][c]);
                }
            }
        }
        for (int c = 0; c < 4; ++c) out.rgba[c] = unorm(channel(q, c));
        return out;
    }
    // The float path: lp_build_sample_mipmap, or lp_build_sample_mipmap_both when min and mag
    // filters differ.
    const Ints weights_only = st.min != st.mag ? any_per_vector(lc.linear, quad_vectors) & ~lc.linear : Ints{};
    soa_level(tex, co, lc.level0, lc.linear, weights_only, gradient, out.rgba, out.d);
    if (blend) {
        Floats c1[4], d1[3][4];
        soa_level(tex, co, lc.level1, lc.linear, weights_only, gradient, c1, d1);
        const Floats f = maxps(lc.blend, Floats{});
        for (int c = 0; c < 4; ++c) {
            out.rgba[c] = lerp(f, out.rgba[c], c1[c]);
            if (gradient) {
                for (int i = 0; i < Dims; ++i) out.d[i][c] += f * (d1[i][c] - out.d[i][c]);
            }
        }
    }
    return out;
}

// ---- glGenerateMipmap ----------------------------------------------------------------------
// llvmpipe has no mipmap generator of its own: Mesa's state tracker blits each level from the
// one above (util_gen_mipmap) through a quad that samples it with LINEAR, CLAMP_TO_EDGE at the
// destination texel's centre, on the 8-bit path above. For even sizes that is
// avg(avg(a, b), avg(c, d)) rounded half up, not a box filter; for odd sizes the weights are
// not one half (37 -> 18 samples at 37 (x + 0.5) / 18). A 3D level is drawn slice by slice, each
// sampling the level above trilinearly at r = (z Ds/Dd + 0.5 Ds/Dd) / Ds (u_blitter.c's
// src_z_step and depth_center_offset, the latter computed in double), then along r as the 8-bit
// path's lerp_3d.
struct Tap {
    int i0, i1, w;
};
// The 8-bit path's linear taps, CLAMP_TO_EDGE, of a source axis of `size` at coordinate s.
Tap clamp_tap(float s, int size) {
    const int u = int(std::nearbyint(s * float(size << 8))) - 128;  // rounds to even, as cvtps2dq
    const int i0 = u >> 8;
    const int l0 = std::clamp(i0, 0, size - 1);
    return {l0, (i0 >= 0 && i0 < size - 1) ? l0 + 1 : l0, u & 255};
}
std::vector<Tap> taps(int src_size, int dst_size) {
    std::vector<Tap> r{std::size_t(dst_size)};
    for (int x = 0; x < dst_size; ++x) r[std::size_t(x)] = clamp_tap((float(x) + 0.5f) / float(dst_size), src_size);
    return r;
}
std::vector<Tap> depth_taps(int src_size, int dst_size) {
    std::vector<Tap> r{std::size_t(dst_size)};
    const float step = float(src_size) / float(dst_size);
    const float center = float(0.5 / dst_size * src_size);
    for (int z = 0; z < dst_size; ++z) {
        const float layer = float(z) * step + center;
        r[std::size_t(z)] = clamp_tap(layer / float(src_size), src_size);
    }
    return r;
}

void next_level(const std::uint32_t* src, const Texture::Level& s, std::uint32_t* dst, const Texture::Level& d, int dims) {
    const std::vector<Tap> xs = taps(s.width, d.width), ys = taps(s.height, d.height);
    const std::vector<Tap> zs = dims == 3 ? depth_taps(s.depth, d.depth) : std::vector<Tap>{Tap{0, 0, 0}};
    auto lerp = [](int w, int a, int b) { return a + ((w * (b - a) + 128) >> 8); };
    auto at = [&](int x, int y, int z) {
        return src[(std::size_t(z) * std::size_t(s.height) + std::size_t(y)) * std::size_t(s.width) + std::size_t(x)];
    };
    std::size_t out_index = 0;
    for (const Tap& tz : zs) {
        for (const Tap& ty : ys) {
            for (const Tap& tx : xs) {
                std::uint32_t out = 0;
                for (int c = 0; c < 4; ++c) {
                    const auto ch = [c](std::uint32_t k) { return int((k >> (8 * c)) & 255u); };
                    auto slice = [&](int z) {
                        const int r0 = lerp(tx.w, ch(at(tx.i0, ty.i0, z)), ch(at(tx.i1, ty.i0, z)));
                        const int r1 = lerp(tx.w, ch(at(tx.i0, ty.i1, z)), ch(at(tx.i1, ty.i1, z)));
                        return lerp(ty.w, r0, r1);
                    };
                    const int v = dims == 3 ? lerp(tz.w, slice(tz.i0), slice(tz.i1)) : slice(0);
                    out |= std::uint32_t(v) << (8 * c);
                }
                dst[out_index++] = out;
            }
        }
    }
}

}  // namespace

Texture::Texture(int n, int w, int h, int d, const std::uint8_t* rgba, SamplerState s)
    : dims(n), width(w), height(h), depth(d), sampler(s) {
    const int max_size = n == 3 ? 2048 : (1 << 15);
    if (w < 1 || h < 1 || d < 1 || w > max_size || h > max_size || d > max_size || (n == 2 && d != 1)) {
        throw std::invalid_argument("texture size " + std::to_string(w) + "x" + std::to_string(h) +
                                    (n == 3 ? "x" + std::to_string(d) : std::string()) + " is outside 1.." +
                                    std::to_string(max_size));
    }
    std::int64_t total = 0;
    for (int lw = w, lh = h, ld = d;; lw = std::max(1, lw / 2), lh = std::max(1, lh / 2), ld = std::max(1, ld / 2)) {
        levels.push_back({lw, lh, ld, std::int32_t(total)});
        total += std::int64_t(lw) * lh * ld;
        if (sampler.mip == MipFilter::None || (lw == 1 && lh == 1 && ld == 1)) break;
    }
    // Texel indices are int32 lanes.
    if (total > std::int64_t(1) << 30) {
        throw std::invalid_argument("texture of " + std::to_string(total) + " texels with its mipmaps: more than 2^30");
    }
    // A single level makes a mipmap filter a plain one (llvmpipe: level_zero_only).
    if (levels.size() == 1) sampler.mip = MipFilter::None;
    texels.resize(std::size_t(total));
    for (std::size_t i = 0; i < std::size_t(w) * std::size_t(h) * std::size_t(d); ++i) {
        texels[i] = std::uint32_t(rgba[4 * i]) | std::uint32_t(rgba[4 * i + 1]) << 8 |
                    std::uint32_t(rgba[4 * i + 2]) << 16 | std::uint32_t(rgba[4 * i + 3]) << 24;
    }
    for (std::size_t l = 1; l < levels.size(); ++l) {
        const Level& a = levels[l - 1];
        const Level& b = levels[l];
        next_level(&texels[std::size_t(a.offset)], a, &texels[std::size_t(b.offset)], b, dims);
    }
}

samplerCube::samplerCube(int size, const std::array<const std::uint8_t*, 6>& faces, SamplerState s) {
    dims = kCubeDims;
    width = height = size;
    // llvmpipe clamps a cube map's faces to their edges whatever the sampler's wraps
    // (lp_build_sample_soa_code's derived sampler state); without seamless filtering (GL's
    // default) a lookup never leaves its face.
    s.wrap_s = s.wrap_t = s.wrap_r = Wrap::ClampToEdge;
    sampler = s;
    if (size < 1 || size > 16384) {
        throw std::invalid_argument("cube map face size " + std::to_string(size) + " is outside 1..16384");
    }
    std::int64_t total = 0;
    for (int l = size;; l = std::max(1, l / 2)) {
        levels.push_back({l, l, 1, std::int32_t(total)});
        total += std::int64_t(6) * l * l;
        if (sampler.mip == MipFilter::None || l == 1) break;
    }
    if (total > std::int64_t(1) << 30) {
        throw std::invalid_argument("cube map of " + std::to_string(total) + " texels with its mipmaps: more than 2^30");
    }
    if (levels.size() == 1) sampler.mip = MipFilter::None;
    texels.resize(std::size_t(total));
    const std::size_t face_texels = std::size_t(size) * std::size_t(size);
    for (std::size_t f = 0; f < 6; ++f) {
        const std::uint8_t* rgba = faces[f];
        for (std::size_t i = 0; i < face_texels; ++i) {
            texels[f * face_texels + i] = std::uint32_t(rgba[4 * i]) | std::uint32_t(rgba[4 * i + 1]) << 8 |
                                          std::uint32_t(rgba[4 * i + 2]) << 16 | std::uint32_t(rgba[4 * i + 3]) << 24;
        }
    }
    // Each face's levels as a 2D texture's (Mesa's mipmap blit draws the faces one by one).
    for (std::size_t l = 1; l < levels.size(); ++l) {
        const Level& a = levels[l - 1];
        const Level& b = levels[l];
        for (std::size_t f = 0; f < 6; ++f) {
            next_level(&texels[std::size_t(a.offset) + f * std::size_t(a.width * a.height)], a,
                       &texels[std::size_t(b.offset) + f * std::size_t(b.width * b.height)], b, 2);
        }
    }
}

std::array<int, 3> Texture::size(int lod) const {
    // lp_build_size_query with is_sviewinfo (NIR's txs): a level outside the texture's gives 0.
    if (lod < 0 || lod >= int(levels.size())) return {0, 0, 0};
    return {std::max(width >> lod, 1), std::max(height >> lod, 1), dims == 3 ? std::max(depth >> lod, 1) : 0};
}

namespace texture_detail {

void throw_lod_without_quads() {
    throw std::logic_error("texture lookup: this texture's sampler needs a level of detail, i.e. the quad's "
                           "derivatives, but the shader was run on independent pixels");
}

namespace {
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

// One register's worth of a lookup's lanes, from `base`.
template <int Dims>
[[gnu::always_inline]] inline void sample_register(const Texture& tex, const Lookup& l, int base,
                                                   const std::int32_t* faces = nullptr) {
    const int n = std::min(l.lanes - base, L);
    const Floats rho2 = l.rho2 ? load_lanes(l.rho2, base, n) : Floats{};
    const Floats bias = l.bias ? load_lanes(l.bias, base, n) : Floats{};
    const Floats lod = l.lod ? load_lanes(l.lod, base, n) : Floats{};
    Coords<Dims> co;
    co.c[0] = load_lanes(l.s, base, n), co.c[1] = load_lanes(l.t, base, n);
    if constexpr (Dims == 3) co.c[2] = load_lanes(l.r, base, n);
    Ints offset[Dims];
    for (int i = 0; i < Dims; ++i) {
        if (l.offset[std::size_t(i)]) offset[i] = load_lanes<Ints>(l.offset[std::size_t(i)], base, n), co.offset[i] = &offset[i];
    }
    Ints face{};
    if (faces) face = load_lanes<Ints>(faces, base, n), co.face = &face;
    const bool gradient = l.d_ds[0] != nullptr;
    const Sample r = sample_lanes<Dims>(tex, co, l.rho2 ? &rho2 : nullptr, l.bias ? &bias : nullptr, l.lod ? &lod : nullptr,
                                        l.rho2_per_pixel, l.quad_vectors, gradient);
    const std::array<float*, 4>* d_out[3] = {&l.d_ds, &l.d_dt, &l.d_dr};
    for (int c = 0; c < 4; ++c) {
        store_lanes(l.rgba[std::size_t(c)], base, n, r.rgba[c]);
        if (gradient) {
            for (int i = 0; i < Dims; ++i) store_lanes((*d_out[i])[std::size_t(c)], base, n, r.d[i][c]);
        }
    }
}
template <int Dims>
[[gnu::always_inline]] inline void sample_dims(const Texture& tex, const Lookup& l) {
    for (int base = 0; base < l.lanes; base += L) sample_register<Dims>(tex, l, base);
}

// ---- the plain 2D lookup: one level, one filter, the 8-bit path ---------------------------
// What single_texture and the halftone do: a 2D texture whose sampler needs no level of detail
// (min == mag, no mipmaps), REPEAT or CLAMP_TO_EDGE, no derivatives. The same arithmetic as
// sample_lanes takes there (choose_levels' first case, aos_level at level 0), with the axes'
// modes fixed at compile time, and one more thing: a texel is gathered only when some lane's
// weight reads it. llvmpipe's 8-bit lerp with weight 0 returns its first operand exactly
// (a + ((0 (b - a) + 128) >> 8) = a), so where every lane's weight along x (or y) is 0 the
// second column (row) changes nothing; lookups at texel centres, as the halftone's explicit
// bilinear filter makes them, read one texel per lane instead of four.
enum class AxisMode { Clamp, RepeatPot, RepeatNpot };

template <AxisMode M, class F>
[[gnu::always_inline]] inline AxisLanes<F> plain_linear_axis(const F& s, const IntsLike<F>& size, const IntsLike<F>& active) {
    AxisLanes<F> a = aos_linear(s, size, M == AxisMode::Clamp ? Wrap::ClampToEdge : Wrap::Repeat, M != AxisMode::RepeatNpot);
    a.w8 = a.w8 & active;  // lanes past the lookup's end weigh nothing (their results are dropped)
    return a;
}
template <AxisMode M, class F>
[[gnu::always_inline]] inline IntsLike<F> plain_nearest_axis(const F& s, const IntsLike<F>& size) {
    return aos_nearest(s, size, M == AxisMode::Clamp ? Wrap::ClampToEdge : Wrap::Repeat, M != AxisMode::RepeatNpot);
}

// gather(texels, index) where the lanes read texels close together, as a magnified texture's
// neighbouring pixels do: when every lane's index lies within 8 texels from lane 0's (and those
// 8 are inside the texture), one load of those 8 and a permute across lanes (vpermd) instead of
// the gather, which costs about as much as 8 separate loads; else, when the register's two
// pixel rows (lanes 0, 1, 4, 5 and 2, 3, 6, 7 of two quads, number/lanes.h) read two texel
// rows, each within 8 texels of its first lane's, two loads, two permutes and a blend. The same
// texels in every case. The plain lookup's on a CPU without AVX-512 (with it, the one below).
[[maybe_unused]] Uints gather_near(const std::uint32_t* texels, std::size_t count, const Ints& index) {
    if constexpr (simd::register_bytes >= sizeof(Uints)) {
        const std::int32_t base = index[0];
        const Ints d = index - base;
        const auto window = [&](std::int32_t at) { return simd::load<Uints>(texels + at); };
        if (std::size_t(base) + L <= count) {
            if (!any(d & ~(L - 1))) return simd::permute(window(base), d);
            const std::int32_t upper_base = index[2];
            static constexpr Ints kUpper{0, 0, -1, -1, 0, 0, -1, -1};
            const Ints d2 = kUpper ? index - upper_base : d;
            if (std::size_t(upper_base) + L <= count && !any(d2 & ~(L - 1))) {
                return simd::blend<0xcc>(simd::permute(window(base), d2), simd::permute(window(upper_base), d2));
            }
        }
    }
    return gather(texels, index);
}

// Sixteen lanes, a 4x4 block of pixels (four quads, core/block_layout.h), where the TexelWindow
// below does not hold their texels (a minified or wrapped texture, lanes in another order):
// windows of 16 texels, one per texel row the lanes read, each lane permuted from the window
// that holds its texel. The first window starts at the lesser index of lane 8, the block's
// lower left pixel in GL's window, and lane 0, the first of a row of pixels laid out in order:
// on a texture mapped without a flip, the least index either way. Each next window starts at
// the first lane still left; lanes that four windows do not hold are gathered. The plain
// lookup's where a register holds sixteen lanes.
[[maybe_unused]] LanesOf<16>::Uints gather_near(const std::uint32_t* texels, std::size_t count, const LanesOf<16>::Ints& index) {
    using U = LanesOf<16>::Uints;
    using I = LanesOf<16>::Ints;
    U texel{};
    simd::LaneBits left = 0xffff;
    std::int32_t first = std::min(index[0], index[8]);
    for (int window = 0; window < 4 && std::size_t(first) + 16 <= count; ++window) {
        const I d = index - first;
        const simd::LaneBits held = left & simd::none_common_bits(d, simd::splat<I>(~15));  // 0 <= d < 16
        texel = simd::permute_into(texel, held, simd::load<U>(texels + first), d);
        left &= ~held;
        if (left == 0) return texel;
        first = index[std::countr_zero(left)];
    }
    return simd::gather_into(texel, left, texels, index);
}

// Four texel rows of eight texels from (x0, y0), in two registers: what a 4x4 block reads where
// the texture is magnified (at 1x to 4x its 16 pixels reach two to four rows and columns, their
// bilinear neighbours one more each). Each lane's texel is one two-source permute (vpermt2d) by
// its offset in the window: straight code in place of gather_near's chain of windows, whose
// every step waits on the one before (single texture's square at 500x500: 0.82 against 1.12 ms
// at best; docs/results.md, stop 49). Opened at the least column and row the block's lanes
// read, moved back from the texture's far edges so that its loads stay inside level 0 (every
// index is in [0, size) after wrap or clamp). Used where a register holds sixteen lanes.
class TexelWindow {
public:
    using Uints = LanesOf<16>::Uints;
    using Ints = LanesOf<16>::Ints;
    static constexpr int kColumns = 8, kRows = 4;
    static bool fits(const Texture& tex) { return tex.width >= kColumns && tex.height >= kRows; }

    // The least column and row a register's lanes read are at its block's corners, where its
    // texels are a monotonic function of its pixels' position (an affine or projective map,
    // clamped): lanes 2, 7, 8 and 13 of core/block_layout.h's 4x4 block. Lanes in any other
    // order may find the window short and take gather_near.
    TexelWindow(const std::uint32_t* texels, int width, int height, const Ints& x, const Ints& y) {
        // x's corners in lanes 0-3, y's in 4-7; the least of each in lanes 0 and 4.
        static constexpr Ints kCorners{2, 7, 8, 13, 18, 23, 24, 29, 0, 0, 0, 0, 0, 0, 0, 0};
        using Eight = LanesOf<8>::Ints;
        const Ints corners = simd::lookup(x, y, kCorners);
        Eight m = __builtin_shufflevector(corners, corners, 0, 1, 2, 3, 4, 5, 6, 7);
        m = imin(m, __builtin_shufflevector(m, m, 2, 3, 0, 1, 6, 7, 4, 5));
        m = imin(m, __builtin_shufflevector(m, m, 1, 0, 3, 2, 5, 4, 7, 6));
        const int x0 = std::min(m[0], width - kColumns);
        const int y0 = std::min(m[4], height - kRows);
        const auto row = [&](int r) { return simd::load<LanesOf<8>::Uints>(texels + std::ptrdiff_t(y0 + r) * width + x0); };
        rows01_ = __builtin_shufflevector(row(0), row(1), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
        rows23_ = __builtin_shufflevector(row(2), row(3), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
        x0_ = simd::splat<Ints>(x0), y0_ = simd::splat<Ints>(y0);
    }
    // Whether the window holds every texel of the lanes whose columns are xa's or xb's and
    // rows ya's or yb's (a bilinear lookup's four; a nearest one's, xb = xa and yb = ya).
    bool holds(const Ints& xa, const Ints& ya, const Ints& xb, const Ints& yb) const {
        const Ints dx = (xa - x0_) | (xb - x0_);
        const Ints dy = (ya - y0_) | (yb - y0_);
        return (simd::less_unsigned_bits(dx, simd::splat<Ints>(kColumns)) &
                simd::less_unsigned_bits(dy, simd::splat<Ints>(kRows))) == 0xffff;
    }
    // The texels at (x, y), for lanes the window holds.
    Uints texels(const Ints& x, const Ints& y) const { return simd::lookup(rows01_, rows23_, ((y - y0_) << 3) + (x - x0_)); }

private:
    Uints rows01_, rows23_;  // rows y0, y0 + 1 | y0 + 2, y0 + 3, each from column x0
    Ints x0_, y0_;
};

// The plain lookup's register: one AVX-512 register of sixteen lanes where the CPU has one
// (docs/results.md, stop 44: a bilinear lookup in about half the time of two 8-lane registers).
constexpr int kPlainLanes = simd::register_floats >= 16 ? 16 : L;
// kPlainLanes as a value of a lookup's template: the sixteen-lane code below is compiled only
// where it is taken.
template <AxisMode>
constexpr int kPlainLanesOf = kPlainLanes;

// 0, 1, 2, ... in the lanes of I.
template <class I>
I lane_indices() {
    I r;
    for (int i = 0; i < lanes_in<I>; ++i) r[i] = i;
    return r;
}

// A register's filtered texels as the lookup's four channels.
template <class U>
[[gnu::always_inline]] inline void store_texels(const PlainLookup& l, int base, int n, const PairsOf<U>& q) {
    // Unrolled, the texels stay in registers (as a loop, GCC picked each channel's half
    // through memory: the halftone's frame took 7% longer).
#pragma GCC unroll 4
    for (int c = 0; c < 4; ++c) store_lanes(l.rgba[std::size_t(c)], base, n, unorm(channel(q, c)));
}

// llvmpipe's 8-bit filter of the texels texel(x, y) returns: the nearest, or the bilinear lerps
// of the four (x.i0 or x.i1, y.i0 or y.i1) by the weights x.w8 and y.w8, skipping a column or
// row of texels that no lane weighs (the lerp by 0 returns its first operand).
template <bool Linear, class F, class Texel>
[[gnu::always_inline]] inline auto filter(const AxisLanes<F>& x, const AxisLanes<F>& y, Texel texel) {
    auto q = split(texel(x.i0, y.i0));
    if constexpr (Linear) {
        const bool along_x = any(x.w8), along_y = any(y.w8);
        if (along_x) q = lerp8(x.w8, q, split(texel(x.i1, y.i0)));
        if (along_y) {
            auto q1 = split(texel(x.i0, y.i1));
            if (along_x) q1 = lerp8(x.w8, q1, split(texel(x.i1, y.i1)));
            q = lerp8(y.w8, q, q1);
        }
    }
    return q;
}

// Flattened, so that gather_near is inlined whatever GCC would choose: a variant of it with one
// more branch became a call (its index vector then went through memory), and the
// single-texture square took 5.7 ms against 3.6 at best.
template <AxisMode MS, AxisMode MT, bool Linear>
[[gnu::flatten]] void sample_plain_2d(const Texture& tex, const PlainLookup& l) {
    constexpr int kLanes = kPlainLanesOf<MS>;
    using F = typename LanesOf<kLanes>::Floats;
    using I = typename LanesOf<kLanes>::Ints;
    const I width = I{} + tex.width, height = I{} + tex.height;
    const std::uint32_t* t = tex.texels.data();
    const std::size_t count = tex.texels.size();
    const bool window_fits = kLanes == 16 && TexelWindow::fits(tex);
    for (int base = 0; base < l.lanes; base += kLanes) {
        const int n = std::min(l.lanes - base, kLanes);
        const F s = load_lanes<F>(l.s, base, n), tc = load_lanes<F>(l.t, base, n);
        AxisLanes<F> x, y;
        if constexpr (Linear) {
            const I active = lane_indices<I>() < n;
            x = plain_linear_axis<MS>(s, width, active), y = plain_linear_axis<MT>(tc, height, active);
        } else {
            x.i0 = plain_nearest_axis<MS>(s, width), y.i0 = plain_nearest_axis<MT>(tc, height);
        }
        if constexpr (kLanes == 16) {
            if (window_fits && n == kLanes) {
                const TexelWindow window(t, tex.width, tex.height, x.i0, y.i0);
                if (window.holds(x.i0, y.i0, Linear ? x.i1 : x.i0, Linear ? y.i1 : y.i0)) {
                    store_texels(l, base, n, filter<Linear>(x, y, [&](const I& xi, const I& yi) { return window.texels(xi, yi); }));
                    continue;
                }
            }
        }
        store_texels(l, base, n, filter<Linear>(x, y, [&](const I& xi, const I& yi) { return gather_near(t, count, yi * width + xi); }));
    }
}

using PlainSampler = void (*)(const Texture&, const PlainLookup&);
template <AxisMode MS, AxisMode MT>
PlainSampler plain_sampler(bool linear) {
    return linear ? &sample_plain_2d<MS, MT, true> : &sample_plain_2d<MS, MT, false>;
}
template <AxisMode MS>
PlainSampler plain_sampler(AxisMode mt, bool linear) {
    switch (mt) {
        case AxisMode::Clamp: return plain_sampler<MS, AxisMode::Clamp>(linear);
        case AxisMode::RepeatPot: return plain_sampler<MS, AxisMode::RepeatPot>(linear);
        case AxisMode::RepeatNpot: break;
    }
    return plain_sampler<MS, AxisMode::RepeatNpot>(linear);
}
// The plain lookup's function for this texture, or null where its lookups are not plain ones.
PlainSampler plain_sampler(const Texture& tex) {
    const SamplerState& st = tex.sampler;
    if (tex.dims != 2 || st.min != st.mag || st.mip != MipFilter::None || st.wrap_s == Wrap::MirroredRepeat ||
        st.wrap_t == Wrap::MirroredRepeat) {
        return nullptr;
    }
    auto mode = [](Wrap w, int size) {
        return w == Wrap::ClampToEdge ? AxisMode::Clamp : std::has_single_bit(unsigned(size)) ? AxisMode::RepeatPot : AxisMode::RepeatNpot;
    };
    const AxisMode ms = mode(st.wrap_s, tex.width), mt = mode(st.wrap_t, tex.height);
    const bool linear = st.min == Filter::Linear;
    switch (ms) {
        case AxisMode::Clamp: return plain_sampler<AxisMode::Clamp>(mt, linear);
        case AxisMode::RepeatPot: return plain_sampler<AxisMode::RepeatPot>(mt, linear);
        case AxisMode::RepeatNpot: break;
    }
    return plain_sampler<AxisMode::RepeatNpot>(mt, linear);
}
}  // namespace

bool sample_plain(const Texture& tex, const PlainLookup& l) {
    const PlainSampler plain = plain_sampler(tex);
    if (plain) plain(tex, l);
    return plain != nullptr;
}

// Flattened: the helpers above become one straight body (called as functions, their vectors
// would travel through memory). A descriptor of a plain lookup takes sample_plain, as shaders do.
[[gnu::flatten]] void sample(const Texture& tex, const Lookup& l) {
    if (!l.rho2 && !l.lod && !l.d_ds[0] && !l.offset[0] && sample_plain(tex, {l.lanes, l.s, l.t, l.rgba})) return;
    if (tex.dims == 3) {
        sample_dims<3>(tex, l);
    } else {
        sample_dims<2>(tex, l);
    }
}

void sample_cube(const Texture& tex, const Lookup& l, const std::int32_t* face) {
    for (int base = 0; base < l.lanes; base += L) sample_register<2>(tex, l, base, face);
}

// lp_build_fetch_texel: the level is lod + first level (0); a lane outside the level's size or
// a level outside the texture's reads zero, alpha included. A gather per register, from texel 0
// where the lane reads nothing.
void fetch(const Texture& tex, const Fetch& f) {
    const Ints last = splat(int(tex.levels.size()) - 1);
    for (int base = 0; base < f.lanes; base += L) {
        const int n = std::min(f.lanes - base, L);
        const Ints level = load_lanes<Ints>(f.level, base, n);
        const Ints x = load_lanes<Ints>(f.x, base, n), y = load_lanes<Ints>(f.y, base, n);
        const Ints z = f.z ? load_lanes<Ints>(f.z, base, n) : Ints{};
        const Ints in_levels = (level >= 0) & (level <= last);
        const LevelLanes lv = level_lanes(tex, level & in_levels);
        const Ints in = in_levels & (x >= 0) & (x < lv.width) & (y >= 0) & (y < lv.height) & (z >= 0) & (z < lv.depth);
        const Ints index = lv.offset + ((z & in) * lv.height + (y & in)) * lv.width + (x & in);
        const Uints texel = gather(tex.texels.data(), index & in) & Uints(in);
        for (int c = 0; c < 4; ++c) store_lanes(f.rgba[std::size_t(c)], base, n, unorm(channel(texel, c)));
    }
}

namespace {
// One axis of a gather: the bilinear lookup's two texels (lp_build_sample_wrap_linear with
// is_gather). REPEAT is the lookup's. CLAMP_TO_EDGE and MIRRORED_REPEAT take their own code
// there, so that a coordinate within half a texel of an edge reads the edge texel twice:
// CLAMP_TO_EDGE i0 = trunc(c - 0.5), i1 = min(trunc(c + 0.5), size - 1) from c = s size (+
// offset) clamped to [0, size]; MIRRORED_REPEAT mirrors s once, signed (2 (s/2 - round_even(s/2)),
// negative in a mirrored period), then i0 = floor(c size - 0.5), i1 = i0 + 1, each negative one
// complemented (-1 is 0, -2 is 1) and clamped to size - 1.
Axis gather_axis(const Floats& s, const Ints& size, Wrap wrap, bool pot, const Ints* offset) {
    if (wrap == Wrap::Repeat) return soa_axis(s, size, wrap, pot, splat(-1), Ints{}, offset);
    const Floats fsize = to_float(size);
    Axis a{};
    if (wrap == Wrap::MirroredRepeat) {
        const Floats half = (offset ? s + to_float(*offset) / fsize : s) * 0.5f;
        const Floats m = half - round_even(half);
        const Ints i0 = cvt_trunc(floor((m + m) * fsize - 0.5f)), i1 = i0 + 1;
        a.i0 = imin(i0 ^ (i0 < 0), size - 1);
        a.i1 = imin(i1 ^ (i1 < 0), size - 1);
        return a;
    }
    Floats c = s * fsize;
    if (offset) c = c + to_float(*offset);
    c = maxps(c < fsize ? c : fsize, Floats{});
    a.i0 = cvt_trunc(c - 0.5f);
    a.i1 = imin(cvt_trunc(c + 0.5f), size - 1);
    return a;
}

// Level 0's lanes [base, base + n), on the faces `faces` gives them (or none).
LevelLanes level0_lanes(const Texture& tex, const std::int32_t* faces, int base, int n) {
    if (!faces) return level_lanes(tex, Ints{});
    const Ints face = load_lanes<Ints>(faces, base, n);
    return face_level_lanes(tex, Ints{}, &face);
}

// A depth comparison texel's test against the reference value, `ref FUNC depth`: 1 where it
// passes, else 0. Ordered comparisons but NOTEQUAL's, which a NaN passes (D3D10's rule, which
// lp_build_sample_comparefunc follows); C's operators on vectors are exactly these.
Floats depth_passes(CompareFunc func, const Floats& ref, const Uints& texel) {
    const Floats depth = unorm(channel(texel, 0));
    Ints pass{};
    switch (func) {
        case CompareFunc::Never: break;
        case CompareFunc::Less: pass = ref < depth; break;
        case CompareFunc::Equal: pass = ref == depth; break;
        case CompareFunc::LessEqual: pass = ref <= depth; break;
        case CompareFunc::Greater: pass = ref > depth; break;
        case CompareFunc::NotEqual: pass = ref != depth; break;
        case CompareFunc::GreaterEqual: pass = ref >= depth; break;
        case CompareFunc::Always: pass = splat(-1); break;
    }
    return pass ? splat(1.0f) : Floats{};
}

// The two axes of a lookup's lanes [base, base + n): its s and t (and texel offsets, where it has
// them) handed to `axis(i, coordinate, offset or null)`.
template <class Lookup, class Axis>
Axes<2> axes_of(const Lookup& l, int base, int n, const Axis& axis) {
    Axes<2> ax;
    for (int i = 0; i < 2; ++i) {
        const std::int32_t* given = l.offset[std::size_t(i)];
        Ints offset;
        if (given) offset = load_lanes<Ints>(given, base, n);
        ax.a[i] = axis(i, load_lanes(i == 0 ? l.s : l.t, base, n), given ? &offset : nullptr);
    }
    return ax;
}
}  // namespace

void gather_channel(const Texture& tex, const Gather& g) {
    const std::array<bool, 3> pot = pot_sizes<2>(tex);
    for (int base = 0; base < g.lanes; base += L) {
        const int n = std::min(g.lanes - base, L);
        const LevelLanes lv = level0_lanes(tex, g.face, base, n);
        const Axes<2> ax = axes_of(g, base, n, [&](int i, const Floats& c, const Ints* offset) {
            return gather_axis(c, size_of(lv, i), wrap_of(tex.sampler, i), pot[std::size_t(i)], offset);
        });
        const Texels<2> k = fetch_texels(tex, lv, ax);  // k[0][row j][column i]
        const Uints order[4] = {k.k[0][1][0], k.k[0][1][1], k.k[0][0][1], k.k[0][0][0]};
        if (g.ref) {
            // each texel's comparison, as a shadow lookup's
            const Floats ref = load_lanes(g.ref, base, n);
            for (std::size_t c = 0; c < 4; ++c) {
                store_lanes(g.out[c], base, n, depth_passes(tex.sampler.compare, ref, order[c]));
            }
            continue;
        }
        for (std::size_t c = 0; c < 4; ++c) store_lanes(g.out[c], base, n, unorm(channel(order[c], g.component)));
    }
}

// lp_build_sample_image_nearest and _linear with a comparison (lp_bld_sample_soa.c): level 0's
// texel, or its four bilinear texels, each compared with the reference value by the sampler's
// function, the 0/1 results blended with the bilinear weights as colours are
// (lp_build_masklerp2d). The float path's coordinates, as a GL_DEPTH_COMPONENT32F texture's.
void sample_shadow(const Texture& tex, const ShadowLookup& l) {
    const std::array<bool, 3> pot = pot_sizes<2>(tex);
    const Ints linear = tex.sampler.mag == Filter::Linear ? splat(-1) : Ints{};
    for (int base = 0; base < l.lanes; base += L) {
        const int n = std::min(l.lanes - base, L);
        const LevelLanes lv = level0_lanes(tex, l.face, base, n);
        const Axes<2> ax = axes_of(l, base, n, [&](int i, const Floats& c, const Ints* offset) {
            return soa_axis(c, size_of(lv, i), wrap_of(tex.sampler, i), pot[std::size_t(i)], linear, Ints{}, offset);
        });
        const Texels<2> k = fetch_texels(tex, lv, ax);  // k[0][row j][column i]
        const Floats ref = load_lanes(l.ref, base, n);
        const auto passes = [&](const Uints& texel) { return depth_passes(tex.sampler.compare, ref, texel); };
        const Floats r0 = lerp(ax.a[0].w, passes(k.k[0][0][0]), passes(k.k[0][0][1]));
        const Floats r1 = lerp(ax.a[0].w, passes(k.k[0][1][0]), passes(k.k[0][1][1]));
        store_lanes(l.out, base, n, lerp(ax.a[1].w, r0, r1));
    }
}

// lp_build_lod_selector with is_lodq (no fast path: log2 of rho^2 halved), and
// lp_build_sample_common's level: 0 without mipmaps, lp_build_round (to even) then clamped to
// [0, last] with NEAREST ones, clamped with LINEAR.
void query_lod(const Texture& tex, const LodQuery& q) {
    const Floats last = splat(float(int(tex.levels.size()) - 1));
    for (int base = 0; base < q.lanes; base += L) {
        const int n = std::min(q.lanes - base, L);
        const Floats lod = fast_log2(load_lanes(q.rho2, base, n)) * 0.5f;
        Floats level{};
        if (tex.sampler.mip == MipFilter::Nearest) level = minps(maxps(round_even(lod), Floats{}), last);
        if (tex.sampler.mip == MipFilter::Linear) level = minps(maxps(lod, Floats{}), last);
        store_lanes(q.level, base, n, level);
        store_lanes(q.lod, base, n, lod);
    }
}

}  // namespace texture_detail

}  // namespace qs::glsl
