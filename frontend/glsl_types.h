#pragma once
// glslang's types as the lowering sees them: how many scalar registers of which banks a value
// of a type takes, and where a member or an element starts. Internal to frontend/.

#include <string>
#include <vector>

#include <glslang/Include/Types.h>

#include "frontend/ir.h"

namespace qs::frontend {

// The bank of a scalar basic type; false for a type the interpreter has no registers for.
bool bank_of(glslang::TBasicType t, ir::Bank& bank);

// The banks of every scalar component of `t`, in GLSL's order (see ir.h). Throws GlslError
// (GlslUnsupported, without a position) for a type that has none: samplers, doubles, 64-bit or 16-bit types.
void component_banks(const glslang::TType& t, std::vector<ir::Bank>& out);
std::vector<ir::Bank> component_banks(const glslang::TType& t);
int component_count(const glslang::TType& t);

// The type of element `i` of an array, column `i` of a matrix, component of a vector, or
// member `i` of a struct, and where its components start among the whole value's.
glslang::TType element_type(const glslang::TType& t);
int member_offset(const glslang::TType& t, int member);
glslang::TType member_type(const glslang::TType& t, int member);

// GLSL's name of a type, for messages ("vec3", "mat2x4", "float[4]", "struct S").
std::string type_name(const glslang::TType& t);

}  // namespace qs::frontend
