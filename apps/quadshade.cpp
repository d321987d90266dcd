// quadshade: the command line. Parses arguments and calls the libraries; nothing else.
//
// Exit codes: 0 success, 1 bad input or failed render (message on stderr), 2 bad usage,
// 3 `compare` found differences over its thresholds.

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "shading/catalogue.h"
#include "shading/glsl_export.h"
#include "render/plugins.h"
#include "scenes/gltf.h"
#include "scenes/image_io.h"
#include "render/scene_render.h"
#include "render/undefined_mask.h"

namespace {

using namespace qs;

constexpr int kExitInput = 1, kExitUsage = 2, kExitDifferent = 3;

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

const char* kHelp =
    "quadshade: CPU renderer of GLSL-style procedural shaders with GPU-exact derivatives\n"
    "\n"
    "usage:\n"
    "  quadshade render SCENE.gltf -o OUT.png [options]   render a glTF scene\n"
    "  quadshade shaders [--export-glsl DIR]              list the shader catalogue (or write its GLSL)\n"
    "  quadshade compare A B [options]                    compare two images\n"
    "  quadshade COMMAND --help                           help on one command\n";

const char* kRenderHelp =
    "usage: quadshade render SCENE.gltf -o OUT [options]\n"
    "\n"
    "  -o, --output FILE       image to write (.png: 8-bit, .exr/.tif: float); with --frames,\n"
    "                          a %d (or %04d ...) in FILE is the frame number, else _NNNN is added\n"
    "  --size WxH              image size (default: the scene's, e.g. 1264x400 for Figure 1.1)\n"
    "  --time T                the `time` uniform in seconds (default: the scene's)\n"
    "  --frames A:B            render frames A..B (inclusive) at time = frame / fps\n"
    "  --fps N                 frames per second for --frames (default 30)\n"
    "  --shader NAME           draw every object with this catalogue shader\n"
    "  --uniform NAME=VALUE    a shader's own uniform, for every object whose shader declares it\n"
    "                          (replaces the material's extras.uniforms): 4.0, 1,0.5,0.2 or [1,0.5,0.2];\n"
    "                          matrices column by column; repeatable\n"
    "  --backend B             raster (default) | raycast (Embree, 2x2 ray quads)\n"
    "  --derivatives RULE      fine (llvmpipe, default) | coarse-lower (softpipe) |\n"
    "                          coarse-upper (first pixel of a top-down quad) | analytic (Dual2;\n"
    "                          with raycast: ray differentials)\n"
    "  --precision P           float (default) | double\n"
    "  --quad-pairing P        top-down (OSMesa's buffer, default) | bottom-up (an FBO)\n"
    "  --fill-rule R           pixel centres on an edge: left-bottom (llvmpipe, default) | right-top (softpipe)\n"
    "  --interpolation I       fused (llvmpipe on FMA hosts; the default there) | separate (softpipe)\n"
    "  --stable-time           reduce time by each shader's exact period in double before it\n"
    "                          becomes the float uniform: long animations (t ~ 1e6 s) keep\n"
    "                          their frame spacing (default: float time, as GL)\n"
    "  --alpha                 keep the alpha channel (the clear colour's alpha is 0)\n"
    "  --general-path          shade every shader in quads with gl_FragCoord and a depth buffer\n"
    "                          (no specialisation)\n"
    "  --undefined-mask FILE   also write where the colour depends on a GLSL case with an undefined\n"
    "                          result: red NaN produced, green division by zero, blue a built-in\n"
    "                          outside its domain (smoothstep e0 >= e1, clamp lo > hi, sqrt, log,\n"
    "                          pow, inversesqrt, atan); shades slower, same colours; float quads or\n"
    "                          pixels only (not with analytic derivatives or double precision)\n"
    "  --threads N             worker threads (default: all cores)\n";

const char* kCompareHelp =
    "usage: quadshade compare A B [options]\n"
    "\n"
    "Compares two images' RGB with OpenImageIO and prints mean, RMS, PSNR and the largest error.\n"
    "  --fail X                per-channel difference that fails a pixel, in 8-bit units (default 2)\n"
    "  --max-failing N         exit 3 when more pixels than this fail (default 0)\n"
    "  --heat-map FILE         write |A - B| as a heat map (full scale = 8/255)\n"
    "  --side-by-side FILE     write A | B | heat map\n";

std::string need_value(int& i, int argc, char** argv) {
    if (i + 1 >= argc) throw UsageError(std::string(argv[i]) + " needs a value");
    return argv[++i];
}

int parse_int(const std::string& flag, const std::string& s, int lo, int hi) {
    char* end = nullptr;
    const long v = std::strtol(s.c_str(), &end, 10);
    if (s.empty() || *end || v < lo || v > hi) {
        throw UsageError(flag + ": expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi) + ", got '" + s + "'");
    }
    return int(v);
}

double parse_double(const std::string& flag, const std::string& s) {
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end || !std::isfinite(v)) throw UsageError(flag + ": expected a finite number, got '" + s + "'");
    return v;
}

float parse_float(const std::string& flag, const std::string& s) {
    char* end = nullptr;
    const float v = std::strtof(s.c_str(), &end);
    if (s.empty() || *end || !std::isfinite(v)) throw UsageError(flag + ": expected a finite number, got '" + s + "'");
    return v;
}

std::string frame_path(const std::string& pattern, int frame) {
    if (pattern.find('%') != std::string::npos) {
        std::vector<char> buf(pattern.size() + 32);
        std::snprintf(buf.data(), buf.size(), pattern.c_str(), frame);
        return buf.data();
    }
    std::filesystem::path p(pattern);
    char suffix[16];
    std::snprintf(suffix, sizeof suffix, "_%04d", frame);
    return (p.parent_path() / (p.stem().string() + suffix + p.extension().string())).string();
}

Image to_image(const Framebuffer& fb) { return Image{fb.width, fb.height, fb.rgba}; }

const char* rule_name(Derivatives d) {
    switch (d) {
        case Derivatives::None: return "none";
        case Derivatives::Fine: return "fine";
        case Derivatives::CoarseLower: return "coarse-lower";
        case Derivatives::CoarseUpper: return "coarse-upper";
        case Derivatives::Analytic: return "analytic";
    }
    return "?";
}

int cmd_render(int argc, char** argv) {
    std::string scene_path, output;
    FrameRequest req;
    std::optional<std::pair<int, int>> frames;
    float fps = 30.0f;
    bool alpha = false;
    std::string mask_output;
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--help" || a == "-h") {
            std::fputs(kRenderHelp, stdout);
            return 0;
        } else if (a == "-o" || a == "--output") {
            output = need_value(i, argc, argv);
        } else if (a == "--size") {
            const std::string v = need_value(i, argc, argv);
            const auto x = v.find('x');
            if (x == std::string::npos) throw UsageError("--size: expected WxH, got '" + v + "'");
            req.width = parse_int("--size", v.substr(0, x), 1, 32768);
            req.height = parse_int("--size", v.substr(x + 1), 1, 32768);
        } else if (a == "--time") {
            req.time = parse_double(a, need_value(i, argc, argv));
        } else if (a == "--frames") {
            const std::string v = need_value(i, argc, argv);
            const auto c = v.find(':');
            if (c == std::string::npos) throw UsageError("--frames: expected A:B, got '" + v + "'");
            frames = {parse_int(a, v.substr(0, c), 0, 1000000), parse_int(a, v.substr(c + 1), 0, 1000000)};
            if (frames->second < frames->first) throw UsageError("--frames: B must not be less than A");
        } else if (a == "--fps") {
            fps = parse_float(a, need_value(i, argc, argv));
            if (fps <= 0.0f) throw UsageError("--fps must be positive");
        } else if (a == "--shader") {
            req.shader_override = need_value(i, argc, argv);
        } else if (a == "--plugin") {
            load_plugin(need_value(i, argc, argv));
        } else if (a == "--uniform") {
            try {
                req.uniforms.push_back(parse_uniform_option(need_value(i, argc, argv)));
            } catch (const UniformOptionError& e) {
                throw UsageError(e.what());
            }
        } else if (a == "--backend") {
            const std::string v = need_value(i, argc, argv);
            if (v == "raster") req.backend = Backend::Rasterizer;
            else if (v == "raycast") req.backend = Backend::RayCaster;
            else throw UsageError("--backend: expected raster or raycast, got '" + v + "'");
        } else if (a == "--derivatives") {
            const std::string v = need_value(i, argc, argv);
            if (v == "fine") req.raster.derivatives = Derivatives::Fine;
            else if (v == "coarse-lower" || v == "coarse") req.raster.derivatives = Derivatives::CoarseLower;
            else if (v == "coarse-upper") req.raster.derivatives = Derivatives::CoarseUpper;
            else if (v == "analytic") req.raster.derivatives = Derivatives::Analytic;
            else throw UsageError("--derivatives: unknown rule '" + v + "'");
        } else if (a == "--precision") {
            const std::string v = need_value(i, argc, argv);
            if (v == "float") req.raster.precision = Precision::Float;
            else if (v == "double") req.raster.precision = Precision::Double;
            else throw UsageError("--precision: expected float or double, got '" + v + "'");
        } else if (a == "--quad-pairing") {
            const std::string v = need_value(i, argc, argv);
            if (v == "top-down") req.raster.pairing = QuadPairing::TopDown;
            else if (v == "bottom-up") req.raster.pairing = QuadPairing::BottomUp;
            else throw UsageError("--quad-pairing: expected top-down or bottom-up, got '" + v + "'");
        } else if (a == "--fill-rule") {
            const std::string v = need_value(i, argc, argv);
            if (v == "left-bottom") req.raster.fill_rule = FillRule::LeftBottom;
            else if (v == "right-top") req.raster.fill_rule = FillRule::RightTop;
            else throw UsageError("--fill-rule: expected left-bottom or right-top, got '" + v + "'");
        } else if (a == "--interpolation") {
            const std::string v = need_value(i, argc, argv);
            if (v == "fused") req.raster.fused_interpolation = true;
            else if (v == "separate") req.raster.fused_interpolation = false;
            else throw UsageError("--interpolation: expected fused or separate, got '" + v + "'");
        } else if (a == "--stable-time") {
            req.stable_time = true;
        } else if (a == "--alpha") {
            alpha = true;
        } else if (a == "--general-path") {
            req.raster.force_general_path = true;
        } else if (a == "--undefined-mask") {
            mask_output = need_value(i, argc, argv);
            req.raster.check_undefined = true;
        } else if (a == "--threads") {
            req.raster.threads = parse_int(a, need_value(i, argc, argv), 1, 1024);
        } else if (!a.empty() && a[0] == '-') {
            throw UsageError("render: unknown option " + a);
        } else if (scene_path.empty()) {
            scene_path = a;
        } else {
            throw UsageError("render: more than one scene given ('" + scene_path + "', '" + a + "')");
        }
    }
    if (scene_path.empty()) throw UsageError("render: no scene given");
    if (output.empty()) throw UsageError("render: no output given (-o FILE)");
    if (req.raster.check_undefined) {
        if (req.raster.derivatives == Derivatives::Analytic) throw UsageError("--undefined-mask: not with --derivatives analytic");
        if (req.raster.precision == Precision::Double) throw UsageError("--undefined-mask: not with --precision double");
        if (mask_output == output) throw UsageError("--undefined-mask: the same file as -o");
    }

    Scene scene = load_scene(scene_path);
    for (const Object& o : scene.objects) program_for(scene, o, req.shader_override);  // fail before any work
    for (const std::string& file : {output, mask_output}) {
        const std::filesystem::path dir = std::filesystem::path(file).parent_path();
        if (!dir.empty() && !std::filesystem::is_directory(dir)) {
            throw std::runtime_error(file + ": no folder " + dir.string() + " to write into");
        }
    }
    const int first = frames ? frames->first : 0, last = frames ? frames->second : 0;
    const bool progress = frames && last > first && ::isatty(STDERR_FILENO);
    const auto start = std::chrono::steady_clock::now();
    double render_seconds = 0.0;
    RasterStats stats;
    UndefinedCounts undefined;
    Framebuffer fb;
    SceneRenderer renderer(scene, req);
    for (int f = first; f <= last; ++f) {
        FrameRequest fr = req;
        if (frames) fr.time = double(f) / double(fps);
        const auto t0 = std::chrono::steady_clock::now();
        renderer.render_into(fb, fr.time, &stats);
        render_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const std::string path = frames ? frame_path(output, f) : output;
        Metadata metadata = {{"quadshade:scene", scene_path},
                             {"quadshade:time", std::to_string(fr.time.value_or(double(scene.time)))},
                             {"quadshade:stable_time", req.stable_time ? "on" : "off"},
                             {"quadshade:derivatives", rule_name(req.raster.derivatives)},
                             {"quadshade:backend", req.backend == Backend::RayCaster ? "raycast" : "raster"},
                             {"quadshade:shader", req.shader_override.empty() ? "(per material)" : req.shader_override}};
        write_image(path, to_image(fb), metadata, alpha);
        if (!mask_output.empty()) {
            metadata.emplace_back("quadshade:undefined_mask",
                                  "red: NaN produced, green: division by zero, blue: built-in outside its domain");
            write_image(frames ? frame_path(mask_output, f) : mask_output, undefined_mask_image(fb), metadata);
            const UndefinedCounts c = count_undefined(fb);
            undefined.pixels += c.pixels;
            for (std::size_t k = 0; k < c.per_case.size(); ++k) undefined.per_case[k] += c.per_case[k];
        }
        if (progress) {
            const int done = f - first + 1, total = last - first + 1, width = 30;
            const int filled = done * width / total;
            std::fprintf(stderr, "\r[%s%s] %d/%d frames", std::string(std::size_t(filled), '#').c_str(),
                         std::string(std::size_t(width - filled), '.').c_str(), done, total);
            if (done == total) std::fputc('\n', stderr);
        }
    }
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const int nframes = last - first + 1;
    const int w = renderer.width(), h = renderer.height();
    std::fprintf(stderr, "quadshade: %d frame%s %dx%d in %.3f s (render %.1f ms/frame, %.1f Mpixel/s), %llu triangles, %llu lanes shaded",
                 nframes, nframes == 1 ? "" : "s", w, h, total, 1e3 * render_seconds / nframes,
                 double(w) * h * nframes / render_seconds * 1e-6, (unsigned long long)stats.triangles_setup,
                 (unsigned long long)stats.lanes_shaded);
    if (req.backend == Backend::RayCaster) {
        std::fprintf(stderr, ", BVH built once in %.1f ms", 1e3 * renderer.bvh_build_seconds());
    } else {
        std::fputs(stats.depth_buffer ? ", depth tested" : ", no depth buffer (no two triangles overlap)", stderr);
    }
    std::fputc('\n', stderr);
    if (!mask_output.empty()) {
        std::fprintf(stderr,
                     "quadshade: undefined GLSL cases on %llu pixels: NaN produced %llu, division by zero %llu, "
                     "built-in outside its domain %llu\n",
                     (unsigned long long)undefined.pixels, (unsigned long long)undefined.per_case[0],
                     (unsigned long long)undefined.per_case[1], (unsigned long long)undefined.per_case[2]);
    }
    return 0;
}

