#pragma once
// A user's GLSL shaders, compiled by the front end (frontend/compile.h) and run by the
// interpreter, added to the catalogue so that every command draws them as it draws a catalogue
// shader: by name. The name is the fragment shader's file name ("marble.frag"), which no
// translated shader's name has, or that name with " (2)" where two files share it.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "render/compiled_glsl.h"
#include "shading/program.h"

namespace qs {

// The catalogue collection the shaders loaded here are listed under (quadshade gallery draws it).
inline constexpr const char* kGlslCollection = "GLSL";

struct GlslShader {
    const Program* program;
    std::vector<std::string> warnings;  // glslang's, FILE:LINE: prefixed
};

// Compiles FRAG with VERT, or with the vertex shader the front end writes for it, once per pair
// of files in a process, for the interpreter, or as the compiled translation `way` asks for where
// it can (render/compiled_glsl.h): for what the `shading` requests ask of it, or (none given) for
// every way of shading. Throws frontend::GlslError (a std::runtime_error) with the file, line and
// column of what it cannot take.
GlslShader load_glsl_shader(const std::filesystem::path& fragment, const std::optional<std::filesystem::path>& vertex,
                            GlslWay way = GlslWay::Interpret, const std::vector<ShadeRequest>& shading = {});

// The catalogue shader `name`'s own GLSL, compiled and run by the interpreter, added to the
// catalogue as "NAME.interpreted" (once) with the translation's documented departures from
// check's bar; returns that name. Throws std::invalid_argument for a name not in the catalogue,
// frontend::GlslError for GLSL the front end does not take.
std::string interpreted_twin(const std::string& name);

}  // namespace qs
