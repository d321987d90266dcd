#pragma once
// 4D simplex noise (ours: the chapter names it, prints none), translated from simplex4d.glsl
// beside this file, line for line. mod289 and permute289 are simplex2d.h's.

#include "shading/glsl.h"
#include "shading/noise/simplex2d.h"

namespace qs::noise {
using namespace qs::glsl;

// Edge midpoint k mod 32 of the 4-cube: component floor(k/8) is 0, the others take the signs of
// the three low bits.
template <class F>
vec4<F> grad4(const F& hash) {
    F k = mod(hash, 32.0f);
    F zero = floor(k / 8.0f);
    F b = mod(k, 8.0f);
    vec3<F> s = vec3<F>(mod(b, 2.0f), mod(floor(b / 2.0f), 2.0f), floor(b / 4.0f)) * 2.0f - 1.0f;
    return vec4<F>(select(zero == 0.0f, F(0.0f), s.x),
                   select(zero == 1.0f, F(0.0f), select(zero < 1.0f, s.x, s.y)),
                   select(zero == 2.0f, F(0.0f), select(zero < 2.0f, s.y, s.z)),
                   select(zero == 3.0f, F(0.0f), s.z));
}

template <class F>
F snoise4(const vec4<F>& v) {
    const float F4 = 0.309016994374947f;  // (sqrt(5) - 1) / 4
    const float G4 = 0.138196601125011f;  // (5 - sqrt(5)) / 20
    vec4<F> i = floor(v + dot(v, vec4<F>(F4)));
    vec4<F> x0 = v - i + dot(i, vec4<F>(G4));
    // rank of each component among the four (3 = largest); each pair compared once
    vec4<F> rank = vec4<F>(0.0f);
    F c;
    c = step(x0.y, x0.x); rank.x += c; rank.y += 1.0f - c;
    c = step(x0.z, x0.x); rank.x += c; rank.z += 1.0f - c;
    c = step(x0.w, x0.x); rank.x += c; rank.w += 1.0f - c;
    c = step(x0.z, x0.y); rank.y += c; rank.z += 1.0f - c;
    c = step(x0.w, x0.y); rank.y += c; rank.w += 1.0f - c;
    c = step(x0.w, x0.z); rank.z += c; rank.w += 1.0f - c;
    // the simplex walks from corner 0 along the largest component first
    vec4<F> i1 = step(2.5f, rank);
    vec4<F> i2 = step(1.5f, rank);
    vec4<F> i3 = step(0.5f, rank);
    vec4<F> x1 = x0 - i1 + G4;
    vec4<F> x2 = x0 - i2 + 2.0f * G4;
    vec4<F> x3 = x0 - i3 + 3.0f * G4;
    vec4<F> x4 = x0 - 1.0f + 4.0f * G4;
    i = mod289(i);
    vec4<F> h = permute289(permute289(permute289(permute289(
                    i.w + vec4<F>(0.0f, i1.w, i2.w, i3.w))
                  + i.z + vec4<F>(0.0f, i1.z, i2.z, i3.z))
                  + i.y + vec4<F>(0.0f, i1.y, i2.y, i3.y))
                  + i.x + vec4<F>(0.0f, i1.x, i2.x, i3.x));
    F h4 = permute289(permute289(permute289(permute289(i.w + 1.0f) + i.z + 1.0f) + i.y + 1.0f) + i.x + 1.0f);
    vec4<F> m = max(0.6f - vec4<F>(dot(x0, x0), dot(x1, x1), dot(x2, x2), dot(x3, x3)), 0.0f);
    F m4 = max(0.6f - dot(x4, x4), 0.0f);
    m = m * m;
    m4 = m4 * m4;
    vec4<F> gx = vec4<F>(dot(grad4(h.x), x0), dot(grad4(h.y), x1), dot(grad4(h.z), x2), dot(grad4(h.w), x3));
    return 27.0f * (dot(m * m, gx) + m4 * m4 * dot(grad4(h4), x4));
}

}  // namespace qs::noise
