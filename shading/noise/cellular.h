#pragma once
// Cellular (Worley) noise, translated from cellular.glsl beside this file.

#include "shading/glsl.h"
#include "shading/noise/cellular_nearby.h"
#include "shading/noise/flow_noise.h"

namespace qs::noise {
using namespace qs::glsl;

// Its constants (cellular_constants) are in cellular_nearby.h, which shares them.

// Keep the two smallest of the squared distances seen so far (and the vectors to them).
template <class F>
void insert(const F& d, const vec2<F>& v, vec2<F>& Fs, vec4<F>& d1d2) {
    auto first = d < Fs.x;
    auto second = d < Fs.y;
    vec2<F> zw = select(first, d1d2.xy(), select(second, v, d1d2.zw()));  // GLSL: d1d2.zw = ...
    d1d2 = vec4<F>(select(first, v, d1d2.xy()), zw);                       // GLSL: d1d2.xy = ...
    Fs = vec2<F>(min(Fs.x, d), min(Fs.y, max(Fs.x, d)));
}

// 2D, 3x3 search, jitter 1.0: F1, F2 and the vectors to the two nearest points.
template <class F>
vec2<F> cellular_vectors(const vec2<F>& P, vec4<F>& d1d2) {
    using namespace cellular_constants;
    const float jitter = 1.0f;
    vec2<F> Pi = mod(floor(P), 289.0f);
    vec2<F> Pf = fract(P);
    vec2<F> Fs(1e6f);
    d1d2 = vec4<F>(0.0f);
    // Where the lanes share their cells, each cell hashed once (cellular_nearby.h).
    if (cellular_search_nearby(Pi, Pf, [&](const F& d, const vec2<F>& v) { insert(d, v, Fs, d1d2); })) return sqrt(Fs);
    for (int i = -1; i <= 1; i++) {
        for (int j = -1; j <= 1; j++) {
            F p = permute_mod(permute_mod(Pi.x + float(i)) + Pi.y + float(j));
            F ox = fract(p * K) - Ko;
            // floor(p * K) of a permutation p is a whole number in [-42, 41] (noise/flow_noise.h).
            F oy = mod_whole(floor(p * K), 7.0f) * K - Ko;
            vec2<F> d(Pf.x - (float(i) + 0.5f) + jitter * ox, Pf.y - (float(j) + 0.5f) + jitter * oy);
            insert(dot(d, d), d, Fs, d1d2);
        }
    }
    return sqrt(Fs);
}
template <class F>
vec2<F> cellular(const vec2<F>& P) {
    vec4<F> d1d2;
    return cellular_vectors(P, d1d2);
}

// 3D, 2x2x2 search, jitter 0.8, F1 only (returned in both components).
template <class F>
vec2<F> cellular2x2x2(const vec3<F>& P) {
    using namespace cellular_constants;
    const float jitter = 0.8f;
    vec3<F> Pi = mod(floor(P), 289.0f);
    vec3<F> Pf = fract(P);
    F F1 = 1e6f;
    for (int a = 0; a <= 1; a++) {
        for (int b = 0; b <= 1; b++) {
            for (int c = 0; c <= 1; c++) {
                F p = permute_mod(permute_mod(permute_mod(Pi.x + float(a)) + Pi.y + float(b)) + Pi.z + float(c));
                vec3<F> o(fract(p * K) - Ko, mod_whole(floor(p * K), 7.0f) * K - Ko, floor(p * K2) * Kz - Kzo);
                vec3<F> d = Pf - vec3<F>(float(a), float(b), float(c)) + jitter * o;
                F1 = min(F1, dot(d, d));
            }
        }
    }
    return vec2<F>(sqrt(F1));
}

// 3D, 3x3x3 search, jitter 1.0: F1 and F2.
template <class F>
vec2<F> cellular(const vec3<F>& P) {
    using namespace cellular_constants;
    const float jitter = 1.0f;
    vec3<F> Pi = mod(floor(P), 289.0f);
    vec3<F> Pf = fract(P) - 0.5f;
    vec2<F> Fs(1e6f);
    for (int a = -1; a <= 1; a++) {
        for (int b = -1; b <= 1; b++) {
            for (int c = -1; c <= 1; c++) {
                F p = permute_mod(permute_mod(permute_mod(Pi.x + float(a)) + Pi.y + float(b)) + Pi.z + float(c));
                vec3<F> o(fract(p * K) - Ko, mod_whole(floor(p * K), 7.0f) * K - Ko, floor(p * K2) * Kz - Kzo);
                vec3<F> d = Pf - vec3<F>(float(a), float(b), float(c)) + jitter * o;
                F d2 = dot(d, d);
                Fs = vec2<F>(min(Fs.x, d2), min(Fs.y, max(Fs.x, d2)));
            }
        }
    }
    return sqrt(Fs);
}

}  // namespace qs::noise
