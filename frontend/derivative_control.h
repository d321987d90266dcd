#pragma once
// GL_ARB_derivative_control below GLSL 4.00. Mesa gives a fragment shader of any version that
// enables the extension dFdxFine, dFdyCoarse and their kin; glslang declares them from 4.00 on
// only (and defines the extension's macro in every version). A fragment shader that enables the
// extension and does not compile without them is parsed again with them declared as functions
// (derivative_control_declarations(), glslang's preamble), and the calls to those declarations are
// made the built-in operations they name. Internal to frontend/.

#include <glslang/MachineIndependent/localintermediate.h>

namespace qs::frontend {

// Prototypes of the extension's functions, for every float type.
const char* derivative_control_declarations();

// Whether `stage` (as glslang parsed it, with or without errors) is a desktop fragment shader
// below 4.00 that enables or requires GL_ARB_derivative_control.
bool wants_derivative_control(const glslang::TIntermediate& stage);

// Calls to those functions, which the shader does not define, made
// glslang's built-in operations (EOpDPdxFine, ...), as a 4.00 shader has them.
void call_derivative_control_builtins(glslang::TIntermediate& stage);

}  // namespace qs::frontend
