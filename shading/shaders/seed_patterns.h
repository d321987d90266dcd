#pragma once
// Shaders from the other procedural-texture texts (shared/seeds): an integer hash and an
// escape-time loop, on the Table 1.1 plane with st in [0,1]^2. They are the benchmark's integer
// and loop shaders (bench/core_bench.cpp). Translated from the .frag files beside this header.

#include "shading/glsl.h"
#include "shading/program.h"
#include "shading/program_of.h"
#include "shading/shaders/table_1_1.h"

namespace qs::shaders {
using namespace qs::glsl;

// uint pcg_hash(uint input): Melissa O'Neill's PCG step as a hash.
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

struct PcgValueNoise {
    static constexpr ShaderInfo info = with_wide_batches(with_glsl_version(
        ShaderInfo{"pcg_value_noise", "Noise is Beautiful: value noise from the PCG integer hash, four octaves (GLSL 1.30)",
                   kPlaneNeeds, {"shaders/plane_st.vert"}, {"shaders/pcg_value_noise.frag"}},
        130));
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> p = in.st * 16.0f;
        F n = 0.5f * value_noise(p) + 0.25f * value_noise(p * 2.0f + 17.0f) + 0.125f * value_noise(p * 4.0f + 31.0f) +
              0.0625f * value_noise(p * 8.0f + 47.0f);
        return vec4<F>(vec3<F>(n), 1.0f);
    }
};

struct Mandelbrot {
    static constexpr ShaderInfo info = with_wide_batches(ShaderInfo{"mandelbrot", "Lawlor, Procedural Solid Texturing: the Mandelbrot set in window coordinates, up to 100 iterations with break",
                                                                    Needs{.coordinates = Coordinates::None, .derivatives = false, .texture = false, .time = false,
                                                                          .frag_coord = true},
                                                                    {"shaders/plane_st.vert"}, {"shaders/mandelbrot.frag"}});
    using VertexStage = PlanePosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        F cx = in.gl_FragCoord.x * (3.0f / 1024.0f) - 2.0f, cy = in.gl_FragCoord.y * (3.0f / 1024.0f) - 1.5f;
        F x = cx, y = cy;  // point to iterate
        F r = 0.0f;        // radius of point (squared)
        Loop loop(x, y, r);
        for (int i = 0; loop(i < 100); i++) {
            F newx = x * x + cx - y * y;
            y = 2.0f * x * y + cy;  // complex multiplication, biased by the location
            x = newx;
            r = x * x + y * y;  // check radius
            loop.break_if(r > 4.0f);
        }
        return vec4<F>(x, r * 0.1f, y, 1.0f);
    }
};

}  // namespace qs::shaders
