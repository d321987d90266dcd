// A plugin whose shader is named like a path out of a folder ("../../escaped"): a shader's name
// names the files `quadshade shaders --export-glsl DIR` writes, so quadshade refuses the plugin as
// it loads and writes nothing (tests/apps/test_outputs.cpp).
#include "shading/glsl.h"
#include "shading/program_of.h"
#include "shading/shaders/vertex_stages.h"
#include "shading/vertex.h"

namespace escaping_name_test {
using namespace qs;
using namespace qs::glsl;

struct Escaping {
    static constexpr ShaderInfo info{
        .name = "../../escaped",
        .description = "a shader named like a path leading out of --export-glsl's folder",
        .needs = {.coordinates = Coordinates::None},
        .glsl_fragment = {"escaped.frag"},
    };
    using VertexStage = shaders::PlanePosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>&, const Uniforms&) {
        return vec4<F>(1.0f, 0.0f, 0.0f, 1.0f);
    }
};

QUADSHADE_SHADERS(Escaping)

}  // namespace escaping_name_test
