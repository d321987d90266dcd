// quadshade: the command line. Parses arguments (CLI11) and calls the libraries; nothing else.
//
// Exit codes: 0 success, 1 bad input or failed render (message on stderr), 2 bad usage,
// 3 `compare` found differences over its thresholds, a `check` case missed its bar, or a `test`
// case failed.

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "apps/check.h"
#include "apps/frame_pattern.h"
#include "apps/golden_suite.h"
#include "render/gallery.h"
#include "render/atlas_bake.h"
#include "render/memory_plan.h"
#include "render/normal_bake.h"
#include "render/plugins.h"
#include "render/scene_render.h"
#include "render/undefined_mask.h"
#include "render/volume_bake.h"
#include "scenes/gltf.h"
#include "scenes/image_io.h"
#include "scenes/temporary_file.h"
#include "scenes/uniforms.h"
#include "shading/catalogue.h"
#include "shading/glsl_export.h"
#include "shading/height_field.h"

namespace {

using namespace qs;
namespace fs = std::filesystem;

constexpr int kExitInput = 1, kExitUsage = 2, kExitDifferent = 3;

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// ---- outputs ------------------------------------------------------------------------------

// The file system entry `p` names: its folder resolved (symlinks and all), its own name kept. An
// output replaces that entry (written beside it, renamed over it), never what a link there points to.
fs::path resolved(const fs::path& p) {
    std::error_code ec;
    const fs::path folder = fs::weakly_canonical(p.parent_path().empty() ? fs::path(".") : p.parent_path(), ec);
    return ec ? p.lexically_normal() : folder / p.filename();
}

// Refuses (UsageError) an output that is a folder or one of the scene's own files. Cheap for a
// million frames: only an output named like an input has its folder resolved.
void check_output(const fs::path& output, const std::vector<fs::path>& inputs, const char* option) {
    if (fs::is_directory(output)) throw UsageError(std::string(option) + " " + output.string() + ": is a folder; give a file name");
    for (const fs::path& in : inputs) {
        if (output.filename() == in.filename() && resolved(output) == in) {
            throw UsageError(std::string(option) + " " + output.string() + ": is an input of this command; it would be overwritten");
        }
    }
}

// ---- arguments ------------------------------------------------------------------------------

// A CLI11 check that a number is finite (CLI11 reads "nan", "inf" and 1e400 as numbers).
const CLI::Validator kFinite(
    [](std::string& s) {
        double v = 0.0;
        return CLI::detail::lexical_cast(s, v) && std::isfinite(v) ? std::string() : "expected a finite number, got '" + s + "'";
    },
    "FINITE");

// An option whose value is one of `choices`, with the old command line's messages.
template <class T>
CLI::Option* add_choice(CLI::App& app, const std::string& name, T& target, std::vector<std::pair<std::string, T>> choices,
                        const std::string& text, const std::string& help) {
    return app
        .add_option_function<std::string>(
            name,
            [&target, choices, name](const std::string& v) {
                std::string names;
                for (const auto& [n, value] : choices) {
                    if (n == v) {
                        target = value;
                        return;
                    }
                    names += (names.empty() ? "" : " | ") + n;
                }
                throw CLI::ValidationError(name, "expected " + names + ", got '" + v + "'");
            },
            help)
        ->option_text(text);
}

// --plugin, repeatable: shared libraries whose shaders join the catalogue (render/plugins.h),
// loaded in order once the command line has parsed.
void add_plugin_option(CLI::App& cmd, std::vector<std::string>& plugins) {
    cmd.add_option("--plugin", plugins, "load a shader plugin (quadshade_add_shader_plugin) first; repeatable")
        ->option_text("LIB")->allow_extra_args(false);
}

struct RenderArgs {
    std::string scene, output, mask_output;
    FrameRequest request;
    std::pair<int, int> frames{-1, -1};  // -1: no animation
    float fps = 30.0f;
    bool alpha = false;
    SceneLoadOptions load;
    std::string memory_limit;  // empty: what the system has available
    std::vector<std::string> plugins;
    std::vector<std::string> uniforms;  // --uniform NAME=VALUE, read by parse_uniform_option
    std::vector<std::string> raster_only;  // the rasterizer's own options given (kRasterOnly)
    bool animated() const { return frames.first >= 0; }
};

// Options only the rasterizer has: the ray caster refuses them, even at their default values,
// rather than render something the command line did not describe.
const char* const kRasterOnly[] = {"--fill-rule", "--interpolation", "--general-path"};

void add_render_options(CLI::App& cmd, RenderArgs& a) {
    FrameRequest& r = a.request;
    cmd.add_option("SCENE", a.scene, "the glTF scene (.gltf or .glb)")->required()->option_text("SCENE.gltf");
    cmd.add_option("-o,--output", a.output,
                   "image to write (.png: 8-bit, .exr/.tif: float); with --frames,\n"
                   "a %d (or %04d ...) in FILE is the frame number, else _NNNN is added")
        ->required()->option_text("FILE")->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    cmd.add_option_function<std::vector<int>>(
           "--size", [&r](const std::vector<int>& v) { r.width = v[0], r.height = v[1]; },
           "image size (default: the scene's, e.g. 1264x400 for Figure 1.1)")
        ->delimiter('x')->expected(2)->check(CLI::Range(1, 1 << 15))->option_text("WxH");
    cmd.add_option("--time", r.time, "the `time` uniform in seconds (default: the scene's)")->check(kFinite)->option_text("T");
    cmd.add_option("--frames", a.frames, "render frames A..B (inclusive) at time = frame / fps")
        ->delimiter(':')->check(CLI::Range(0, 1000000))->option_text("A:B");
    cmd.add_option("--fps", a.fps, "frames per second for --frames (default 30)")
        ->check(kFinite & CLI::PositiveNumber)->option_text("N");
    cmd.add_option("--shader", r.shader_override, "draw every object with this catalogue shader")->option_text("NAME");
    add_plugin_option(cmd, a.plugins);
    cmd.add_option("--uniform", a.uniforms,
                   "a shader's own uniform, for every object whose shader declares it\n"
                   "(replaces the material's extras.uniforms): 4.0, 1,0.5,0.2 or [1,0.5,0.2];\n"
                   "matrices column by column; repeatable")
        ->option_text("NAME=VALUE")->allow_extra_args(false);
    add_choice<Backend>(cmd, "--backend", r.backend, {{"raster", Backend::Rasterizer}, {"raycast", Backend::RayCaster}}, "B",
                        "raster (default) | raycast (Embree, 2x2 ray quads)");
    add_choice<Derivatives>(cmd, "--derivatives", r.shading.derivatives,
                            {{"fine", Derivatives::Fine}, {"coarse-lower", Derivatives::CoarseLower},
                             {"coarse", Derivatives::CoarseLower}, {"coarse-upper", Derivatives::CoarseUpper},
                             {"analytic", Derivatives::Analytic}},
                            "RULE",
                            "fine (llvmpipe, default) | coarse-lower (softpipe) |\n"
                            "coarse-upper (first pixel of a top-down quad) | analytic (Dual2;\n"
                            "with raycast: ray differentials)");
    add_choice<Precision>(cmd, "--precision", r.shading.precision, {{"float", Precision::Float}, {"double", Precision::Double}},
                          "P", "float (default) | double");
    add_choice<QuadPairing>(cmd, "--quad-pairing", r.shading.pairing,
                            {{"top-down", QuadPairing::TopDown}, {"bottom-up", QuadPairing::BottomUp}}, "P",
                            "top-down (OSMesa's buffer, default) | bottom-up (an FBO)");
    add_choice<FillRule>(cmd, "--fill-rule", r.raster.fill_rule,
                         {{"left-bottom", FillRule::LeftBottom}, {"right-top", FillRule::RightTop}}, "R",
                         "pixel centres on an edge: left-bottom (llvmpipe, default) | right-top (softpipe)");
    add_choice<bool>(cmd, "--interpolation", r.raster.fused_interpolation, {{"fused", true}, {"separate", false}}, "I",
                     "fused (llvmpipe on FMA hosts; the default there) | separate (softpipe)");
    cmd.add_flag("--stable-time", r.stable_time,
                 "reduce time by each shader's exact period in double before it\n"
                 "becomes the float uniform: long animations (t ~ 1e6 s) keep\n"
                 "their frame spacing (default: float time, as GL)");
    cmd.add_flag("--alpha", a.alpha, "keep the alpha channel (the clear colour's alpha is 0)");
    cmd.add_flag("--general-path", r.raster.force_general_path,
                 "shade every shader in quads with gl_FragCoord and a depth buffer\n(no specialisation)");
    cmd.add_option("--undefined-mask", a.mask_output,
                   "also write where the colour depends on a GLSL case with an undefined\n"
                   "result: red NaN produced, green division by zero, blue a built-in\n"
                   "outside its domain (smoothstep e0 >= e1, clamp lo > hi, sqrt, log,\n"
                   "pow, inversesqrt, atan); shades slower, same colours; float quads or\n"
                   "pixels only (not with analytic derivatives or double precision)")
        ->option_text("FILE");
    cmd.add_option("--threads", r.shading.threads, "worker threads (default: all cores)")
        ->check(CLI::Range(1, 1024))->option_text("N");
    cmd.add_flag("--allow-outside-paths", a.load.paths.allow_outside,
                 "let the scene read files outside its own folder (absolute paths,\n"
                 "../, symlinks); by default only files beside it are read");
    cmd.add_option("--memory-limit", a.memory_limit,
                   "memory the render may use, e.g. 4G (default: what the system has\n"
                   "available); larger images are rendered and written in bands of rows")
        ->option_text("SIZE");
}

struct CompareArgs {
    std::vector<std::string> images;
    float fail = 2.0f;
    long long max_failing = 0;
    std::string heat, side, memory_limit;
};

void add_compare_options(CLI::App& cmd, CompareArgs& a) {
    cmd.add_option("images", a.images, "the two images")->required()->expected(2)->option_text("A B");
    cmd.add_option("--fail", a.fail, "per-channel difference that fails a pixel, in 8-bit units (default 2)")
        ->check(kFinite)->option_text("X");
    cmd.add_option("--max-failing", a.max_failing, "exit 3 when more pixels than this fail (default 0)")
        ->check(CLI::Range(0, 1 << 30))->option_text("N");
    cmd.add_option("--heat-map", a.heat, "write |A - B| as a heat map (full scale = 8/255)")->option_text("FILE");
    cmd.add_option("--side-by-side", a.side, "write A | B | heat map")->option_text("FILE");
    cmd.add_option("--memory-limit", a.memory_limit, "memory the comparison may use (default: what is available)")
        ->option_text("SIZE");
}

struct CheckArgs {
    std::vector<std::string> shaders, rules{"fine"}, plugins;
    bool all = false;
    std::string scenes, output = "quadshade-check";
    int jobs = 0;
};

void add_check_options(CLI::App& cmd, CheckArgs& a) {
    cmd.add_option("shaders", a.shaders, "the shaders to check (catalogue names)")->option_text("SHADER...");
    cmd.add_flag("--all", a.all, "check every shader of the catalogue, plugins' included (not the\nbuilt-in probes)");
    cmd.add_option("--scenes", a.scenes,
                   "check on every .gltf/.glb scene in DIR (default: the conformance\n"
                   "scenes and the Table 1.1 plane)")
        ->option_text("DIR");
    cmd.add_option("--rules", a.rules,
                   "derivative rules, each against its OSMesa driver: fine (llvmpipe,\n"
                   "default), coarse-lower (softpipe)")
        ->delimiter(',')->option_text("R,...");
    cmd.add_option("-o,--output", a.output,
                   "folder for the exported GLSL, report.csv and the heat maps\n(default quadshade-check)")
        ->option_text("DIR");
    cmd.add_option("--jobs", a.jobs, "cases checked at once, each a reference process and a render\n(default: one per core)")
        ->check(CLI::Range(1, 1024))->option_text("N");
    add_plugin_option(cmd, a.plugins);
}

struct TestArgs {
    std::vector<std::string> inputs, plugins;
    bool update = false, merge = false;
    int jobs = 0;
    std::string junit, html, shard, report;
};

void add_test_options(CLI::App& cmd, TestArgs& a) {
    cmd.add_option("inputs", a.inputs, "the suite file (JSON: docs/golden-suites.md); with --merge, report fragments")
        ->required()->option_text("SUITE | FRAGMENT...");
    cmd.add_flag("--update", a.update, "re-bless: write each case's image as its expected image");
    cmd.add_option("--jobs", a.jobs, "cases rendered at once (default: one per core)")->check(CLI::Range(1, 1024))->option_text("N");
    cmd.add_option("--shard", a.shard, "run case i when i mod N = K - 1 (cases counted from 0)")->option_text("K/N");
    cmd.add_option("--report", a.report, "write this run's report fragment (JSON), for --merge")->option_text("FILE");
    cmd.add_flag("--merge", a.merge, "merge the report fragments of every shard (1..N, each once) instead of running");
    cmd.add_option("--junit", a.junit, "write a JUnit XML report")->option_text("FILE");
    cmd.add_option("--html", a.html, "write an HTML report, images side by side, to DIR/index.html")->option_text("DIR");
    add_plugin_option(cmd, a.plugins);
}

std::uint64_t memory_limit(const std::string& option) {
    if (option.empty()) return available_memory();
    try {
        return parse_byte_size(option);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--memory-limit: ") + e.what());
    }
}

struct VolumeArgs {
    std::string shader, output, scene;
    int size = 32;
    std::optional<double> time;
    std::vector<std::string> uniforms, plugins;
    Derivatives derivatives = Derivatives::Fine;
    int threads = 0;
    bool allow_outside = false;
};

void add_volume_options(CLI::App& cmd, VolumeArgs& a) {
    cmd.add_option("--shader", a.shader, "the catalogue shader to evaluate (its object-space position is the grid's)")
        ->required()->option_text("NAME");
    cmd.add_option("-o,--output", a.output,
                   "the volume as a 3D texture: N x N^2 pixels, slice k in rows [kN, (k+1)N)\n"
                   "(.png: 8-bit, loadable as a sampler3D; .exr/.tif: float)")
        ->required()->option_text("FILE");
    cmd.add_option("--size", a.size, "texels per side, N (default 32)")->check(CLI::Range(1, kMaxVolumeSide))->option_text("N");
    cmd.add_option("--time", a.time, "the `time` uniform in seconds (default 0)")->check(kFinite)->option_text("T");
    cmd.add_option("--scene", a.scene, "take the shader's textures and uniforms from this scene's first object")
        ->option_text("SCENE.gltf");
    cmd.add_option("--uniform", a.uniforms, "a shader's own uniform, as for render; repeatable")
        ->option_text("NAME=VALUE")->allow_extra_args(false);
    add_choice<Derivatives>(cmd, "--derivatives", a.derivatives,
                            {{"fine", Derivatives::Fine}, {"coarse-lower", Derivatives::CoarseLower},
                             {"coarse-upper", Derivatives::CoarseUpper}, {"analytic", Derivatives::Analytic}},
                            "RULE", "for shaders that take derivatives: per texel along x and y (default fine)");
    add_plugin_option(cmd, a.plugins);
    cmd.add_option("--threads", a.threads, "worker threads (default: all cores)")->check(CLI::Range(1, 1024))->option_text("N");
    cmd.add_flag("--allow-outside-paths", a.allow_outside, "let --scene read files outside its own folder");
}

struct GalleryArgs {
    std::string output;
    std::vector<std::string> scenes, plugins;
    int size = 160, columns = 6, threads = 0;
    double time = 1.0;
};

void add_gallery_options(CLI::App& cmd, GalleryArgs& a) {
    cmd.add_option("output", a.output, "the folder for the sheets, one PNG per collection (made if missing)")
        ->required()->option_text("OUT_DIR");
    cmd.add_option("--size", a.size, "each shader's square in pixels (default 160)")->check(CLI::Range(16, 1024))->option_text("N");
    cmd.add_option("--columns", a.columns, "squares per row, at most (default 6)")->check(CLI::Range(1, 64))->option_text("N");
    cmd.add_option("--scenes", a.scenes,
                   "scenes to draw on, in order of preference (default: the installed Table 1.1 plane, seed 004's\n"
                   "plane, the solids, seed 001's spheres and the conformance scenes); a shader goes on the first\n"
                   "that binds its textures")
        ->option_text("SCENE...");
    cmd.add_option("--time", a.time, "the `time` uniform in seconds (default 1)")->check(kFinite)->option_text("T");
    add_plugin_option(cmd, a.plugins);
    cmd.add_option("--threads", a.threads, "worker threads (default: all cores)")->check(CLI::Range(1, 1024))->option_text("N");
}

struct BakeArgs {
    std::string mesh, shader, output;
    int size = 1024;
    std::vector<std::string> maps{"color"};
    int skirt = 0;
    std::optional<double> time;
    std::vector<std::string> uniforms, plugins;
    Derivatives derivatives = Derivatives::Fine;
    int threads = 0;
    bool allow_outside = false;
    // The normal map (--maps normal): how, and the finite differences' step.
    CLI::Option* normals_option = nullptr;
    NormalMethod normals = NormalMethod::Analytic;
    CLI::Option* precision_option = nullptr;
    Precision normal_precision = Precision::Float;
    std::optional<double> normal_step;
};

void add_bake_options(CLI::App& cmd, BakeArgs& a) {
    cmd.add_option("mesh", a.mesh, "a glTF scene whose meshes have a UV atlas in TEXCOORD_0 (in [0, 1], no overlaps)")
        ->required()->option_text("MESH.gltf");
    cmd.add_option("--shader", a.shader, "the catalogue shader to bake (its own vertex stage gives its varyings)")
        ->required()->option_text("NAME");
    cmd.add_option("-o,--output", a.output,
                   "the baked scene: OUT.gltf and OUT.bin, its maps beside them (OUT-color.png, and\n"
                   "OUT-height.png and OUT-normal.png as --maps asks), drawn with a shader that samples them")
        ->required()->option_text("OUT.gltf");
    cmd.add_option("--size", a.size, "atlas texels per side (default 1024)")->check(CLI::Range(1, kMaxAtlasSide))->option_text("N");
    cmd.add_option("--maps", a.maps,
                   "the maps to bake, of color, height and normal (default color; color is required): height\n"
                   "is the shader's height as grey (OUT-height.png), normal the object-space normal map its\n"
                   "height gives (OUT-normal.png, 0.5 + 0.5 n), drawn lit by baked_lit")
        ->delimiter(',')->option_text("MAP,...");
    a.normals_option = add_choice<NormalMethod>(
        cmd, "--normals", a.normals, {{"analytic", NormalMethod::Analytic}, {"finite", NormalMethod::FiniteDifferences}},
        "HOW",
        "the normal map from the height's gradient through Dual2 (analytic, the default) or from\n"
        "three heights and a cross product (finite: seed 001's way)");
    cmd.add_option("--normal-step", a.normal_step, "--normals finite's step along the tangents, in object units (default 1e-4)")
        ->check(CLI::PositiveNumber & kFinite)->option_text("E");
    a.precision_option = add_choice<Precision>(cmd, "--normal-precision", a.normal_precision,
                                               {{"float", Precision::Float}, {"double", Precision::Double}}, "P",
                                               "the height's evaluations for the normal map in float (default) or double");
    cmd.add_option("--skirt", a.skirt, "skirts around each UV chart, in texels (default 0: none)")
        ->check(CLI::Range(0, kMaxSkirt))->option_text("PIXELS");
    cmd.add_option("--time", a.time, "the `time` uniform in seconds (default: the scene's)")->check(kFinite)->option_text("T");
    cmd.add_option("--uniform", a.uniforms, "a shader's own uniform, as for render; repeatable")
        ->option_text("NAME=VALUE")->allow_extra_args(false);
    add_choice<Derivatives>(cmd, "--derivatives", a.derivatives,
                            {{"fine", Derivatives::Fine}, {"coarse-lower", Derivatives::CoarseLower},
                             {"coarse-upper", Derivatives::CoarseUpper}, {"analytic", Derivatives::Analytic}},
                            "RULE",
                            "dFdx/dFdy per atlas texel (default fine: quad differences); analytic: exact\n"
                            "partials of the varyings (Dual2), also across chart edges");
    add_plugin_option(cmd, a.plugins);
    cmd.add_option("--threads", a.threads, "worker threads (default: all cores)")->check(CLI::Range(1, 1024))->option_text("N");
    cmd.add_flag("--allow-outside-paths", a.allow_outside, "let the scene read files outside its own folder");
}

// ---- render ---------------------------------------------------------------------------------

const char* precision_name(Precision p) { return p == Precision::Double ? "double" : "float"; }

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

// Refuses (UsageError) what no backend honours as asked, before anything is read or written:
// the rasterizer's own options with the ray caster, a shading request no instantiation honours.
void refuse_unsupported(const RenderArgs& a) {
    const FrameRequest& req = a.request;
    if (req.backend == Backend::RayCaster && !a.raster_only.empty()) {
        throw UsageError(a.raster_only.front() + ": a rasterizer option; the ray caster (--backend raycast) has no fill "
                         "rule, plane interpolation or general path");
    }
    try {
        check_supported(req);
    } catch (const UnsupportedRequest& e) {
        throw UsageError("--derivatives " + std::string(rule_name(req.shading.derivatives)) + " --precision " +
                         precision_name(req.shading.precision) + (a.mask_output.empty() ? "" : " --undefined-mask") +
                         ": " + e.what());
    }
}

// The settings that decide the image's pixels beside the scene, as image metadata, so that an
// image says how it was made (the undefined-case mask, threads and bands change no pixel).
Metadata render_metadata(const RenderArgs& a, double time) {
    const FrameRequest& req = a.request;
    const RasterOptions r = req.raster_options();
    const bool raster = req.backend == Backend::Rasterizer;
    Metadata m = {{"quadshade:scene", a.scene},
                  {"quadshade:time", std::to_string(time)},
                  {"quadshade:stable_time", req.stable_time ? "on" : "off"},
                  {"quadshade:backend", raster ? "raster" : "raycast"},
                  {"quadshade:shader", req.shader_override.empty() ? "(per material)" : req.shader_override},
                  {"quadshade:derivatives", rule_name(r.derivatives)},
                  {"quadshade:precision", precision_name(r.precision)},
                  {"quadshade:quad_pairing", r.pairing == QuadPairing::BottomUp ? "bottom-up" : "top-down"}};
    if (raster) {
        m.emplace_back("quadshade:fill_rule", r.fill_rule == FillRule::RightTop ? "right-top" : "left-bottom");
        m.emplace_back("quadshade:interpolation", r.fused_interpolation ? "fused" : "separate");
    }
    std::string uniforms, plugins;
    for (const std::string& u : a.uniforms) uniforms += (uniforms.empty() ? "" : " ") + u;
    for (const std::string& p : a.plugins) plugins += (plugins.empty() ? "" : " ") + p;
    if (!uniforms.empty()) m.emplace_back("quadshade:uniforms", uniforms);
    if (!plugins.empty()) m.emplace_back("quadshade:plugins", plugins);
    return m;
}

bool writes_in_bands(const fs::path& file) {
    std::string ext = file.extension().string();
    for (char& c : ext) c = char(std::tolower((unsigned char)c));
    return ext == ".png" || ext == ".exr" || ext == ".tif" || ext == ".tiff";
}

// What a render of the whole frame, or of bands of it, needs beside the loaded scene.
std::vector<RowBand> plan_render(const SceneRenderer& renderer, const RenderArgs& a, std::uint64_t limit) {
    const int w = renderer.width();
    MemoryPlanInput in;
    in.height = renderer.height();
    in.pairing = a.request.shading.pairing;
    in.limit = limit;
    in.can_band = writes_in_bands(a.output) && (a.mask_output.empty() || writes_in_bands(a.mask_output));
    in.bytes_for_rows = [&](int rows) {
        std::uint64_t bytes = renderer.frame_bytes(rows) + ImageWriter::conversion_bytes(a.output, w, rows, a.alpha);
        if (!a.mask_output.empty()) {
            bytes += std::uint64_t(w) * std::uint64_t(rows) * 4 * sizeof(float) +
                     ImageWriter::conversion_bytes(a.mask_output, w, rows, false);
        }
        return bytes;
    };
    return plan_bands(in);
}

struct FrameTotals {
    double render_seconds = 0.0;
    int renders = 0;  // frames rendered, not reused
    RenderStats stats;  // of the last frame
    UndefinedCounts undefined;
};

// Renders the frame at `time` band by band into `output` (and the undefined-case mask into
// `mask_output` unless empty). The files are opened once the first band is rendered (OpenImageIO
// keeps every string attribute, the frame's time among them, for the process's lifetime: made
// after the frame's working memory is freed, it does not pin the heap) and renamed into place
// once complete.
// `rendered`: `fb` already holds this frame's image (one band, a frame that does not depend on
// its time), which is written again without rendering.
void write_frame(SceneRenderer& renderer, const std::vector<RowBand>& bands, double time, const RenderArgs& a,
                 const std::string& output, const std::string& mask_output, Framebuffer& fb, FrameTotals& totals,
                 bool rendered) {
    std::optional<ImageWriter> image, mask;
    if (!rendered) totals.stats = {};
    for (const RowBand& band : bands) {
        if (!rendered) {
            RenderStats band_stats;
            const auto t0 = std::chrono::steady_clock::now();
            renderer.render_into(fb, time, &band_stats, band);
            totals.render_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            totals.stats.triangles_setup = band_stats.triangles_setup, totals.stats.lanes_shaded += band_stats.lanes_shaded;
            totals.stats.depth_buffer = band_stats.depth_buffer;  // decided for the whole frame, the same in every band
            ++totals.renders;
        }
        if (!image) {
            Metadata metadata = render_metadata(a, time);
            image.emplace(output, fb.width, fb.height, a.alpha, metadata);
            if (!mask_output.empty()) {
                metadata.emplace_back("quadshade:undefined_mask",
                                      "red: NaN produced, green: division by zero, blue: built-in outside its domain");
                mask.emplace(mask_output, fb.width, fb.height, false, metadata);
            }
        }
        image->write_rows(fb.rows, fb.rgba.data());
        if (mask) {
            mask->write_rows(fb.rows, undefined_mask_image(fb).rgba.data());
            const UndefinedCounts c = count_undefined(fb);
            totals.undefined.pixels += c.pixels;
            for (std::size_t k = 0; k < c.per_case.size(); ++k) totals.undefined.per_case[k] += c.per_case[k];
        }
    }
    image->commit();
    if (mask) mask->commit();
}

void print_progress(int done, int total) {
    const int width = 30, filled = done * width / total;
    std::fprintf(stderr, "\r[%s%s] %d/%d frames", std::string(std::size_t(filled), '#').c_str(),
                 std::string(std::size_t(width - filled), '.').c_str(), done, total);
    if (done == total) std::fputc('\n', stderr);
}

int cmd_render(RenderArgs& a) {
    FrameRequest& req = a.request;
    if (a.animated() && a.frames.second < a.frames.first) throw UsageError("--frames: B must not be less than A");
    req.shading.check_undefined = !a.mask_output.empty();
    if (req.shading.check_undefined && resolved(a.mask_output) == resolved(a.output)) {
        throw UsageError("--undefined-mask: the same file as -o");
    }
    refuse_unsupported(a);
    for (const std::string& u : a.uniforms) req.uniforms.push_back(parse_uniform_option(u));
    const std::uint64_t limit = memory_limit(a.memory_limit);
    const int first = a.animated() ? a.frames.first : 0, last = a.animated() ? a.frames.second : 0;
    auto path_of = [&](const std::string& pattern, int f) {
        try {
            return a.animated() ? frame_path(pattern, f) : pattern;
        } catch (const std::invalid_argument& e) {
            throw UsageError(e.what());
        }
    };
    path_of(a.output, first);  // a bad pattern is refused before anything is read
    if (!a.mask_output.empty()) path_of(a.mask_output, first);

    for (const std::string& plugin : a.plugins) load_plugin(plugin);
    Scene scene = load_scene(a.scene, a.load);
    for (const Object& o : scene.objects) program_for(scene, o, req.shader_override);  // fail before any work
    for (int f = first; f <= last; ++f) {
        check_output(path_of(a.output, f), scene.inputs, "-o");
        if (!a.mask_output.empty()) check_output(path_of(a.mask_output, f), scene.inputs, "--undefined-mask");
    }
    SceneRenderer renderer(scene, req);
    for (const std::string& note : renderer.notes()) std::fprintf(stderr, "quadshade: warning: %s\n", note.c_str());
    const std::vector<RowBand> bands = plan_render(renderer, a, limit);

    const bool progress = last > first && ::isatty(STDERR_FILENO);
    const auto start = std::chrono::steady_clock::now();
    FrameTotals totals;
    Framebuffer fb;
    // Frames that cannot differ (no drawn shader reads time) are rendered once, when one band
    // holds the whole frame.
    const bool render_once = !renderer.depends_on_time() && bands.size() == 1;
    for (int f = first; f <= last; ++f) {
        const double time = a.animated() ? double(f) / double(a.fps) : req.time.value_or(double(scene.time));
        const std::string mask = a.mask_output.empty() ? "" : path_of(a.mask_output, f);
        write_frame(renderer, bands, time, a, path_of(a.output, f), mask, fb, totals, render_once && f > first);
        if (progress) print_progress(f - first + 1, last - first + 1);
    }
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const int nframes = last - first + 1, w = renderer.width(), h = renderer.height();
    const double render_seconds = totals.render_seconds;
    const int renders = totals.renders;
    const RenderStats& stats = totals.stats;
    const UndefinedCounts& undefined = totals.undefined;
    std::fprintf(stderr, "quadshade: %d frame%s %dx%d in %.3f s (render %.1f ms/frame, %.1f Mpixel/s), %llu triangles, %llu lanes shaded",
                 nframes, nframes == 1 ? "" : "s", w, h, total, 1e3 * render_seconds / renders,
                 double(w) * h * renders / render_seconds * 1e-6, (unsigned long long)stats.triangles_setup,
                 (unsigned long long)stats.lanes_shaded);
    if (renders < nframes) std::fputs(", rendered once (no drawn shader reads time)", stderr);
    if (bands.size() > 1) std::fprintf(stderr, ", in %zu bands of rows", bands.size());
    if (req.backend == Backend::RayCaster) {
        std::fprintf(stderr, ", BVH built once in %.1f ms", 1e3 * renderer.bvh_build_seconds());
    } else {
        std::fputs(stats.depth_buffer ? ", depth tested" : ", no depth buffer (no two triangles overlap)", stderr);
    }
    std::fputc('\n', stderr);
    if (!a.mask_output.empty()) {
        std::fprintf(stderr,
                     "quadshade: undefined GLSL cases on %llu pixels: NaN produced %llu, division by zero %llu, "
                     "built-in outside its domain %llu\n",
                     (unsigned long long)undefined.pixels, (unsigned long long)undefined.per_case[0],
                     (unsigned long long)undefined.per_case[1], (unsigned long long)undefined.per_case[2]);
    }
    return 0;
}

int cmd_shaders(const std::string& export_dir) {
    if (!export_dir.empty()) {
        const int n = export_glsl(export_dir);
        std::printf("wrote the GLSL of %d shaders to %s\n", n, export_dir.c_str());
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
    std::printf("%-26s %-11s %-11s %-7s %-4s %s\n", "name", "coordinates", "derivatives", "texture", "time",
                "description");
    for (const auto& [collection, programs] : catalogue_by_collection()) {
        std::printf("\n%s\n", collection.c_str());
        for (const Program* p : programs) {
            const ShaderInfo& s = p->info();
            std::printf("  %-24s %-11s %-11s %-7s %-4s %s\n", std::string(s.name).c_str(),
                        coordinates(s.needs.coordinates), s.needs.derivatives ? "yes" : "-",
                        samples_textures(s.needs) ? "yes" : "-", s.needs.time ? "yes" : "-",
                        std::string(s.description).c_str());
        }
    }
    return 0;
}

int cmd_bake_volume(const VolumeArgs& a) {
    VolumeRequest req;
    req.shader = a.shader, req.size = a.size;
    req.frame.time = a.time.value_or(0.0);
    req.frame.shading.derivatives = a.derivatives;
    req.frame.shading.threads = a.threads;
    for (const std::string& u : a.uniforms) req.frame.uniforms.push_back(parse_uniform_option(u));
    std::optional<Scene> scene;
    if (!a.scene.empty()) {
        SceneLoadOptions load;
        load.paths.allow_outside = a.allow_outside;
        scene = load_scene(a.scene, load);
        if (scene->objects.empty()) throw UsageError("--scene " + a.scene + ": has no object to take a material from");
        req.material_scene = &*scene;
    }
    check_output(a.output, scene ? scene->inputs : std::vector<fs::path>{}, "-o");
    const Program* program = find_program(a.shader);
    if (!program) throw UsageError("--shader: no shader named '" + a.shader + "' (quadshade shaders lists them)");
    const auto t0 = std::chrono::steady_clock::now();
    const Image volume = bake_volume(req);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    write_image(a.output, volume,
                {{"quadshade:shader", a.shader},
                 {"quadshade:volume", std::to_string(a.size) + "^3: slice k is rows [k N, (k + 1) N); texel centres at "
                                                               "object positions -1 + 2 (i + 0.5) / N"},
                 {"quadshade:time", std::to_string(*req.frame.time)},
                 {"quadshade:derivatives", rule_name(a.derivatives)}},
                true);
    std::fprintf(stderr, "quadshade: %s: %d^3 texels of %s in %.1f ms (as a sampler3D: \"depth\": %d)\n", a.output.c_str(),
                 a.size, a.shader.c_str(), seconds * 1e3, a.size);
    return 0;
}

int cmd_gallery(const GalleryArgs& a) {
    GalleryRequest request;
    request.tile = a.size, request.columns = a.columns;
    request.frame.time = a.time;
    request.frame.shading.threads = a.threads;
    if (a.scenes.empty()) {
        const fs::path folder = installed_scenes_folder();
        for (const char* name : {"table-1.1-plane.gltf", "seed-004-plane.gltf", "solids.gltf", "seed-001-spheres.gltf"}) {
            if (!fs::exists(folder / name)) throw std::runtime_error((folder / name).string() + ": missing (an incomplete installation?)");
            request.scenes.push_back(folder / name);
        }
        std::vector<fs::path> conformance;
        for (const fs::directory_entry& e : fs::directory_iterator(folder / "conformance")) {
            if (e.path().extension() == ".gltf" || e.path().extension() == ".glb") conformance.push_back(e.path());
        }
        std::sort(conformance.begin(), conformance.end());
        request.scenes.insert(request.scenes.end(), conformance.begin(), conformance.end());
    } else {
        request.scenes.assign(a.scenes.begin(), a.scenes.end());
    }
    const fs::path out = a.output;
    std::error_code ec;
    if (fs::exists(out, ec) && !fs::is_directory(out, ec)) throw UsageError(a.output + ": not a folder");
    const std::vector<GallerySheet> sheets = render_gallery(request);
    fs::create_directories(out);
    std::vector<std::string> stems;
    for (const GallerySheet& sheet : sheets) {
        std::string stem = gallery_file_stem(sheet.collection);
        const std::string base = stem;
        for (int k = 2; std::find(stems.begin(), stems.end(), stem) != stems.end(); ++k) stem = base + "-" + std::to_string(k);
        stems.push_back(stem);
        const fs::path file = out / (stem + ".png");
        write_image(file, sheet.image, {{"quadshade:gallery", sheet.collection}});
        std::size_t undrawn = 0;
        for (const auto& [name, scene] : sheet.drawn) undrawn += scene.empty();
        std::printf("%s: %s, %zu shaders%s\n", file.c_str(), sheet.collection.c_str(), sheet.drawn.size(),
                    undrawn ? (" (" + std::to_string(undrawn) + " without a scene that binds their textures)").c_str() : "");
    }
    return 0;
}

int cmd_bake(const BakeArgs& a) {
    const fs::path output(a.output);
    if (output.extension() != ".gltf") throw UsageError("-o " + a.output + ": the baked scene is written as .gltf");
    bool height = false, normal = false, color = false;
    for (const std::string& map : a.maps) {
        if (map != "color" && map != "height" && map != "normal") {
            throw UsageError("--maps: '" + map + "' is not a map bake makes (color, height, normal)");
        }
        bool& wanted = map == "color" ? color : map == "height" ? height : normal;
        if (wanted) throw UsageError("--maps: '" + map + "' is named twice");
        wanted = true;
    }
    if (!color) throw UsageError("--maps: color is required (the baked scene is drawn with it)");
    if (!normal && (a.normals_option->count() || a.normal_step || a.precision_option->count())) {
        throw UsageError("--normals, --normal-step and --normal-precision make the normal map: add normal to --maps");
    }
    if (a.normal_step && a.normals != NormalMethod::FiniteDifferences) {
        throw UsageError("--normal-step is the finite differences' step: it needs --normals finite");
    }
    const HeightField* field = nullptr;
    if (height || normal) {
        field = find_height_field(a.shader);
        if (!field) {
            std::string with;
            for (const HeightField* f : height_fields()) with += (with.empty() ? "" : ", ") + std::string(f->shader());
            throw UsageError("--maps " + std::string(normal ? "normal" : "height") + ": shader '" + a.shader +
                             "' has no height (shaders with one: " + (with.empty() ? "none in this build" : with) + ")");
        }
    }
    SceneLoadOptions load;
    load.paths.allow_outside = a.allow_outside;
    Scene scene = load_scene(a.mesh, load);
    const std::string stem = output.stem().string();
    const std::string bin = stem + ".bin", color_file = stem + "-color.png", height_file = stem + "-height.png",
                      normal_file = stem + "-normal.png";
    check_output(output, scene.inputs, "-o");
    check_output(output.parent_path() / bin, scene.inputs, "-o (its buffer)");
    check_output(output.parent_path() / color_file, scene.inputs, "-o (its texture)");
    if (height) check_output(output.parent_path() / height_file, scene.inputs, "-o (its height map)");
    if (normal) check_output(output.parent_path() / normal_file, scene.inputs, "-o (its normal map)");
    const Program* program = find_program(a.shader);
    if (!program) throw UsageError("--shader: no shader named '" + a.shader + "' (quadshade shaders lists them)");

    AtlasRequest req;
    req.size = a.size;
    req.skirt = a.skirt;
    req.frame.shader_override = a.shader;
    if (a.time) req.frame.time = *a.time;
    req.frame.shading.derivatives = a.derivatives;
    req.frame.shading.threads = a.threads;
    for (const std::string& u : a.uniforms) req.frame.uniforms.push_back(parse_uniform_option(u));
    auto clock = std::chrono::steady_clock::now;
    auto ms_since = [](auto t0) { return 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
    auto t0 = clock();
    const Image atlas = bake_atlas(scene, req);
    const double color_ms = ms_since(t0);
    // Every map is made before any file is written: an error leaves no output.
    Image height_map, normal_map;
    double height_ms = 0.0, normal_ms = 0.0;
    if (height) {
        AtlasRequest h = req;
        h.frame.shader_override = std::string(field->height_shader());
        t0 = clock();
        height_map = bake_atlas(scene, h);
        height_ms = ms_since(t0);
    }
    NormalBakeRequest n;
    n.size = a.size, n.skirt = a.skirt, n.method = a.normals, n.precision = a.normal_precision, n.threads = a.threads;
    if (a.normal_step) n.step = *a.normal_step;
    if (normal) {
        t0 = clock();
        normal_map = bake_normal_map(scene, *field, n);
        normal_ms = ms_since(t0);
    }

    OutputSet out(output);
    const Metadata common = {{"quadshade:shader", a.shader},
                             {"quadshade:time", std::to_string(req.frame.time.value_or(double(scene.time)))},
                             {"quadshade:skirt", std::to_string(a.skirt)}};
    Metadata meta = common;
    meta.push_back({"quadshade:atlas", "the shader at each texel's surface point (TEXCOORD_0); row 0 is t = 0"});
    meta.push_back({"quadshade:derivatives", rule_name(a.derivatives)});
    write_image(out.staged(color_file), atlas, meta, true);
    if (height) {
        meta = common;
        meta.push_back({"quadshade:atlas", "the height of " + a.shader + " (" + std::string(field->height_shader()) +
                                               "), 0 to 1 for 0 to " + std::to_string(field->amplitude()) +
                                               " object units of relief; row 0 is t = 0"});
        write_image(out.staged(height_file), height_map, meta, true);
    }
    if (normal) {
        meta = common;
        meta.push_back({"quadshade:atlas", "object-space unit normals as 0.5 + 0.5 n (not tangent-space), alpha 0 in the "
                                           "gutter; row 0 is t = 0"});
        meta.push_back({"quadshade:normals", n.method == NormalMethod::Analytic
                                                 ? "analytic (Dual2)"
                                                 : "finite differences, step " + std::to_string(n.step) + " object units"});
        meta.push_back({"quadshade:precision", n.precision == Precision::Double ? "double" : "float"});
        write_image(out.staged(normal_file), normal_map, meta, true);
    }
    const Scene baked = baked_scene(scene, out.staged(color_file), normal ? out.staged(normal_file) : fs::path(),
                                    height ? out.staged(height_file) : fs::path());
    save_scene(baked, out.staged(output.filename().string()));
    out.commit(output.filename().string());
    std::fprintf(stderr, "quadshade: %s: %s baked into a %dx%d atlas in %.1f ms (%s)", a.output.c_str(), a.shader.c_str(),
                 a.size, a.size, color_ms, color_file.c_str());
    if (height) std::fprintf(stderr, ", its height in %.1f ms (%s)", height_ms, height_file.c_str());
    if (normal) std::fprintf(stderr, ", its normal map in %.1f ms (%s)", normal_ms, normal_file.c_str());
    std::fputc('\n', stderr);
    return 0;
}

int cmd_compare(const CompareArgs& a) {
    std::vector<fs::path> inputs;  // each image's entry and, if it is a link, what it points to
    for (const std::string& image : a.images) {
        std::error_code ec;
        inputs.insert(inputs.end(), {resolved(image), fs::weakly_canonical(image, ec)});
    }
    if (!a.heat.empty()) check_output(a.heat, inputs, "--heat-map");
    if (!a.side.empty()) check_output(a.side, inputs, "--side-by-side");
    // Per pixel: both images and their copies inside the comparison (4 x 16 bytes), the heat
    // map with its two intermediates (48) and the side-by-side strip (48).
    constexpr std::uint64_t kBytesPerPixel = 160;
    ImageReadLimits limits;
    limits.max_pixels = std::min<std::uint64_t>(limits.max_pixels, memory_limit(a.memory_limit) / kBytesPerPixel);
    const Image A = read_image(a.images[0], limits), B = read_image(a.images[1], limits);
    // A margin of half a step: 8-bit values differ by whole multiples of 1/255.
    const Comparison c = compare_images(A, B, (a.fail + 0.5f) / 255.0f, (1.0f + 0.5f) / 255.0f);
    std::printf("mean %.6f  rms %.6f  psnr %.2f dB  max %.1f/255 at (%d, %d) channel %d\n", c.mean_error, c.rms_error,
                c.psnr, c.max_error * 255.0, c.max_x, c.max_y, c.max_channel);
    std::printf("pixels over %g/255: %llu   over 1/255: %llu   of %d\n", double(a.fail),
                (unsigned long long)c.pixels_over_fail, (unsigned long long)c.pixels_over_warn, A.width * A.height);
    if (!a.heat.empty() || !a.side.empty()) {
        const Image heat = difference_heat_map(A, B, 8.0f / 255.0f);
        if (!a.heat.empty()) write_image(a.heat, heat);
        if (!a.side.empty()) write_image(a.side, side_by_side({&A, &B, &heat}));
    }
    return (long long)c.pixels_over_fail > a.max_failing ? kExitDifferent : 0;
}

int cmd_check(const CheckArgs& a) {
    if (a.all == !a.shaders.empty()) throw UsageError("check: name the shaders to check, or --all (not both)");
    CheckRequest request;
    request.shaders = a.shaders;
    request.scenes = a.scenes;
    request.output = a.output;
    request.jobs = a.jobs;
    request.rules.clear();
    for (const std::string& rule : a.rules) {
        if (rule == "fine") request.rules.push_back(CheckRule::Fine);
        else if (rule == "coarse-lower" || rule == "coarse") request.rules.push_back(CheckRule::CoarseLower);
        else throw UsageError("--rules: '" + rule + "' has no OSMesa reference (fine: llvmpipe, coarse-lower: softpipe)");
    }
    return run_check(request);
}

int cmd_test(const TestArgs& a) {
    std::vector<fs::path> inputs;  // the suite or the fragments, and what a link among them points to
    for (const std::string& input : a.inputs) {
        std::error_code ec;
        inputs.insert(inputs.end(), {resolved(input), fs::weakly_canonical(input, ec)});
    }
    if (!a.junit.empty()) check_output(a.junit, inputs, "--junit");
    if (!a.report.empty()) check_output(a.report, inputs, "--report");
    SuiteRun run;
    if (a.merge) {
        if (a.update || !a.shard.empty() || !a.report.empty() || a.jobs) throw UsageError("--merge: only with --junit and --html");
        run = merge_fragments({a.inputs.begin(), a.inputs.end()});
    } else {
        if (a.inputs.size() != 1) throw UsageError("test: one suite file (or --merge FRAGMENT...)");
        SuiteRequest request;
        request.suite = a.inputs[0];
        request.update = a.update;
        request.jobs = a.jobs;
        if (!a.shard.empty()) {
            int k = 0, n = 0;
            char slash = 0, rest = 0;
            if (std::sscanf(a.shard.c_str(), "%d%c%d%c", &k, &slash, &n, &rest) != 3 || slash != '/' || n < 1 || k < 1 || k > n || n > 100000) {
                throw UsageError("--shard: expected K/N with 1 <= K <= N, got '" + a.shard + "'");
            }
            request.shard = k, request.shards = n;
        }
        run = run_suite(request);
        if (!a.report.empty()) write_fragment(run, a.report);
    }
    if (!a.junit.empty()) write_junit(run, a.junit);
    if (!a.html.empty()) write_html(run, a.html);
    return summarize(run);
}

}  // namespace

int main(int argc, char** argv) {
    remove_temporaries_on_signals();
    CLI::App app("quadshade: CPU renderer of GLSL-style procedural shaders with GPU-exact derivatives", "quadshade");
    app.require_subcommand(1, 1);
    app.get_formatter()->column_width(26);
    RenderArgs render;
    CompareArgs compare;
    CLI::App* render_cmd = app.add_subcommand("render", "render a glTF scene");
    add_render_options(*render_cmd, render);
    CLI::App* shaders_cmd = app.add_subcommand("shaders", "list the shader catalogue, with what each shader needs");
    std::string export_dir;
    std::vector<std::string> shader_plugins;
    add_plugin_option(*shaders_cmd, shader_plugins);
    shaders_cmd->add_option("--export-glsl", export_dir,
                            "write each shader's complete GLSL (DIR/NAME.vert, DIR/NAME.frag) as an OpenGL program "
                            "compiles it (quadshade-reference --glsl DIR renders scenes from it)")
        ->option_text("DIR");
    CLI::App* compare_cmd = app.add_subcommand(
        "compare", "compare two images' RGB with OpenImageIO: mean, RMS, PSNR and the largest error");
    add_compare_options(*compare_cmd, compare);
    CheckArgs check;
    CLI::App* check_cmd = app.add_subcommand(
        "check", "render shaders with quadshade and their GLSL with OSMesa (quadshade-reference) on a\n"
                 "set of scenes and compare: exit 0 when every case meets the bar, 3 otherwise");
    add_check_options(*check_cmd, check);
    TestArgs test;
    CLI::App* test_cmd = app.add_subcommand(
        "test", "run a golden-image suite: render its cases, compare with the expected images, report\n"
                "(exit 3 when a case fails)");
    add_test_options(*test_cmd, test);
    VolumeArgs volume;
    CLI::App* volume_cmd = app.add_subcommand(
        "bake-volume", "evaluate a shader on an N^3 grid of object positions into a 3D texture (a sampler3D)");
    add_volume_options(*volume_cmd, volume);
    GalleryArgs gallery;
    CLI::App* gallery_cmd = app.add_subcommand(
        "gallery", "render every catalogue shader into labelled contact sheets, one PNG per collection (seed)");
    add_gallery_options(*gallery_cmd, gallery);
    BakeArgs bake;
    CLI::App* bake_cmd = app.add_subcommand(
        "bake", "render a shader into a mesh's UV atlas (each triangle at its TEXCOORD_0) and write the\n"
                "mesh drawn with the baked texture");
    add_bake_options(*bake_cmd, bake);
    CLI::App* help_cmd = app.add_subcommand("help", "this help");
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "quadshade: %s\n\n%s", e.what(), app.help().c_str());
        return kExitUsage;
    }
    for (const char* option : kRasterOnly) {
        if (render_cmd->count(option) > 0) render.raster_only.emplace_back(option);
    }
    try {
        if (render_cmd->parsed()) return cmd_render(render);  // loads its plugins once its options are checked
        const std::vector<std::string>& plugins = check_cmd->parsed()    ? check.plugins
                                                  : test_cmd->parsed()   ? test.plugins
                                                  : volume_cmd->parsed() ? volume.plugins
                                                  : gallery_cmd->parsed() ? gallery.plugins
                                                  : bake_cmd->parsed()   ? bake.plugins
                                                                         : shader_plugins;
        for (const std::string& plugin : plugins) load_plugin(plugin);
        if (shaders_cmd->parsed()) return cmd_shaders(export_dir);
        if (compare_cmd->parsed()) return cmd_compare(compare);
        if (check_cmd->parsed()) return cmd_check(check);
        if (test_cmd->parsed()) return cmd_test(test);
        if (volume_cmd->parsed()) return cmd_bake_volume(volume);
        if (gallery_cmd->parsed()) return cmd_gallery(gallery);
        if (bake_cmd->parsed()) return cmd_bake(bake);
        if (help_cmd->parsed()) std::fputs(app.get_formatter()->make_help(&app, "quadshade", CLI::AppFormatMode::Normal).c_str(), stdout);
        return 0;
    } catch (const UsageError& e) {
        std::fprintf(stderr, "quadshade: %s\n", e.what());
        return kExitUsage;
    } catch (const UniformOptionError& e) {  // a bad --uniform, or one no drawn shader takes
        std::fprintf(stderr, "quadshade: %s\n", e.what());
        return kExitUsage;
    } catch (const UnsupportedRequest& e) {  // options no backend honours together
        std::fprintf(stderr, "quadshade: %s\n", e.what());
        return kExitUsage;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "quadshade: %s\n", e.what());
        return kExitInput;
    }
}
