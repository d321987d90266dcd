#pragma once
// A shader_test's [require] section against what quadshade is as a GL implementation: the GL and
// GLSL versions it answers, its extensions and limits. Each line is met, not met (the test is
// skipped, with the requirement as the reason) or malformed (the test fails), as piglit's
// shader_runner decides.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "piglit/shader_test.h"

namespace qs::piglit {

// What quadshade answers to GL's queries: versions (GL 4.5 as 45, GLSL 4.50 as 450), the
// extensions whose shading features the front end runs, and the limits its renderer has.
struct Implementation {
    int gl_version = 45;
    int glsl_version = 450;
    std::vector<std::string> extensions;
    std::vector<std::pair<std::string, int>> limits;  // GL_MAX_... and their values
    // quadshade's own answers.
    static const Implementation& quadshade();
    bool has_extension(const std::string& name) const;
    std::optional<int> limit(const std::string& name) const;
};

struct Requirements {
    int glsl_version = 0;              // GLSL >= x.yz as xyz (0: no such line: GLSL cannot be compiled)
    bool glsl_es = false;              // GLSL ES
    std::optional<int> gl_version;     // GL >= x.y as xy
    bool gl_es = false, gl_core = false;
    int width = 250, height = 250;     // SIZE w h, else piglit's default window
    bool depth_buffer = false;         // depthbuffer
    // The first requirement not met, as the reason to skip ("GL_ARB_foo", "GLSL ES >= 3.00"), or
    // the first malformed line (FILE:LINE: message), which fails the test as in piglit: whichever
    // comes first.
    std::optional<std::string> unmet;
    std::optional<std::string> error;
};

Requirements check_requirements(const ShaderTest& test, const Implementation& implementation);

}  // namespace qs::piglit
