#pragma once
// The vertex stages several shaders share, one per .vert file beside this header (shading/
// varyings.h says what a vertex stage is). A shader names one with `using VertexStage = PlaneSt;`
// and reads its varyings by name in the fragment stage.

#include <tuple>

#include "shading/glsl.h"
#include "shading/program.h"
#include "shading/varyings.h"
#include "shading/vertex.h"

namespace qs::shaders {

// plane_st.vert: st = gl_MultiTexCoord0.st
struct PlaneSt {
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
    template <class T>
    using Varyings = PlaneSt::Varyings<T>;
    static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<PlaneSt10>& out) {
        out.st = {in.texcoord.x * 10.0f, in.texcoord.y * 10.0f};
        out.gl_Position = transform_point(u.model_view_projection, in.position);
    }
};

// plane_texcoords.vert: texcoords = gl_MultiTexCoord0.st (Lawlor's name for it).
struct PlaneTexcoords {
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
    template <class T>
    using Varyings = SolidVaryings<T>;
    static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<Sphere>& out) {
        const glm::vec3 P = in.position * float(scale) + glm::vec3(0.0f, 0.0f, float(time_sign) * u.time);
        out.P = {P.x, P.y, P.z};
        out.gl_Position = transform_point(u.model_view_projection, in.position);
    }
};

}  // namespace qs::shaders
