#pragma once
// The 32-bit word a stage input bound to a uniform holds (a user uniform's, the time, a
// transform's component, the `dims` texture size): the same for every fragment, in every
// number type, and so computed once here, outside the per-type code.

#include <cstdint>

#include "frontend/ir.h"
#include "shading/program.h"

namespace qs::interpreter {

// False for a binding that is not a uniform's (a varying, gl_FragCoord, an attribute).
bool uniform_word(const ir::Program& program, const ir::Binding& b, const Uniforms& u, std::uint32_t& word);

}  // namespace qs::interpreter
