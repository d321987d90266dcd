// shader_test scripts of the project's own run through the runner: each command's meaning as
// piglit's shader_runner gives it (coordinates, probes and tolerances, uniforms of every type,
// vertex data, GL's fixed-function state) and each result word with its reason.

#include <catch2/catch.hpp>

#include <fstream>

#include "piglit/run_test.h"
#include "tests/test_paths.h"

namespace {

using namespace qs;
using namespace qs::piglit;

TestResult run(const std::string& name, const std::string& text, RunOptions options = {}) {
    static const std::filesystem::path dir = test::temp_dir("shader-test");
    const std::filesystem::path file = dir / (name + ".shader_test");
    std::ofstream(file) << text;
    return run_shader_test(file, options);
}

std::string describe(const TestResult& r) {
    std::string s = std::string(status_word(r.status)) + " (" + r.reason + ") " + r.message;
    for (const ProbeMismatch& p : r.probes) {
        s += "\nline " + std::to_string(p.line) + " at " + std::to_string(p.x) + "," + std::to_string(p.y) + " observed " +
             std::to_string(p.observed[0]) + " " + std::to_string(p.observed[1]) + " " + std::to_string(p.observed[2]) +
             " " + std::to_string(p.observed[3]);
    }
    return s;
}

}  // namespace

TEST_CASE("uniforms of every numeric type reach the shader, by GL's names", "[piglit]") {
    const TestResult r = run("uniforms", R"([require]
GLSL >= 1.30

[vertex shader]
in vec4 piglit_vertex;
void main() { gl_Position = piglit_vertex; }

[fragment shader]
uniform float f;
uniform int i;
uniform uint u;
uniform bool b;
uniform uvec2 uv;
uniform ivec3 iv;
uniform mat2x3 m;
uniform mat4 m4;
uniform vec2 a[3];
struct S { float x; vec2 y; };
uniform S s;
void main() {
    bool ok = f == 0.25 && i == -3 && u == 4000000000u && b && uv == uvec2(1u, 0xffffffffu) && iv == ivec3(-1, 0, 16)
        && m[0] == vec3(1.0, 2.0, 3.0) && m[1] == vec3(4.0, 5.0, 6.0) && m4[3] == vec4(13.0, 14.0, 15.0, 16.0)
        && a[0] == vec2(1.0, 2.0) && a[2] == vec2(5.0, 6.0) && s.x == 0.5 && s.y == vec2(7.0, 8.0);
    gl_FragColor = ok ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0);
}

[test]
uniform float f 0.25
uniform int i -3
uniform uint u 4000000000
uniform int b 1
uniform uvec2 uv 1 -1
uniform ivec3 iv -1 0 0x10
uniform mat2x3 m 1 2 3 4 5 6
uniform mat4 m4 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16
uniform vec2 a 1 2
uniform vec2 a[2] 5 6
uniform float s.x 0.5
uniform vec2 s.y 7 8
draw rect -1 -1 2 2
probe all rgba 0.0 1.0 0.0 1.0
)");
    INFO(describe(r));
    CHECK(r.status == Status::Pass);
}

TEST_CASE("probes read the 8-bit framebuffer in window coordinates, y up, within the tolerance", "[piglit]") {
    const std::string shaders = R"([require]
GLSL >= 1.10

[vertex shader]
void main() { gl_Position = gl_Vertex; }

[fragment shader]
void main() { gl_FragColor = vec4(gl_FragCoord.x / 250.0, gl_FragCoord.y / 250.0, 0.5, 1.0); }

[test]
draw rect -1 -1 2 2
)";
    // Pixel (x, y)'s centre is (x + 0.5, y + 0.5); 0.5 is 128/255 in an RGBA8 buffer.
    TestResult r = run("coordinates", shaders + R"(probe rgba 0 249 0.002 0.998 0.502 1.0
relative probe rgb (0.5, 0.0) (0.502, 0.002, 0.502)
probe rect rgba (100, 0, 1, 1) (0.4, 0.0, 0.5, 1.0)
tolerance 0.0001 0.0001 0.0001 0.0001
probe rgba 0 0 0.00392 0.00392 0.50196 1.0
)");
    INFO(describe(r));
    CHECK(r.status == Status::Pass);
    r = run("coordinates-off", shaders + "probe rgba 10 20 0.0 0.0 0.5 1.0\n");
    REQUIRE(r.status == Status::Fail);
    REQUIRE(r.probes.size() == 1);
    CHECK(r.probes[0].x == 10);
    CHECK(r.probes[0].y == 20);
    CHECK(r.probes[0].line == 12);
    CHECK(r.probes[0].observed[0] == Approx(10.5 / 250).margin(0.5 / 255));
    CHECK(r.probes[0].observed[1] == Approx(20.5 / 250).margin(0.5 / 255));
}

