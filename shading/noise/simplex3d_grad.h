#pragma once
// The analytic gradient of the chapter's 3D simplex noise (simplex3d.h), translated from
// simplex3d_grad.glsl beside this file, line for line: snoise3 with its last line differentiated
// corner by corner, d/dx [m^4 (p.x)] = m^4 p - 8 m^3 (p.x) x with m = max(falloff - x.x, 0), x the
// offset from the corner (the corners are constant within a simplex, so dx/dv is the identity).
// The value is snoise3's, bit for bit (tests/shading/test_noise_gradients.cpp).

#include "shading/glsl.h"
#include "shading/noise/simplex3d.h"

namespace qs::noise {
using namespace qs::glsl;

template <class Variant, class F>
F snoise3_grad(const vec3<F>& v, vec3<F>& gradient) {
    const vec2<F> C(1.0f / 6.0f, 1.0f / 3.0f);
    const vec4<F> D(0.0f, 0.5f, 1.0f, 2.0f);
    // First corner
    vec3<F> i = floor(v + dot(v, vec3<F>(C.y)));
    vec3<F> x0 = v - i + dot(i, vec3<F>(C.x));
    // Other corners
    vec3<F> g = step(x0.yzx(), x0.xyz());
    vec3<F> l = 1.0f - g;
    vec3<F> i1 = min(g.xyz(), l.zxy());
    vec3<F> i2 = max(g.xyz(), l.zxy());
    vec3<F> x1 = x0 - i1 + 1.0f * vec3<F>(C.x);
    vec3<F> x2 = x0 - i2 + 2.0f * vec3<F>(C.x);
    vec3<F> x3 = x0 - 1.0f + 3.0f * vec3<F>(C.x);
    // Permutations, z first
    i = mod289(i);
    vec4<F> p = permute289(permute289(permute289(
                    i.z + vec4<F>(0.0f, i1.z, i2.z, 1.0f))
                  + i.y + vec4<F>(0.0f, i1.y, i2.y, 1.0f))
                  + i.x + vec4<F>(0.0f, i1.x, i2.x, 1.0f));
    // Gradients: 7x7 points over a square, mapped onto an octahedron
    F n_ = 1.0f / 7.0f;
    vec3<F> ns = n_ * vec3<F>(D.w, D.y, D.z) - vec3<F>(D.x, D.z, D.x);  // GLSL: n_ * D.wyz - D.xzx
    // Fused where the product is exact, as in snoise3 (simplex3d.h).
    vec4<F> j = exact_product_add(floor(p * ns.z * ns.z), vec4<F>(-49.0f), p);  // GLSL: p - 49.0 * floor(p * ns.z * ns.z)
    vec4<F> x_ = floor(j * ns.z);
    vec4<F> y_ = floor(exact_product_add(x_, vec4<F>(-7.0f), j));  // GLSL: floor(j - 7.0 * x_)
    vec4<F> x = x_ * ns.x + vec4<F>(ns.y);
    vec4<F> y = y_ * ns.x + vec4<F>(ns.y);
    vec4<F> h = 1.0f - abs(x) - abs(y);
    vec4<F> b0(x.xy(), y.xy());
    vec4<F> b1(x.zw(), y.zw());
    vec4<F> s0 = exact_product_add(floor(b0), vec4<F>(2.0f), vec4<F>(1.0f));  // GLSL: floor(b0)*2.0 + 1.0
    vec4<F> s1 = exact_product_add(floor(b1), vec4<F>(2.0f), vec4<F>(1.0f));
    vec4<F> sh = -step(h, vec4<F>(0.0f));
    // GLSL: a0 = b0.xzyw + s0.xzyw*sh.xxyy, a1 = b1.xzyw + s1.xzyw*sh.zzww
    vec4<F> a0 = exact_product_add(s0.xzyw(), vec4<F>(sh.x, sh.x, sh.y, sh.y), b0.xzyw());
    vec4<F> a1 = exact_product_add(s1.xzyw(), vec4<F>(sh.z, sh.z, sh.w, sh.w), b1.xzyw());
    vec3<F> p0(a0.xy(), h.x);
    vec3<F> p1(a0.zw(), h.y);
    vec3<F> p2(a1.xy(), h.z);
    vec3<F> p3(a1.zw(), h.w);
    // Normalise gradients: taylorInvSqrt(r) = A - B r
    vec4<F> norm = Variant::taylor_a - Variant::taylor_b * vec4<F>(dot(p0, p0), dot(p1, p1), dot(p2, p2), dot(p3, p3));
    p0 *= vec3<F>(norm.x);
    p1 *= vec3<F>(norm.y);
    p2 *= vec3<F>(norm.z);
    p3 *= vec3<F>(norm.w);
    vec4<F> m = max(Variant::falloff - vec4<F>(dot(x0, x0), dot(x1, x1), dot(x2, x2), dot(x3, x3)), 0.0f);
    vec4<F> m2 = m * m;
    vec4<F> m3 = m2 * m;
    vec4<F> m4 = m2 * m2;
    vec4<F> px(dot(p0, x0), dot(p1, x1), dot(p2, x2), dot(p3, x3));
    gradient = Variant::scale * (m4.x * p0 + m4.y * p1 + m4.z * p2 + m4.w * p3
             - 8.0f * (m3.x * px.x * x0 + m3.y * px.y * x1 + m3.z * px.z * x2 + m3.w * px.w * x3));
    return Variant::scale * dot(m2 * m2, px);
}

}  // namespace qs::noise
