#pragma once
// samplerCube and samplerCubeShadow, and GLSL's lookups in them, as Mesa's llvmpipe samples a
// GL_RGBA8 (or GL_DEPTH_COMPONENT32F) GL_TEXTURE_CUBE_MAP with GL_TEXTURE_CUBE_MAP_SEAMLESS off,
// GL's default (lp_build_cube_lookup in lp_bld_sample.c, lp_build_sample_common in
// lp_bld_sample_soa.c):
//  - the face per pixel from the direction's largest magnitude, z over y over x where two are
//    equal; the face's coordinates mirrored from the other two by the major one's sign and
//    projected by 0.5 / |major| (s = sc 0.5 / |ma| + 0.5);
//  - the face then sampled as a 2D texture clamped to its edges whatever the sampler's wraps (a
//    lookup never leaves its face), with the filters, mipmaps and 8-bit or float path a 2D
//    texture takes (texture.h);
//  - a level of detail from the direction's derivatives carried through the projection, pixel by
//    pixel: (d.sc - sc d.ma / ma) 0.5 / ma, the derivatives of the direction fine ones (along x
//    the pixel's row of its quad, along y its column); each pixel keeps its own level (so a
//    lookup with different minification and magnification filters takes the float path), but
//    for an implicit lookup on a texture without mipmaps, which takes its quad's upper-left
//    pixel's (and the 8-bit path). Measured bit for bit against llvmpipe 22.3 under every filter
//    (tests/reference/test_glsl_reference.cpp).
//
// A cube map is a Texture whose levels each hold the six faces one after another, in GL's order
// (+X, -X, +Y, -Y, +Z, -Z), every face square; its `dims` is kCubeDims. Apart from texture.h so
// that what includes the lookups alone (every hand translation) does not depend on these: the
// interpreter and generated translations include both.

#include <bit>
#include <cmath>

#include "shading/glsl/texture.h"
#include "shading/glsl/texture_queries.h"
#include "shading/glsl/texture_shadow.h"