TEST_CASE("draws land where shader_runner puts them, later ones over earlier ones without a depth test", "[piglit]") {
    const TestResult r = run("rects", R"([require]
GLSL >= 1.10
SIZE 64 32

[vertex shader passthrough]

[fragment shader]
uniform vec4 color;
void main() { gl_FragColor = color; }

[test]
clear color 0.0 0.0 1.0 1.0
clear
uniform vec4 color 1 0 0 1
draw rect ortho 0 0 32 32
uniform vec4 color 0 1 0 1
draw rect ortho 16 8 32 16
probe rect rgba (0, 0, 16, 32) (1, 0, 0, 1)
probe rect rgba (16, 8, 32, 16) (0, 1, 0, 1)
probe rect rgba (48, 0, 16, 32) (0, 0, 1, 1)
probe rgba 20 4 1 0 0 1
relative probe rect rgb (0.75, 0.0, 0.25, 1.0) (0, 0, 1)
)");
    INFO(describe(r));
    CHECK(r.status == Status::Pass);
}

TEST_CASE("vertex data feeds attributes by name, with gl_VertexID and integer attributes", "[piglit]") {
    const TestResult r = run("vertex-data", R"([require]
GLSL >= 1.30

[vertex shader]
in vec2 vertex;
in vec3 color;
in ivec2 count;
flat out int id;
out vec3 c;
flat out int n;
void main() { gl_Position = vec4(vertex, 0.0, 1.0); c = color; id = gl_VertexID; n = count.x + count.y; }

[fragment shader]
in vec3 c;
flat in int id;
flat in int n;
void main() { gl_FragColor = vec4(c, float(id + n) / 8.0); }

[vertex data]
vertex/float/2  color/float/3  count/int/ivec2
-1 -1  1 0 0  1 1
 1 -1  1 0 0  1 1
-1  1  1 0 0  1 1
 1  1  0 1 0  2 3

[test]
draw arrays GL_TRIANGLE_STRIP 0 4
# The second triangle's provoking vertex is the last: gl_VertexID 3, n 5.
probe rgba 249 249 0.0 1.0 0.0 1.0
probe rgba 1 1 1.0 0.0 0.0 0.5
)");
    INFO(describe(r));
    CHECK(r.status == Status::Pass);
}

TEST_CASE("a uniform's initializer is its value until the script sets it, in both stages", "[piglit]") {
    // As Mesa links them: a uniform with an initializer is active unused, and one program-wide.
    const TestResult r = run("uniform-initializers", R"([require]
GLSL >= 1.20

[vertex shader]
uniform float from_vertex = 0.5;
void main() { gl_Position = gl_Vertex; }

[fragment shader]
uniform float unused = 4.0;
uniform float from_vertex;
uniform vec2 kept = vec2(0.25, 0.75);
uniform float set = 1.0;
void main() { gl_FragColor = vec4(from_vertex, kept, set); }

[test]
uniform float unused 3.0
uniform float set 0.0
draw rect -1 -1 2 2
probe all rgba 0.5 0.25 0.75 0.0
)");
    INFO(describe(r));
    CHECK(r.status == Status::Pass);
    const TestResult differ = run("uniform-initializers-differ", R"([require]
GLSL >= 1.20

[vertex shader]
uniform float u = 0.5;
void main() { gl_Position = gl_Vertex * u; }

[fragment shader]
uniform float u = 0.25;
void main() { gl_FragColor = vec4(u); }

[test]
draw rect -1 -1 2 2
)");
    CHECK(differ.status == Status::Fail);
    CHECK(differ.message.find("uniform 'u' has another initializer in the other stage") != std::string::npos);
}

