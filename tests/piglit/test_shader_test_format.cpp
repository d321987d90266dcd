// The shader_test format as piglit's shader_runner reads it: sections, requirements, vertex data,
// the [test] commands and their numbers.

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <limits>

#include "piglit/numbers.h"
#include "piglit/requirements.h"
#include "piglit/shader_test.h"
#include "piglit/skip_reason.h"
#include "piglit/test_commands.h"
#include "piglit/vertex_data.h"

namespace {

using namespace qs::piglit;

const char* const kFile = R"(# a comment before the first section
[require]
GLSL >= 1.30
GL_ARB_derivative_control

[vertex shader passthrough]

[fragment shader]
void main()
{
	gl_FragColor = vec4(1.0);
}

[vertex data]
vertex/float/2  color/float/3 # the header
-1 -1  1 0 0
 1 -1  0 1 0

[test]
clear color 0.0 0.0 0.0 0.0
clear
draw rect -1 -1 2 2
[not a section]
)";

}  // namespace

TEST_CASE("a shader_test's sections keep their text and line numbers", "[piglit]") {
    const ShaderTest t = parse_shader_test("t.shader_test", kFile);
    REQUIRE(t.require.size() == 3);
    CHECK(t.require[0].number == 3);
    CHECK(t.require[0].text == "GLSL >= 1.30");
    CHECK(t.vertex_passthrough);
    REQUIRE(t.shaders.size() == 1);
    CHECK(t.shaders[0].stage == Stage::Fragment);
    CHECK(t.shaders[0].first_line == 9);
    CHECK(t.shaders[0].text.rfind("void main()\n{\n", 0) == 0);
    CHECK(t.has_vertex_data);
    CHECK(t.vertex_data.size() == 4);
    // Everything after [test] is its script, a line that looks like a section included.
    REQUIRE(t.test.size() == 4);
    CHECK(t.test[3].text == "[not a section]");
    CHECK(t.test[0].number == 20);
}

TEST_CASE("a shader_test without [require] or with an unknown section is refused at its line", "[piglit]") {
    CHECK_THROWS_WITH(parse_shader_test("a.shader_test", "[vertex shader]\nvoid main() {}\n"),
                      Catch::Contains("a.shader_test: no [require] section"));
    CHECK_THROWS_WITH(parse_shader_test("b.shader_test", "[require]\nGLSL >= 1.10\n[vertex shadr]\n"),
                      Catch::Contains("b.shader_test:3: unknown section '[vertex shadr]'"));
    // Sections quadshade does not run are listed, SPIR-V ones a GLSL run ignores are not.
    const ShaderTest t = parse_shader_test("c.shader_test", "[require]\nGLSL >= 1.10\n[vertex program]\n!!ARBvp1.0\n"
                                                            "[fragment shader spirv]\n; SPIR-V\n");
    REQUIRE(t.unsupported.size() == 1);
    CHECK(t.unsupported[0].text == "[vertex program]");
}

TEST_CASE("requirements are met, unmet with a reason, or malformed", "[piglit]") {
    const auto check = [](const std::string& lines) {
        return check_requirements(parse_shader_test("r.shader_test", "[require]\n" + lines), Implementation::quadshade());
    };
    Requirements r = check("GLSL >= 1.20\nGL >= 2.1\nGL_ARB_derivative_control\nrlimit 1000\nSIZE 20 30\n");
    CHECK_FALSE(r.unmet);
    CHECK_FALSE(r.error);
    CHECK(r.glsl_version == 120);
    CHECK(r.width == 20);
    CHECK(r.height == 30);
    CHECK(check("GLSL >= 1.10\nGL_ARB_gpu_shader_fp64\n").unmet == "GL_ARB_gpu_shader_fp64");
    CHECK(check("GLSL >= 4.60\n").unmet == "GLSL >= 4.60");
    CHECK(check("GLSL ES >= 3.00\n").unmet == "GLSL ES >= 3.00");
    CHECK(check("GLSL >= 1.10\nGL_MAX_VARYING_COMPONENTS >= 1024\n").unmet == "GL_MAX_VARYING_COMPONENTS >= 1024");
    CHECK_FALSE(check("GLSL >= 1.10\n  GL_MAX_VERTEX_ATTRIBS >= 16\n").unmet);
    CHECK(check("GLSL >= 1.10\n!GL_ARB_derivative_control\n").unmet == "!GL_ARB_derivative_control");
    // shader_runner fails a GLSL requirement other than >=, and a version it cannot read.
    CHECK(check("GLSL == 1.10\n").error);
    CHECK(check("GLSL >= 1.1x\n").error);
    CHECK(check("GL_ARB_gpu_shader_fp64\nGLSL == 1.10\n").unmet);  // the first line decides
    CHECK(check("GL >= 3.3\n").glsl_version == 0);
}

