#pragma once
// Gustavson's chapter (Procedural Textures in GLSL): what the catalogue lacked of it. Listing 1.2's
// Jacobian3 (an analytic 3D gradient taken to window space, for an anti-aliased contour), 4D
// simplex noise as an animated solid texture (section 1.6), and a bump map from the noise's
// analytic gradient (section 1.1). Solid textures, compared on the sphere scene. Translated from
// the .frag files beside this header and shading/noise/ (simplex3d, simplex3d_grad, simplex4d),
// line for line.

#include <tuple>

#include "shading/glsl.h"
#include "shading/noise/simplex3d_grad.h"
#include "shading/noise/simplex4d.h"
#include "shading/program.h"
#include "shading/program_of.h"
#include "shading/shaders/collections.h"
#include "shading/shaders/vertex_stages.h"

namespace qs::shaders {
using namespace qs::glsl;

struct Simplex3dContourAa {
    static constexpr ShaderInfo info{
        .name = "simplex3d_contour_aa",
        .description = "a contour line of 3D simplex noise, anti-aliased by its analytic gradient through Jacobian3",
        .needs = {.coordinates = Coordinates::Object3D, .derivatives = true},
        .glsl_fragment = {"noise/simplex3d.glsl", "noise/simplex3d_grad.glsl", "shaders/simplex3d_contour_aa.frag"},
        .glsl_defines = noise::Simplex3dDemo::glsl_defines,
        .wide_batches = true,
    };
    using VertexStage = ObjectPosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec3<F> stp = in.P;
        vec3<F> G3_stp;
        F n = noise::snoise3_grad<noise::Simplex3dDemo>(stp, G3_stp);
        mat2x3<F> Jacobian3 = mat2x3<F>(dFdx(stp), dFdy(stp));
        vec2<F> G3_xy = G3_stp * Jacobian3;
        // The noise's change over about a pixel, and the contour n = 0 as a line 0.1 wide in noise
        // units, its edges smoothed over that change.
        F afwidth = 0.7f * length(G3_xy);
        F line = smoothstep(0.1f - afwidth, 0.1f + afwidth, abs(n));
        return vec4<F>(mix(vec3<F>(0.1f, 0.2f, 0.5f), vec3<F>(1.0f, 0.95f, 0.8f), line), 1.0f);
    }
};

// simplex4d_animated.vert: P = vec4(gl_Vertex.xyz * 3.0, 0.3 * time)
struct SolidTime4 {
    static constexpr GlslFiles glsl{"shaders/simplex4d_animated.vert"};
    template <class T>
    struct Varyings {
        glsl::vec4<T> P;
        auto fields() { return std::tie(P); }
    };
    static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<SolidTime4>& out) {
        const glm::vec3 P = in.position * 3.0f;
        out.P = {P.x, P.y, P.z, 0.3f * u.time};
        out.gl_Position = transform_point(u.model_view_projection, in.position);
    }
};

// No time period: w = 0.3 time repeats its hash every 289 / 0.3 s, but 0.3 t and 0.3 (t + 963.3)
// are not the same floats' offsets, so the output does not repeat exactly.
struct Simplex4dAnimated {
    static constexpr ShaderInfo info{
        .name = "simplex4d_animated",
        .description = "4D simplex noise of (object position, time), an animated solid texture (the noise ours: the chapter prints none)",
        .needs = {.coordinates = Coordinates::Object3D, .time = true},
        .glsl_fragment = {"noise/simplex4d.glsl", "shaders/simplex4d_animated.frag"},
        .wide_batches = true,
    };
    using VertexStage = SolidTime4;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        F n = noise::snoise4(in.P);
        return vec4<F>(vec3<F>(0.5f + 0.5f * n), 1.0f);
    }
};

struct SimplexBump {
    static constexpr ShaderInfo info{
        .name = "simplex_bump",
        .description = "a bump map of 3D simplex noise from its analytic gradient, one directional light (the normal a unit sphere's)",
        .needs = {.coordinates = Coordinates::Object3D},
        .glsl_fragment = {"noise/simplex3d.glsl", "noise/simplex3d_grad.glsl", "shaders/simplex_bump.frag"},
        .glsl_defines = noise::Simplex3dDemo::glsl_defines,
        .wide_batches = true,
    };
    using VertexStage = ObjectPosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec3<F> N = normalize(in.P);
        vec3<F> G;
        noise::snoise3_grad<noise::Simplex3dDemo>(in.P, G);
        vec3<F> dh = 0.16f * G;
        vec3<F> bumped = normalize(N - (dh - dot(dh, N) * N));
        vec3<F> L = normalize(vec3<F>(0.3f, -0.8f, 0.6f));
        F diffuse = max(dot(bumped, L), 0.0f);
        return vec4<F>(vec3<F>(0.9f, 0.8f, 0.6f) * (0.15f + 0.85f * diffuse), 1.0f);
    }
};

QUADSHADE_SHADERS_IN(kGustavson, Simplex3dContourAa, Simplex4dAnimated, SimplexBump)

}  // namespace qs::shaders
