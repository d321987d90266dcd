// The exported GLSL of a stage: the #version line a file keeps (a user's GLSL as it is written
// for any GL program), or the one ShaderInfo gives; the file's line numbers kept for the
// compiler's messages; and the refusals that name the file and line.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>

#include "shading/glsl_export.h"

namespace qs {

TEST_CASE("a stage's first file keeps its own #version line, first, its other lines where they were", "[glsl]") {
    const std::string frag = "// a comment first\n/* and a block\n   of two lines */\n#version 130\nin vec2 uv;\nvoid main() {}\n";
    const std::string out = stage_source({{"a.frag", frag}}, 0, "#define X 1\n");
    CHECK(out == "#version 130\n#define X 1\n#line 1\n// a comment first\n/* and a block\n   of two lines */\n\nin vec2 uv;\n"
                 "void main() {}\n");
    // Profiles and spacing are the file's.
    CHECK(stage_source({{"b.vert", "#  version 330 compatibility\nvoid main() {}\n"}}, 330, "").starts_with(
        "#  version 330 compatibility\n#line 1\n\nvoid main() {}"));
}

TEST_CASE("without a #version line, ShaderInfo's (120 when unset, the compatibility profile from 150)", "[glsl]") {
    CHECK(stage_source({{"a.glsl", "float f();\n"}, {"a.frag", "void main() {}\n"}}, 0, "") ==
          "#version 120\n#line 1\nfloat f();\n#line 1\nvoid main() {}\n");
    CHECK(stage_source({{"a.frag", "void main() {}\n"}}, 150, "#define Y\n") ==
          "#version 150 compatibility\n#define Y\n#line 1\nvoid main() {}\n");
    // A #version that is not the first thing is the compiler's to refuse, as any GL program's.
    CHECK(stage_source({{"a.frag", "float x;\n#version 130\n"}}, 0, "").starts_with("#version 120\n"));
}

TEST_CASE("a #version in a stage's later file, or one that contradicts ShaderInfo, is refused naming file and line", "[glsl]") {
    CHECK_THROWS_WITH(stage_source({{"noise.glsl", "float f();\n"}, {"main.frag", "\n#version 130\nvoid main() {}\n"}}, 0, ""),
                      Catch::Contains("main.frag:2: #version in a stage's second or later file"));
    CHECK_THROWS_WITH(stage_source({{"main.frag", "#version 130\nvoid main() {}\n"}}, 330, ""),
                      Catch::Contains("main.frag:1: #version 130, but the shader's ShaderInfo::glsl_version is 330"));
}

}  // namespace qs
