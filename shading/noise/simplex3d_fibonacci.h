#pragma once
// The "Noise is Beautiful" notes' 3D simplex noise with gradients on a Fibonacci sphere, and its analytic gradient:
// translated from simplex3d_fibonacci.glsl beside this file, line for line.

#include "shading/glsl.h"
#include "shading/noise/permute_polynomial.h"

namespace qs::noise::noise_is_beautiful {
using namespace qs::glsl;

template <class F>
vec3<F> fibonacci_sphere(const F& i) {
    // Point i of 289 on a Fibonacci sphere. The azimuth is taken as a fraction of a turn first so
    // that sin and cos see arguments in [0, 2 pi), not up to 289 * 2.4.
    F z = 1.0f - (2.0f * i + 1.0f) / 289.0f;
    F r = sqrt(1.0f - z * z);
    F phi = 6.28318531f * fract(i * 0.618033989f);
    return vec3<F>(r * cos(phi), r * sin(phi), z);
}
template <class F>
vec3<F> corner_gradient(const vec3<F>& c) {
    return fibonacci_sphere(permute(permute(permute(c.x, 10.0f) + c.y, 10.0f) + c.z, 10.0f));
}
// The noise in [0,1]; grad receives its gradient in p, d/dp [t^4 (g.v)] = t^4 g - 8 t^3 (g.v) v
// for each corner (dv/dp the identity).
template <class F>
F noise3(const vec3<F>& p, vec3<F>& grad) {
    const float F3 = 1.0f / 3.0f;
    const float G3 = 1.0f / 6.0f;
    vec3<F> c0 = floor(p + dot(p, vec3<F>(F3)));
    vec3<F> v0 = p - c0 + dot(c0, vec3<F>(G3));
    vec3<F> g = step(v0.yzx(), v0.xyz());
    vec3<F> l = 1.0f - g;
    vec3<F> i1 = min(g.xyz(), l.zxy());
    vec3<F> i2 = max(g.xyz(), l.zxy());
    vec3<F> v1 = v0 - i1 + G3;
    vec3<F> v2 = v0 - i2 + 2.0f * G3;
    vec3<F> v3 = v0 - 1.0f + 3.0f * G3;
    vec3<F> g0 = corner_gradient(c0);
    vec3<F> g1 = corner_gradient(c0 + i1);
    vec3<F> g2 = corner_gradient(c0 + i2);
    vec3<F> g3 = corner_gradient(c0 + 1.0f);
    vec4<F> t = max(0.6f - vec4<F>(dot(v0, v0), dot(v1, v1), dot(v2, v2), dot(v3, v3)), 0.0f);
    vec4<F> gv = vec4<F>(dot(g0, v0), dot(g1, v1), dot(g2, v2), dot(g3, v3));
    vec4<F> t3 = t * t * t;
    vec4<F> t4 = t3 * t;
    F n = dot(t4, gv);
    grad = t4.x * g0 + t4.y * g1 + t4.z * g2 + t4.w * g3
         - 8.0f * (t3.x * gv.x * v0 + t3.y * gv.y * v1 + t3.z * gv.z * v2 + t3.w * gv.w * v3);
    const float scale = 32.0f;  // so that the output fills about [0,1]
    grad *= 0.5f * scale;
    return (scale * n + 1.0f) / 2.0f;
}

}  // namespace qs::noise::noise_is_beautiful
