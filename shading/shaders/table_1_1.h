#pragma once
// The eight benchmark shaders of Table 1.1, each on the full-window plane with st in [0,1]^2,
// translated from the .frag files beside this header. Worley tiles and the halftone, with their
// anti-aliasing variants, are in aastep_shaders.h.

#include "shading/glsl.h"
#include "shading/noise/cellular.h"
#include "shading/noise/simplex3d.h"
#include "shading/program.h"
#include "shading/program_of.h"
#include "shading/shaders/aastep_shaders.h"
#include "shading/shaders/collections.h"
#include "shading/shaders/vertex_stages.h"

namespace qs::shaders {
using namespace qs::glsl;

struct ConstantColor {
    static constexpr ShaderInfo info{
        .name = "constant_color",
        .description = "Table 1.1: constant colour",
        .needs = {.coordinates = Coordinates::None},
        .glsl_fragment = {"shaders/constant_color.frag"},
    };
    using VertexStage = PlanePosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>&, const Uniforms&) { return vec4<F>(1.0f, 0.5f, 0.0f, 1.0f); }
};

struct SingleTexture {
    static constexpr ShaderInfo info{
        .name = "single_texture",
        .description = "Table 1.1: one bilinear texture lookup (clamp, no mipmaps)",
        .needs = {.texture = true},
        .glsl_fragment = {"shaders/single_texture.frag"},
        .wide_batches = true,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        return texture2D(*u.teximage, in.st);
    }
};

struct Dots {
    static constexpr ShaderInfo info{
        .name = "dots",
        .description = "Table 1.1 / Figure 1.2: dots, smoothstep(0.3, 0.32, ...)",
        .glsl_fragment = {"shaders/dots.frag"},
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> st = in.st;
        F grey = smoothstep(0.3f, 0.32f, length(fract(5.0f * st) - 0.5f));
        return vec4<F>(vec3<F>(grey), 1.0f);
    }
};

struct Perlin {
    static constexpr ShaderInfo info{
        .name = "perlin",
        .description = "Table 1.1 / Figure 1.4: 3D simplex noise (benchmark variant 0.51/93)",
        .glsl_fragment = {"noise/simplex3d.glsl", "shaders/perlin.frag"},
        .glsl_defines = noise::Simplex3dBenchmark::glsl_defines,
        .wide_batches = true,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> st = in.st;
        F n = noise::snoise3<noise::Simplex3dBenchmark>(vec3<F>(10.0f * st, 60.0f));
        return vec4<F>(vec3<F>(0.5f * n + 0.5f), 1.0f);
    }
};

struct Perlin5 {
    static constexpr ShaderInfo info{
        .name = "perlin5",
        .description = "Table 1.1 / Figure 1.4: five octaves of 3D simplex noise",
        .glsl_fragment = {"noise/simplex3d.glsl", "shaders/perlin5.frag"},
        .glsl_defines = noise::Simplex3dBenchmark::glsl_defines,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        using V = noise::Simplex3dBenchmark;
        vec2<F> st = in.st;
        F n = noise::snoise3<V>(vec3<F>(5.0f * st, 50.0f));
        n += 0.5f * noise::snoise3<V>(vec3<F>(10.0f * st, 60.0f));
        n += 0.25f * noise::snoise3<V>(vec3<F>(20.0f * st, 70.0f));
        n += 0.125f * noise::snoise3<V>(vec3<F>(40.0f * st, 80.0f));
        n += 0.0625f * noise::snoise3<V>(vec3<F>(80.0f * st, 90.0f));
        return vec4<F>(vec3<F>(0.4f * n + 0.5f), 1.0f);
    }
};

struct Worley {
    static constexpr ShaderInfo info{
        .name = "worley",
        .description = "Table 1.1 / Figure 1.5: F1 of 2D cellular noise (3x3 search)",
        .glsl_fragment = {"noise/cellular.glsl", "shaders/worley.frag"},
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> Fs = noise::cellular(in.st * 10.0f);  // GLSL: vec2 F
        return vec4<F>(vec3<F>(Fs.x), 1.0f);
    }
};

QUADSHADE_SHADERS_IN(kGustavson, ConstantColor, SingleTexture, Dots, Perlin, Perlin5, Worley, WorleyTiles<>, Halftone<>)

}  // namespace qs::shaders
