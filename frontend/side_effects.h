#pragma once
// Whether evaluating an expression may change a variable: assignments, ++ and --, and calls of
// the shader's own functions (which may write globals or out parameters). The lowering copies
// operands and keeps GLSL's short-circuits where this says so. Internal to frontend/.

#include <glslang/Include/intermediate.h>

namespace qs::frontend {

bool has_side_effects(TIntermNode* node);

}  // namespace qs::frontend
