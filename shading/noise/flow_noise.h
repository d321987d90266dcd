#pragma once
// Flow noise: 2D simplex noise with rotating gradients and analytic gradient, translated from
// flow_noise.glsl beside this file.

#include "shading/glsl.h"

namespace qs::noise {
using namespace qs::glsl;

// GLSL's mod(x, m) = x - m * floor(x / m) for a whole number x whose m * floor(x / m) stays below
// 2^24: that product is exact, so the subtraction rounds once with it (exact_product_add,
// noise/simplex2d.h) with the GLSL's bits.
template <class V>
V mod_whole(const V& x, float m) {
    return exact_product_add(floor(x / m), V(-m), x);
}

// GLSL: permute(x) = mod(((x*34.0)+1.0)*x, 289.0). The noises permute whole numbers |x| <= 577:
// a permutation or mod(floor(P), 289.0) lies in [-288, 288] (the quotient of a whole number below
// 2^24 rounds at most up to the next whole number), and a hash adds two and a corner offset. Up to
// |x| = 702, (34 x + 1) x < 2^24 and every product is a whole number, exact, so each multiply and
// the addition after it round once with the GLSL's bits (tests/shading/test_exact_product_add.cpp
// runs each such x).
template <class V>
V permute_mod(const V& x) {
    return mod_whole(exact_product_add(x, V(34.0f), V(1.0f)) * x, 289.0f);
}

template <class F>
F srdnoise(const vec2<F>& P, const F& rot, vec2<F>& grad) {
    const float F2 = 0.366025403f;
    const float G2 = 0.211324865f;
    const float K = 0.0243902439f;  // 1/41
    // Skew to the simplex grid and find the first corner
    vec2<F> Pi = floor(P + dot(P, vec2<F>(F2)));
    vec2<F> v0 = P - (Pi - dot(Pi, vec2<F>(G2)));
    // The other two corners
    vec2<F> i1 = select(v0.x > v0.y, vec2<F>(1.0f, 0.0f), vec2<F>(0.0f, 1.0f));
    vec2<F> v1 = v0 - i1 + G2;
    vec2<F> v2 = v0 - 1.0f + 2.0f * G2;
    Pi = mod(Pi, 289.0f);
    // Hash of the three corners, then a rotated gradient on a diamond
    vec3<F> x = Pi.x + vec3<F>(0.0f, i1.x, 1.0f);
    vec3<F> y = Pi.y + vec3<F>(0.0f, i1.y, 1.0f);
    vec3<F> u = permute_mod(permute_mod(x) + y) * K + rot;
    u = 4.0f * fract(u) - 2.0f;
    vec3<F> gx = abs(u) - 1.0f;
    vec3<F> gy = abs(abs(u + 1.0f) - 2.0f) - 1.0f;
    // Radial kernels
    vec3<F> t = max(0.5f - vec3<F>(dot(v0, v0), dot(v1, v1), dot(v2, v2)), 0.0f);
    vec3<F> t2 = t * t;
    vec3<F> t4 = t2 * t2;
    vec3<F> gv(gx.x * v0.x + gy.x * v0.y, gx.y * v1.x + gy.y * v1.y, gx.z * v2.x + gy.z * v2.y);
    F n = 40.0f * dot(t4, gv);
    // d/dv [t^4 (g.v)] = t^4 g - 8 t^3 (g.v) v, since dt/dv = -2 v
    vec3<F> t3gv = t2 * t * gv;
    grad.x = dot(t4, gx) - 8.0f * dot(t3gv, vec3<F>(v0.x, v1.x, v2.x));
    grad.y = dot(t4, gy) - 8.0f * dot(t3gv, vec3<F>(v0.y, v1.y, v2.y));
    grad *= vec2<F>(40.0f);
    return n;
}

}  // namespace qs::noise
