// A fragment stage reads its vertex stage's varyings by name: reading one the stage does not
// write is a compile error, not a NaN or another draw's numbers at run time. Built twice by
// tests/CMakeLists.txt: as is (reads a varying the stage writes: must compile) and with
// QS_MISREAD (reads `st` from a stage that writes only `P`: must fail, naming `st`).
#include "shading/glsl.h"
#include "shading/shaders/vertex_stages.h"

namespace {
using namespace qs;
using namespace qs::glsl;

struct Reader {
    using VertexStage = shaders::ObjectPosition;  // writes P only
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
#ifdef QS_MISREAD
        return vec4<F>(in.st, 0.0f, 1.0f);
#else
        return vec4<F>(in.P, 1.0f);
#endif
    }
};

}  // namespace

vec4<Pixels<float, kBatchLanes>> read_varyings(const FragmentIn<Pixels<float, kBatchLanes>, Reader::VertexStage>& in) {
    return Reader::fragment(in, Uniforms{});
}
