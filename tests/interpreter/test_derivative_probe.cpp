// A derivative probe (frontend/compile_options.h): an expression a user names, evaluated where a
// fragment shader's main ends and drawn as (dFdx(e), dFdy(e), e, 1). What it sees (main's
// outermost variables, the lanes main returned early), what it draws (every rule's derivative,
// the analytic one), and what it refuses: anything but one float expression, in glslang's words
// and naming the option.

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "frontend/compile.h"
#include "interpreter/glsl_program.h"
#include "render/scene_render.h"
#include "shading/catalogue.h"
#include "tests/test_paths.h"

namespace {

using namespace qs;

// main keeps a local, sets some lanes aside with an early return, and discards others.
const char* const kShader = R"(#version 130
in vec2 st;
out vec4 colour;
void main() {
    float k = 4.0 * gl_FragCoord.x;
    vec2 twice = 2.0 * gl_FragCoord.xy;
    if (gl_FragCoord.y < 8.0) discard;
    if (gl_FragCoord.x < 16.0) {
        colour = vec4(1.0);
        return;
    }
    {
        float inner = 1.0;
        colour = vec4(st, k, inner);
    }
}
)";

frontend::CompiledProgram probed(const std::string& expression, int component = 0, const char* shader = kShader) {
    frontend::CompileOptions options;
    options.derivative_probe = frontend::DerivativeProbe{expression, component, "--derivatives-of"};
    return frontend::compile_glsl({"probe.frag", shader}, std::nullopt, options);
}

// The message compiling the probe throws, or "" when it compiles.
std::string refusal(const std::string& expression) {
    try {
        (void)probed(expression);
    } catch (const frontend::GlslError& e) {
        return e.what();
    }
    return "";
}

// The probe drawn on the Table 1.1 plane at 32x24 under `rule`.
Framebuffer draw(const std::string& expression, int component, Derivatives rule) {
    const std::string name = "probe " + expression + " " + std::to_string(component);
    if (!find_program(name)) {
        add_compiled_program(std::make_unique<interpreter::GlslProgram>(name, probed(expression, component)), "tests",
                             "", kShader);
    }
    Scene scene = load_scene(test::kPlane);
    scene.clear_color = glm::vec4(0.0f);
    FrameRequest r;
    r.width = 32, r.height = 24;
    r.shader_override = name;
    r.shading.derivatives = rule;
    return render_frame(scene, r);
}

// Every drawn pixel's colour is (dx, dy, the value at the pixel's centre, 1); the pixels that
// draw nothing are those main discards (window y < 8, framebuffer rows from the top).
void check_map(const Framebuffer& fb, float dx, float dy, float (*value)(float x, float y)) {
    int drawn = 0;
    for (int y = 0; y < fb.height; ++y) {
        for (int x = 0; x < fb.width; ++x) {
            const float* p = &fb.rgba[(std::size_t(y) * std::size_t(fb.width) + std::size_t(x)) * 4];
            const float wx = float(x) + 0.5f, wy = float(fb.height - 1 - y) + 0.5f;
            INFO("pixel " << x << ", " << y);
            if (wy < 8.0f) {
                CHECK(p[3] == 0.0f);
                continue;
            }
            CHECK(p[0] == dx);
            CHECK(p[1] == dy);
            CHECK(p[2] == value(wx, wy));
            CHECK(p[3] == 1.0f);
            ++drawn;
        }
    }
    CHECK(drawn == fb.width * (fb.height - 8));
}

}  // namespace

TEST_CASE("a probe sees main's outermost variables where main ends, the lanes it returned included",
          "[interpreter][probe]") {
    CHECK(probed("k").probe_components == 1);
    CHECK(probed("twice").probe_components == 2);
    CHECK(probed("st * 8.0").probe_components == 2);
    for (const Derivatives rule : {Derivatives::Fine, Derivatives::CoarseLower, Derivatives::Analytic}) {
        INFO("rule " << int(rule));
        // k = 4 x: the lanes that returned early (x < 16) are drawn, those discarded are not.
        check_map(draw("k", 0, rule), 4.0f, 0.0f, [](float x, float) { return 4.0f * x; });
        check_map(draw("twice", 1, rule), 0.0f, 2.0f, [](float, float y) { return 2.0f * y; });
        check_map(draw("k * 0.5 + gl_FragCoord.y", 0, rule), 2.0f, 1.0f,
                  [](float x, float y) { return 2.0f * x + y; });
    }
}

TEST_CASE("a probe is one float expression: anything else is refused naming the option, in glslang's words",
          "[interpreter][probe]") {
    struct Case {
        const char* expression;
        const char* words;
    };
    const Case cases[] = {
        // Statements, blocks, directives and comments cannot get in.
        {"k; colour = vec4(1.0)", "';' at offset 1"},
        {"k) ; } void f() { (k", "')' at offset 1 closes nothing"},
        {"(k) ; } void f() { (k)", "';' at offset 4"},
        {"k) + (k", "')' at offset 1 closes nothing"},  // its parentheses close where they open
        {"(k) + (k, twice.x)", ""},                      // and then it is an expression
        {"k)", "')' at offset 1 closes nothing"},
        {"(k", "'(' is not closed"},
        {"k /* colour */", "a comment"},
        {"k // colour", "a comment"},
        {"k\n#define X", "not printable"},
        {"k \\", "'\\'"},
        {"  ", "an empty expression"},
        // glslang's own messages, placed in the expression
        {"kk", "'kk': undeclared identifier"},
        {"inner", "'inner': undeclared identifier"},  // declared in a block of main's: out of reach
        {"k +", "syntax error"},
        {"1 + 2", "the expression is int"},
        {"mat2(k)", "dFdx and dFdy take a float or a float vector"},
    };
    for (const Case& c : cases) {
        const std::string message = refusal(c.expression);
        INFO(c.expression << "\n-> " << message);
        if (std::string(c.words).empty()) {
            CHECK(message.empty());
            continue;
        }
        CHECK(message.rfind("--derivatives-of", 0) == 0);
        CHECK(message.find(c.words) != std::string::npos);
    }
    // glslang's message is placed in the expression, not at a line of the shader.
    CHECK(refusal("kk").rfind("--derivatives-of \"kk\": ", 0) == 0);
    CHECK_THROWS_WITH(probed("twice", 2), Catch::Contains("no component 2"));
}
