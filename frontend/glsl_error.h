#pragma once
// What the GLSL front end throws for a shader it cannot take: a message that starts with
// FILE:LINE:COL (or FILE:LINE) of the construct, as compilers word theirs.

#include <stdexcept>
#include <string>

namespace qs::frontend {

struct GlslError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Stages that compile but do not link, as GL's linker refuses them: a varying read and not
// written, no main(), no gl_Position, a uniform of two types.
struct GlslLinkError : GlslError {
    using GlslError::GlslError;
};

// Valid GLSL that quadshade does not run: a construct the interpreter lacks, or more than the
// renderer passes (varyings, samplers). The shader is right; a conformance run skips it rather
// than failing it.
struct GlslUnsupported : GlslError {
    using GlslError::GlslError;
};

// "FILE:LINE:COL: " (":COL" left out when col <= 0, ":LINE" when line <= 0).
inline std::string source_position(const std::string& file, int line, int col = 0) {
    std::string s = file;
    if (line > 0) s.append(":").append(std::to_string(line));
    if (line > 0 && col > 0) s.append(":").append(std::to_string(col));
    return s.append(": ");
}

}  // namespace qs::frontend