TEST_CASE("numbers are read as piglit reads them", "[piglit]") {
    // Floats through strtod rounded to float, or their bits in hex; ints in any base, 32 bits;
    // uints through strtoul, so that -1 is 0xffffffff.
    const std::vector<float> f = parse_floats("0.1 0x3f800000 -2e3 inf", 4);
    REQUIRE(f.size() == 4);
    CHECK(f[0] == float(0.1));
    CHECK(f[1] == 1.0f);
    CHECK(f[2] == -2000.0f);
    CHECK(std::isinf(f[3]));
    const std::vector<std::int32_t> i = parse_ints("-7 0x10 010 4294967295", 4);
    CHECK(i == std::vector<std::int32_t>{-7, 16, 8, -1});
    const std::vector<std::uint32_t> u = parse_uints("-1 0xffffffff 3", 3);
    CHECK(u == std::vector<std::uint32_t>{0xffffffffu, 0xffffffffu, 3u});
    CHECK(parse_floats("1 2", 4).size() == 2);  // fewer than asked: as many as there are
}

TEST_CASE("half-precision vertex data rounds to the nearest half, ties to even", "[piglit]") {
    CHECK(round_to_half(1.0f) == 1.0f);
    CHECK(round_to_half(0.1f) == 0.0999755859375f);                      // 0x2e66
    CHECK(round_to_half(1.0f + 0x1p-11f) == 1.0f);                       // a tie: to the even 1.0
    CHECK(round_to_half(1.0f + 3 * 0x1p-11f) == 1.0f + 0x1p-9f);         // a tie: up to the even
    CHECK(round_to_half(-2049.0f) == -2048.0f);                           // the step is 2 from 2048
    CHECK(round_to_half(65504.0f) == 65504.0f);                           // the largest half
    CHECK(round_to_half(65519.0f) == 65504.0f);
    CHECK(std::isinf(round_to_half(65520.0f)));                           // the tie past it overflows
    CHECK(round_to_half(0x1p-24f) == 0x1p-24f);                           // the smallest subnormal
    CHECK(round_to_half(0x1p-26f) == 0.0f);
    CHECK(round_to_half(3 * 0x1p-25f) == 0x1p-23f);                       // subnormal tie to even
    CHECK(std::isnan(round_to_half(std::numeric_limits<float>::quiet_NaN())));
    char* end = nullptr;
    CHECK(parse_half("0.1 x", &end) == 0.0999755859375f);
    CHECK(*end == ' ');
}

TEST_CASE("vertex data columns feed generic attributes with GL's conversions and defaults", "[piglit]") {
    const std::vector<Line> lines = {{1, "vertex/float/vec2  c/ubyte/vec4  i/int/int  m/float/mat2x3/1  a[2]/float/2 # x"},
                                     {2, ""},
                                     {3, "1.5 -2  1 2 3 255  -5  7 8 9  0.25 0.5"},
                                     {4, "# a comment line"},
                                     {5, "0 0  0 0 0 0  0x7fffffff  0 0 0  0 0"}};
    const VertexData d = parse_vertex_data("v.shader_test", lines);
    REQUIRE(d.columns.size() == 5);
    REQUIRE(d.vertices == 2);
    CHECK(d.columns[0].rows == 2);
    CHECK(d.columns[1].kind == AttributeKind::Float);  // a ubyte read as vec4: converted, not normalized
    CHECK(d.columns[2].kind == AttributeKind::Int);
    CHECK(d.columns[3].columns == 2);
    CHECK(d.columns[3].rows == 3);
    CHECK(d.columns[3].matrix_column == 1);
    CHECK(d.columns[4].name == "a");
    CHECK(d.columns[4].array_index == 2);
    const auto as_float = [](std::uint32_t w) { return std::bit_cast<float>(w); };
    CHECK(as_float(d.values[0][0][0]) == 1.5f);
    CHECK(as_float(d.values[0][0][1]) == -2.0f);
    CHECK(as_float(d.values[0][0][2]) == 0.0f);  // missing components: (0, 0, 0, 1)
    CHECK(as_float(d.values[0][0][3]) == 1.0f);
    CHECK(as_float(d.values[1][0][3]) == 255.0f);
    CHECK(std::int32_t(d.values[2][0][0]) == -5);
    CHECK(d.values[2][0][3] == 1u);  // an integer attribute's default w is the integer 1
    CHECK(std::int32_t(d.values[2][1][0]) == 0x7fffffff);
    CHECK_THROWS_WITH(parse_vertex_data("v.shader_test", {{7, "vertex/float"}}), Catch::Contains("v.shader_test:7:"));
    CHECK_THROWS_WITH(parse_vertex_data("v.shader_test", {{7, "b/ubyte/vec2"}, {8, "1 300"}}),
                      Catch::Contains("v.shader_test:8: [vertex data]: cannot read a ubyte"));
}

