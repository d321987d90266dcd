#pragma once
// Melissa O'Neill's PCG step as an integer hash, a cell hash from it and value noise over the
// cells, as hash_pcg.frag and pcg_value_noise.frag (shading/shaders/) define them: GLSL 1.30
// (uint). Translated line for line.

#include "shading/glsl.h"

namespace qs::noise {
using namespace qs::glsl;

// uint pcg_hash(uint input)
template <class F>
uint_t<F> pcg_hash(const uint_t<F>& v) {
    uint_t<F> state = v * 747796405u + 2891336453u;
    uint_t<F> word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

template <class F>
F cellnoise_pcg2(const vec2<F>& p) {
    // Convert to integer input, and apply a bit mask to remove the sign bit
    uvec2<F> pu = uvec2<F>(ivec2<F>(floor(p)) & ivec2<F>(0x7FFFFFFF));
    // Chain hash calls and then squish the noise output to [0,1]
    return F(pcg_hash<F>(pu.x + pcg_hash<F>(pu.y)) & 0xFFFFu) / 65536.0f;
}

template <class F>
F value_noise(const vec2<F>& p) {
    vec2<F> i = floor(p);
    vec2<F> f = p - i;
    vec2<F> u = f * f * (3.0f - 2.0f * f);
    F a = cellnoise_pcg2(i), b = cellnoise_pcg2(i + vec2<F>(1.0f, 0.0f));
    F c = cellnoise_pcg2(i + vec2<F>(0.0f, 1.0f)), d = cellnoise_pcg2(i + vec2<F>(1.0f, 1.0f));
    return mix(mix(a, b, u.x), mix(c, d, u.x), u.y);
}

}  // namespace qs::noise
