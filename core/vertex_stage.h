#pragma once
// A draw's vertices through its program's vertex stage, the same for both backends: the draw
// checked, then its vertices in parallel chunks with denormals flushed as Mesa's draw module runs
// vertex shaders (float_environment.h; what a backend derives from them runs flushed too:
// tile_frame.h), so the rasterizer and the ray caster start from the same gl_Position and
// varyings.

#include <vector>

#include "core/draw_call.h"
#include "shading/batches.h"

namespace qs {

// out[i] is vertex i's gl_Position and varyings. Throws std::invalid_argument for a draw without
// a program or a triangle that indexes a vertex the draw does not have (naming both).
std::vector<VertexOut> run_vertex_stage(const DrawCall& call);

}  // namespace qs
