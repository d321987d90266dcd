#pragma once
// The names by which a shader's own attributes and matrix uniforms are bound to what a scene
// provides: scenes/shader_inputs.h's, the same for the reference and every renderer. gl_Vertex,
// gl_Normal, gl_Color, gl_MultiTexCoord0/1 and the gl_*Matrix uniforms are the same data under
// GL's names. Any other attribute is refused by name.

#include <optional>
#include <string>

#include "frontend/ir.h"

namespace qs::frontend {

std::optional<ir::Attribute> attribute_named(const std::string& name);
std::optional<ir::TransformUniform> transform_named(const std::string& name);
// "the model-view-projection matrix", ...
std::string transform_description(ir::TransformUniform t);
// The attribute names, for a message.
std::string attribute_names_help();

}  // namespace qs::frontend