int cmd_shaders(int argc, char** argv) {
    std::optional<std::string> export_dir;
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--help" || a == "-h") {
            std::puts("usage: quadshade shaders [--export-glsl DIR]\n"
                      "Lists every catalogue shader and what it needs; with --export-glsl, writes each shader's\n"
                      "complete GLSL (DIR/NAME.vert, DIR/NAME.frag) as an OpenGL program compiles it\n"
                      "(quadshade-reference --glsl DIR renders scenes from it).");
            return 0;
        } else if (a == "--export-glsl") {
            export_dir = need_value(i, argc, argv);
        } else if (a == "--plugin") {
            load_plugin(need_value(i, argc, argv));
        } else {
            throw UsageError("shaders: unexpected argument " + a);
        }
    }
    if (export_dir) {
        const int n = export_glsl(*export_dir);
        std::printf("wrote the GLSL of %d shaders to %s\n", n, export_dir->c_str());
        return 0;
    }
    auto coordinates = [](Coordinates c) {
        switch (c) {
            case Coordinates::None: return "window";
            case Coordinates::Texcoord2D: return "st 2D";
            case Coordinates::Object2D: return "object 2D";
            case Coordinates::Object3D: return "object 3D";
        }
        return "?";
    };
    std::printf("%-20s %-11s %-11s %-7s %-4s %s\n", "name", "coordinates", "derivatives", "texture", "time",
                "description");
    for (const Program* p : catalogue()) {
        const ShaderInfo& s = p->info();
        std::printf("%-20s %-11s %-11s %-7s %-4s %s\n", std::string(s.name).c_str(), coordinates(s.needs.coordinates),
                    s.needs.derivatives ? "yes" : "-", samples_textures(s.needs) ? "yes" : "-", s.needs.time ? "yes" : "-",
                    std::string(s.description).c_str());
    }
    return 0;
}

