#pragma once
// Shaders with a height (shading/height_field.h), and the shader that draws a baked atlas lit by
// its normal map. Translated from the .frag, .vert and .glsl files beside this header.

#include <tuple>

#include "shading/glsl.h"
#include "shading/height_field_of.h"
#include "shading/noise/simplex3d.h"
#include "shading/noise/simplex3d_grad.h"
#include "shading/program.h"
#include "shading/program_of.h"
#include "shading/shaders/collections.h"
#include "shading/shaders/vertex_stages.h"

namespace qs::shaders {
using namespace qs::glsl;

// surface_point.vert: P = gl_Vertex.xyz
struct SurfacePoint {
    static constexpr GlslFiles glsl{"shaders/surface_point.vert"};
    template <class T>
    using Varyings = SolidVaryings<T>;
    static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<SurfacePoint>& out) {
        out.P = {in.position.x, in.position.y, in.position.z};
        out.gl_Position = transform_point(u.model_view_projection, in.position);
    }
};

// 3D simplex noise with a kernel radius^2 of 0.5: each corner's kernel ends where the simplices
// around it do, so the noise and its gradient are continuous. The chapter's 0.6 (and the
// benchmark's 0.51) let a kernel reach past the four corners a point sums, and the noise jumps
// a little where it leaves them: harmless in a colour, but a height's finite differences divide
// that jump by the step (docs/results.md, "Normal maps from a height"). Scale 95 keeps the
// range near [-1, 1] (the peak grows as falloff^4.5: 42 (0.6 / 0.5)^4.5).
struct Simplex3dSmooth {
    static constexpr float falloff = 0.5f, scale = 95.0f;
    static constexpr float taylor_a = 1.79284291400159f, taylor_b = 0.85373472095314f;
    static constexpr const char* glsl_defines =
        "#define SNOISE3_FALLOFF 0.5\n#define SNOISE3_SCALE 95.0\n"
        "#define SNOISE3_TAYLOR_A 1.79284291400159\n#define SNOISE3_TAYLOR_B 0.85373472095314\n";
};

// noise_bumps_height.glsl
struct NoiseBumpsHeight {
    static constexpr float amplitude = 0.05f;
    template <class F>
    static F height(const vec3<F>& P) {
        using noise::snoise3;
        F n = snoise3<Simplex3dSmooth>(3.0f * P) + 0.5f * snoise3<Simplex3dSmooth>(6.0f * P) +
              0.25f * snoise3<Simplex3dSmooth>(12.0f * P);
        return 0.5f + 0.25f * n;
    }
};

inline constexpr Needs kHeightNeeds{.coordinates = Coordinates::Object3D};

struct NoiseBumps {
    static constexpr ShaderInfo info{
        .name = "noise_bumps",
        .description = "a stone colour from a height of three octaves of 3D simplex noise (noise_bumps_height), for bakes with normal maps",
        .needs = kHeightNeeds,
        .glsl_fragment = {"noise/simplex3d.glsl", "shaders/noise_bumps_height.glsl", "shaders/noise_bumps.frag"},
        .glsl_defines = Simplex3dSmooth::glsl_defines,
    };
    using VertexStage = SurfacePoint;
    using Height = NoiseBumpsHeight;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        F h = Height::height(in.P);
        return vec4<F>(mix(vec3<F>(0.35f, 0.25f, 0.2f), vec3<F>(0.85f, 0.8f, 0.7f), h), 1.0f);
    }
};

struct NoiseBumpsHeightMap {
    static constexpr ShaderInfo info{
        .name = "noise_bumps_height",
        .description = "noise_bumps' height as grey: the height map of its bake",
        .needs = kHeightNeeds,
        .glsl_fragment = {"noise/simplex3d.glsl", "shaders/noise_bumps_height.glsl", "shaders/noise_bumps_height.frag"},
        .glsl_defines = Simplex3dSmooth::glsl_defines,
    };
    using VertexStage = SurfacePoint;
    using Height = NoiseBumpsHeight;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return vec4<F>(vec3<F>(Height::height(in.P)), 1.0f);
    }
};

// noise_bumps_lit.frag: the live counterpart of noise_bumps baked and drawn by baked_lit.
struct NoiseBumpsLit {
    static constexpr ShaderInfo info{
        .name = "noise_bumps_lit",
        .description = "noise_bumps lit live: the height's analytic gradient bends the face normal (cross(dFdx(P), dFdy(P))), Lambert as baked_lit",
        .needs = {.coordinates = Coordinates::Object3D, .derivatives = true},
        .glsl_fragment = {"noise/simplex3d.glsl", "noise/simplex3d_grad.glsl", "shaders/noise_bumps_lit.frag"},
        .glsl_defines = Simplex3dSmooth::glsl_defines,
    };
    using VertexStage = SurfacePoint;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        using noise::snoise3_grad;
        vec3<F> G1, G2, G3;
        F n = snoise3_grad<Simplex3dSmooth>(3.0f * in.P, G1) + 0.5f * snoise3_grad<Simplex3dSmooth>(6.0f * in.P, G2) +
              0.25f * snoise3_grad<Simplex3dSmooth>(12.0f * in.P, G3);
        F h = 0.5f + 0.25f * n;
        vec3<F> g = 0.25f * (3.0f * G1 + 3.0f * G2 + 3.0f * G3);
        vec3<F> N = normalize(cross(dFdx(in.P), dFdy(in.P)));
        vec3<F> bumped = normalize(N - 0.05f * (g - dot(g, N) * N));
        vec3<F> L = vec3<F>(0.2873479f, 0.7662610f, 0.5746958f);
        F diffuse = max(dot(bumped, L), 0.0f);
        vec3<F> color = mix(vec3<F>(0.35f, 0.25f, 0.2f), vec3<F>(0.85f, 0.8f, 0.7f), h);
        return vec4<F>(color * (0.2f + 0.8f * diffuse), 1.0f);
    }
};

// baked_lit.frag: what `quadshade bake --maps color,normal` draws its baked scene with.
struct BakedLit {
    static constexpr ShaderInfo info{
        .name = "baked_lit",
        .description = "a baked atlas lit: teximage's colour, Lambert with the object-space normal map `normalmap` (quadshade bake)",
        .needs = {.texture = true, .samplers = {SamplerUse{"normalmap", 2}}},
        .glsl_fragment = {"shaders/baked_lit.frag"},
        .wide_batches = true,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        vec4<F> color = texture2D(*u.teximage, in.st);
        vec3<F> N = normalize(texture2D(u.sampler2D(0), in.st).xyz() * 2.0f - 1.0f);
        vec3<F> L = vec3<F>(0.2873479f, 0.7662610f, 0.5746958f);
        F diffuse = max(dot(N, L), 0.0f);
        return vec4<F>(color.xyz() * (0.2f + 0.8f * diffuse), color.w);
    }
};

QUADSHADE_SHADERS_IN(kProcTexGen, NoiseBumps, NoiseBumpsHeightMap, NoiseBumpsLit, BakedLit)
QUADSHADE_HEIGHT_FIELD(NoiseBumps, NoiseBumpsHeightMap)

}  // namespace qs::shaders
