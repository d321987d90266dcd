// A deliberately wrong translation, for the test that `quadshade check` fails it: the GLSL is
// examples/my-shader's my_stripes (fwidth(ramp) = |dFdx(ramp)| + |dFdy(ramp)|), the C++ forgets
// the dFdy term, as a hurried translation might. The stripes' anti-aliased edges come out
// narrower wherever the ramp changes along y, which is most of them.
#include "shading/glsl.h"
#include "shading/program_of.h"
#include "shading/varyings.h"
#include "shading/vertex.h"

namespace check_test {
using namespace qs;
using namespace qs::glsl;

struct MistranslatedStripes {
    static constexpr ShaderInfo info{
        .name = "mistranslated_stripes",
        .description = "my_stripes.frag translated with abs(dFdx(ramp)) for fwidth(ramp) (a test of quadshade check)",
        .needs = Needs{.coordinates = Coordinates::Texcoord2D, .derivatives = true},
        .glsl_fragment = {"my_stripes.frag"},
    };

    struct VertexStage {
        static constexpr GlslFiles glsl{"my_stripes.vert"};
        template <class T>
        struct Varyings {
            vec2<T> st;
            auto fields() { return std::tie(st); }
        };
        static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<VertexStage>& out) {
            out.st = {in.texcoord.x, in.texcoord.y};
            out.gl_Position = transform_point(u.model_view_projection, in.position);
        }
    };

    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> st = in.st;
        F ramp = abs(fract(8.0f * (st.x + st.y)) * 2.0f - 1.0f);
        F w = 0.7f * abs(dFdx(ramp));  // the mistake: fwidth(ramp) in the GLSL
        F stripe = smoothstep(0.5f - w, 0.5f + w, ramp);
        return vec4<F>(mix(vec3<F>(0.9f, 0.3f, 0.1f), vec3<F>(0.1f, 0.2f, 0.5f), stripe), 1.0f);
    }
};

QUADSHADE_SHADERS(MistranslatedStripes)

}  // namespace check_test
