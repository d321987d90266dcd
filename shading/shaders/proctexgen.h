#pragma once
// The ProcTexGen articles' solid textures (collections.h cites them). Ken Perlin's improved noise
// over the articles' permutation and gradient tables, its looping variant, and the volume the fast
// noise (textures.h: fast_noise) reads, baked by `quadshade bake-volume`; the articles' 3D Worley
// noise in its eight displays and as fBm. Their integer lattice needs GLSL 1.30. Translated from
// the .frag files beside this header and shading/noise/improved_noise.glsl, worley3d.glsl.

#include "shading/glsl.h"
#include "shading/noise/improved_noise.h"
#include "shading/noise/worley3d.h"
#include "shading/program.h"
#include "shading/program_of.h"
#include "shading/shaders/collections.h"
#include "shading/shaders/vertex_stages.h"
#include "shading/vertex.h"

namespace qs::shaders {
using namespace qs::glsl;

// object_position8.vert: P = gl_Vertex.xyz * 8.0
struct ObjectPosition8 {
    static constexpr GlslFiles glsl{"shaders/object_position8.vert"};
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
    static constexpr GlslFiles glsl{"shaders/fast_noise_volume.vert"};
    template <class T>
    using Varyings = SolidVaryings<T>;
    static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<FastNoiseVolumeStage>& out) {
        const glm::vec3 P = (in.position * 0.5f + 0.5f) * 8.0f;
        out.P = {P.x, P.y, P.z};
        out.gl_Position = transform_point(u.model_view_projection, in.position);
    }
};

struct ImprovedNoise {
    static constexpr ShaderInfo info{
        .name = "improved_noise",
        .description = "Ken Perlin's improved noise (permutation table, 16 gradients), 4 cells per unit (GLSL 1.30)",
        .needs = {.coordinates = Coordinates::Object3D},
        .glsl_fragment = {"noise/perlin_permutation.glsl", "noise/improved_noise.glsl", "shaders/improved_noise.frag"},
        .glsl_version = 130,
    };
    using VertexStage = ObjectPosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return vec4<F>(vec3<F>(0.5f + 0.5f * noise::inoise(in.P)), 1.0f);
    }
};

struct ImprovedNoiseLoop {
    static constexpr ShaderInfo info{
        .name = "improved_noise_loop",
        .description = "texShaderNoise, improved noise looping every 8 cells (repeat 8, base 0), 8 cells per unit (GLSL 1.30)",
        .needs = {.coordinates = Coordinates::Object3D},
        .glsl_fragment = {"noise/perlin_permutation.glsl", "noise/improved_noise.glsl", "shaders/improved_noise_loop.frag"},
        .glsl_version = 130,
    };
    using VertexStage = ObjectPosition8;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return vec4<F>(vec3<F>(0.5f + 0.5f * noise::texShaderNoise(in.P, 8, 0)), 1.0f);
    }
};

struct FastNoiseVolume {
    static constexpr ShaderInfo info{
        .name = "fast_noise_volume",
        .description = "the fast noise's volume, looping noise of 8 cells (R: base 0, G: base 8) over [-1, 1]^3; bake it with bake-volume --size 32 (GLSL 1.30)",
        .needs = {.coordinates = Coordinates::Object3D},
        .glsl_fragment = {"noise/perlin_permutation.glsl", "noise/improved_noise.glsl", "shaders/fast_noise_volume.frag"},
        .glsl_version = 130,
    };
    using VertexStage = FastNoiseVolumeStage;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        using noise::texShaderNoise;
        return vec4<F>(0.5f + 0.5f * texShaderNoise(in.P, 8, 0), 0.5f + 0.5f * texShaderNoise(in.P, 8, 8), 0.0f, 1.0f);
    }
};

// The blog's eight displays of voronoi(): F1, F2, F2 - F1 and (F1 + F2) / 2, each with the
// Euclidean and the Manhattan metric (halved: its distances run to about 1.8).
enum class WorleyShow { F1, F2, F2MinusF1, Mean };

