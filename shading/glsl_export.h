#pragma once
// The GLSL each catalogue shader translates, as the complete source of each stage: the text any
// OpenGL program compiles. `quadshade shaders --export-glsl DIR` writes it for the OSMesa
// reference, which shares nothing else with the renderer.

#include <filesystem>
#include <string>

#include "shading/program.h"

namespace qs {

// One stage's source: the #version line of ShaderInfo::glsl_version, the shader's defines, then
// its files (in its GLSL folder, catalogue.h) in order, each after a "#line 1". Throws
// std::runtime_error naming a file that cannot be read.
std::string glsl_source(const Program& program, bool vertex_stage);

// Writes DIR/NAME.vert and DIR/NAME.frag for every catalogue shader, plugins' included (DIR is created); returns
// how many shaders it wrote. Throws std::runtime_error naming a file that cannot be written.
int export_glsl(const std::filesystem::path& dir);

}  // namespace qs
