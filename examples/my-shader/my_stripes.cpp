// my_stripes.vert and my_stripes.frag in C++, line for line, for quadshade's renderers: a
// shader struct (its info, its vertex stage, its fragment stage over any number type F) and
// the line that registers it.
#include "shading/glsl.h"
#include "shading/program_of.h"
#include "shading/varyings.h"
#include "shading/vertex.h"

namespace my_shaders {
using namespace qs;
using namespace qs::glsl;

struct MyStripes {
    static constexpr ShaderInfo info{
        .name = "my_stripes",
        .description = "diagonal stripes anti-aliased with fwidth (examples/my-shader)",
        .needs = Needs{.coordinates = Coordinates::Texcoord2D, .derivatives = true},
        .glsl_fragment = {"my_stripes.frag"},  // beside the plugin
    };

    // my_stripes.vert: what it hands the fragment stage (its `varying`s), and its main().
    struct VertexStage {
        static constexpr GlslFiles glsl{"my_stripes.vert"};
        template <class T>
        struct Varyings {
            vec2<T> st;
            auto fields() { return std::tie(st); }
        };
        static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<VertexStage>& out) {
            out.st = {in.texcoord.x, in.texcoord.y};  // st = gl_MultiTexCoord0.st
            out.gl_Position = transform_point(u.model_view_projection, in.position);  // as Mesa sums it
        }
    };

    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> st = in.st;
        F ramp = abs(fract(8.0f * (st.x + st.y)) * 2.0f - 1.0f);
        F w = 0.7f * fwidth(ramp);
        F stripe = smoothstep(0.5f - w, 0.5f + w, ramp);
        return vec4<F>(mix(vec3<F>(0.9f, 0.3f, 0.1f), vec3<F>(0.1f, 0.2f, 0.5f), stripe), 1.0f);
    }
};

QUADSHADE_SHADERS(MyStripes)

}  // namespace my_shaders
