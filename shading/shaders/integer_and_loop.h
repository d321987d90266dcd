#pragma once
// The benchmarks' integer and loop shaders (bench/core_bench.cpp), from two of the texts: value
// noise from the PCG integer hash ("Noise is Beautiful") and an escape-time loop (Lawlor's
// Mandelbrot in window coordinates), on the Table 1.1 plane. Translated from the .frag files beside
// this header.

#include "shading/glsl.h"
#include "shading/noise/pcg_hash.h"
#include "shading/program.h"
#include "shading/program_of.h"
#include "shading/shaders/collections.h"
#include "shading/shaders/vertex_stages.h"

namespace qs::shaders {
using namespace qs::glsl;

struct PcgValueNoise {
    static constexpr ShaderInfo info{
        .name = "pcg_value_noise",
        .description = "Noise is Beautiful: value noise from the PCG integer hash, four octaves (GLSL 1.30)",
        .glsl_fragment = {"shaders/pcg_value_noise.frag"},
        .glsl_version = 130,
        .wide_batches = true,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> p = in.st * 16.0f;
        using noise::value_noise;
        F n = 0.5f * value_noise(p) + 0.25f * value_noise(p * 2.0f + 17.0f) + 0.125f * value_noise(p * 4.0f + 31.0f) +
              0.0625f * value_noise(p * 8.0f + 47.0f);
        return vec4<F>(vec3<F>(n), 1.0f);
    }
};

struct Mandelbrot {
    static constexpr ShaderInfo info{
        .name = "mandelbrot",
        .description = "Lawlor, Procedural Solid Texturing: the Mandelbrot set in window coordinates, up to 100 iterations with break",
        .needs = {.coordinates = Coordinates::None, .frag_coord = true},
        .glsl_fragment = {"shaders/mandelbrot.frag"},
        .wide_batches = true,
    };
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

QUADSHADE_SHADERS_IN(kNoiseIsBeautiful, PcgValueNoise)
QUADSHADE_SHADERS_IN(kLawlor, Mandelbrot)

}  // namespace qs::shaders
