#pragma once
// A draw call made ready for shading, the same for both backends: its shader instantiation and
// the inputs its fragments need, resolved once per frame from the shader's Needs and the request
// (shading/shade_choice.h), never per fragment.

#include <span>
#include <vector>

#include "core/draw_call.h"
#include "shading/shade_choice.h"

namespace qs {

struct PreparedDraw {
    const DrawCall* call;
    ShadeMode mode;    // the instantiation its batches run
    bool quads;        // 2x2 quads with helper lanes; false: independent pixels or Dual2
    bool frag_coord;   // gl_FragCoord is read (Needs::frag_coord), or the general path fills it
    int varyings;      // Needs::varyings
    unsigned flat;     // Needs::flat_varyings
    unsigned noperspective;  // Needs::noperspective_varyings
};

// Each of `draws` prepared under `request`, in order. Throws UnsupportedRequest for a request no
// instantiation honours (before looking at any draw), std::invalid_argument for a draw without
// a program.
std::vector<PreparedDraw> prepare_draws(std::span<const DrawCall> draws, const ShadeRequest& request);

}  // namespace qs