namespace qs::glsl {

// Texture::dims of a cube map, and a shader's SamplerUse::dims for a samplerCube.
inline constexpr int kCubeDims = 6;

struct samplerCube : Texture {
    samplerCube() { dims = kCubeDims; }
    // Six square faces of size x size RGBA8 texels (4 bytes each, rows from t = 0; a Depth32F
    // cube map's depth the red byte, as a 2D one's), in GL's order +X, -X, +Y, -Y, +Z, -Z;
    // mipmaps face by face as glGenerateMipmap makes them when the sampler's minification filter
    // reads them. Throws std::invalid_argument for a size outside 1..16384
    // (GL_MAX_CUBE_MAP_TEXTURE_SIZE).
    samplerCube(int size, const std::array<const std::uint8_t*, 6>& faces, SamplerState sampler,
                TexelFormat format = TexelFormat::Rgba8);
};

namespace texture_detail {

// `lookup` on each lane's face (0..5) of a cube map; its s and t are the face's coordinates.
void sample_cube(const Texture& cube, const Lookup& lookup, const std::int32_t* face);

// One lane's face: llvmpipe's selection and mirroring, on the floats' bits as llvmpipe does them
// (a sign flipped is an xor, so -0 and NaN keep their bits).
struct CubeFace {
    int face;   // 0..5: +X, -X, +Y, -Y, +Z, -Z
    int axis;   // 0, 1, 2: the major axis
    float ma;   // the major coordinate
    float sc, tc;  // the face's coordinates before the projection
    std::uint32_t sign;  // ma's sign bit
};
inline CubeFace cube_face(float s, float t, float r) {
    constexpr std::uint32_t kSign = 0x80000000u;
    const float as = std::fabs(s), at = std::fabs(t), ar = std::fabs(r);
    const bool x_over_y = as > at;
    const float larger = as > at ? as : at;  // maxps
    CubeFace f;
    f.axis = ar >= larger ? 2 : x_over_y ? 0 : 1;
    f.ma = f.axis == 0 ? s : f.axis == 1 ? t : r;
    f.sign = std::bit_cast<std::uint32_t>(f.ma) & kSign;
    const std::uint32_t si = std::bit_cast<std::uint32_t>(s), ti = std::bit_cast<std::uint32_t>(t),
                        ri = std::bit_cast<std::uint32_t>(r);
    f.sc = std::bit_cast<float>(f.axis == 0 ? f.sign ^ ri ^ kSign : f.axis == 1 ? si : f.sign ^ si);
    f.tc = std::bit_cast<float>(f.axis == 1 ? f.sign ^ ri : ti ^ kSign);
    f.face = 2 * f.axis + int(f.sign >> 31);
    return f;
}
// The projection onto the face, s = sc scale + 0.5: 0.5 / |ma| (0 where ma is 0), or, where the
// lookup carries derivatives through it, |0.5 (1 / ma)| as llvmpipe computes it then (the same
// bits for any ma but 0).
inline float face_scale(float ma, bool with_derivatives) {
    if (with_derivatives) return std::fabs(0.5f * (1.0f / ma));
    const float a = std::fabs(ma);
    return a > 0.0f ? 0.5f / a : 0.0f;
}

// The derivative (dx, dy, dz) of the direction mirrored as the face mirrors it: its (d.sc, d.tc)
// and d.ma.
struct FaceDerivative {
    float sc, tc, ma;
};
inline FaceDerivative face_derivative(const CubeFace& f, float dx, float dy, float dz) {
    constexpr std::uint32_t kSign = 0x80000000u;
    const std::uint32_t xi = std::bit_cast<std::uint32_t>(dx), yi = std::bit_cast<std::uint32_t>(dy),
                        zi = std::bit_cast<std::uint32_t>(dz);
    FaceDerivative d;
    d.ma = f.axis == 0 ? dx : f.axis == 1 ? dy : dz;
    d.sc = std::bit_cast<float>(f.axis == 0 ? f.sign ^ zi ^ kSign : f.axis == 1 ? xi : f.sign ^ xi);
    d.tc = std::bit_cast<float>(f.axis == 1 ? f.sign ^ zi : yi ^ kSign);
    return d;
}

// A direction projected onto its faces, lane by lane: the face and its (s, t), and, where the
// level of detail is wanted, llvmpipe's squared scale factor from the direction's derivatives
// carried through the projection, and those derivatives of (s, t) (which Dual2 carries on).
template <int N>
struct CubeProjection {
    alignas(64) float s[N], t[N], rho2[N];
    alignas(64) float fdx[3][N], fdy[3][N];  // the face's (s, t) derivatives along x and along y
    alignas(64) std::int32_t face[N];
    bool have_derivs = false;  // fdx and fdy hold them
    LaneCases lod_cases;       // a checked lane's level reads its whole quad
};

// The projection of direction p. `need_derivs`: the level of detail is wanted, from the given
// derivatives (ddx, ddy), else from Dual2's partials, else from the quad; Dual2 carries its
// partials through the projection either way.
template <Number F>
void project_cube(const Texture& tex, const vec3<F>& p, bool need_derivs, const vec3<F>* ddx, const vec3<F>* ddy,
                  CubeProjection<lanes_of<F>()>& out) {
    constexpr int N = lanes_of<F>();
    alignas(64) float c[3][N], gx[3][N], gy[3][N];
    for (int k = 0; k < 3; ++k) to_floats(p[k], c[k]);
    out.have_derivs = false;
    if (ddx && need_derivs) {
        for (int k = 0; k < 3; ++k) to_floats((*ddx)[k], gx[k]), to_floats((*ddy)[k], gy[k]);
        out.have_derivs = true;
    } else if (need_derivs || sampler_traits<F>::carries_partials) {
        sampler_traits<F>::coordinate_derivatives(std::array<F, 3>{p.x, p.y, p.z}, c, gx, gy, out.lod_cases);
        out.have_derivs = true;
    }
    for (int i = 0; i < N; ++i) {
        const CubeFace f = cube_face(c[0][i], c[1][i], c[2][i]);
        out.face[i] = f.face;
        const float ima = 1.0f / f.ma, imahalf = 0.5f * ima;
        const float scale = face_scale(f.ma, need_derivs);
        out.s[i] = f.sc * scale + 0.5f;
        out.t[i] = f.tc * scale + 0.5f;
        if (!out.have_derivs) continue;
        // dx.s = 0.5 (dx.sc - sc dx.ma / ma) / ma, in llvmpipe's order of operations
        for (int a = 0; a < 2; ++a) {
            const float(&g)[3][N] = a == 0 ? gx : gy;
            const FaceDerivative d = face_derivative(f, g[0][i], g[1][i], g[2][i]);
            const float ma_over_ma = d.ma * ima;
            float(&fd)[3][N] = a == 0 ? out.fdx : out.fdy;
            fd[0][i] = (d.sc - ma_over_ma * f.sc) * imahalf;
            fd[1][i] = (d.tc - ma_over_ma * f.tc) * imahalf;
        }
    }
    // lp_build_rho from the face coordinates' derivatives, as from explicit ones
    const float size = float(tex.width);
    if (need_derivs) gradient_rho2<2>(out.fdx, out.fdy, {size, size, 0.0f}, out.rho2);
}

// Every lookup in a samplerCube: the direction p, and what `kind` adds to it (a bias or an
// explicit level in `lod_or_bias`, derivatives of p in `ddx` and `ddy`); in a samplerCubeShadow,
// with its reference value `ref` (the result in channel 0, constant under Dual2).
template <Number F>
vec4<F> cube_lookup(const Texture& tex, const vec3<F>& p, Lod kind, const F* lod_or_bias, const vec3<F>* ddx,
                    const vec3<F>* ddy, const F* ref = nullptr) {
    constexpr int N = lanes_of<F>();
    // a comparison's result is a step of it, whose derivatives are 0
    const bool derivatives = sampler_traits<F>::carries_partials && !ref;
    alignas(64) float extra[N], refs[N], rgba[4][N], d_dc[2][4][N];
    if (kind == Lod::Bias || kind == Lod::Explicit) to_floats(*lod_or_bias, extra);
    if (ref) to_floats(*ref, refs);
    // llvmpipe carries derivatives through the projection where the texture needs a level of
    // detail and the lookup gives none.
    const bool need_derivs = kind != Lod::Explicit && tex.needs_lod();
    CubeProjection<N> pr;
    project_cube<F>(tex, p, need_derivs, kind == Lod::Gradient ? ddx : nullptr, ddy, pr);
    // llvmpipe keeps a level of detail per pixel where the texture has mipmaps (its default,
    // GALLIVM_PERF without quad_lod, for a cube map), and where a bias or derivatives are given;
    // an implicit one that only chooses between the minification and magnification filters is
    // its quad's, from its upper-left pixel (the quad's first element in llvmpipe's order).
    const bool quad_lod = need_derivs && kind == Lod::Implicit && tex.sampler.mip == MipFilter::None;
    if (quad_lod && QuadNumber<F>) {
        float own[N];
        for (int i = 0; i < N; ++i) own[i] = pr.rho2[i];
        for (int i = 0; i < N; ++i) pr.rho2[i] = own[quad_tl(i)];
    }
    for (int i = 0; i < N; i += kMaxLanes) {
        Lookup l;
        l.lanes = N - i < kMaxLanes ? N - i : kMaxLanes;
        l.s = pr.s + i, l.t = pr.t + i;
        l.rho2 = need_derivs ? pr.rho2 + i : nullptr;
        l.bias = kind == Lod::Bias ? extra + i : nullptr;
        l.lod = kind == Lod::Explicit ? extra + i : nullptr;
        l.rho2_per_pixel = !quad_lod;
        l.quad_vectors = QuadNumber<F>;
        l.ref = ref ? refs + i : nullptr;
        for (std::size_t ch = 0; ch < 4; ++ch) {
            l.rgba[ch] = rgba[ch] + i;
            if (derivatives) l.d_ds[ch] = d_dc[0][ch] + i, l.d_dt[ch] = d_dc[1][ch] + i;
        }
        sample_cube(tex, l, pr.face + i);
    }
    LaneCases cases = pr.lod_cases | cases_of(p.x) | cases_of(p.y) | cases_of(p.z);
    if (kind == Lod::Bias || kind == Lod::Explicit) cases = cases | cases_of(*lod_or_bias);
    if (kind == Lod::Gradient) {
        for (int k = 0; k < 3; ++k) cases = cases | cases_of((*ddx)[k]) | cases_of((*ddy)[k]);
    }
    if (ref) cases = cases | cases_of(*ref);
    // The face coordinates' derivatives, which the projection carried.
    using Partials = typename sampler_traits<F>::Partials;
    const std::array<Partials, 2> dface{sampler_traits<F>::partials(pr.fdx[0], pr.fdy[0]),
                                        sampler_traits<F>::partials(pr.fdx[1], pr.fdy[1])};
    vec4<F> out;
    for (int ch = 0; ch < 4; ++ch) {
        if (ref) {
            out[ch] = sampler_traits<F>::constant(rgba[ch], cases);
            continue;
        }
        const std::array<const float*, 2> d_dface{d_dc[0][ch], d_dc[1][ch]};
        out[ch] = sampler_traits<F>::sampled(rgba[ch], d_dface, dface, cases);
    }
    return out;
}

// textureQueryLod in a cube map: the level of detail an implicit lookup in direction p computes,
// and the level it reads (query_lod). Where the sampler needs a level of detail, llvmpipe carries
// the quad's derivatives through the projection, each pixel its own; where it does not (one
// level, one filter), it projects without them and takes the quad's scale factor from the face
// coordinates' differences across it, TR - TL and BL - TL, as a 2D texture's (quad_rho2). Dual2
// carries its partials through the projection either way.
template <Number F>
vec2<F> cube_lod_query(const Texture& tex, const vec3<F>& p) {
    constexpr int N = lanes_of<F>();
    alignas(64) float level[N], lod[N];
    CubeProjection<N> pr;
    const bool carried = tex.needs_lod() || sampler_traits<F>::carries_partials;
    project_cube<F>(tex, p, carried, nullptr, nullptr, pr);
    if (!carried) {
        const float size = float(tex.width);
        quad_rho2_of_floats<F, 2>({pr.s, pr.t}, {size, size, 0.0f}, pr.rho2);
        pr.lod_cases = sampler_traits<F>::across_quads(cases_of(p.x) | cases_of(p.y) | cases_of(p.z));
    }
    query_lod(tex, {N, pr.rho2, level, lod});
    const LaneCases cases = pr.lod_cases | cases_of(p.x) | cases_of(p.y) | cases_of(p.z);
    return vec2<F>(constant_lanes<F>(level, cases), constant_lanes<F>(lod, cases));
}

// Each lane's face of direction p and its coordinates on it, s = sc scale + 0.5 (face_scale: as
// a lookup that carries derivatives projects, or not).
template <Number F>
void face_coordinates(const vec3<F>& p, bool with_derivatives, float* s, float* t, std::int32_t* face) {
    constexpr int N = lanes_of<F>();
    alignas(64) float c[3][N];
    for (int k = 0; k < 3; ++k) to_floats(p[k], c[k]);
    for (int i = 0; i < N; ++i) {
        const CubeFace f = cube_face(c[0][i], c[1][i], c[2][i]);
        face[i] = f.face;
        const float scale = face_scale(f.ma, with_derivatives);
        s[i] = f.sc * scale + 0.5f;
        t[i] = f.tc * scale + 0.5f;
    }
}

// textureGather on a cube map: the face's four texels a bilinear lookup at direction p reads on
// level 0, as gather_channel reads a 2D texture's (CLAMP_TO_EDGE's gather wrap); channel
// `component`, or, with a reference value, each texel's comparison with it.
template <Number F>
vec4<F> cube_gather(const Texture& tex, const vec3<F>& p, int component, const F* ref) {
    constexpr int N = lanes_of<F>();
    alignas(64) float s[N], t[N];
    alignas(64) std::int32_t face[N];
    face_coordinates(p, tex.needs_lod(), s, t, face);
    Gather g;
    g.lanes = N, g.s = s, g.t = t, g.component = component, g.face = face;
    return run_gather<F>(tex, g, ref, cases_of(p.x) | cases_of(p.y) | cases_of(p.z));
}

}  // namespace texture_detail

// textureGather(samplerCube, P [, comp]): channel `comp` (0: red, a constant) of the four texels
// a bilinear lookup in direction P reads on its face's level 0, in GL's order; constants under
// Dual2.
template <Number F>
vec4<F> textureGather(const samplerCube& tex, const vec3<F>& p, int comp = 0) {
    return texture_detail::cube_gather<F>(tex, p, comp, nullptr);
}
// textureGather(samplerCubeShadow, P, refZ): each of those texels' comparison with refZ.
template <Number F>
vec4<F> textureGatherCompare(const samplerCube& depth, const vec3<F>& p, const F& ref) {
    return texture_detail::cube_gather<F>(depth, p, 0, &ref);
}

// GLSL's lookups in a samplerCube: a direction (any length but 0), the level of detail from the
// quad (implicit), a bias added to it, an explicit level, or explicit derivatives of the direction.
template <Number F>
vec4<F> textureCube(const samplerCube& tex, const vec3<F>& p) {
    return texture_detail::cube_lookup<F>(tex, p, texture_detail::Lod::Implicit, nullptr, nullptr, nullptr);
}
template <Number F>
vec4<F> textureCube(const samplerCube& tex, const vec3<F>& p, const F& bias) {
    return texture_detail::cube_lookup<F>(tex, p, texture_detail::Lod::Bias, &bias, nullptr, nullptr);
}
template <Number F>
vec4<F> textureCubeLod(const samplerCube& tex, const vec3<F>& p, const F& lod) {
    return texture_detail::cube_lookup<F>(tex, p, texture_detail::Lod::Explicit, &lod, nullptr, nullptr);
}
template <Number F>
vec4<F> texture(const samplerCube& tex, const vec3<F>& p) { return textureCube(tex, p); }
template <Number F>
vec4<F> texture(const samplerCube& tex, const vec3<F>& p, const F& bias) { return textureCube(tex, p, bias); }
template <Number F>
vec4<F> textureLod(const samplerCube& tex, const vec3<F>& p, const F& lod) { return textureCubeLod(tex, p, lod); }
// llvmpipe's level from the given derivatives, pixel by pixel, carried through the projection.
template <Number F>
vec4<F> textureGrad(const samplerCube& tex, const vec3<F>& p, const vec3<F>& dPdx, const vec3<F>& dPdy) {
    return texture_detail::cube_lookup<F>(tex, p, texture_detail::Lod::Gradient, nullptr, &dPdx, &dPdy);
}
// A face's size at level `lod`: textureSize<F>(cube, lod).
template <Number F>
ivec2<F> textureSize(const samplerCube& tex, const int_t<F>& lod) {
    const auto s = texture_detail::size_query<F, 2>(tex, lod);
    return ivec2<F>(s[0], s[1]);
}

// textureQueryLod(samplerCube, P): (the mipmap level an implicit lookup in direction P reads, its
// level of detail relative to the base level), as llvmpipe computes them. Needs the quad's
// derivatives (quads, or Dual2's partials); under Dual2 the result's derivatives are 0.
template <Number F>
vec2<F> textureQueryLod(const samplerCube& tex, const vec3<F>& p) {
    return texture_detail::cube_lod_query<F>(tex, p);
}

// texture(samplerCubeShadow, P [, bias]) and textureGrad(samplerCubeShadow, ...): P.w compared
// with the depth in direction P.xyz, filtered and mipmapped as a sampler2DShadow's lookups are,
// with the level of detail a samplerCube's lookup takes. The result is a step of the comparison:
// under Dual2 its derivatives are 0.
template <Number F>
F textureCubeShadow(const samplerCube& depth, const vec4<F>& p) {
    return texture_detail::cube_lookup<F>(depth, p.xyz(), texture_detail::Lod::Implicit, nullptr, nullptr, nullptr, &p.w)[0];
}
template <Number F>
F textureCubeShadow(const samplerCube& depth, const vec4<F>& p, const F& bias) {
    return texture_detail::cube_lookup<F>(depth, p.xyz(), texture_detail::Lod::Bias, &bias, nullptr, nullptr, &p.w)[0];
}
// An explicit level (GL_EXT_texture_shadow_lod's textureLod): a vertex shader's implicit lookup
// reads level 0 so.
template <Number F>
F textureCubeShadowLod(const samplerCube& depth, const vec4<F>& p, const F& lod) {
    return texture_detail::cube_lookup<F>(depth, p.xyz(), texture_detail::Lod::Explicit, &lod, nullptr, nullptr, &p.w)[0];
}
template <Number F>
F textureCubeShadowGrad(const samplerCube& depth, const vec4<F>& p, const vec3<F>& dPdx, const vec3<F>& dPdy) {
    return texture_detail::cube_lookup<F>(depth, p.xyz(), texture_detail::Lod::Gradient, nullptr, &dPdx, &dPdy, &p.w)[0];
}

}  // namespace qs::glsl
