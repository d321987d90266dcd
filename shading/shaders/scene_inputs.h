#pragma once
// A test of the renderer, as a shader of the catalogue: the scene's inputs read by name
// (scenes/shader_inputs.h) from a GLSL 1.30 vertex stage. Not a probe, so that every conformance
// scene (mirrored and nested nodes, rolled cameras, the near plane) draws it against OSMesa like
// the catalogue's other shaders, and each binding is checked there. Translated from
// scene_inputs.vert and scene_inputs.frag beside this header.

#include <tuple>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "shading/glsl.h"
#include "shading/program.h"
#include "shading/program_of.h"
#include "shading/shaders/collections.h"
#include "shading/vertex.h"

namespace qs::shaders {
using namespace qs::glsl;

struct SceneInputs {
    static constexpr ShaderInfo info{
        .name = "scene_inputs",
        .description = "the scene's transforms and vertex inputs read by name from a GLSL 1.30 vertex stage",
        .needs = {.coordinates = Coordinates::Object3D},
        .glsl_fragment = {"shaders/scene_inputs.frag"},
    };
    // scene_inputs.vert
    struct VertexStage {
        static constexpr GlslFiles glsl{"shaders/scene_inputs.vert"};
        template <class T>
        struct Varyings {
            vec3<T> world;
            vec3<T> turned;
            vec2<T> ndc;
            auto fields() { return std::tie(world, turned, ndc); }
        };
        // m * v, the columns weighted by v's components and summed left to right, as Mesa lowers it.
        template <int N, class V>
        static V product(const glm::mat<N, N, float>& m, const V& v) {
            V r = m[0] * v[0];
            for (int c = 1; c < N; ++c) r = r + m[c] * v[c];
            return r;
        }
        static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<VertexStage>& out) {
            const glm::vec4 w = product(u.model, glm::vec4(in.position, 1.0f));
            out.world = {w.x + in.texcoord.x, w.y + in.texcoord.y, w.z + 0.0f};
            const glm::vec3 turned = product(u.normal_matrix, glm::vec3(0.6f, 0.0f, 0.8f));
            out.turned = {turned.x, turned.y, turned.z};
            const glm::vec4 clip = product(u.projection, product(u.view, w));
            out.ndc = {clip.x / clip.w, clip.y / clip.w};
            out.gl_Position = transform_point(u.model_view_projection, in.position);
        }
    };
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec3<F> w = 0.5f + 0.5f * sin(in.world);
        F r = (w.x + w.y + w.z) / 3.0f;
        F g = clamp(0.5f + 0.2f * (in.turned.x + in.turned.y) + 0.25f * in.ndc.x, 0.0f, 1.0f);
        F b = clamp(0.5f + 0.2f * in.turned.z + 0.25f * in.ndc.y, 0.0f, 1.0f);
        return vec4<F>(r, g, b, 1.0f);
    }
};

QUADSHADE_SHADERS_IN(kProbes, SceneInputs)

}  // namespace qs::shaders
