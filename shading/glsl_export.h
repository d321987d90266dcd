#pragma once
// The GLSL each catalogue shader translates, as the complete source of each stage: the text any
// OpenGL program compiles. `quadshade shaders --export-glsl DIR` writes it for the OSMesa
// reference, which shares nothing else with the renderer.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "shading/program.h"

namespace qs {

// One stage's source: its #version line, the shader's defines, then its files (in its GLSL folder,
// catalogue.h) in order, each after a "#line 1". The #version line is the one the stage's first
// file starts with, if it has one (kept as written, the file's line left empty so that compiler
// messages keep its line numbers), else ShaderInfo::glsl_version's (120 when unset). Throws
// std::runtime_error naming the file and line of a file that cannot be read, of a #version in a
// stage's later file, or of one that contradicts ShaderInfo::glsl_version.
std::string glsl_source(const Program& program, bool vertex_stage);

// A GLSL file's text, and its name for messages.
struct GlslText {
    std::string name, text;
};
// glsl_source's work on the texts of a stage's files, given the shader's glsl_version and defines.
std::string stage_source(const std::vector<GlslText>& files, int glsl_version, std::string_view defines);

// Writes DIR/NAME.vert and DIR/NAME.frag for every catalogue shader, plugins' included (DIR is created); returns
// how many shaders it wrote. Throws std::runtime_error naming a file that cannot be written.
int export_glsl(const std::filesystem::path& dir);

}  // namespace qs
