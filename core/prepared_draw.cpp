#include "core/prepared_draw.h"

#include <stdexcept>

namespace qs {

std::vector<PreparedDraw> prepare_draws(std::span<const DrawCall> draws, const ShadeRequest& request) {
    check_supported(request);
    std::vector<PreparedDraw> prepared;
    prepared.reserve(draws.size());
    for (const DrawCall& call : draws) {
        if (!call.program) throw std::invalid_argument("draw call without a program");
        const Needs& needs = call.program->info().needs;
        const DrawShading shading = choose_shading(needs, call.texture_lod, request);
        prepared.push_back({&call, shading.mode, shading.quads, needs.frag_coord || request.general_path,
                            needs.varyings, needs.flat_varyings, needs.noperspective_varyings});
    }
    return prepared;
}

}  // namespace qs
