#include "core/vertex_stage.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/float_environment.h"
#include "core/parallel.h"

namespace qs {

namespace {

void check_indices(const DrawCall& call) {
    const std::size_t n = call.vertices.size();
    for (std::size_t i = 0; i + 2 < call.indices.size(); i += 3) {
        const std::uint32_t a = call.indices[i], b = call.indices[i + 1], c = call.indices[i + 2];
        if (a >= n || b >= n || c >= n) {
            throw std::invalid_argument("triangle " + std::to_string(i / 3) + " indexes vertex " +
                                        std::to_string(std::max({a, b, c})) + " of " + std::to_string(n));
        }
    }
}

}  // namespace

std::vector<VertexOut> run_vertex_stage(const DrawCall& call) {
    if (!call.program) throw std::invalid_argument("draw call without a program");
    check_indices(call);
    std::vector<VertexOut> out(call.vertices.size());
    parallel_chunks<std::size_t>(0, out.size(), 256, [&](const auto& r) {
        const FlushDenormals ftz;  // per thread: the setting is the calling thread's
        for (std::size_t i = r.begin(); i != r.end(); ++i) call.program->vertex(call.vertices[i], call.uniforms, out[i]);
    });
    return out;
}

}  // namespace qs
