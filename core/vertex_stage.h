#pragma once
// A draw's vertices through its program's vertex stage, for both backends: in parallel chunks,
// with denormals flushed as Mesa's draw module runs vertex shaders (float_environment.h), so the
// rasterizer and the ray caster start from the same gl_Position and varyings.

#include <vector>

#include "core/draw_call.h"
#include "shading/program.h"

namespace qs {

// out[i] is vertex i's gl_Position and varyings. Throws std::invalid_argument for a draw
// without a program.
std::vector<VertexOut> run_vertex_stage(const DrawCall& call);

}  // namespace qs
