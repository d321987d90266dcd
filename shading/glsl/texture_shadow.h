#pragma once
// sampler2DShadow's lookups, as Mesa's llvmpipe answers them on a GL_DEPTH_COMPONENT32F texture
// with GL_TEXTURE_COMPARE_MODE = GL_COMPARE_REF_TO_TEXTURE and the sampler's compare function
// (SamplerState::compare, GL_LEQUAL by default): each texel read passes (1) where `reference
// FUNC depth` holds, else fails (0) (a NaN reference fails every function but NOTEQUAL, which it
// passes), and these are filtered as colours are on llvmpipe's float path: nearest, bilinear
// (lp_build_sample_compare, lp_build_masklerp2d), and between two mipmap levels, with the level
// of detail a colour lookup takes (from the quad, a bias, an explicit level or derivatives). The
// reference value is not clamped, as a float format's is not.
//
// A depth comparison texture is a sampler2D of TexelFormat::Depth32F: its base level is an
// image's red bytes, red / 255 (the scene marks it: a binding's "compare", scenes/gltf.h; the
// OSMesa reference uploads those floats as GL_DEPTH_COMPONENT32F), and its mipmaps are floats,
// made as llvmpipe's glGenerateMipmap blits them.
//
// Apart from texture.h so that what includes the lookups alone (every hand translation) does not
// depend on these: the interpreter and generated translations include both.

#include "shading/glsl/texture.h"
#include "shading/glsl/texture_queries.h"

namespace qs::glsl {

namespace texture_detail {

// A shadow lookup: P.z compared at P.xy, with what `args` adds (its ref is set here).
template <Number F>
F compared(const Texture& depth, const vec3<F>& p, LookupArgs<F, 2> args) {
    const F ref = p.z;
    args.ref = &ref;
    return lookup<F, 2>(depth, {p.x, p.y}, args)[0];
}
// A projective one's P: P.xyz times the reciprocal of P.w (the reference value too), as Mesa
// lowers a projective lookup.
template <Number F>
vec3<F> projected_shadow(const vec4<F>& p) {
    const F q = F(1.0f) / p.w;
    return vec3<F>(p.x * q, p.y * q, p.z * q);
}
template <Number F>
std::array<F, 2> coords2(const vec2<F>& d) { return {d.x, d.y}; }

}  // namespace texture_detail

// texture(sampler2DShadow, P [, bias]), textureLod and textureGrad: P.z compared with the depth at
// P.xy. The result is a step of the comparison: under Dual2 its derivatives are 0.
template <Number F>
F textureShadow(const sampler2D& depth, const vec3<F>& p) {
    return texture_detail::compared<F>(depth, p, {});
}
template <Number F>
F textureShadow(const sampler2D& depth, const vec3<F>& p, const F& bias) {
    return texture_detail::compared<F>(depth, p, {texture_detail::Lod::Bias, &bias});
}
template <Number F>
F textureShadowLod(const sampler2D& depth, const vec3<F>& p, const F& lod) {
    return texture_detail::compared<F>(depth, p, {texture_detail::Lod::Explicit, &lod});
}
template <Number F>
F textureShadowGrad(const sampler2D& depth, const vec3<F>& p, const vec2<F>& dPdx, const vec2<F>& dPdy) {
    const auto dx = texture_detail::coords2(dPdx), dy = texture_detail::coords2(dPdy);
    return texture_detail::compared<F>(depth, p, {texture_detail::Lod::Gradient, nullptr, &dx, &dy});
}
// ... with texel offsets added as a colour lookup's are (GLSL's argument order).
template <Number F>
F textureShadowOffset(const sampler2D& depth, const vec3<F>& p, const ivec2<F>& offset) {
    const std::array<int_t<F>, 2> o{offset.x, offset.y};
    return texture_detail::compared<F>(depth, p, {texture_detail::Lod::Implicit, nullptr, nullptr, nullptr, &o});
}
template <Number F>
F textureShadowOffset(const sampler2D& depth, const vec3<F>& p, const ivec2<F>& offset, const F& bias) {
    const std::array<int_t<F>, 2> o{offset.x, offset.y};
    return texture_detail::compared<F>(depth, p, {texture_detail::Lod::Bias, &bias, nullptr, nullptr, &o});
}
template <Number F>
F textureShadowLodOffset(const sampler2D& depth, const vec3<F>& p, const F& lod, const ivec2<F>& offset) {
    const std::array<int_t<F>, 2> o{offset.x, offset.y};
    return texture_detail::compared<F>(depth, p, {texture_detail::Lod::Explicit, &lod, nullptr, nullptr, &o});
}
template <Number F>
F textureShadowGradOffset(const sampler2D& depth, const vec3<F>& p, const vec2<F>& dPdx, const vec2<F>& dPdy,
                          const ivec2<F>& offset) {
    const auto dx = texture_detail::coords2(dPdx), dy = texture_detail::coords2(dPdy);
    const std::array<int_t<F>, 2> o{offset.x, offset.y};
    return texture_detail::compared<F>(depth, p, {texture_detail::Lod::Gradient, nullptr, &dx, &dy, &o});
}

// textureProj(sampler2DShadow, P) and its kin: P.xyz times the reciprocal of P.w, then as above.
template <Number F>
F textureShadowProj(const sampler2D& depth, const vec4<F>& p) {
    return textureShadow(depth, texture_detail::projected_shadow(p));
}
template <Number F>
F textureShadowProj(const sampler2D& depth, const vec4<F>& p, const F& bias) {
    return textureShadow(depth, texture_detail::projected_shadow(p), bias);
}
template <Number F>
F textureShadowProjLod(const sampler2D& depth, const vec4<F>& p, const F& lod) {
    return textureShadowLod(depth, texture_detail::projected_shadow(p), lod);
}
template <Number F>
F textureShadowProjGrad(const sampler2D& depth, const vec4<F>& p, const vec2<F>& dPdx, const vec2<F>& dPdy) {
    return textureShadowGrad(depth, texture_detail::projected_shadow(p), dPdx, dPdy);
}
template <Number F>
F textureShadowProjOffset(const sampler2D& depth, const vec4<F>& p, const ivec2<F>& offset) {
    return textureShadowOffset(depth, texture_detail::projected_shadow(p), offset);
}
template <Number F>
F textureShadowProjOffset(const sampler2D& depth, const vec4<F>& p, const ivec2<F>& offset, const F& bias) {
    return textureShadowOffset(depth, texture_detail::projected_shadow(p), offset, bias);
}
template <Number F>
F textureShadowProjLodOffset(const sampler2D& depth, const vec4<F>& p, const F& lod, const ivec2<F>& offset) {
    return textureShadowLodOffset(depth, texture_detail::projected_shadow(p), lod, offset);
}
template <Number F>
F textureShadowProjGradOffset(const sampler2D& depth, const vec4<F>& p, const vec2<F>& dPdx, const vec2<F>& dPdy,
                              const ivec2<F>& offset) {
    return textureShadowGradOffset(depth, texture_detail::projected_shadow(p), dPdx, dPdy, offset);
}

// shadow2D's vec4: (r, r, r, 1), as GL_DEPTH_TEXTURE_MODE's default, GL_LUMINANCE, makes it.
template <Number F>
vec4<F> depthLuminance(const F& r) {
    return vec4<F>(r, r, r, F(1.0f));
}

}  // namespace qs::glsl
