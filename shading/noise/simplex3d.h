#pragma once
// 3D simplex noise, 2011 variant, translated from simplex3d.glsl beside this file. The variant's
// constants are a template argument, as the GLSL takes them from #defines.

#include "shading/glsl.h"
#include "shading/noise/simplex2d.h"

namespace qs::noise {
using namespace qs::glsl;

// Figure 1.1 demo: kernel radius^2 0.6, scale 42, full-precision Taylor constants.
struct Simplex3dDemo {
    static constexpr float falloff = 0.6f, scale = 42.0f;
    static constexpr float taylor_a = 1.79284291400159f, taylor_b = 0.85373472095314f;
    static constexpr const char* glsl_defines =
        "#define SNOISE3_FALLOFF 0.6\n#define SNOISE3_SCALE 42.0\n"
        "#define SNOISE3_TAYLOR_A 1.79284291400159\n#define SNOISE3_TAYLOR_B 0.85373472095314\n";
};
// Table 1.1 benchmark: radius^2 0.51, scale 93, truncated Taylor constants.
struct Simplex3dBenchmark {
    static constexpr float falloff = 0.51f, scale = 93.0f;
    static constexpr float taylor_a = 1.792843f, taylor_b = 0.853735f;
    static constexpr const char* glsl_defines =
        "#define SNOISE3_FALLOFF 0.51\n#define SNOISE3_SCALE 93.0\n"
        "#define SNOISE3_TAYLOR_A 1.792843\n#define SNOISE3_TAYLOR_B 0.853735\n";
};

template <class Variant, class F>
F snoise3(const vec3<F>& v) {
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
    // Fused where the product is exact (noise/simplex2d.h): p, a permutation, is a whole number
    // in [-2, 290], so 49 floor(p / 49), 7 x_ and 2 floor(b) are small whole numbers, and s * sh
    // below is 0 or +-1.
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
    // Mix final noise value
    vec4<F> m = max(Variant::falloff - vec4<F>(dot(x0, x0), dot(x1, x1), dot(x2, x2), dot(x3, x3)), 0.0f);
    m = m * m;
    return Variant::scale * dot(m * m, vec4<F>(dot(p0, x0), dot(p1, x1), dot(p2, x2), dot(p3, x3)));
}

}  // namespace qs::noise
