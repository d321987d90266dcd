#include "piglit/test_commands.h"

#include <cctype>
#include <cstdio>
#include <cstring>

#include "piglit/numbers.h"

namespace qs::piglit {

namespace {

// `line` starts with `prefix`; `rest` is what follows.
bool starts(const std::string& line, const char* prefix, const char** rest = nullptr) {
    const std::size_t n = std::strlen(prefix);
    if (line.compare(0, n, prefix) != 0) return false;
    if (rest) *rest = line.c_str() + n;
    return true;
}

template <std::size_t N>
std::array<float, N> floats(const char* s) {
    std::array<float, N> a{};
    const std::vector<float> v = parse_floats(s, N);
    for (std::size_t i = 0; i < v.size(); ++i) a[i] = v[i];
    return a;
}

// piglit's commands that quadshade does not run, by the prefix shader_runner matches them with,
// in its order; each its own skip reason.
constexpr const char* kUnsupported[] = {
    "active shader program", "atomic counter", "compute ", "draw rect ortho patch ", "draw rect patch ",
    "draw instanced rect", "draw arrays instanced ", "depthfunc ", "fb ", "blit ", "image texture ", "memory barrier ",
    "blend barrier", "fbfetch barrier", "viewport indexed ", "probe depth ", "probe atomic counter", "probe ssbo ",
    "relative probe rect rgba int ", "polygon mode ", "ssbo ", "xfb ", "probe xfb ", "resident ", "texture integer ",
    "texture quads ", "texture junk ", "texture storage ", "texture rgbw 1D", "texture rgbw 3D", "texture rgbw 2DArray",
    "texture rgbw 1DArray", "texture shadow", "subuniform ", "parameter ", "patch parameter ", "program binary save restore",
    "provoking vertex ", "ubo array index ", "block array index ", "block binding ", "block offset ", "block matrix stride",
    "block row major", "active uniform ", "verify program_query", "verify program_interface_query ", "verify query_object",
    "vertex attrib ", "newlist ", "endlist", "calllist", "deletelist", "viewport swizzle ",
};

// The enables shader_runner accepts (its enable_table).
constexpr const char* kEnables[] = {
    "GL_CLIP_PLANE0", "GL_CLIP_PLANE1", "GL_CLIP_PLANE2", "GL_CLIP_PLANE3", "GL_CLIP_PLANE4", "GL_CLIP_PLANE5",
    "GL_CLIP_PLANE6", "GL_CLIP_PLANE7", "GL_VERTEX_PROGRAM_TWO_SIDE", "GL_PROGRAM_POINT_SIZE", "GL_DEPTH_TEST",
    "GL_DEPTH_CLAMP",
};

// The name of an unsupported command, for its skip reason: the prefix without trailing blanks.
std::string command_name(const char* prefix) {
    std::string s = prefix;
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
}

// The draw commands: rectangles and arrays.
std::optional<Command> parse_draw(const std::string& line) {
    const char* rest = nullptr;
    int x = 0, y = 0;
    char word[32] = {};
    if (starts(line, "draw rect tex ", &rest)) {
        const std::array<float, 8> v = floats<8>(rest);
        return DrawRect{false, {v[0], v[1], v[2], v[3]}, std::array<float, 4>{v[4], v[5], v[6], v[7]}};
    }
    for (const char* prefix : {"draw rect ortho patch ", "draw rect patch ", "draw instanced rect"}) {
        if (starts(line, prefix)) return Unsupported{command_name(prefix)};
    }
    if (starts(line, "draw rect ortho ", &rest)) return DrawRect{true, floats<4>(rest), std::nullopt};
    if (starts(line, "draw rect ", &rest)) return DrawRect{false, floats<4>(rest), std::nullopt};
    if (starts(line, "draw arrays instanced ")) return Unsupported{"draw arrays instanced"};
    if (std::sscanf(line.c_str(), "draw arrays %31s %d %d", word, &x, &y) == 3) return DrawArrays{word, x, y};
    return std::nullopt;
}

// The probes of the colour buffer at pixels: one pixel, a rectangle or the whole window, RGB or
// RGBA.
std::optional<Command> parse_probe(const std::string& line) {
    const char* rest = nullptr;
    float c[4] = {};
    int x = 0, y = 0, w = 0, h = 0;
    if (starts(line, "probe rgba ", &rest)) {
        const std::array<float, 6> v = floats<6>(rest);
        Probe p;
        p.at = {float(int(v[0])), float(int(v[1])), 1, 1};
        p.expected = {v[2], v[3], v[4], v[5]};
        return p;
    }
    if (starts(line, "probe rgb ", &rest)) {
        const std::array<float, 5> v = floats<5>(rest);
        Probe p;
        p.components = 3;
        p.at = {float(int(v[0])), float(int(v[1])), 1, 1};
        p.expected = {v[2], v[3], v[4], 0};
        return p;
    }
    if (std::sscanf(line.c_str(), "probe rect rgba ( %d , %d , %d , %d ) ( %f , %f , %f , %f )", &x, &y, &w, &h, &c[0], &c[1],
                    &c[2], &c[3]) == 8) {
        Probe p;
        p.area = Probe::Area::Rect;
        p.at = {float(x), float(y), float(w), float(h)};
        p.expected = {c[0], c[1], c[2], c[3]};
        return p;
    }
    if (starts(line, "probe all rgba ", &rest) || starts(line, "probe warn all rgba ", &rest)) {
        Probe p;
        p.area = Probe::Area::All;
        p.warn = line.compare(0, 10, "probe warn") == 0;
        p.expected = floats<4>(rest);
        return p;
    }
    if (starts(line, "probe all rgb", &rest)) {
        Probe p;
        p.area = Probe::Area::All, p.components = 3;
        const std::array<float, 3> v = floats<3>(rest);
        p.expected = {v[0], v[1], v[2], 0};
        return p;
    }
    return std::nullopt;
}

// The probes at coordinates relative to the window's size, a point or a rectangle.
std::optional<Command> parse_relative_probe(const std::string& line) {
    float c[8] = {};
    if (std::sscanf(line.c_str(), "relative probe rgba ( %f , %f ) ( %f , %f , %f , %f )", &c[0], &c[1], &c[2], &c[3],
                    &c[4], &c[5]) == 6) {
        Probe p;
        p.relative = true;
        p.at = {c[0], c[1], 0, 0};
        p.expected = {c[2], c[3], c[4], c[5]};
        return p;
    }
    if (std::sscanf(line.c_str(), "relative probe rgb ( %f , %f ) ( %f , %f , %f )", &c[0], &c[1], &c[2], &c[3], &c[4]) == 5) {
        Probe p;
        p.relative = true, p.components = 3;
        p.at = {c[0], c[1], 0, 0};
        p.expected = {c[2], c[3], c[4], 0};
        return p;
    }
    if (std::sscanf(line.c_str(), "relative probe rect rgb ( %f , %f , %f , %f ) ( %f , %f , %f )", &c[0], &c[1], &c[2],
                    &c[3], &c[4], &c[5], &c[6]) == 7) {
        Probe p;
        p.area = Probe::Area::Rect, p.relative = true, p.components = 3;
        p.at = {c[0], c[1], c[2], c[3]};
        p.expected = {c[4], c[5], c[6], 0};
        return p;
    }
    if (std::sscanf(line.c_str(), "relative probe rect rgba ( %f , %f , %f , %f ) ( %f , %f , %f , %f )", &c[0], &c[1],
                    &c[2], &c[3], &c[4], &c[5], &c[6], &c[7]) == 8) {
        Probe p;
        p.area = Probe::Area::Rect, p.relative = true;
        p.at = {c[0], c[1], c[2], c[3]};
        p.expected = {c[4], c[5], c[6], c[7]};
        return p;
    }
    return std::nullopt;
}

// The textures a test makes, and texture coordinates and parameters.
std::optional<Command> parse_texture(const std::string& line) {
    const char* rest = nullptr;
    float c[8] = {};
    int x = 0, y = 0, w = 0, h = 0;
    if (std::sscanf(line.c_str(), "texture rgbw %d ( %d", &x, &w) == 2) {
        char format[32] = {};
        const int n = std::sscanf(line.c_str(), "texture rgbw %d ( %d , %d ) %31s", &x, &w, &h, format);
        if (n < 3) return Invalid{"invalid texture rgbw command"};
        return TextureRgbw{x, w, h, n >= 4 ? format : ""};
    }
    if (std::sscanf(line.c_str(), "texture miptree %d", &x) == 1) return TextureMiptree{x};
    if (std::sscanf(line.c_str(), "texture checkerboard %d %d ( %d , %d ) ( %f , %f , %f , %f ) ( %f , %f , %f , %f )", &x,
                    &y, &w, &h, &c[0], &c[1], &c[2], &c[3], &c[4], &c[5], &c[6], &c[7]) == 12) {
        return TextureCheckerboard{x, y, w, h, {c[0], c[1], c[2], c[3]}, {c[4], c[5], c[6], c[7]}};
    }
    if (std::sscanf(line.c_str(), "texcoord %d ( %f , %f , %f , %f )", &x, &c[0], &c[1], &c[2], &c[3]) == 5) {
        return CurrentTexcoord{x, {c[0], c[1], c[2], c[3]}};
    }
    if (starts(line, "texparameter ", &rest)) {
        char target[32] = {}, parameter[32] = {}, value[64] = {};
        if (std::sscanf(rest, "%31s %31s %63s", target, parameter, value) != 3) return Invalid{"texparameter: expected TARGET PARAMETER VALUE"};
        return TexParameter{target, parameter, value};
    }
    return std::nullopt;
}

Command parse(const std::string& line) {
    const char* rest = nullptr;
    float c[4] = {};
    int x = 0;
    // In shader_runner's order: a prefix of one command can begin another ("clear color", "clear").
    if (starts(line, "active shader program") || starts(line, "atomic counter")) return Unsupported{command_name("atomic counter")};
    if (starts(line, "clear color ", &rest)) return ClearColor{floats<4>(rest)};
    if (starts(line, "clear depth ", &rest)) return ClearDepth{floats<1>(rest)[0]};
    if (starts(line, "clear")) return Clear{};
    double d[4] = {};
    if (std::sscanf(line.c_str(), "clip plane %d %lf %lf %lf %lf", &x, &d[0], &d[1], &d[2], &d[3]) == 5) {
        return ClipPlane{x, {d[0], d[1], d[2], d[3]}};
    }
    if (starts(line, "color ", &rest)) return CurrentColor{floats<4>(rest)};
    if (auto draw = parse_draw(line)) return *draw;
    if (starts(line, "disable ", &rest) || starts(line, "enable ", &rest)) {
        const bool on = line[0] == 'e';
        std::string what = rest;
        what = what.substr(0, what.find_first_of(" \t"));
        for (const char* e : kEnables) {
            if (std::strncmp(rest, e, std::strlen(e)) == 0) return Enable{e, on};
        }
        return Invalid{"bad enable/disable enum '" + what + "'"};
    }
    if (starts(line, "frustum", &rest)) {
        const std::array<float, 6> v = floats<6>(rest);
        return Frustum{v};
    }
    if (starts(line, "hint")) return NoEffect{};
    if (std::sscanf(line.c_str(), "ortho %f %f %f %f", &c[0], &c[1], &c[2], &c[3]) == 4) {
        return Ortho{std::array<float, 4>{c[0], c[1], c[2], c[3]}};
    }
    if (starts(line, "ortho")) return Ortho{};
    if (auto probe = parse_probe(line)) return *probe;
    if (auto probe = parse_relative_probe(line)) return *probe;
    if (starts(line, "tolerance", &rest)) return Tolerance{floats<4>(rest)};
    if (starts(line, "shade model smooth")) return ShadeModel{false};
    if (starts(line, "shade model flat")) return ShadeModel{true};
    if (auto texture = parse_texture(line)) return *texture;
    if (starts(line, "uniform ", &rest)) {
        char type[64] = {}, name[512] = {};
        int consumed = 0;
        if (std::sscanf(rest, "%63s %511s%n", type, name, &consumed) < 2) return Invalid{"invalid set uniform command"};
        return SetUniform{type, name, rest + consumed};
    }
    if (starts(line, "link error")) return LinkError{};
    if (starts(line, "link success")) return LinkSuccess{};
    for (const char* prefix : kUnsupported) {
        if (starts(line, prefix)) return Unsupported{command_name(prefix)};
    }
    return Invalid{"unknown command"};
}

}  // namespace

std::vector<TestCommand> parse_test_commands(const std::vector<Line>& lines) {
    std::vector<TestCommand> out;
    for (const Line& l : lines) {
        std::size_t start = 0;
        while (start < l.text.size() && std::isspace(static_cast<unsigned char>(l.text[start]))) ++start;
        const std::string text = l.text.substr(start);
        if (text.empty() || text[0] == '#') continue;
        out.push_back({l.number, text, parse(text)});
    }
    return out;
}

}  // namespace qs::piglit
