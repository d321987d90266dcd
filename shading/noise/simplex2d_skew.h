#pragma once
// The "Noise is Beautiful" notes' 2D simplex noise on the xy_to_uv shear, and its analytic gradient dnoise: translated
// from simplex2d_skew.glsl beside this file, line for line.

#include "shading/glsl.h"
#include "shading/noise/permute_polynomial.h"

namespace qs::noise::noise_is_beautiful {
using namespace qs::glsl;

template <class F>
vec2<F> gradient(const vec2<F>& p) {
    float B1 = 7.f;
    float B2 = 6.f;
    F x = permute(permute(p.x, B1) + p.y, B1) / 288.f;
    F y = permute(permute(p.x, B2) + p.y, B2) / 288.f;
    // Our permutation function gives us a value in [0,1].
    // Convert this to a gradient vector that can go in any direction.
    return normalize(vec2<F>(x, y) - vec2<F>(0.5f, 0.5f));
}
template <class F>
vec2<F> xy_to_uv(const vec2<F>& xy) { return vec2<F>(xy.x + xy.y * 0.5f, xy.y); }
template <class F>
vec2<F> uv_to_xy(const vec2<F>& uv) { return vec2<F>(uv.x - uv.y * 0.5f, uv.y); }

// In [0,1] (measured: [0.16, 0.84] over 80x80 cells).
template <class F>
F noise(const vec2<F>& p) {
    vec2<F> uv = xy_to_uv(p);
    // Find the corners of my simplex
    vec2<F> uv0 = floor(uv);
    vec2<F> luv = fract(uv);  // Local
    vec2<F> uv1 = uv0;
    uv1 += vec2<F>(step(luv.y, luv.x), step(luv.x, luv.y));
    vec2<F> uv2 = uv0 + vec2<F>(1.f, 1.f);
    // Sample my gradient function
    vec2<F> g0 = gradient(uv0);
    vec2<F> g1 = gradient(uv1);
    vec2<F> g2 = gradient(uv2);
    // Compute my noise contributions
    vec2<F> v0 = p - uv_to_xy(uv0);
    F w0 = max(0.75f - dot(v0, v0), 0.f);
    w0 = w0 * w0;
    w0 = w0 * w0;
    vec2<F> v1 = p - uv_to_xy(uv1);
    F w1 = max(0.75f - dot(v1, v1), 0.f);
    w1 = w1 * w1;
    w1 = w1 * w1;
    vec2<F> v2 = p - uv_to_xy(uv2);
    F w2 = max(0.75f - dot(v2, v2), 0.f);
    w2 = w2 * w2;
    w2 = w2 * w2;
    F n0 = w0 * dot(g0, v0);
    F n1 = w1 * dot(g1, v1);
    F n2 = w2 * dot(g2, v2);
    F n = n0 + n1 + n2;
    // Scale to [0,1]
    return (10.9f * n + 1.f) / 2.f;
}

// One corner's term of dnoise: d/dp [max(0.75 - v.v, 0)^4 (g.v)] = t^4 g - 8 t^3 (g.v) v, v's
// derivative in p being the identity (at t = 0 both sides are 0: the term is C^3 there).
template <class F>
vec2<F> dcorner(const vec2<F>& g, const vec2<F>& v) {
    F t = max(0.75f - dot(v, v), 0.f);
    F t3 = t * t * t;
    return t3 * (t * g - 8.f * dot(g, v) * v);
}
// d noise / dp, analytic: noise()'s simplex and gradients, each corner's term by the product
// rule, times the output's scale 10.9 / 2.
template <class F>
vec2<F> dnoise(const vec2<F>& p) {
    // noise()'s simplex and gradients
    vec2<F> uv = xy_to_uv(p);
    vec2<F> uv0 = floor(uv);
    vec2<F> luv = fract(uv);
    vec2<F> uv1 = uv0;
    uv1 += vec2<F>(step(luv.y, luv.x), step(luv.x, luv.y));
    vec2<F> uv2 = uv0 + vec2<F>(1.f, 1.f);
    vec2<F> d = dcorner(gradient(uv0), p - uv_to_xy(uv0))
              + dcorner(gradient(uv1), p - uv_to_xy(uv1))
              + dcorner(gradient(uv2), p - uv_to_xy(uv2));
    return 10.9f / 2.f * d;
}

}  // namespace qs::noise::noise_is_beautiful
