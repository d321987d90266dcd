#pragma once
// GLSL 4.00's texture gathers and level-of-detail query on sampler2D and sampler3D, as Mesa's
// llvmpipe answers them (lp_bld_sample_soa.c, lp_bld_sample.c): textureGather and
// textureGatherOffset return one channel of the four texels a bilinear lookup of level 0 reads;
// textureQueryLod the level of detail an implicit lookup computes, and the level it reads.
//
// Apart from texture.h so that what includes the lookups alone (every hand translation) does not
// depend on these: the interpreter and generated translations include both.

#include "shading/glsl/texture.h"

namespace qs::glsl {

namespace texture_detail {

// textureGather's lanes: the texels a bilinear lookup at (s, t) reads at level 0, whatever the
// sampler's filters, as llvmpipe's gather takes the linear path with no mipmaps; channel
// `component` of each, in GL's order: (i0, j1), (i1, j1), (i1, j0), (i0, j0).
struct Gather {
    int lanes = 0;
    const float* s = nullptr;
    const float* t = nullptr;
    std::array<const std::int32_t*, 2> offset{};  // texel offsets, or none
    int component = 0;
    const std::int32_t* face = nullptr;  // a cube map's face per lane, or none
    // A depth comparison texture's reference value per lane, or none: each texel's comparison
    // (1 or 0) in place of a channel.
    const float* ref = nullptr;
    std::array<float*, 4> out{};
};
void gather_channel(const Texture& tex, const Gather& gather);

// textureQueryLod's lanes from the implicit level's squared scale factor `rho2` (Lookup's):
// `lod` = log2(rho) as llvmpipe computes it (lp_build_fast_log2 of rho^2, halved), and `level`
// the mipmap level it reads (0 without mipmaps; rounded to even and clamped to the levels with
// NEAREST mipmaps, clamped with LINEAR).
struct LodQuery {
    int lanes = 0;
    const float* rho2 = nullptr;
    float* level = nullptr;
    float* lod = nullptr;
};
void query_lod(const Texture& tex, const LodQuery& query);

// Gather `g` (its lanes' coordinates set) with, where given, each texel compared with `ref`: the
// four channels as F, constant over `cases` and ref's.
template <Number F>
vec4<F> run_gather(const Texture& tex, Gather& g, const F* ref, LaneCases cases) {
    constexpr int N = lanes_of<F>();
    alignas(64) float r[N], out[4][N];
    if (ref) {
        to_floats(*ref, r);
        g.ref = r;
        cases = cases | cases_of(*ref);
    }
    for (std::size_t k = 0; k < 4; ++k) g.out[k] = out[k];
    gather_channel(tex, g);
    return vec4<F>(constant_lanes<F>(out[0], cases), constant_lanes<F>(out[1], cases), constant_lanes<F>(out[2], cases),
                   constant_lanes<F>(out[3], cases));
}

template <Number F>
vec4<F> gather_lanes(const Texture& tex, const vec2<F>& p, const ivec2<F>* offset, int component,
                     const F* ref = nullptr) {
    constexpr int N = lanes_of<F>();
    alignas(64) float s[N], t[N];
    alignas(64) std::int32_t o[2][N];
    to_floats(p.x, s), to_floats(p.y, t);
    Gather g;
    g.lanes = N, g.s = s, g.t = t, g.component = component;
    LaneCases cases = cases_of(p.x) | cases_of(p.y);
    if (offset) {
        to_ints(offset->x, o[0]), to_ints(offset->y, o[1]);
        g.offset = {o[0], o[1]};
        cases = cases | cases_of(offset->x) | cases_of(offset->y);
    }
    return run_gather<F>(tex, g, ref, cases);
}

template <Number F, std::size_t Dims>
vec2<F> lod_query(const Texture& tex, const std::array<F, Dims>& coord) {
    constexpr int N = lanes_of<F>();
    alignas(64) float rho2[N], level[N], lod[N];
    LaneCases cases;
    sampler_traits<F>::implicit_rho2(coord, {float(tex.width), float(tex.height), float(tex.depth)}, rho2, cases);
    query_lod(tex, {N, rho2, level, lod});
    return vec2<F>(constant_lanes<F>(level, cases), constant_lanes<F>(lod, cases));
}

}  // namespace texture_detail

// textureGather(s, P [, comp]): channel `comp` (0: red, a constant) of the four texels a bilinear
// lookup at P reads on level 0, in GL's order (i0 j1, i1 j1, i1 j0, i0 j0). The texels are
// constants: under Dual2 the result's derivatives are 0.
template <Number F>
vec4<F> textureGather(const sampler2D& tex, const vec2<F>& p, int comp = 0) {
    return texture_detail::gather_lanes<F>(tex, p, nullptr, comp);
}
// ... with texel offsets added as a lookup's are.
template <Number F>
vec4<F> textureGatherOffset(const sampler2D& tex, const vec2<F>& p, const ivec2<F>& offset, int comp = 0) {
    return texture_detail::gather_lanes<F>(tex, p, &offset, comp);
}

// textureGather(sampler2DShadow, P, refZ) and textureGatherOffset(sampler2DShadow, P, refZ,
// offset): each of those four texels compared with refZ by the depth comparison texture's
// function, 1 where it passes, else 0.
template <Number F>
vec4<F> textureGatherCompare(const sampler2D& depth, const vec2<F>& p, const F& ref) {
    return texture_detail::gather_lanes<F>(depth, p, nullptr, 0, &ref);
}
template <Number F>
vec4<F> textureGatherOffsetCompare(const sampler2D& depth, const vec2<F>& p, const F& ref, const ivec2<F>& offset) {
    return texture_detail::gather_lanes<F>(depth, p, &offset, 0, &ref);
}

// textureGatherOffsets(s, P, offsets [, comp]): component i is texel i0 j0 (a gather's w) of the
// footprint at offsets[i], as Mesa lowers it (four gathers, nir_lower_tex); the ...Compare form,
// a sampler2DShadow's, compares each with refZ.
template <Number F>
vec4<F> textureGatherOffsets(const sampler2D& tex, const vec2<F>& p, const std::array<ivec2<F>, 4>& offsets, int comp = 0) {
    vec4<F> r;
    for (std::size_t i = 0; i < 4; ++i) r[int(i)] = texture_detail::gather_lanes<F>(tex, p, &offsets[i], comp).w;
    return r;
}
template <Number F>
vec4<F> textureGatherOffsetsCompare(const sampler2D& depth, const vec2<F>& p, const F& ref,
                                    const std::array<ivec2<F>, 4>& offsets) {
    vec4<F> r;
    for (std::size_t i = 0; i < 4; ++i) r[int(i)] = texture_detail::gather_lanes<F>(depth, p, &offsets[i], 0, &ref).w;
    return r;
}

// textureQueryLevels(s): the texture's mipmap levels (1 where its sampler reads none, as the
// texture GL samples then has): textureQueryLevels<F>(s).
template <Number F>
int_t<F> textureQueryLevels(const Texture& tex) {
    constexpr int N = lanes_of<F>();
    alignas(64) std::int32_t levels[N];
    for (int i = 0; i < N; ++i) levels[i] = std::int32_t(tex.levels.size());
    return texture_detail::from_ints<int_t<F>>(levels);
}

// textureQueryLod(s, P): (the mipmap level an implicit lookup at P reads, its level of detail
// relative to the base level), as llvmpipe computes them, one per quad. Needs the quad's
// derivatives (quads, or Dual2's partials); the result is constant over the quad: its Dual2
// derivatives are 0.
template <Number F>
vec2<F> textureQueryLod(const sampler2D& tex, const vec2<F>& p) {
    return texture_detail::lod_query<F, 2>(tex, texture_detail::coords(p));
}
template <Number F>
vec2<F> textureQueryLod(const sampler3D& tex, const vec3<F>& p) {
    return texture_detail::lod_query<F, 3>(tex, texture_detail::coords(p));
}

}  // namespace qs::glsl
