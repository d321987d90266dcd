#pragma once
// The GLSL front end: a vertex and fragment shader pair, as GL takes it, compiled into the
// program the interpreter runs (ir.h). glslang parses and checks the language; this folder is
// the only place that includes it.
//
// Accepted: GLSL 1.10 to 4.50 vertex and fragment shaders, the compatibility profile's built-ins
// included; what the interpreter cannot run is refused with FILE:LINE:COL, the construct and
// why, never run otherwise (docs/glsl.md lists what is supported).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "frontend/compile_options.h"
#include "frontend/glsl_error.h"
#include "frontend/ir.h"

namespace qs::frontend {

struct GlslSource {
    std::string file;  // as messages name it
    std::string text;
};

// A GLSL file's text. Throws GlslError for a file that cannot be read, is not text (a NUL
// byte), or is larger than kMaxGlslBytes.
inline constexpr std::size_t kMaxGlslBytes = 1u << 20;
GlslSource read_glsl_file(const std::filesystem::path& path);

struct CompiledProgram {
    ir::Program program;
    GlslSource vertex;                  // the vertex shader compiled: given, or written for the fragment one
    std::vector<std::string> warnings;  // glslang's, FILE:LINE: prefixed
};

// Compiles `fragment` with `vertex`, or with the vertex shader default_vertex_shader() writes
// for it. Throws GlslError with glslang's messages (FILE:LINE:COL: error: ...) for GLSL that
// does not compile, GlslLinkError for stages that do not link, GlslUnsupported (a GlslError) for
// what the interpreter does not run.
CompiledProgram compile_glsl(const GlslSource& fragment, const std::optional<GlslSource>& vertex,
                             const CompileOptions& options = {});

// The vertex shader quadshade pairs with a fragment shader given alone: gl_Position from the
// scene's transform, and each varying the fragment shader reads from the vertex attribute of
// its name (binding_names.h; `st` and `uv` are texture coordinates, `P` the object-space
// position). Throws GlslError naming a varying it cannot supply.
GlslSource default_vertex_shader(const GlslSource& fragment);

}  // namespace qs::frontend
