// stripes.frag in C++, line for line: the shader's description, the vertex stage it runs after
// (a stock one, whose GLSL quadshade ships), and its fragment stage over any number type F.
#include "shading/glsl.h"
#include "shading/program_of.h"
#include "shading/shaders/vertex_stages.h"

namespace minimal {
using namespace qs;
using namespace qs::glsl;

struct Stripes {
    static constexpr ShaderInfo info{
        .name = "stripes",
        .description = "diagonal stripes anti-aliased with fwidth (examples/minimal)",
        .needs = {.derivatives = true},
        .glsl_fragment = {"stripes.frag"},  // beside the plugin
    };
    using VertexStage = shaders::PlaneSt;

    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> st = in.st;
        F ramp = abs(fract(8.0f * (st.x + st.y)) * 2.0f - 1.0f);
        F w = 0.7f * fwidth(ramp);
        F stripe = smoothstep(0.5f - w, 0.5f + w, ramp);
        return vec4<F>(mix(vec3<F>(0.9f, 0.3f, 0.1f), vec3<F>(0.1f, 0.2f, 0.5f), stripe), 1.0f);
    }
};
QUADSHADE_SHADERS(Stripes)

}  // namespace minimal