TEST_CASE("ortho, frustum and the current colour drive GL's fixed-function inputs", "[piglit]") {
    const TestResult r = run("fixed-function", R"([require]
GLSL >= 1.10

[vertex shader]
uniform float z;
void main() { gl_Position = gl_ModelViewProjectionMatrix * vec4(gl_Vertex.xy, z, 1.0); gl_FrontColor = gl_Color; }

[fragment shader]
void main() { gl_FragColor = gl_Color; }

[test]
ortho
color 0.0 1.0 0.0 1.0
draw rect 10 10 20 20
# At z = -2 in front of this frustum, x and y in [-1, 0] are halved: window 62.5 to 125, pixels 62
# (its centre on the left edge, which GL's fill rule draws) to 124.
frustum -1 1 -1 1 1 10
uniform float z -2
color 1.0 0.0 1.0 1.0
draw rect -1 -1 1 1
probe rect rgba (10, 10, 20, 20) (0, 1, 0, 1)
probe rgba 9 9 0 0 0 0
probe rgba 125 125 0 0 0 0
probe rgba 124 124 1 0 1 1
probe rgba 62 70 1 0 1 1
probe rgba 61 70 0 0 0 0
)");
    INFO(describe(r));
    CHECK(r.status == Status::Pass);
}

TEST_CASE("two-sided colour, the shade model and gl_FrontFacing follow the primitive's winding", "[piglit]") {
    const TestResult r = run("two-sided", R"([require]
GLSL >= 1.10

[vertex shader]
attribute vec4 piglit_vertex;
void main() {
    gl_Position = piglit_vertex;
    gl_FrontColor = vec4(0.0, piglit_vertex.x < 0.5 ? 1.0 : 0.0, 0.0, 1.0);
    gl_BackColor = vec4(1.0, 0.0, 0.0, 1.0);
}

[fragment shader]
void main() { gl_FragColor = gl_Color + (gl_FrontFacing ? vec4(0.0, 0.0, 0.0, 0.0) : vec4(0.0, 0.0, 1.0, 0.0)); }

[test]
enable GL_VERTEX_PROGRAM_TWO_SIDE
draw rect -1 -1 1 1
# Clockwise in the window: a back face.
draw rect 1 -1 -1 1
disable GL_VERTEX_PROGRAM_TWO_SIDE
shade model flat
draw rect -1 0 2 1
probe rgba 60 60 0 1 0 1
probe rgba 190 60 1 0 1 1
# Flat: the provoking (last) vertex's colour: x = -1 for the first triangle, 1 for the second.
probe rgba 10 190 0 1 0 1
probe rgba 240 240 0 0 0 1
)");
    INFO(describe(r));
    CHECK(r.status == Status::Pass);
}