int cmd_compare(int argc, char** argv) {
    std::vector<std::string> files;
    float fail = 2.0f;
    long long max_failing = 0;
    std::string heat, side;
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--help" || a == "-h") {
            std::fputs(kCompareHelp, stdout);
            return 0;
        } else if (a == "--fail") {
            fail = parse_float(a, need_value(i, argc, argv));
        } else if (a == "--max-failing") {
            max_failing = parse_int(a, need_value(i, argc, argv), 0, 1 << 30);
        } else if (a == "--heat-map") {
            heat = need_value(i, argc, argv);
        } else if (a == "--side-by-side") {
            side = need_value(i, argc, argv);
        } else if (!a.empty() && a[0] == '-') {
            throw UsageError("compare: unknown option " + a);
        } else {
            files.push_back(a);
        }
    }
    if (files.size() != 2) throw UsageError("compare: expected two images");
    const Image a = read_image(files[0]), b = read_image(files[1]);
    // A margin of half a step: 8-bit values differ by whole multiples of 1/255.
    const Comparison c = compare_images(a, b, (fail + 0.5f) / 255.0f, (1.0f + 0.5f) / 255.0f);
    std::printf("mean %.6f  rms %.6f  psnr %.2f dB  max %.1f/255 at (%d, %d) channel %d\n", c.mean_error, c.rms_error,
                c.psnr, c.max_error * 255.0, c.max_x, c.max_y, c.max_channel);
    std::printf("pixels over %g/255: %llu   over 1/255: %llu   of %d\n", double(fail),
                (unsigned long long)c.pixels_over_fail, (unsigned long long)c.pixels_over_warn, a.width * a.height);
    if (!heat.empty() || !side.empty()) {
        const Image h = difference_heat_map(a, b, 8.0f / 255.0f);
        if (!heat.empty()) write_image(heat, h);
        if (!side.empty()) write_image(side, side_by_side({&a, &b, &h}));
    }
    return (long long)c.pixels_over_fail > max_failing ? kExitDifferent : 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const std::string cmd = argc > 1 ? argv[1] : "";
        if (cmd == "render") return cmd_render(argc, argv);
        if (cmd == "shaders") return cmd_shaders(argc, argv);
        if (cmd == "compare") return cmd_compare(argc, argv);
        if (cmd == "--help" || cmd == "-h" || cmd == "help") {
            std::fputs(kHelp, stdout);
            return 0;
        }
        throw UsageError(cmd.empty() ? "no command given" : "unknown command '" + cmd + "'");
    } catch (const UsageError& e) {
        std::fprintf(stderr, "quadshade: %s\n\n%s", e.what(), kHelp);
        return kExitUsage;
    } catch (const UniformOptionError& e) {  // a --uniform no drawn shader takes
        std::fprintf(stderr, "quadshade: %s\n", e.what());
        return kExitUsage;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "quadshade: %s\n", e.what());
        return kExitInput;
    }
}