template <WorleyShow show, bool manhattan>
struct Worley3d {
    static constexpr int kIndex = int(show) + (manhattan ? 4 : 0);
    static constexpr const char* kNames[8] = {"worley3d_f1", "worley3d_f2", "worley3d_f2_minus_f1", "worley3d_f1_plus_f2_half",
                                              "worley3d_f1_manhattan", "worley3d_f2_manhattan",
                                              "worley3d_f2_minus_f1_manhattan", "worley3d_f1_plus_f2_half_manhattan"};
    static constexpr const char* kDescriptions[8] = {
        "3D Worley noise, F1 (Euclidean, jitter .9, 4 cells per unit; GLSL 1.30)",
        "3D Worley noise, F2 (Euclidean, jitter .9, 4 cells per unit; GLSL 1.30)",
        "3D Worley noise, F2 - F1 (Euclidean, jitter .9, 4 cells per unit; GLSL 1.30)",
        "3D Worley noise, (F1 + F2) / 2 (Euclidean, jitter .9, 4 cells per unit; GLSL 1.30)",
        "3D Worley noise, F1 / 2 (Manhattan, jitter .9, 4 cells per unit; GLSL 1.30)",
        "3D Worley noise, F2 / 2 (Manhattan, jitter .9, 4 cells per unit; GLSL 1.30)",
        "3D Worley noise, (F2 - F1) / 2 (Manhattan, jitter .9, 4 cells per unit; GLSL 1.30)",
        "3D Worley noise, (F1 + F2) / 4 (Manhattan, jitter .9, 4 cells per unit; GLSL 1.30)"};
    static constexpr const char* kDefines[8] = {
        "#define WORLEY3D_MANHATTAN false\n#define WORLEY3D_SCALE 1.0\n#define WORLEY3D_SHOW(f1, f2) (f1)\n",
        "#define WORLEY3D_MANHATTAN false\n#define WORLEY3D_SCALE 1.0\n#define WORLEY3D_SHOW(f1, f2) (f2)\n",
        "#define WORLEY3D_MANHATTAN false\n#define WORLEY3D_SCALE 1.0\n#define WORLEY3D_SHOW(f1, f2) (f2 - f1)\n",
        "#define WORLEY3D_MANHATTAN false\n#define WORLEY3D_SCALE 1.0\n#define WORLEY3D_SHOW(f1, f2) ((f1 + f2) / 2.0)\n",
        "#define WORLEY3D_MANHATTAN true\n#define WORLEY3D_SCALE 0.5\n#define WORLEY3D_SHOW(f1, f2) (f1)\n",
        "#define WORLEY3D_MANHATTAN true\n#define WORLEY3D_SCALE 0.5\n#define WORLEY3D_SHOW(f1, f2) (f2)\n",
        "#define WORLEY3D_MANHATTAN true\n#define WORLEY3D_SCALE 0.5\n#define WORLEY3D_SHOW(f1, f2) (f2 - f1)\n",
        "#define WORLEY3D_MANHATTAN true\n#define WORLEY3D_SCALE 0.5\n#define WORLEY3D_SHOW(f1, f2) ((f1 + f2) / 2.0)\n"};
    static constexpr ShaderInfo info{
        .name = kNames[kIndex],
        .description = kDescriptions[kIndex],
        .needs = {.coordinates = Coordinates::Object3D},
        .glsl_fragment = {"noise/perlin_permutation.glsl", "noise/worley3d.glsl", "shaders/worley3d.frag"},
        .glsl_defines = kDefines[kIndex],
        .glsl_version = 130,
    };
    using VertexStage = ObjectPosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        F f1, f2;
        vec3<F> pos1, pos2;
        noise::voronoi(in.P, f1, pos1, f2, pos2, .9f, manhattan);
        F shown = show == WorleyShow::F1 ? f1 : show == WorleyShow::F2 ? f2 : show == WorleyShow::F2MinusF1 ? f2 - f1 : (f1 + f2) / 2.0f;
        return vec4<F>(vec3<F>((manhattan ? 0.5f : 1.0f) * shown), 1.0f);
    }
};

struct Worley3dFbm {
    static constexpr ShaderInfo info{
        .name = "worley3d_fbm",
        .description = "4 octaves of 3D Worley F1 (frequencies 1 to 8, weights 1 to 1/8; GLSL 1.30)",
        .needs = {.coordinates = Coordinates::Object3D},
        .glsl_fragment = {"noise/perlin_permutation.glsl", "noise/worley3d.glsl", "shaders/worley3d_fbm.frag"},
        .glsl_version = 130,
    };
    using VertexStage = ObjectPosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        F sum = 0.0f;
        float amplitude = 1.0f, frequency = 1.0f;
        for (int octave = 0; octave < 4; octave++) {
            F f1, f2;
            vec3<F> pos1, pos2;
            noise::voronoi(in.P * frequency, f1, pos1, f2, pos2, .9f, false);
            sum += amplitude * f1;
            frequency *= 2.0f;
            amplitude *= 0.5f;
        }
        return vec4<F>(vec3<F>(sum / 1.875f), 1.0f);
    }
};

QUADSHADE_SHADERS_IN(kProcTexGen, ImprovedNoise, ImprovedNoiseLoop, FastNoiseVolume, Worley3d<WorleyShow::F1, false>,
                     Worley3d<WorleyShow::F2, false>, Worley3d<WorleyShow::F2MinusF1, false>, Worley3d<WorleyShow::Mean, false>,
                     Worley3d<WorleyShow::F1, true>, Worley3d<WorleyShow::F2, true>, Worley3d<WorleyShow::F2MinusF1, true>,
                     Worley3d<WorleyShow::Mean, true>, Worley3dFbm)

}  // namespace qs::shaders
