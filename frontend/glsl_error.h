#pragma once
// What the GLSL front end throws for a shader it cannot take: a message that starts with
// FILE:LINE:COL (or FILE:LINE) of the construct, as compilers word theirs.

#include <stdexcept>
#include <string>

namespace qs::frontend {

struct GlslError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// "FILE:LINE:COL: " (":COL" left out when col <= 0, ":LINE" when line <= 0).
inline std::string source_position(const std::string& file, int line, int col = 0) {
    std::string s = file;
    if (line > 0) s.append(":").append(std::to_string(line));
    if (line > 0 && col > 0) s.append(":").append(std::to_string(col));
    return s.append(": ");
}

}  // namespace qs::frontend
