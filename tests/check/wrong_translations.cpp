// Deliberately wrong translations, for the tests that `quadshade check` fails them.
//  - mistranslated_stripes: the GLSL is examples/minimal's stripes.frag (fwidth(ramp) =
//    |dFdx(ramp)| + |dFdy(ramp)|), the C++ forgets the dFdy term, as a hurried translation might.
//    The stripes' anti-aliased edges come out narrower wherever the ramp changes along y, which is
//    most of them.
//  - unheld_loop: unheld_loop.frag beside this file, an escape-time loop translated with a Loop
//    that is not given the iteration count its body increments: the count runs on for the
//    fragments that have left, which check's run of the checked instantiation names.
#include "shading/glsl.h"
#include "shading/program_of.h"
#include "shading/shaders/vertex_stages.h"

namespace check_test {
using namespace qs;
using namespace qs::glsl;

struct MistranslatedStripes {
    static constexpr ShaderInfo info{
        .name = "mistranslated_stripes",
        .description = "stripes.frag translated with abs(dFdx(ramp)) for fwidth(ramp) (a test of quadshade check)",
        .needs = {.derivatives = true},
        .glsl_fragment = {"stripes.frag"},
    };
    using VertexStage = shaders::PlaneSt;

    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> st = in.st;
        F ramp = abs(fract(8.0f * (st.x + st.y)) * 2.0f - 1.0f);
        F w = 0.7f * abs(dFdx(ramp));  // the mistake: fwidth(ramp) in the GLSL
        F stripe = smoothstep(0.5f - w, 0.5f + w, ramp);
        return vec4<F>(mix(vec3<F>(0.9f, 0.3f, 0.1f), vec3<F>(0.1f, 0.2f, 0.5f), stripe), 1.0f);
    }
};

struct UnheldLoop {
    static constexpr ShaderInfo info{
        .name = "unheld_loop",
        .description = "an escape-time loop whose Loop does not hold the count it increments (a test of quadshade check)",
        .glsl_fragment = {"unheld_loop.frag"},
    };
    using VertexStage = shaders::PlaneSt;

    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        F x = 0.0f, t = in.st.x * 4.0f;
        int_t<F> n = 0;
        Loop loop(x);  // the mistake: n is written below and not held
        for (int i = 0; loop(i < 16); i++) {
            loop.break_if(x > t);
            x += 0.5f;
            n++;
        }
        return vec4<F>(F(n) / 16.0f, x / 8.0f, 0.0f, 1.0f);
    }
};

QUADSHADE_SHADERS(MistranslatedStripes, UnheldLoop)

}  // namespace check_test
