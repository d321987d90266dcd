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

// A shadow lookup: p[2] compared at (p[0], p[1]), with what `kind` adds (a bias or an explicit
// level in `lod_or_bias`, derivatives of (s, t) along x and y), at texel offsets where given.
template <Number F>
F compared(const Texture& depth, const std::array<F, 3>& p, Lod kind = Lod::Implicit, const F* lod_or_bias = nullptr,
           const vec2<F>* dPdx = nullptr, const vec2<F>* dPdy = nullptr, const ivec2<F>* offset = nullptr) {
    std::array<F, 2> dx, dy;
    if (dPdx) dx = coords(*dPdx), dy = coords(*dPdy);
    std::array<int_t<F>, 2> o;
    if (offset) o = coords<F>(*offset);
    const LookupArgs<F, 2> args{kind, lod_or_bias, dPdx ? &dx : nullptr, dPdy ? &dy : nullptr, offset ? &o : nullptr,
                                &p[2]};
    return lookup<F, 2>(depth, {p[0], p[1]}, args)[0];
}

}  // namespace texture_detail

// texture(sampler2DShadow, P [, bias]), textureLod and textureGrad: P.z compared with the depth at
// P.xy. The result is a step of the comparison: under Dual2 its derivatives are 0.
template <Number F>
F textureShadow(const sampler2D& depth, const vec3<F>& p) {
    return texture_detail::compared<F>(depth, texture_detail::coords(p));
}
template <Number F>
F textureShadow(const sampler2D& depth, const vec3<F>& p, const F& bias) {
    return texture_detail::compared<F>(depth, texture_detail::coords(p), texture_detail::Lod::Bias, &bias);
}
template <Number F>
F textureShadowLod(const sampler2D& depth, const vec3<F>& p, const F& lod) {
    return texture_detail::compared<F>(depth, texture_detail::coords(p), texture_detail::Lod::Explicit, &lod);
}
template <Number F>
F textureShadowGrad(const sampler2D& depth, const vec3<F>& p, const vec2<F>& dPdx, const vec2<F>& dPdy) {
    return texture_detail::compared<F>(depth, texture_detail::coords(p), texture_detail::Lod::Gradient, nullptr, &dPdx,
                                       &dPdy);
}
// ... with texel offsets added as a colour lookup's are (GLSL's argument order).
template <Number F>
F textureShadowOffset(const sampler2D& depth, const vec3<F>& p, const ivec2<F>& offset) {
    return texture_detail::compared<F>(depth, texture_detail::coords(p), texture_detail::Lod::Implicit, nullptr,
                                       nullptr, nullptr, &offset);
}
template <Number F>
F textureShadowOffset(const sampler2D& depth, const vec3<F>& p, const ivec2<F>& offset, const F& bias) {
    return texture_detail::compared<F>(depth, texture_detail::coords(p), texture_detail::Lod::Bias, &bias, nullptr,
                                       nullptr, &offset);
}
template <Number F>
F textureShadowLodOffset(const sampler2D& depth, const vec3<F>& p, const F& lod, const ivec2<F>& offset) {
    return texture_detail::compared<F>(depth, texture_detail::coords(p), texture_detail::Lod::Explicit, &lod, nullptr,
                                       nullptr, &offset);
}
template <Number F>
F textureShadowGradOffset(const sampler2D& depth, const vec3<F>& p, const vec2<F>& dPdx, const vec2<F>& dPdy,
                          const ivec2<F>& offset) {
    return texture_detail::compared<F>(depth, texture_detail::coords(p), texture_detail::Lod::Gradient, nullptr, &dPdx,
                                       &dPdy, &offset);
}

// textureProj(sampler2DShadow, P) and its kin: P.xyz times the reciprocal of P.w (projected3: the
// reference value too, as Mesa lowers a projective lookup), then as above.
template <Number F>
F textureShadowProj(const sampler2D& depth, const vec4<F>& p) {
    return texture_detail::compared<F>(depth, texture_detail::projected3(p));
}
template <Number F>
F textureShadowProj(const sampler2D& depth, const vec4<F>& p, const F& bias) {
    return texture_detail::compared<F>(depth, texture_detail::projected3(p), texture_detail::Lod::Bias, &bias);
}
template <Number F>
F textureShadowProjLod(const sampler2D& depth, const vec4<F>& p, const F& lod) {
    return texture_detail::compared<F>(depth, texture_detail::projected3(p), texture_detail::Lod::Explicit, &lod);
}
template <Number F>
F textureShadowProjGrad(const sampler2D& depth, const vec4<F>& p, const vec2<F>& dPdx, const vec2<F>& dPdy) {
    return texture_detail::compared<F>(depth, texture_detail::projected3(p), texture_detail::Lod::Gradient, nullptr,
                                       &dPdx, &dPdy);
}
template <Number F>
F textureShadowProjOffset(const sampler2D& depth, const vec4<F>& p, const ivec2<F>& offset) {
    return texture_detail::compared<F>(depth, texture_detail::projected3(p), texture_detail::Lod::Implicit, nullptr,
                                       nullptr, nullptr, &offset);
}
template <Number F>
F textureShadowProjOffset(const sampler2D& depth, const vec4<F>& p, const ivec2<F>& offset, const F& bias) {
    return texture_detail::compared<F>(depth, texture_detail::projected3(p), texture_detail::Lod::Bias, &bias, nullptr,
                                       nullptr, &offset);
}
template <Number F>
F textureShadowProjLodOffset(const sampler2D& depth, const vec4<F>& p, const F& lod, const ivec2<F>& offset) {
    return texture_detail::compared<F>(depth, texture_detail::projected3(p), texture_detail::Lod::Explicit, &lod,
                                       nullptr, nullptr, &offset);
}
template <Number F>
F textureShadowProjGradOffset(const sampler2D& depth, const vec4<F>& p, const vec2<F>& dPdx, const vec2<F>& dPdy,
                              const ivec2<F>& offset) {
    return texture_detail::compared<F>(depth, texture_detail::projected3(p), texture_detail::Lod::Gradient, nullptr,
                                       &dPdx, &dPdy, &offset);
}

// shadow2D's vec4: (r, r, r, 1), as GL_DEPTH_TEXTURE_MODE's default, GL_LUMINANCE, makes it.
template <Number F>
vec4<F> depthLuminance(const F& r) {
    return vec4<F>(r, r, r, F(1.0f));
}

}  // namespace qs::glsl
