#pragma once
// The level of detail and the levels a lookup reads, as llvmpipe chooses them with the default
// sampler state (lp_bld_sample.c: lp_build_lod_selector, lp_build_nearest_mip_level and
// lp_build_linear_mip_levels, lp_build_minify): from a quad's squared scale factor, a bias or
// an explicit level, per lane; and where each lane's level (and cube face) keeps its texels.
//
// Private to the sampler's sources, as texture_lanes.h.

#include "shading/glsl/texture_lanes.h"

namespace qs::glsl {

namespace {

// The biased exponent field minus (127 - bias): floor(log2 x) + bias for normal x
// (lp_build_extract_exponent).
inline Ints exponent(const Floats& x, int bias) { return ((bits(x) >> 23) & 255) - (127 - bias); }
// lp_build_fast_log2: exponent plus mantissa - 1, piecewise linear and exact at powers of two.
inline Floats fast_log2(const Floats& x) {
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
inline LevelChoice choose_levels(const Texture& tex, const Floats* rho2_lanes, const Floats* bias_lanes, const Floats* lod_lanes) {
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

// Per lane, a level's size and where its texels start.
struct LevelLanes {
    Ints width, height, depth, offset;
};
inline LevelLanes level_lanes(const Texture& tex, const Ints& level) {
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

// A level's lanes, on each lane's face of a cube map (`face`, or none): the faces of a level
// follow one another, +X first, each width x height texels.
inline LevelLanes face_level_lanes(const Texture& tex, const Ints& level, const Ints* face) {
    LevelLanes lv = level_lanes(tex, level);
    if (face) lv.offset = lv.offset + *face * lv.width * lv.height;
    return lv;
}

}  // namespace

}  // namespace qs::glsl
