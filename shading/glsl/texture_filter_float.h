#pragma once
// llvmpipe's float filtering path (lp_bld_sample_soa.c), which it takes where the 8-bit one does
// not (a mirrored axis; different minification and magnification filters with a level of detail
// per pixel) and for depth comparisons: per axis, two texels and a float weight under every wrap
// mode, and one level's texels blended by float lerps.
//
// Private to the sampler's sources, as texture_lanes.h.

#include "shading/glsl/texture_texels.h"

namespace qs::glsl {

namespace {

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

// A depth comparison texel's test against the reference value, `ref FUNC depth`: 1 where it
// passes, else 0. Ordered comparisons but NOTEQUAL's, which a NaN passes (D3D10's rule, which
// lp_build_sample_comparefunc follows); C's operators on vectors are exactly these.
Floats depth_passes(CompareFunc func, const Floats& ref, const Uints& texel) {
    const Floats depth = from_bits(texel);  // TexelFormat::Depth32F
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

// One level, float path; a shadow lookup's (co.ref) compares each texel and blends the results
// into out[0] (lp_build_sample_compare).
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
    if (co.ref) {
        const auto passes = [&](const Uints& texel) { return depth_passes(tex.sampler.compare, *co.ref, texel); };
        const Floats r0 = lerp(ax.a[0].w, passes(k.k[0][0][0]), passes(k.k[0][0][1]));
        const Floats r1 = lerp(ax.a[0].w, passes(k.k[0][1][0]), passes(k.k[0][1][1]));
        out[0] = lerp(ax.a[1].w, r0, r1);
        return;
    }
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

}  // namespace

}  // namespace qs::glsl
