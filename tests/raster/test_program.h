#pragma once
// Small programs for rasterizer tests: they expose varyings and derivatives as colours, so the
// tests can read exactly what the rasterizer interpolated.

#include <glm/gtc/matrix_transform.hpp>

#include "shading/program_of.h"
#include "raster/rasterizer.h"
#include "shading/vertex.h"

namespace qs::test {
using namespace qs::glsl;

// Vertex stage for all: clip = MVP * position; varyings = object position (3), texcoord (2).
inline void pass_through_vertex(const VertexIn& in, const Uniforms& u, VertexOut& out) {
    out.clip = transform_point(u.model_view_projection, in.position);
    out.varyings = {in.position.x, in.position.y, in.position.z, in.texcoord.x, in.texcoord.y};
}

// Writes (1, 1, 1, 1): coverage.
struct Flat {
    static constexpr ShaderInfo info{"test_flat", "", Needs{.coordinates = Coordinates::None, .derivatives = false, .varyings = 0}, {}, {}};
    static void vertex(const VertexIn& in, const Uniforms& u, VertexOut& out) { pass_through_vertex(in, u, out); }
    template <class F>
    static vec4<F> fragment(const FragmentIn<F>&, const Uniforms&) { return vec4<F>(1.0f); }
};

// Writes the first three varyings (the object position): interpolation.
struct Position {
    static constexpr ShaderInfo info{"test_position", "", Needs{.coordinates = Coordinates::Object3D, .derivatives = false, .varyings = 5}, {}, {}};
    static void vertex(const VertexIn& in, const Uniforms& u, VertexOut& out) { pass_through_vertex(in, u, out); }
    template <class F>
    static vec4<F> fragment(const FragmentIn<F>& in, const Uniforms&) {
        return vec4<F>(in.varying[0], in.varying[1], in.varying[2], 1.0f);
    }
};

// Writes varying 0 flat (the provoking vertex's) and varying 1 smooth.
struct FlatX {
    static constexpr ShaderInfo info{"test_flat_x", "", Needs{.coordinates = Coordinates::Object3D, .derivatives = false, .varyings = 5, .flat_varyings = 1u}, {}, {}};
    static void vertex(const VertexIn& in, const Uniforms& u, VertexOut& out) { pass_through_vertex(in, u, out); }
    template <class F>
    static vec4<F> fragment(const FragmentIn<F>& in, const Uniforms&) {
        return vec4<F>(in.varying[0], in.varying[1], 0.0f, 1.0f);
    }
};

// Writes dFdx and dFdy of varying 0 and the varying itself.
struct Slopes {
    static constexpr ShaderInfo info{"test_slopes", "", Needs{.coordinates = Coordinates::Object3D, .derivatives = true, .varyings = 5}, {}, {}};
    static void vertex(const VertexIn& in, const Uniforms& u, VertexOut& out) { pass_through_vertex(in, u, out); }
    template <class F>
    static vec4<F> fragment(const FragmentIn<F>& in, const Uniforms&) {
        return vec4<F>(dFdx(in.varying[0]), dFdy(in.varying[0]), in.varying[0], 1.0f);
    }
};

// Maps window coordinates (x right, y up, pixels) to clip space for a width x height image, so
// that test geometry can be written in pixels. Exact for power-of-two sizes.
inline glm::mat4 window_to_clip(int width, int height) {
    return glm::translate(glm::mat4(1.0f), glm::vec3(-1.0f, -1.0f, 0.0f)) *
           glm::scale(glm::mat4(1.0f), glm::vec3(2.0f / float(width), 2.0f / float(height), 1.0f));
}

}  // namespace qs::test