TEST_CASE("test commands are parsed in shader_runner's order, unknown ones named", "[piglit]") {
    const std::vector<TestCommand> c = parse_test_commands({{1, "clear color 0.5 0 0 1"},
                                                            {2, "  # comment"},
                                                            {3, "clear"},
                                                            {4, "draw rect ortho 0 0 10 20"},
                                                            {5, "probe rect rgba (1, 2, 3, 4) (0.0, 1.0, 0.0, 1.0)"},
                                                            {6, "relative probe rgb (0.5, 0.25) (1 0 0)"},
                                                            {7, "relative probe rgb (0.5, 0.25) (1, 0, 0)"},
                                                            {8, "uniform mat2x3 m 1 2 3 4 5 6"},
                                                            {9, "texture shadow2D 0 (32, 32)"},
                                                            {10, "florp"},
                                                            {11, "draw arrays GL_TRIANGLE_FAN 0 4"},
                                                            {12, "probe warn all rgba 0 0 0 0"},
                                                            {13, "enable GL_FOO"}});
    REQUIRE(c.size() == 12);
    CHECK(std::get<ClearColor>(c[0].command).rgba[0] == 0.5f);
    CHECK(std::holds_alternative<Clear>(c[1].command));
    CHECK(c[1].line == 3);
    const DrawRect& r = std::get<DrawRect>(c[2].command);
    CHECK(r.ortho);
    CHECK(r.rect[3] == 20.0f);
    const Probe& p = std::get<Probe>(c[3].command);
    CHECK(p.area == Probe::Area::Rect);
    CHECK(p.at[2] == 3.0f);
    CHECK(p.expected[1] == 1.0f);
    // sscanf's pattern wants the commas: without them the line is no command shader_runner knows.
    CHECK(std::holds_alternative<Invalid>(c[4].command));
    CHECK(std::get<Probe>(c[5].command).relative);
    CHECK(std::get<SetUniform>(c[6].command).type == "mat2x3");
    CHECK(std::get<Unsupported>(c[7].command).name == "texture shadow");
    CHECK(std::holds_alternative<Invalid>(c[8].command));
    CHECK(std::get<DrawArrays>(c[9].command).mode == "GL_TRIANGLE_FAN");
    CHECK(std::get<Probe>(c[10].command).warn);
    CHECK(std::holds_alternative<Invalid>(c[11].command));
}

TEST_CASE("skip reasons name the construct, not the test's own names or positions", "[piglit]") {
    CHECK(skip_reason_of("x.shader_test:12:7: uniform 'weights' of type 'double' is not supported", "x.shader_test") ==
          "GLSL: uniform '...' of type 'double' is not supported");
    CHECK(skip_reason_of("x.shader_test:3: sampler type 'sampler2DShadow' is not supported", "x.shader_test") ==
          "GLSL: sampler type 'sampler2DShadow' is not supported");
    CHECK(skip_reason_of("x.shader_test: the shaders pass 12 varying floats; quadshade interpolates 8", "x.shader_test") ==
          "GLSL: the shaders pass N varying floats; quadshade interpolates 8");
}
