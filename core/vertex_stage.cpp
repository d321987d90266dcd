#include "core/vertex_stage.h"

#include <stdexcept>

#include "core/float_environment.h"
#include "core/parallel.h"

namespace qs {

std::vector<VertexOut> run_vertex_stage(const DrawCall& call) {
    if (!call.program) throw std::invalid_argument("draw call without a program");
    std::vector<VertexOut> out(call.vertices.size());
    parallel_chunks<std::size_t>(0, out.size(), 256, [&](const auto& r) {
        const FlushDenormals ftz;  // per thread: the setting is the calling thread's
        for (std::size_t i = r.begin(); i != r.end(); ++i) call.program->vertex(call.vertices[i], call.uniforms, out[i]);
    });
    return out;
}

}  // namespace qs
