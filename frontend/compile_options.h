#pragma once
// How a program is compiled beyond its GLSL: how its vertex inputs are bound, and the
// fixed-function state GL applies to the built-in colour varyings. The defaults are quadshade's
// scenes: inputs bound by name to a scene's data (binding_names.h), colours as GL's defaults.

#include <map>
#include <optional>
#include <string>

namespace qs::frontend {

struct CompileOptions {
    // When set, every vertex input the shader declares (other than GL's built-in gl_Vertex,
    // gl_Color, ...) is a generic attribute, as glVertexAttribPointer feeds it: at the location
    // this map binds to its name (glBindAttribLocation), else at its layout(location), else at
    // the lowest free locations, as GL's linker assigns them (ir::Program::generic_attributes
    // lists them). When not set, inputs are bound by name to a scene's data.
    std::optional<std::map<std::string, int>> attribute_locations;
    // GL_VERTEX_PROGRAM_TWO_SIDE: on back-facing primitives a fragment's gl_Color and
    // gl_SecondaryColor are the vertex stage's gl_BackColor and gl_BackSecondaryColor.
    bool two_sided_color = false;
    // glShadeModel(GL_FLAT): gl_Color and gl_SecondaryColor are flat, unless the fragment shader
    // declares them with an interpolation qualifier of their own.
    bool flat_colors = false;
};

}  // namespace qs::frontend
