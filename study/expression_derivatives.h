#pragma once
// Derivative maps of expressions a user names (`--derivatives-of EXPR`): each a GLSL expression
// over what the fragment shader sees where its main ends (its inputs, uniforms, globals and main's
// outermost variables), evaluated by the GLSL front end and the interpreter in the shader's GLSL:
// a --glsl shader's own, a catalogue or plugin shader's exported GLSL (glsl_export.h), the text
// llvmpipe runs. Each component of the expression is a Program of its own, added to the
// catalogue, whose colour is (dFdx(e), dFdy(e), e, 1) under the rule it is shaded with
// (frontend::DerivativeProbe); fragments main discards draw nothing.

#include <string>
#include <vector>

#include "study/derivative_maps.h"

namespace qs::study {

// The maps of `expressions` in `shader` (labelled by the expression, ".x" ... added for a
// vector's components; their images d-expression-N[.x]). Throws std::invalid_argument with
// glslang's message, naming `option` and the expression, for one the shader cannot evaluate (not
// an expression, a name it does not declare, not a float or float vector); std::runtime_error for
// a shader whose GLSL the front end does not take.
std::vector<DerivativeMap> expression_maps(const std::string& shader, const std::vector<std::string>& expressions,
                                           const std::string& option);

}  // namespace qs::study