TEST_CASE("a colour the vertex stage does not write: the back one is the front one, the front one zero", "[piglit]") {
    // What llvmpipe draws (GL leaves them undefined): piglit's shader_runner passes both scripts.
    // The left triangle faces the viewer, the right one (clockwise) faces away.
    const std::string triangles = R"(
[vertex data]
vertex/float/2
-1.0 -1.0
 0.0 -1.0
-1.0  1.0
 1.0 -1.0
 0.0 -1.0
 1.0  1.0
)";
    const TestResult front_only = run("front-color-only", R"([require]
GLSL >= 1.10

[vertex shader]
attribute vec4 vertex;
void main() {
    gl_Position = vertex;
    gl_FrontColor = vec4(0.25, 0.5, 0.75, 1.0);
}

[fragment shader]
void main() { gl_FragColor = gl_Color; }
)" + triangles + R"(
[test]
enable GL_VERTEX_PROGRAM_TWO_SIDE
draw arrays GL_TRIANGLES 0 6
probe rgba 10 125 0.25 0.5 0.75 1.0
probe rgba 240 125 0.25 0.5 0.75 1.0
)");
    INFO(describe(front_only));
    CHECK(front_only.status == Status::Pass);
    const TestResult back_only = run("back-secondary-color-only", R"([require]
GLSL >= 1.10

[vertex shader]
attribute vec4 vertex;
void main() {
    gl_Position = vertex;
    gl_BackSecondaryColor = vec4(0.25, 0.5, 0.75, 1.0);
}

[fragment shader]
void main() { gl_FragColor = gl_SecondaryColor; }
)" + triangles + R"(
[test]
enable GL_VERTEX_PROGRAM_TWO_SIDE
draw arrays GL_TRIANGLES 0 6
probe rgba 10 125 0.0 0.0 0.0 0.0
probe rgba 240 125 0.25 0.5 0.75 1.0
disable GL_VERTEX_PROGRAM_TWO_SIDE
draw arrays GL_TRIANGLES 0 6
probe rgba 240 125 0.0 0.0 0.0 0.0
)");
    INFO(describe(back_only));
    CHECK(back_only.status == Status::Pass);
}

TEST_CASE("gl_Color redeclared smooth stays smooth under the flat shade model", "[piglit]") {
    const TestResult r = run("smooth-color", R"([require]
GLSL >= 1.30

[vertex shader]
in vec4 piglit_vertex;
smooth out vec4 gl_FrontColor;
void main() {
    gl_Position = piglit_vertex;
    gl_FrontColor = vec4(0.0, piglit_vertex.x < 0.5 ? 1.0 : 0.0, 0.0, 1.0);
}

[fragment shader]
smooth in vec4 gl_Color;
void main() { gl_FragColor = gl_Color; }

[test]
shade model flat
draw rect -1 -1 2 2
# Halfway between the left edge's green and the right edge's none, in either triangle.
probe rgba 124 30 0 0.5 0 1
probe rgba 124 220 0 0.5 0 1
)");
    INFO(describe(r));
    CHECK(r.status == Status::Pass);
}

TEST_CASE("draw arrays GL_TRIANGLES draws every triangle of the vertex data", "[piglit]") {
    const TestResult r = run("triangles", R"([require]
GLSL >= 1.10

[vertex shader]
attribute vec4 vertex;
attribute vec4 color;
void main() { gl_Position = vertex; gl_FrontColor = color; }

[fragment shader]
void main() { gl_FragColor = gl_Color; }

[vertex data]
vertex/float/2  color/float/3
-1 -1  1 0 0
 1 -1  1 0 0
-1  1  1 0 0
 1 -1  0 0 1
 1  1  0 0 1
-1  1  0 0 1

[test]
draw arrays GL_TRIANGLES 0 6
probe rgba 10 10 1 0 0 1
probe rgba 240 240 0 0 1 1
)");
    INFO(describe(r));
    CHECK(r.status == Status::Pass);
}

TEST_CASE("user clip planes clip at gl_ClipVertex and gl_ClipDistance", "[piglit]") {
    const TestResult r = run("clip-planes", R"([require]
GLSL >= 1.30

[vertex shader]
in vec4 piglit_vertex;
out float gl_ClipDistance[2];
void main() {
    gl_Position = piglit_vertex;
    gl_ClipDistance[0] = piglit_vertex.x;  // x >= 0 kept
    gl_ClipDistance[1] = piglit_vertex.y;  // y >= 0 kept while plane 1 is on
}

[fragment shader]
void main() { gl_FragColor = vec4(1.0); }

[test]
enable GL_CLIP_PLANE0
draw rect -1 -1 2 1
enable GL_CLIP_PLANE1
disable GL_CLIP_PLANE0
draw rect -1 0 2 1
probe rect rgba (0, 0, 125, 125) (0, 0, 0, 0)
probe rect rgba (125, 0, 125, 125) (1, 1, 1, 1)
probe rect rgba (0, 125, 250, 125) (1, 1, 1, 1)
)");
    INFO(describe(r));
    CHECK(r.status == Status::Pass);
    const TestResult v = run("clip-vertex", R"([require]
GLSL >= 1.10

[vertex shader]
void main() { gl_Position = gl_Vertex; gl_ClipVertex = gl_Vertex; }

[fragment shader]
void main() { gl_FragColor = vec4(1.0); }

[test]
clip plane 0 -1 0 0 0.5
enable GL_CLIP_PLANE0
draw rect -1 -1 2 2
probe rect rgba (0, 0, 187, 250) (1, 1, 1, 1)
probe rect rgba (188, 0, 62, 250) (0, 0, 0, 0)
)");
    INFO(describe(v));
    CHECK(v.status == Status::Pass);
}

