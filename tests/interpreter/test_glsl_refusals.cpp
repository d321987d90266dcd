// What the front end refuses, and how: the file, line and column of the construct and why for what
// the interpreter cannot run, glslang's own words for GLSL that does not compile, and a named
// bound for hostile text (a macro blow-up, nesting past the parser's depth, a file too large).

#include <catch2/catch.hpp>

#include <fstream>
#include <string>

#include "frontend/compile.h"
#include "tests/test_paths.h"

namespace {

using namespace qs;

// The message compile_glsl throws for `fragment` (file name "user.frag"), or "" when it compiles.
std::string refusal(const std::string& fragment) {
    try {
        (void)frontend::compile_glsl({"user.frag", fragment}, std::nullopt);
    } catch (const frontend::GlslError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("the front end refuses what it cannot run at the construct's line and column, and says why", "[interpreter]") {
    struct Case {
        const char* source;
        const char* position;  // "user.frag:LINE" or "user.frag:LINE:COL"
        const char* words;     // a part of the message that names the construct
    };
    const Case cases[] = {
        {"#version 400\nuniform samplerCubeArray sky;\nin vec2 st;\nout vec4 c;\nvoid main() {\n"
         "  c = texture(sky, vec4(st, 1.0, 0.0));\n}\n",
         "user.frag:6", "samplerCubeArray"},
        {"#version 110\nfloat f(float x) { return x < 1.0 ? x : f(x - 1.0); }\nvoid main() { gl_FragColor = vec4(f(2.0)); }\n",
         "user.frag:2", "recurs"},
        {"#version 130\nin vec2 st;\nout vec4 c;\nvoid main() {\n  c = vec4(gl_PointCoord, 0.0, 1.0);\n}\n",
         "user.frag:5:12", "gl_PointCoord"},
        {"#version 130\nuniform sampler1DShadow depth;\nin vec2 st;\nout vec4 c;\nvoid main() {\n"
         "  c = vec4(texture(depth, vec3(st, 0.5)));\n}\n",
         "user.frag:6", "sampler1DShadow"},
        {"#version 130\nin vec2 unknown_varying;\nout vec4 c;\nvoid main() { c = vec4(unknown_varying, 0.0, 1.0); }\n",
         "user.frag:4", "unknown_varying"},
        // glslang's own message for GLSL that does not compile
        {"#version 110\nvoid main() {\n  gl_FragColor = vec4(1.0) +;\n}\n", "user.frag:3", "error: "},
        // GL_ARB_derivative_control's functions below 4.00: only where the shader enables it, and
        // the lines of a shader that does are its own
        {"#version 150\nout vec4 c;\nvoid main() {\n  c = vec4(dFdxFine(gl_FragCoord.x));\n}\n", "user.frag:4", "dFdxFine"},
        {"#version 150\n#extension GL_ARB_derivative_control : enable\nout vec4 c;\nvoid main() {\n"
         "  c = vec4(dFdxFine(gl_FragCoord.x)) +;\n}\n", "user.frag:5", "error: "},
    };
    for (const Case& c : cases) {
        const std::string message = refusal(c.source);
        INFO(c.source << "\n-> " << message);
        CHECK(message.rfind(c.position, 0) == 0);
        CHECK(message.find(c.words) != std::string::npos);
    }
}

TEST_CASE("hostile GLSL ends with a named bound, never a hang or a crash", "[interpreter]") {
    SECTION("macros that expand to 2^40 tokens") {
        std::string bomb = "#version 110\n#define A0 1.0\n";
        for (int i = 1; i <= 40; ++i) bomb += "#define A" + std::to_string(i) + " (A" + std::to_string(i - 1) + "+A" + std::to_string(i - 1) + ")\n";
        bomb += "void main() { gl_FragColor = vec4(A40); }\n";
        const std::string message = refusal(bomb);
        INFO(message);
        CHECK(message.rfind("user.frag: error: its macros expand", 0) == 0);
    }
    SECTION("parentheses nested 100,000 deep") {
        const std::string deep = "#version 110\nvoid main() { float x = " + std::string(100000, '(') + "1.0" + std::string(100000, ')') +
                                 "; gl_FragColor = vec4(x); }\n";
        const std::string message = refusal(deep);
        INFO(message);
        CHECK(message.rfind("user.frag:2: error: ", 0) == 0);
    }
    SECTION("a file larger than a shader may be") {
        const std::filesystem::path big = test::temp_dir("glsl-hostile") / "big.frag";
        std::ofstream(big) << std::string(frontend::kMaxGlslBytes + 1, ' ');
        CHECK_THROWS_WITH(frontend::read_glsl_file(big), Catch::Contains("larger than a GLSL shader can be here"));
    }
}
