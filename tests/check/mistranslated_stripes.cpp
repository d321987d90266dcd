// A deliberately wrong translation, for the test that `quadshade check` fails it: the GLSL is
// examples/my-shader's my_stripes (fwidth(ramp) = |dFdx(ramp)| + |dFdy(ramp)|), the C++ forgets
// the dFdy term, as a hurried translation might. The stripes' anti-aliased edges come out
// narrower wherever the ramp changes along y, which is most of them.
#include "shading/glsl.h"
#include "shading/program_of.h"
#include "shading/vertex.h"

namespace check_test {
using namespace qs;
using namespace qs::glsl;

struct MistranslatedStripes {
    static constexpr ShaderInfo info{
        .name = "mistranslated_stripes",
        .description = "my_stripes.frag translated with abs(dFdx(ramp)) for fwidth(ramp) (a test of quadshade check)",
        .needs = Needs{.coordinates = Coordinates::Texcoord2D, .derivatives = true, .varyings = 2},
        .glsl_vertex = {"my_stripes.vert"},
        .glsl_fragment = {"my_stripes.frag"},
    };

    static void vertex(const VertexIn& in, const Uniforms& u, VertexOut& out) {
        out.varyings[0] = in.texcoord.x;
        out.varyings[1] = in.texcoord.y;
        out.clip = transform_point(u.model_view_projection, in.position);
    }

    template <class F>
    static vec4<F> fragment(const FragmentIn<F>& in, const Uniforms&) {
        vec2<F> st = in.vec2_at(0);
        F ramp = abs(fract(8.0f * (st.x + st.y)) * 2.0f - 1.0f);
        F w = 0.7f * abs(dFdx(ramp));  // the mistake: fwidth(ramp) in the GLSL
        F stripe = smoothstep(0.5f - w, 0.5f + w, ramp);
        return vec4<F>(mix(vec3<F>(0.9f, 0.3f, 0.1f), vec3<F>(0.1f, 0.2f, 0.5f), stripe), 1.0f);
    }
};

QUADSHADE_SHADERS(MistranslatedStripes)

}  // namespace check_test
