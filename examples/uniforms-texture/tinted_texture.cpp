// tinted_texture.vert and tinted_texture.frag in C++, line for line.
#include <tuple>

#include "shading/glsl.h"
#include "shading/glsl/uniform.h"
#include "shading/program_of.h"
#include "shading/vertex.h"

namespace tinted {
using namespace qs;
using namespace qs::glsl;

// The shader's own uniforms, in the order the fragment stage reads them by index.
inline constexpr UniformDecl kUniforms[] = {
    {"uTint", UniformType::Vec3, {1.0f, 0.6f, 0.2f}},
    {"uBands", UniformType::Float, {6.0f}},
};
enum { kTint, kBands };

struct TintedTexture {
    static constexpr ShaderInfo info{
        .name = "tinted_texture",
        .description = "the scene's texture, tinted in bands (examples/uniforms-texture)",
        .needs = {.texture = true},
        .glsl_fragment = {"tinted_texture.frag"},
        .glsl_version = 130,
        .uniforms = kUniforms,
    };

    // tinted_texture.vert: `mvp` is the scene's transform, `position` and `texcoord` its mesh's.
    struct VertexStage {
        static constexpr GlslFiles glsl{"tinted_texture.vert"};
        template <class T>
        struct Varyings {
            vec2<T> uv;
            auto fields() { return std::tie(uv); }
        };
        static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<VertexStage>& out) {
            out.uv = {in.texcoord.x, in.texcoord.y};
            out.gl_Position = transform_point(u.model_view_projection, in.position);  // mvp * vec4(position, 1.0)
        }
    };

    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        const vec3<F> uTint = uniform<vec3<F>>(u, kTint);
        const F uBands = uniform<F>(u, kBands);
        vec3<F> texel = texture2D(*u.teximage, in.uv).rgb();
        F band = step(0.5f, fract(uBands * in.uv.y));
        return vec4<F>(mix(texel, texel * uTint, band), 1.0f);
    }
};
QUADSHADE_SHADERS(TintedTexture)

}  // namespace tinted
