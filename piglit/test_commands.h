#pragma once
// The [test] script of a shader_test: one command per line, parsed as piglit's shader_runner
// reads it (piglit_display in tests/shaders/shader_runner.c). Commands quadshade runs have their
// own kind; piglit's other commands are Unsupported, named, so that the test is skipped with
// that reason before anything runs; a line piglit does not know either is Invalid, which fails
// the test as in piglit.

#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "piglit/shader_test.h"

namespace qs::piglit {

struct ClearColor {
    std::array<float, 4> rgba;
};
struct ClearDepth {
    float depth;
};
struct Clear {};

// draw rect [ortho] [tex] x y w h [tx ty tw th]: a rectangle as a triangle strip of four
// vertices, in clip coordinates or (ortho) in window pixels.
struct DrawRect {
    bool ortho = false;
    std::array<float, 4> rect{};      // x, y, w, h
    std::optional<std::array<float, 4>> tex;  // s, t, ds, dt: gl_MultiTexCoord0 / piglit_texcoord
};
// draw arrays MODE FIRST COUNT: [vertex data] rows first..first+count-1.
struct DrawArrays {
    std::string mode;  // GL_TRIANGLES, ...
    int first = 0, count = 0;
};

// probe [all] rgb[a] / probe rect / relative probe ...: the framebuffer read back as 8-bit
// values and compared with `expected` within the tolerance.
struct Probe {
    enum class Area { Pixel, Rect, All } area = Area::Pixel;
    bool relative = false;            // x, y, w, h are fractions of the framebuffer
    bool warn = false;                // probe warn all: a mismatch warns instead of failing
    int components = 4;               // rgb: 3
    std::array<float, 4> at{};        // x, y (and w, h)
    std::array<float, 4> expected{};
};
struct Tolerance {
    std::array<float, 4> values;
};
// uniform TYPE NAME VALUES...: the values are read as TYPE says when the uniform is set.
struct SetUniform {
    std::string type, name, values;
};
struct Ortho {
    std::optional<std::array<float, 4>> box;  // left right bottom top; none: the window in pixels
};
struct Frustum {
    std::array<float, 6> planes;  // left right bottom top near far
};
struct CurrentColor {
    std::array<float, 4> rgba;  // color: glColor4f
};
struct CurrentTexcoord {
    int unit = 0;
    std::array<float, 4> stpq;  // texcoord N (s, t, r, q): glMultiTexCoord4f
};
struct ShadeModel {
    bool flat = false;
};
struct Enable {
    std::string what;  // GL_VERTEX_PROGRAM_TWO_SIDE, GL_CLIP_PLANE0, ...
    bool on = true;
};
struct ClipPlane {
    int index = 0;
    std::array<double, 4> plane;
};
// texture rgbw UNIT (W, H) [FORMAT]: piglit's red, green, blue, white quadrants.
struct TextureRgbw {
    int unit = 0, width = 0, height = 0;
    std::string format;  // empty: GL_RGBA
};
// texture checkerboard UNIT LEVEL (W, H) (COLOR0) (COLOR1)
struct TextureCheckerboard {
    int unit = 0, level = 0, width = 0, height = 0;
    std::array<float, 4> color0, color1;
};
// texture miptree UNIT: an 8x8 texture with mipmaps, a colour per level.
struct TextureMiptree {
    int unit = 0;
};
// texparameter TARGET PARAMETER VALUE
struct TexParameter {
    std::string target, parameter, value;
};
struct LinkError {};
struct LinkSuccess {};
// A command that changes nothing quadshade draws (hint).
struct NoEffect {};
// One of piglit's commands that quadshade does not run; `name` says which ("draw instanced rect").
struct Unsupported {
    std::string name;
};
// A line piglit's shader_runner does not understand: it fails the test.
struct Invalid {
    std::string message;
};

using Command = std::variant<ClearColor, ClearDepth, Clear, DrawRect, DrawArrays, Probe, Tolerance, SetUniform, Ortho,
                             Frustum, CurrentColor, CurrentTexcoord, ShadeModel, Enable, ClipPlane, TextureRgbw,
                             TextureCheckerboard, TextureMiptree, TexParameter, LinkError, LinkSuccess, NoEffect,
                             Unsupported, Invalid>;

struct TestCommand {
    int line;
    std::string text;
    Command command;
};

// Each non-blank line of the [test] section that is not a comment, parsed.
std::vector<TestCommand> parse_test_commands(const std::vector<Line>& lines);

}  // namespace qs::piglit
