#pragma once
// llvmpipe's 8-bit fixed-point filtering path (lp_bld_sample_aos.c), which it takes for RGBA8
// textures whose wraps are REPEAT or CLAMP_TO_EDGE: per axis, two texels and a weight in 1/256,
// and one level's texels blended by the 8-bit lerp.
//
// Private to the sampler's sources, as texture_lanes.h.

#include "shading/glsl/texture_texels.h"

namespace qs::glsl {

namespace {

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
inline Axis aos_axis(const Floats& s, const Ints& size, Wrap wrap, bool pot, const Ints& linear, const Ints* offset) {
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

}  // namespace

}  // namespace qs::glsl
