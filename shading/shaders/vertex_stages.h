#pragma once
// The stock vertex stages: the ones several shaders share, one per .vert file beside this header
// (shading/varyings.h says what a vertex stage is). A shader, a plugin's included, names one with
// `using VertexStage = shaders::PlaneSt;`, reads its varyings by name in the fragment stage, and
// lists no vertex GLSL: the stage's file ships with quadshade (share/quadshade/shading).

#include <tuple>

#include "shading/glsl.h"
#include "shading/program.h"
#include "shading/varyings.h"
#include "shading/vertex.h"

namespace qs::shaders {

// plane_st.vert: st = gl_MultiTexCoord0.st
struct PlaneSt {
    static constexpr GlslFiles glsl{"shaders/plane_st.vert"};
    static constexpr bool stock = true;
    template <class T>
    struct Varyings {
        glsl::vec2<T> st;
        auto fields() { return std::tie(st); }
    };
    static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<PlaneSt>& out) {
        out.st = {in.texcoord.x, in.texcoord.y};
        out.gl_Position = transform_point(u.model_view_projection, in.position);
    }
};

// plane_st.vert for fragment stages that read no varying (only gl_FragCoord, or nothing): GL's
// linker drops a varying no fragment stage reads, and so nothing is interpolated here either.
struct PlanePosition {
    static constexpr GlslFiles glsl{"shaders/plane_st.vert"};
    static constexpr bool stock = true;
    template <class T>
    struct Varyings {
        std::tuple<> fields() { return {}; }
    };
    static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<PlanePosition>& out) {
        out.gl_Position = transform_point(u.model_view_projection, in.position);
    }
};

// plane_st10.vert: st = gl_MultiTexCoord0.st * 10.0, for the listings that print their fragment
// stage only.
struct PlaneSt10 {
    static constexpr GlslFiles glsl{"shaders/plane_st10.vert"};
    static constexpr bool stock = true;
    template <class T>
    using Varyings = PlaneSt::Varyings<T>;
    static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<PlaneSt10>& out) {
        out.st = {in.texcoord.x * 10.0f, in.texcoord.y * 10.0f};
        out.gl_Position = transform_point(u.model_view_projection, in.position);
    }
};

// plane_texcoords.vert: texcoords = gl_MultiTexCoord0.st (Lawlor's name for it).
struct PlaneTexcoords {
    static constexpr GlslFiles glsl{"shaders/plane_texcoords.vert"};
    static constexpr bool stock = true;
    template <class T>
    struct Varyings {
        glsl::vec2<T> texcoords;
        auto fields() { return std::tie(texcoords); }
    };
    static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<PlaneTexcoords>& out) {
        out.texcoords = {in.texcoord.x, in.texcoord.y};
        out.gl_Position = transform_point(u.model_view_projection, in.position);
    }
};

// object_plane.vert: p = gl_Vertex.xy * 8.0
struct ObjectPlane {
    static constexpr GlslFiles glsl{"shaders/object_plane.vert"};
    static constexpr bool stock = true;
    template <class T>
    struct Varyings {
        glsl::vec2<T> p;
        auto fields() { return std::tie(p); }
    };
    static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<ObjectPlane>& out) {
        out.p = {in.position.x * 8.0f, in.position.y * 8.0f};
        out.gl_Position = transform_point(u.model_view_projection, in.position);
    }
};

// The solid textures' varying: P, an object-space position.
template <class T>
struct SolidVaryings {
    glsl::vec3<T> P;
    auto fields() { return std::tie(P); }
};

// object_position.vert: P = gl_Vertex.xyz * 4.0
struct ObjectPosition {
    static constexpr GlslFiles glsl{"shaders/object_position.vert"};
    static constexpr bool stock = true;
    template <class T>
    using Varyings = SolidVaryings<T>;
    static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<ObjectPosition>& out) {
        const glm::vec3 P = in.position * 4.0f;
        out.P = {P.x, P.y, P.z};
        out.gl_Position = transform_point(u.model_view_projection, in.position);
    }
};

// sphere_simplex.vert, sphere_spots.vert, sphere_turbulence.vert:
// P = gl_Vertex.xyz * scale + vec3(0.0, 0.0, time_sign * time)
template <int scale, int time_sign>
struct Sphere {
    static_assert(scale == 4 || (scale == 2 && time_sign == -1), "one of the three .vert files");
    static constexpr GlslFiles glsl{scale == 2      ? "shaders/sphere_turbulence.vert"
                                    : time_sign > 0 ? "shaders/sphere_simplex.vert"
                                                    : "shaders/sphere_spots.vert"};
    static constexpr bool stock = true;
    template <class T>
    using Varyings = SolidVaryings<T>;
    static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<Sphere>& out) {
        const glm::vec3 P = in.position * float(scale) + glm::vec3(0.0f, 0.0f, float(time_sign) * u.time);
        out.P = {P.x, P.y, P.z};
        out.gl_Position = transform_point(u.model_view_projection, in.position);
    }
};

}  // namespace qs::shaders