TEST_CASE("noperspective varyings are linear in the window, smooth ones perspective-correct", "[piglit]") {
    const TestResult r = run("noperspective", R"([require]
GLSL >= 1.30

[vertex shader]
in vec4 piglit_vertex;
noperspective out float linear;
out float perspective;
void main() {
    // The right edge four times as far: w 1 on the left, 4 on the right.
    float w = piglit_vertex.x < 0.0 ? 1.0 : 4.0;
    gl_Position = vec4(piglit_vertex.xy * w, 0.0, w);
    linear = piglit_vertex.x * 0.5 + 0.5;
    perspective = linear;
}

[fragment shader]
noperspective in float linear;
in float perspective;
void main() { gl_FragColor = vec4(linear, perspective, 0.0, 1.0); }

[test]
draw rect -1 -1 2 2
# Half way across the window: 0.5 linearly; 1/(1 + 4) = 0.2 perspective-correctly.
probe rgba 125 125 0.5 0.2 0.0 1.0
)");
    INFO(describe(r));
    CHECK(r.status == Status::Pass);
}

TEST_CASE("what quadshade does not run is a named skip, decided before anything is drawn", "[piglit]") {
    const std::string vertex = "[vertex shader passthrough]\n\n";
    const std::string fragment = "[fragment shader]\nvoid main() { gl_FragColor = vec4(1.0); }\n\n";
    TestResult r = run("skip-extension", "[require]\nGLSL >= 1.10\nGL_ARB_bindless_texture\n\n" + vertex + fragment + "[test]\n");
    CHECK(r.status == Status::Skip);
    CHECK(r.reason == "requires GL_ARB_bindless_texture");
    r = run("skip-command", "[require]\nGLSL >= 1.10\n\n" + vertex + fragment +
                                "[test]\ndraw rect -1 -1 2 2\nprobe all rgba 1 0 0 1\ntexture shadow2D 0 (8, 8)\n");
    CHECK(r.status == Status::Skip);  // not the failing probe: nothing ran
    CHECK(r.reason == "command 'texture shadow'");
    r = run("skip-stage", "[require]\nGLSL >= 1.50\n\n" + vertex + "[geometry shader]\nvoid main() {}\n\n" + fragment + "[test]\n");
    CHECK(r.status == Status::Skip);
    CHECK(r.reason == "geometry shader");
    r = run("skip-glsl", "[require]\nGLSL >= 1.30\n\n" + vertex +
                             "[fragment shader]\nuniform sampler1D s;\nvoid main() { gl_FragColor = texture(s, 1.0); }\n\n[test]\n");
    CHECK(r.status == Status::Skip);
    CHECK(r.reason.rfind("GLSL: sampler type 'sampler1D'", 0) == 0);
}

TEST_CASE("compile and link errors fail, or pass where the script expects them", "[piglit]") {
    const std::string head = "[require]\nGLSL >= 1.10\n\n[vertex shader]\nvoid main() { gl_Position = gl_Vertex; }\n\n";
    TestResult r = run("compile-error", head + "[fragment shader]\nvoid main() { gl_FragColor = vec4(1.0) }\n\n[test]\n");
    CHECK(r.status == Status::Fail);
    CHECK(r.message.find("compile-error.shader_test:8") != std::string::npos);  // the file's line
    const std::string unlinked = head + "[fragment shader]\nvarying vec4 v;\nvoid main() { gl_FragColor = v; }\n\n[test]\n";
    r = run("link-error", unlinked + "link error\n");
    CHECK(r.status == Status::Pass);
    r = run("link-error-unexpected", unlinked + "draw rect -1 -1 2 2\n");
    CHECK(r.status == Status::Fail);
    r = run("unknown-command", head + "[fragment shader]\nvoid main() { gl_FragColor = vec4(1.0); }\n\n[test]\nflorp 1 2\n");
    CHECK(r.status == Status::Fail);
    CHECK(r.message.find("unknown command") != std::string::npos);
}

