#pragma once
// sampler2DShadow's lookups, as Mesa's llvmpipe answers them on a GL_DEPTH_COMPONENT32F texture
// with GL_TEXTURE_COMPARE_MODE = GL_COMPARE_REF_TO_TEXTURE and the sampler's compare function
// (SamplerState::compare, GL_LEQUAL by default): 1 where `reference FUNC depth` holds, else 0 (a
// NaN fails every function but NOTEQUAL, which it passes), with nearest filtering that of the
// nearest texel, with linear filtering the four texels' results blended with the bilinear
// weights (lp_build_sample_compare, lp_build_masklerp2d). The reference value is not clamped, as
// a float format's is not.
//
// A depth comparison texture is a sampler2D whose texels' red byte is the depth, red / 255 as
// llvmpipe turns a unorm8 into a float (the scene marks it: a binding's "compare", scenes/gltf.h;
// the OSMesa reference uploads those floats as GL_DEPTH_COMPONENT32F). It has one level and one
// filter for minification and magnification, so no lookup needs a level of detail.
//
// Apart from texture.h so that what includes the lookups alone (every hand translation) does not
// depend on these: the interpreter and generated translations include both.

#include "shading/glsl/texture.h"
#include "shading/glsl/texture_queries.h"

namespace qs::glsl {

namespace texture_detail {

struct ShadowLookup {
    int lanes = 0;
    const float* s = nullptr;
    const float* t = nullptr;
    const float* ref = nullptr;
    std::array<const std::int32_t*, 2> offset{};  // texel offsets, or none
    const std::int32_t* face = nullptr;           // a cube map's face per lane, or none
    float* out = nullptr;
};
void sample_shadow(const Texture& tex, const ShadowLookup& lookup);

template <Number F>
F shadow_lanes(const Texture& tex, const vec3<F>& p, const ivec2<F>* offset) {
    constexpr int N = lanes_of<F>();
    alignas(64) float s[N], t[N], ref[N], out[N];
    alignas(64) std::int32_t o[2][N];
    to_floats(p.x, s), to_floats(p.y, t), to_floats(p.z, ref);
    ShadowLookup l;
    l.lanes = N, l.s = s, l.t = t, l.ref = ref, l.out = out;
    LaneCases cases = cases_of(p.x) | cases_of(p.y) | cases_of(p.z);
    if (offset) {
        to_ints(offset->x, o[0]), to_ints(offset->y, o[1]);
        l.offset = {o[0], o[1]};
        cases = cases | cases_of(offset->x) | cases_of(offset->y);
    }
    sample_shadow(tex, l);
    return constant_lanes<F>(out, cases);
}

}  // namespace texture_detail

// texture(sampler2DShadow, P) and its Lod and Grad forms (which read the one level the same
// way): P.z compared with the depth at P.xy. The result is a step of the comparison: under Dual2
// its derivatives are 0.
template <Number F>
F textureShadow(const sampler2D& depth, const vec3<F>& p) {
    return texture_detail::shadow_lanes<F>(depth, p, nullptr);
}
// ... with texel offsets added as a lookup's are.
template <Number F>
F textureShadowOffset(const sampler2D& depth, const vec3<F>& p, const ivec2<F>& offset) {
    return texture_detail::shadow_lanes<F>(depth, p, &offset);
}
// textureProj(sampler2DShadow, P): P.xyz times the reciprocal of P.w (the reference value too),
// as Mesa lowers a projective lookup.
template <Number F>
F textureShadowProj(const sampler2D& depth, const vec4<F>& p) {
    const F q = F(1.0f) / p.w;
    return textureShadow(depth, vec3<F>(p.x * q, p.y * q, p.z * q));
}
template <Number F>
F textureShadowProjOffset(const sampler2D& depth, const vec4<F>& p, const ivec2<F>& offset) {
    const F q = F(1.0f) / p.w;
    return textureShadowOffset(depth, vec3<F>(p.x * q, p.y * q, p.z * q), offset);
}
// shadow2D's vec4: (r, r, r, 1), as GL_DEPTH_TEXTURE_MODE's default, GL_LUMINANCE, makes it.
template <Number F>
vec4<F> depthLuminance(const F& r) {
    return vec4<F>(r, r, r, F(1.0f));
}

}  // namespace qs::glsl
