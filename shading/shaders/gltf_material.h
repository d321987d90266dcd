#pragma once
// The default material: what a glTF material that names no shader is drawn with. glTF's
// metallic-roughness base colour (baseColorFactor x the base colour texture on its texCoord,
// with its sampler and KHR_texture_transform, x COLOR_0), lit simply: one directional light
// fixed to the camera and an ambient term, by Lambert's law on the vertex normals (per vertex,
// interpolated) where the mesh has NORMAL, or per fragment on the flat normal of each triangle
// (from the derivatives of the view-space position) where it has none; not at all under
// KHR_materials_unlit. alphaMode OPAQUE, MASK (alphaCutoff) and BLEND as GL draws them; texels
// decoded from sRGB and the result encoded to it, as glTF's colour spaces ask. Translated from
// gltf_material.glsl, .vert and .frag beside this header; its uniforms are set from the scene
// (scenes/object_uniforms.h).

#include <bit>
#include <cstdint>
#include <tuple>

#include "shading/glsl.h"
#include "shading/program.h"
#include "shading/program_of.h"
#include "shading/vertex.h"

namespace qs::shaders {
using namespace qs::glsl;

struct GltfMaterial {
    static constexpr UniformDecl kUniforms[] = {
        {"uBaseColorFactor", UniformType::Vec4, {1.0f, 1.0f, 1.0f, 1.0f}},
        {"uBaseColorTexCoord", UniformType::Int, {0.0f}},
        {"uTextureTransform", UniformType::Mat3, {1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f}},
        {"uLighting", UniformType::Int, {2.0f}},
        {"uModelView", UniformType::Mat4,
         {1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f}},
        {"uNormalMatrix", UniformType::Mat3, {1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f}},
        {"uUnproject", UniformType::Vec4, {1.0f, 1.0f, 0.0f, 1.0f}},
        {"uAlphaMode", UniformType::Int, {0.0f}},
        {"uAlphaCutoff", UniformType::Float, {0.5f}},
        // The frame's size, always set by both renderers; this is for draws without a scene.
        {"uResolution", UniformType::Vec2, {64.0f, 64.0f}},
    };
    enum : int {
        uBaseColorFactor, uBaseColorTexCoord, uTextureTransform, uLighting, uModelView, uNormalMatrix, uUnproject,
        uAlphaMode, uAlphaCutoff, uResolution
    };
    static_assert(kUniforms[uResolution].name == "uResolution" && kUniforms[uAlphaCutoff].name == "uAlphaCutoff");

    static constexpr ShaderInfo info = ShaderInfo{
        .name = "gltf_material",
        .description = "the default material: glTF's base colour (baseColorFactor x base colour texture x COLOR_0), "
                       "Lambert-lit by a light fixed to the camera, alphaMode, KHR_materials_unlit",
        .needs = Needs{.coordinates = Coordinates::Texcoord2D, .derivatives = true, .texture = true, .time = false,
                       .frag_coord = true},
        .glsl_fragment = {"shaders/gltf_material.glsl", "shaders/gltf_material.frag"},
        .uniforms = kUniforms,
    };

    // An int uniform, one value for every fragment: the stages branch on it as GLSL's uniform
    // control flow does.
    static std::int32_t int_uniform(const Uniforms& u, int index) {
        return std::bit_cast<std::int32_t>(u.user[index * kUniformWords]);
    }

    // gltf_material.glsl
    template <class F>
    static F lambert(const vec3<F>& n) {
        return 0.3f + 0.7f * max(dot(n, vec3<F>(0.36f, 0.48f, 0.8f)), F(0.0f));
    }
    template <class F>
    static F decode_srgb(const F& c) {
        return select(c <= 0.04045f, c * 0.0773993808f, pow((c + 0.055f) * 0.947867299f, F(2.4f)));
    }
    template <class F>
    static F encode_srgb(const F& c) {
        return select(c <= 0.0031308f, c * 12.92f, 1.055f * pow(c, F(0.416666667f)) - 0.055f);
    }

    // gltf_material.vert
    struct VertexStage {
        static constexpr GlslFiles glsl{"shaders/gltf_material.glsl", "shaders/gltf_material.vert"};
        template <class T>
        struct Varyings {
            vec4<T> color;
            vec2<T> uv;
            T viewZ;
            auto fields() { return std::tie(color, uv, viewZ); }
        };
        static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<VertexStage>& out) {
            using F = float;
            const vec4<F> gl_Color(in.color.r, in.color.g, in.color.b, in.color.a);
            const vec4<F> gl_Vertex(in.position.x, in.position.y, in.position.z, 1.0f);
            vec4<F> base = uniform<vec4<F>>(u, uBaseColorFactor) * gl_Color;
            const vec4<F> p = uniform<mat4<F>>(u, uModelView) * gl_Vertex;
            if (int_uniform(u, uLighting) == 1) {
                const vec3<F> gl_Normal(in.normal.x, in.normal.y, in.normal.z);
                vec3<F> n = normalize(uniform<mat3<F>>(u, uNormalMatrix) * gl_Normal);
                const vec4<F> unproject = uniform<vec4<F>>(u, uUnproject);
                const vec3<F> toEye = vec3<F>(0.0f, 0.0f, unproject.w) + unproject.z * p.xyz();
                if (dot(n, toEye) < 0.0f) n = -n;
                base = vec4<F>(base.xyz() * lambert(n), base.w);
            }
            out.color = base;
            const vec2<F> st = int_uniform(u, uBaseColorTexCoord) == 1 ? vec2<F>(in.texcoord1.x, in.texcoord1.y)
                                                                        : vec2<F>(in.texcoord.x, in.texcoord.y);
            out.uv = (uniform<mat3<F>>(u, uTextureTransform) * vec3<F>(st, 1.0f)).xy();
            out.viewZ = p.z;
            out.gl_Position = transform_point(u.model_view_projection, in.position);
        }
    };

    // gltf_material.frag
    template <class F>
    static FragmentOut<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        FragmentOut<F> out;
        const vec4<F> texel = texture2D(*u.teximage, in.uv);
        vec4<F> base = vec4<F>(decode_srgb(texel.x), decode_srgb(texel.y), decode_srgb(texel.z), texel.w) * in.color;
        if (int_uniform(u, uLighting) == 2) {
            const vec4<F> unproject = uniform<vec4<F>>(u, uUnproject);
            const vec2<F> ndc = in.gl_FragCoord.xy() / uniform<vec2<F>>(u, uResolution) * 2.0f - 1.0f;
            const F w = unproject.z * in.viewZ + unproject.w;
            const vec3<F> p(ndc * w * unproject.xy(), in.viewZ);
            base = vec4<F>(base.xyz() * lambert(normalize(cross(dFdx(p), dFdy(p)))), base.w);
        }
        const std::int32_t alpha_mode = int_uniform(u, uAlphaMode);
        if (alpha_mode == 1) out.discard_if(base.w < uniform<F>(u, uAlphaCutoff));
        const vec3<F> c = clamp(base.xyz(), 0.0f, 1.0f);
        out.gl_FragColor =
            vec4<F>(encode_srgb(c.x), encode_srgb(c.y), encode_srgb(c.z), alpha_mode == 2 ? base.w : F(1.0f));
        return out;
    }
};

QUADSHADE_SHADERS_IN("glTF: the default material", GltfMaterial)

}  // namespace qs::shaders
