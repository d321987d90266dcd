#pragma once
// Small programs for rasterizer tests: they expose varyings and derivatives as colours, so the
// tests can read exactly what the rasterizer interpolated.

#include <tuple>

#include <glm/gtc/matrix_transform.hpp>

#include "raster/rasterizer.h"
#include "shading/program_of.h"
#include "shading/varyings.h"
#include "shading/vertex.h"

namespace qs::test {
using namespace qs::glsl;

// Vertex stage for all: gl_Position = MVP * position; P = object position, st = texcoord.
struct PassThrough {
    static constexpr GlslFiles glsl{};  // drawn without the reference
    template <class T>
    struct Varyings {
        vec3<T> P;
        vec2<T> st;
        auto fields() { return std::tie(P, st); }
    };
    static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<PassThrough>& out) {
        out.P = {in.position.x, in.position.y, in.position.z};
        out.st = {in.texcoord.x, in.texcoord.y};
        out.gl_Position = transform_point(u.model_view_projection, in.position);
    }
};

// Writes (1, 1, 1, 1): coverage.
struct Flat {
    static constexpr ShaderInfo info{.name = "test_flat", .description = "a test shader", .needs = {.coordinates = Coordinates::Object3D, .derivatives = false}};
    using VertexStage = PassThrough;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>&, const Uniforms&) { return vec4<F>(1.0f); }
};

// Writes the object position: interpolation.
struct Position {
    static constexpr ShaderInfo info{.name = "test_position", .description = "a test shader", .needs = {.coordinates = Coordinates::Object3D, .derivatives = false}};
    using VertexStage = PassThrough;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) { return vec4<F>(in.P, 1.0f); }
};

// Writes x flat (the provoking vertex's) and y smooth.
struct FlatX {
    static constexpr ShaderInfo info{.name = "test_flat_x", .description = "a test shader", .needs = {.coordinates = Coordinates::Object3D, .derivatives = false}};
    struct VertexStage {
        static constexpr GlslFiles glsl{};
        template <class T>
        struct Varyings {
            T x;  // flat varying float x;
            T y;  // varying float y;
            static constexpr unsigned flat_fields = 1u << 0;
            auto fields() { return std::tie(x, y); }
        };
        static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<VertexStage>& out) {
            out.x = in.position.x;
            out.y = in.position.y;
            out.gl_Position = transform_point(u.model_view_projection, in.position);
        }
    };
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) { return vec4<F>(in.x, in.y, 0.0f, 1.0f); }
};

// Writes dFdx and dFdy of the object x and x itself.
struct Slopes {
    static constexpr ShaderInfo info{.name = "test_slopes", .description = "a test shader", .needs = {.coordinates = Coordinates::Object3D, .derivatives = true}};
    using VertexStage = PassThrough;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return vec4<F>(dFdx(in.P.x), dFdy(in.P.x), in.P.x, 1.0f);
    }
};

// Maps window coordinates (x right, y up, pixels) to clip space for a width x height image, so
// that test geometry can be written in pixels. Exact for power-of-two sizes.
inline glm::mat4 window_to_clip(int width, int height) {
    return glm::translate(glm::mat4(1.0f), glm::vec3(-1.0f, -1.0f, 0.0f)) *
           glm::scale(glm::mat4(1.0f), glm::vec3(2.0f / float(width), 2.0f / float(height), 1.0f));
}

}  // namespace qs::test
