#pragma once
// Seed 001: the ProcTexGen blog's solid textures. Ken Perlin's improved noise over the blog's
// permutation and gradient tables, its looping variant, and the volume the fast noise
// (textures.h: fast_noise) reads, baked by `quadshade bake-volume`. Translated from the .frag
// files beside this header and shading/noise/improved_noise.glsl.

#include "shading/glsl.h"
#include "shading/noise/improved_noise.h"
#include "shading/program.h"
#include "shading/program_of.h"
#include "shading/shaders/vertex_stages.h"
#include "shading/vertex.h"

namespace qs::shaders {
using namespace qs::glsl;

// A solid texture without derivatives or time; the integer lattice needs GLSL 1.30.
inline constexpr Needs kSeed001SolidNeeds{.coordinates = Coordinates::Object3D, .derivatives = false, .texture = false,
                                          .time = false};

// object_position8.vert: P = gl_Vertex.xyz * 8.0
struct ObjectPosition8 {
    template <class T>
    using Varyings = SolidVaryings<T>;
    static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<ObjectPosition8>& out) {
        const glm::vec3 P = in.position * 8.0f;
        out.P = {P.x, P.y, P.z};
        out.gl_Position = transform_point(u.model_view_projection, in.position);
    }
};

// fast_noise_volume.vert: P = (gl_Vertex.xyz * 0.5 + 0.5) * 8.0
struct FastNoiseVolumeStage {
    template <class T>
    using Varyings = SolidVaryings<T>;
    static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<FastNoiseVolumeStage>& out) {
        const glm::vec3 P = (in.position * 0.5f + 0.5f) * 8.0f;
        out.P = {P.x, P.y, P.z};
        out.gl_Position = transform_point(u.model_view_projection, in.position);
    }
};

struct ImprovedNoise {
    static constexpr ShaderInfo info = with_glsl_version(
        ShaderInfo{"improved_noise", "seed 001: Ken Perlin's improved noise (permutation table, 16 gradients), 4 cells per unit (GLSL 1.30)",
                   kSeed001SolidNeeds, {"shaders/object_position.vert"},
                   {"noise/perlin_permutation.glsl", "noise/improved_noise.glsl", "shaders/improved_noise.frag"}},
        130);
    using VertexStage = ObjectPosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return vec4<F>(vec3<F>(0.5f + 0.5f * noise::inoise(in.P)), 1.0f);
    }
};

struct ImprovedNoiseLoop {
    static constexpr ShaderInfo info = with_glsl_version(
        ShaderInfo{"improved_noise_loop", "seed 001: texShaderNoise, improved noise looping every 8 cells (repeat 8, base 0), 8 cells per unit (GLSL 1.30)",
                   kSeed001SolidNeeds, {"shaders/object_position8.vert"},
                   {"noise/perlin_permutation.glsl", "noise/improved_noise.glsl", "shaders/improved_noise_loop.frag"}},
        130);
    using VertexStage = ObjectPosition8;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return vec4<F>(vec3<F>(0.5f + 0.5f * noise::texShaderNoise(in.P, 8, 0)), 1.0f);
    }
};

struct FastNoiseVolume {
    static constexpr ShaderInfo info = with_glsl_version(
        ShaderInfo{"fast_noise_volume", "seed 001: the fast noise's volume, looping noise of 8 cells (R: base 0, G: base 8) over [-1, 1]^3; bake it with bake-volume --size 32 (GLSL 1.30)",
                   kSeed001SolidNeeds, {"shaders/fast_noise_volume.vert"},
                   {"noise/perlin_permutation.glsl", "noise/improved_noise.glsl", "shaders/fast_noise_volume.frag"}},
        130);
    using VertexStage = FastNoiseVolumeStage;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        using noise::texShaderNoise;
        return vec4<F>(0.5f + 0.5f * texShaderNoise(in.P, 8, 0), 0.5f + 0.5f * texShaderNoise(in.P, 8, 8), 0.0f, 1.0f);
    }
};

}  // namespace qs::shaders