TEST_CASE("derivatives follow the rule asked for; a probe warn warns instead of failing", "[piglit]") {
    // dFdx of 16 x y at row y is 16 (y + 0.5) by the fine rule; a coarse rule gives both rows of a
    // quad the same one.
    const std::string script = R"([require]
GLSL >= 1.10

[vertex shader passthrough]

[fragment shader]
void main() {
    float x = 16.0 * gl_FragCoord.x * gl_FragCoord.y;
    gl_FragColor = vec4(dFdx(x) / 255.0, 0.0, 0.0, 1.0);
}

[test]
draw rect -1 -1 2 2
probe warn all rgba 0 0 0 1
probe rgba 10 10 0.6588 0.0 0.0 1.0
probe rgba 10 11 0.7216 0.0 0.0 1.0
)";
    const TestResult fine = run("derivatives-fine", script);
    CHECK(fine.status == Status::Warn);
    const TestResult coarse = run("derivatives-coarse", script, {Derivatives::CoarseLower, Backend::Rasterizer});
    CHECK(coarse.status == Status::Fail);  // the last line that did not pass decides
}

TEST_CASE("GL_ARB_derivative_control's functions below GLSL 4.00: fine under every rule, coarse by the rule", "[piglit]") {
    // llvmpipe's coarse derivatives are its fine ones, as under the default rule here.
    const auto script = [](const char* coarse_at_row_11) {
        return std::string(R"([require]
GLSL >= 1.50
GL_ARB_derivative_control

[vertex shader passthrough]

[fragment shader]
#extension GL_ARB_derivative_control: require
void main() {
    float x = 16.0 * gl_FragCoord.x * gl_FragCoord.y;
    gl_FragColor = vec4(dFdxFine(x) / 255.0, dFdxCoarse(x) / 255.0, 0.0, 1.0);
}

[test]
draw rect -1 -1 2 2
probe rgba 10 10 0.6588 0.6588 0.0 1.0
probe rgba 10 11 0.7216 )") + coarse_at_row_11 + " 0.0 1.0\n";
    };
    const TestResult fine = run("derivative-control", script("0.7216"));
    INFO(describe(fine));
    CHECK(fine.status == Status::Pass);
    const TestResult coarse = run("derivative-control-coarse", script("0.6588"), {Derivatives::CoarseLower, Backend::Rasterizer});
    INFO(describe(coarse));
    CHECK(coarse.status == Status::Pass);
}

TEST_CASE("an out argument's run-time index is the one the call finds, converted or not", "[piglit]") {
    // What llvmpipe draws: the function assigns the variable the index was read from.
    const TestResult r = run("out-argument-index", R"([require]
GLSL >= 1.20

[vertex shader passthrough]

[fragment shader]
uniform int u = 1;
void reset(inout int i, inout float f) { i = 0; f = 0.25; }
void reset_int(inout int i, out int x) { i = 0; x = 2; }
void main() {
    vec4 v = vec4(0.0);
    int i = u;
    reset(i, v[i]);        // v[1]: the index as the call finds it
    i = u + 1;
    reset_int(i, v[i]);    // v[2], converted from int on the way out
    int j = u + 2;
    // The shader's own comma, as glslang's for a conversion but for where its parts stand: v[0],
    // j being 0 by then.
    int tempArg;
    reset_int(j, tempArg), v[j] = float(tempArg);
    gl_FragColor = v * vec4(0.375, 1.0, 0.25, 1.0);
}

[test]
draw rect -1 -1 2 2
probe all rgba 0.75 0.25 0.5 0.0
)");
    INFO(describe(r));
    CHECK(r.status == Status::Pass);
}
