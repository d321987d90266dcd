#pragma once
// A piglit .shader_test file split into its sections, as piglit's shader_runner reads it
// (tests/shaders/shader_runner.c): [require], the shaders of each stage, [vertex data] and [test].
// Sections start with a line that begins with their bracketed name; text before the first one is
// ignored. The sections are kept as text with their line numbers, so that what is wrong in one is
// reported at its line in the file.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace qs::piglit {

// A file that is not a shader_test as piglit reads it: an unknown section, a missing [require].
// The message starts with FILE:LINE.
struct ShaderTestError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Line {
    int number;        // in the file, from 1
    std::string text;  // without its line break
};

enum class Stage { Vertex, TessControl, TessEvaluation, Geometry, Fragment, Compute };
const char* stage_name(Stage s);  // "vertex", "fragment", ...

// The GLSL text of a [... shader] section.
struct ShaderSection {
    Stage stage;
    int first_line;    // the file's line of the text's first line (the one after the header)
    std::string text;  // with its line breaks
};

struct ShaderTest {
    std::string file;  // as messages name it
    std::vector<Line> require;
    std::vector<ShaderSection> shaders;  // in file order; a stage may have several
    bool vertex_passthrough = false;     // [vertex shader passthrough]
    bool has_vertex_data = false;
    std::vector<Line> vertex_data;
    bool has_test = false;
    std::vector<Line> test;
    // Sections quadshade does not run, as "[name]" with their line: assembly programs, SPIR-V,
    // shader includes, geometry layouts. Those a GLSL run ignores are not listed (SPIR-V
    // specializations; a SPIR-V shader beside its GLSL).
    std::vector<Line> unsupported;
};

// Throws ShaderTestError for an unknown section or a file without [require], as piglit fails it.
ShaderTest parse_shader_test(const std::string& file, const std::string& text);
// The file's text parsed; throws ShaderTestError for a file that cannot be read, holds a NUL byte
// or is larger than kMaxShaderTestBytes.
inline constexpr std::size_t kMaxShaderTestBytes = 4u << 20;
ShaderTest read_shader_test(const std::filesystem::path& path);

}  // namespace qs::piglit
