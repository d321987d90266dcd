// The integer cases GLSL leaves undefined, as the interpreter's checked run (the undefined-case
// mask) flags them: an array index outside the array, bitfieldExtract past its operand, int
// division's overflow; and the wrapping GLSL defines, which it does not flag.

#include <catch2/catch.hpp>

#include <memory>
#include <string>

#include "frontend/compile.h"
#include "interpreter/glsl_program.h"
#include "render/scene_render.h"
#include "shading/catalogue.h"
#include "tests/test_paths.h"

using namespace qs;

TEST_CASE("the checked run flags the integer cases GLSL leaves undefined, and no defined one",
          "[interpreter][undefined]") {
    // Column by column (window x / 8): an index past the array, bitfieldExtract past the
    // operand, INT_MIN / -1, and the defined ones: int + wrapping, uint wrapping, a shift by 31.
    const char* const shader = R"(#version 400
out vec4 colour;
void main() {
    int column = int(gl_FragCoord.x) / 8;
    int big = 2147483647 + 0 * column;  // INT_MAX, computed where it runs
    float table[3] = float[3](0.25, 0.5, 0.75);
    float v = 0.0;
    if (column == 0) v = table[column + 3];
    if (column == 1) v = float(bitfieldExtract(7, 30, column + 3));
    if (column == 2) v = float(-big - 1) / float((-big - 1) / (column - 3));
    if (column == 3) v = float(big + column);
    if (column == 4) v = float(uint(big) * 4u + uint(column));
    if (column == 5) v = float(1 << (column + 26));
    colour = vec4(v, 0.0, 0.0, 1.0);
}
)";
    const std::string name = "undefined integers";
    if (!find_program(name)) {
        add_compiled_program(std::make_unique<interpreter::GlslProgram>(
                                 name, frontend::compile_glsl({"integers.frag", shader}, std::nullopt)),
                             "tests", "", shader);
    }
    Scene scene = load_scene(test::kPlane);
    FrameRequest r;
    r.width = 48, r.height = 8;
    r.shader_override = name;
    r.shading.check_undefined = true;
    const Framebuffer fb = render_frame(scene, r);
    const std::uint8_t expected[6] = {std::uint8_t(Undefined::Argument), std::uint8_t(Undefined::Argument),
                                      std::uint8_t(Undefined::Overflow), 0, 0, 0};
    for (int column = 0; column < 6; ++column) {
        INFO("column " << column << ", red " << fb.rgba[std::size_t(column * 8 + 3) * 4]);
        CHECK(fb.undefined[std::size_t(column * 8 + 3)] == expected[column]);
    }
    r.shading.check_undefined = false;
    const Framebuffer unchecked = render_frame(scene, r);
    CHECK(unchecked.rgba == fb.rgba);  // checking changes no colour
}
