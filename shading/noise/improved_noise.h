#pragma once
// Ken Perlin's improved noise and the ProcTexGen articles' looping variant, translated from improved_noise.glsl
// beside this file, line for line. Integer lattice arithmetic in int lanes (int_t<F>), tables
// read per lane.

#include "shading/glsl.h"
#include "shading/glsl/table.h"
#include "shading/noise/perlin_permutation.h"

namespace qs::noise {
using namespace qs::glsl;

// The 16 gradients, g[16] of the GLSL, one table per component. Every gradient has two
// components of +-1 and one 0, so dot(g, p) is exact whatever order a compiler sums it in.
inline constexpr table<float, 16> g_x{{1, -1, 1, -1, 1, -1, 1, -1, 0, 0, 0, 0, 1, 0, -1, 0}};
inline constexpr table<float, 16> g_y{{1, 1, -1, -1, 0, 0, 0, 0, 1, -1, 1, -1, 1, -1, 1, -1}};
inline constexpr table<float, 16> g_z{{0, 0, 0, 0, 1, 1, -1, -1, 1, 1, -1, -1, 0, 1, 0, -1}};

template <class F>
vec3<F> texfade(const vec3<F>& t) {
    return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);  // new curve
}

template <class F>
F texgrad(const int_t<F>& hash, const vec3<F>& p) {
    const int_t<F> h = hash & 15;
    return dot(vec3<F>(F(g_x[h]), F(g_y[h]), F(g_z[h])), p);  // g[hash & 15]
}

template <class F>
F texgradperm(const int_t<F>& x, const vec3<F>& p) {
    return texgrad<F>(perm(x), p);
}

template <class F>
F inoise(vec3<F> p) {
    using Int = int_t<F>;
    ivec3<F> P = ivec3<F>(floor(p)) & 255;
    p -= floor(p);
    vec3<F> f = texfade(p);
    Int A = perm(P.x) + P.y, AA = perm(A) + P.z, AB = perm(A + 1) + P.z;
    Int B = perm(P.x + 1) + P.y, BA = perm(B) + P.z, BB = perm(B + 1) + P.z;
    return mix(mix(mix(texgradperm<F>(AA,     p + vec3<F>( 0,  0,  0)),
                       texgradperm<F>(BA,     p + vec3<F>(-1,  0,  0)), f.x),
                   mix(texgradperm<F>(AB,     p + vec3<F>( 0, -1,  0)),
                       texgradperm<F>(BB,     p + vec3<F>(-1, -1,  0)), f.x), f.y),
               mix(mix(texgradperm<F>(AA + 1, p + vec3<F>( 0,  0, -1)),
                       texgradperm<F>(BA + 1, p + vec3<F>(-1,  0, -1)), f.x),
                   mix(texgradperm<F>(AB + 1, p + vec3<F>( 0, -1, -1)),
                       texgradperm<F>(BB + 1, p + vec3<F>(-1, -1, -1)), f.x), f.y), f.z);
}

// repeat > 0 and base >= 0, as the blog calls it.
template <class F>
F texShaderNoise(vec3<F> p, int repeat, int base) {
    using Int = int_t<F>;
    ivec3<F> I = ivec3<F>(mod(floor(p), float(repeat)));
    ivec3<F> J = (I + 1) % repeat;
    I += ivec3<F>(Int(base));  // I += base
    J += ivec3<F>(Int(base));

    p -= floor(p);

    vec3<F> f = texfade(p);

    Int A  = perm(I.x);
    Int AA = perm(A+I.y);
    Int AB = perm(A+J.y);

    Int B  = perm(J.x);
    Int BA = perm(B+I.y);
    Int BB = perm(B+J.y);

    return mix( mix( mix( texgradperm<F>(AA+I.z, p + vec3<F>( 0,  0,  0) ),
                          texgradperm<F>(BA+I.z, p + vec3<F>(-1,  0,  0) ), f.x),
                     mix( texgradperm<F>(AB+I.z, p + vec3<F>( 0, -1,  0) ),
                          texgradperm<F>(BB+I.z, p + vec3<F>(-1, -1,  0) ), f.x), f.y),
                mix( mix( texgradperm<F>(AA+J.z, p + vec3<F>( 0,  0, -1) ),
                          texgradperm<F>(BA+J.z, p + vec3<F>(-1,  0, -1) ), f.x),
                     mix( texgradperm<F>(AB+J.z, p + vec3<F>( 0, -1, -1) ),
                          texgradperm<F>(BB+J.z, p + vec3<F>(-1, -1, -1) ), f.x), f.y), f.z);
}

}  // namespace qs::noise
