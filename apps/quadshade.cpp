// quadshade: the command line. Parses arguments (CLI11) and calls the libraries; nothing else.
// Each subcommand's options and command are in their own file (render_command, bake_commands);
// the small ones (shaders, compare, check, test, gallery) are here.
//
// Exit codes: 0 success, 1 bad input or failed render (message on stderr), 2 bad usage,
// 3 `compare` found differences over its thresholds, a `check` case missed its bar, or a `test`
// case failed.

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "apps/bake_commands.h"
#include "apps/command_line.h"
#include "apps/render_command.h"
#include "apps/shader_test_command.h"
#include "apps/study_command.h"
#include "apps/translate_command.h"
#include "files/output_file.h"
#include "files/temporary_file.h"
#include "images/image_io.h"
#include "regression/check.h"
#include "regression/golden_suite.h"
#include "regression/suite_reports.h"
#include "render/gallery.h"
#include "render/glsl_shaders.h"
#include "render/plugins.h"
#include "scenes/gltf.h"
#include "scenes/uniforms.h"
#include "shading/catalogue.h"
#include "shading/glsl_export.h"

namespace {

using namespace qs;
using namespace qs::app;
namespace fs = std::filesystem;

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
    std::vector<std::string> shaders, rules{"fine"}, plugins, scenes;
    bool all = false, interpret = false, compile_glsl = false;
    std::string glsl, vertex_glsl;
    std::string output = "quadshade-check", memory_limit;
    int jobs = 0, width = 0, height = 0;
};

void add_check_options(CLI::App& cmd, CheckArgs& a) {
    cmd.add_option("shaders", a.shaders, "the shaders to check (catalogue names)")->option_text("SHADER...");
    cmd.add_flag("--all", a.all, "check every shader of the catalogue, plugins' included (not the\nbuilt-in probes)");
    cmd.add_option("--scenes", a.scenes,
                   "check on these scenes: .gltf/.glb files, and folders standing for\n"
                   "every scene in them (repeatable; default: the conformance scenes\n"
                   "and the Table 1.1 plane)")
        ->option_text("SCENE|DIR ...");
    cmd.add_option_function<std::vector<int>>(
           "--size", [&a](const std::vector<int>& v) { a.width = v[0], a.height = v[1]; },
           "render every case at this size (default: each scene's own)")
        ->delimiter('x')->expected(2)->check(CLI::Range(1, 16384))->option_text("WxH");
    cmd.add_option("--rules", a.rules,
                   "derivative rules, each against its OSMesa driver: fine (llvmpipe,\n"
                   "default), coarse-lower (softpipe)")
        ->delimiter(',')->option_text("R,...");
    cmd.add_option("-o,--output", a.output,
                   "folder for the exported GLSL, report.csv and the heat maps\n(default quadshade-check)")
        ->option_text("DIR");
    cmd.add_option("--jobs", a.jobs, "cases checked at once, each a reference process and a render\n(default: one per core)")
        ->check(CLI::Range(1, 1024))->option_text("N");
    add_glsl_options(cmd, a.glsl, a.vertex_glsl, a.compile_glsl);
    cmd.add_flag("--interpret", a.interpret,
                 "check the shaders' GLSL run by the interpreter (as --glsl runs a\nfile) instead of their translations");
    cmd.add_option(
           "--memory-limit", a.memory_limit,
           "memory the cases checked at once may use together, e.g. 4G (default: what the\nsystem has available)")
        ->option_text("SIZE");
    add_plugin_option(cmd, a.plugins);
}

struct TestArgs {
    std::vector<std::string> inputs, plugins;
    bool update = false, merge = false, allow_outside = false, compile_glsl = false;
    int jobs = 0;
    std::string junit, html, shard, report, memory_limit;
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
    cmd.add_flag("--allow-outside-paths", a.allow_outside,
                 "let the suite name scenes and expected images outside its own folder (and --merge --html\n"
                 "read images outside each fragment's folder); by default only files beside it");
    cmd.add_flag("--compile", a.compile_glsl, kCompileHelp);
    cmd.add_option("--memory-limit", a.memory_limit,
                   "memory the cases rendered at once may use together, e.g. 4G (default: what the system\n"
                   "has available)")
        ->option_text("SIZE");
    add_plugin_option(cmd, a.plugins);
}

struct GalleryArgs {
    std::string output;
    std::vector<std::string> scenes, plugins, glsl;
    bool compile_glsl = false;
    int size = 160, columns = 6, threads = 0;
    double time = 1.0;
};

void add_gallery_options(CLI::App& cmd, GalleryArgs& a) {
    cmd.add_option("output", a.output, "the folder for the sheets, one PNG per collection (made if missing)")
        ->required()->option_text("OUT_DIR");
    cmd.add_option("--size", a.size, "each shader's square in pixels (default 160)")->check(CLI::Range(16, 1024))->option_text("N");
    cmd.add_option("--columns", a.columns, "squares per row, at most (default 6)")->check(CLI::Range(1, 64))->option_text("N");
    cmd.add_option("--scenes", a.scenes,
                   "scenes to draw on, in order of preference (default: the installed Table 1.1 plane, Lawlor's\n"
                   "plane, the solids, the ProcTexGen spheres and the conformance scenes); a shader goes on the first\n"
                   "that binds its textures")
        ->option_text("SCENE...");
    cmd.add_option("--time", a.time, "the `time` uniform in seconds (default 1)")->check(kFinite)->option_text("T");
    cmd.add_option("--glsl", a.glsl, "GLSL fragment shaders to draw instead of the catalogue, on one sheet (docs/glsl.md)")
        ->option_text("FRAG...");
    cmd.add_flag("--compile", a.compile_glsl, kCompileHelp);
    add_plugin_option(cmd, a.plugins);
    cmd.add_option("--threads", a.threads, "worker threads (default: all cores)")->check(CLI::Range(1, 1024))->option_text("N");
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

int cmd_gallery(const GalleryArgs& a) {
    GalleryRequest request;
    for (const std::string& file : a.glsl) {
        const GlslShader shader = load_glsl_shader(file, std::nullopt, glsl_way(a.compile_glsl), {shade_request(request.frame)});
        for (const std::string& w : shader.warnings) std::fprintf(stderr, "quadshade: %s\n", w.c_str());
        request.collections = {kGlslCollection};
    }
    request.tile = a.size, request.columns = a.columns;
    request.frame.time = a.time;
    request.frame.shading.threads = a.threads;
    if (a.scenes.empty()) {
        const fs::path folder = installed_scenes_folder();
        for (const char* name : {"table-1.1-plane.gltf", "lawlor-plane.gltf", "solids.gltf", "proctexgen-spheres.gltf"}) {
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
    CheckRequest request;
    request.shaders = a.shaders;
    std::string glsl;
    if (use_glsl_options(a.glsl, a.vertex_glsl, a.compile_glsl, glsl)) request.shaders.push_back(glsl);
    if (a.all == !request.shaders.empty()) throw UsageError("check: name the shaders to check, or --all, or --glsl (one of them)");
    if (a.interpret) {
        // The GLSL of each shader to check, run by the interpreter, in its translation's place.
        if (request.shaders.empty()) {
            for (const Program* p : catalogue()) {
                if (!std::string_view(p->info().name).ends_with("_probe")) request.shaders.emplace_back(p->info().name);
            }
        }
        for (std::string& name : request.shaders) name = interpreted_twin(name);
    }
    request.scenes.assign(a.scenes.begin(), a.scenes.end());
    request.width = a.width, request.height = a.height;
    request.output = a.output;
    request.jobs = a.jobs;
    if (!a.memory_limit.empty()) request.memory_limit = memory_limit(a.memory_limit);
    request.rules.clear();
    for (const std::string& rule : a.rules) {
        if (rule == "fine") request.rules.push_back(CheckRule::Fine);
        else if (rule == "coarse-lower" || rule == "coarse") request.rules.push_back(CheckRule::CoarseLower);
        else throw UsageError("--rules: '" + rule + "' has no OSMesa reference (fine: llvmpipe, coarse-lower: softpipe)");
    }
    return run_check(request);
}

// "K/N" with 1 <= K <= N <= kSuiteShards, nothing else (no wrapping: 4294967297 is not 1).
bool parse_shard(const std::string& text, int& k, int& n) {
    const std::size_t slash = text.find('/');
    if (slash == std::string::npos) return false;
    auto number = [](std::string_view t, int& v) {
        const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
        return !t.empty() && ec == std::errc() && end == t.data() + t.size();
    };
    return number(std::string_view(text).substr(0, slash), k) && number(std::string_view(text).substr(slash + 1), n) &&
           k >= 1 && k <= n && n <= kSuiteShards;
}

int cmd_test(const TestArgs& a) {
    const std::uint64_t memory = a.memory_limit.empty() ? 0 : memory_limit(a.memory_limit);
    // What no report may be written over: the suite or fragments, what the suite reads, and every
    // file a case reads or writes (expected images, a failure's actual and difference images).
    InputFiles taken;
    for (const std::string& input : a.inputs) taken.add(input);
    auto take_case_files = [&](const fs::path& expected, const fs::path& actual, const fs::path& diff) {
        for (const fs::path* f : {&expected, &actual, &diff}) {
            if (!f->empty()) taken.add(*f);
        }
    };
    // The reports, each checked against those and against the reports before it.
    auto check_reports = [&](const std::vector<fs::path>& html) {
        InputFiles reports;
        auto check = [&](const fs::path& file, const char* option, Streams streams) {
            check_output(file, taken, option, streams);
            if (output_place(file, streams) == OutputPlace::File && reports.contains(file)) {
                throw UsageError(std::string(option) + " " + file.string() +
                                 ": another report of this run is written there");
            }
            reports.add(file);
        };
        if (!a.junit.empty()) check(a.junit, "--junit", Streams::Allowed);
        if (!a.report.empty()) check(a.report, "--report", Streams::Allowed);
        if (std::error_code ec; !a.html.empty() && fs::exists(a.html, ec) && !fs::is_directory(a.html, ec)) {
            throw UsageError("--html " + a.html + ": is not a folder");
        }
        for (const fs::path& file : html) check(file, "--html", Streams::Refused);
    };
    SuiteRun run;
    if (a.merge) {
        if (a.update || !a.shard.empty() || !a.report.empty() || a.jobs) throw UsageError("--merge: only with --junit and --html");
        MergeOptions options;
        options.reads_images = !a.html.empty();
        options.allow_outside = a.allow_outside;
        options.memory_limit = memory;
        run = merge_fragments({a.inputs.begin(), a.inputs.end()}, options);
        for (const CaseResult& r : run.results) take_case_files(r.expected, r.actual, r.diff);
        check_reports(a.html.empty() ? std::vector<fs::path>{} : html_files(run, a.html));
    } else {
        if (a.inputs.size() != 1) throw UsageError("test: one suite file (or --merge FRAGMENT...)");
        SuiteRequest request;
        request.update = a.update;
        request.jobs = a.jobs;
        request.load.allow_outside = a.allow_outside;
        request.load.memory_limit = memory;
        request.load.glsl_way = glsl_way(a.compile_glsl);
        if (!a.shard.empty() && !parse_shard(a.shard, request.shard, request.shards)) {
            throw UsageError("--shard: expected K/N with 1 <= K <= N <= " + std::to_string(kSuiteShards) + ", got '" +
                             a.shard + "'");
        }
        Suite suite = load_suite(a.inputs[0], request.load);
        add_scene_inputs(suite, request.load);
        for (const std::string& input : a.inputs) suite.inputs.add(input);
        taken = suite.inputs;
        for (const SuiteCase& c : suite.cases) take_case_files(c.expected, c.actual, c.diff);
        check_reports(a.html.empty() ? std::vector<fs::path>{} : html_files(suite, a.html));
        run = run_suite(suite, request);
        if (!a.report.empty()) write_fragment(run, a.report);
    }
    if (!a.junit.empty()) write_junit(run, a.junit);
    if (!a.html.empty()) write_html(run, a.html);
    return summarize(run);
}

}  // namespace

namespace {

// A subcommand: its options (held by the lambda), the plugins to load before it runs (render loads
// its own once its options are checked) and what it runs.
struct Command {
    CLI::App* app;
    const std::vector<std::string>* plugins;
    std::function<int()> run;
};

// The subcommand `name` with the options add_options gives it into `args`, run by `run(args)`.
template <class Args, class AddOptions, class Run>
Command command(CLI::App& app, const char* name, const char* about, AddOptions add_options, Run run,
                const std::vector<std::string> Args::*plugins = nullptr) {
    auto args = std::make_shared<Args>();
    CLI::App* sub = app.add_subcommand(name, about);
    add_options(*sub, *args);
    return {sub, plugins ? &((*args).*plugins) : nullptr, [args, run] { return run(*args); }};
}

struct ShadersArgs {
    std::string export_dir;
    std::vector<std::string> plugins;
};

std::vector<Command> add_commands(CLI::App& app) {
    std::vector<Command> c;
    c.push_back(command<RenderArgs>(
        app, "render", "render a glTF scene", add_render_options, [&app](RenderArgs& a) {
            note_raster_only(*app.get_subcommand("render"), a);
            return cmd_render(a);
        }));
    c.push_back(command<ShadersArgs>(
        app, "shaders", "list the shader catalogue, with what each shader needs",
        [](CLI::App& sub, ShadersArgs& a) {
            add_plugin_option(sub, a.plugins);
            sub.add_option("--export-glsl", a.export_dir,
                           "write each shader's complete GLSL (DIR/NAME.vert, DIR/NAME.frag) as an OpenGL program "
                           "compiles it (quadshade-reference --glsl DIR renders scenes from it)")
                ->option_text("DIR");
        },
        [](ShadersArgs& a) { return cmd_shaders(a.export_dir); }, &ShadersArgs::plugins));
    c.push_back(command<CompareArgs>(app, "compare",
                                     "compare two images' RGB with OpenImageIO: mean, RMS, PSNR and the largest error",
                                     add_compare_options, cmd_compare));
    c.push_back(command<CheckArgs>(
        app, "check",
        "render shaders with quadshade and their GLSL with OSMesa (quadshade-reference) on a\n"
        "set of scenes and compare: exit 0 when every case meets the bar, 3 otherwise",
        add_check_options, cmd_check, &CheckArgs::plugins));
    c.push_back(command<TestArgs>(app, "test",
                                  "run a golden-image suite: render its cases, compare with the expected images, report\n"
                                  "(exit 3 when a case fails)",
                                  add_test_options, cmd_test, &TestArgs::plugins));
    c.push_back(command<VolumeArgs>(
        app, "bake-volume", "evaluate a shader on an N^3 grid of object positions into a 3D texture (a sampler3D)",
        add_volume_options, cmd_bake_volume, &VolumeArgs::plugins));
    c.push_back(command<GalleryArgs>(
        app, "gallery", "render every catalogue shader into labelled contact sheets, one PNG per collection (source)",
        add_gallery_options, cmd_gallery, &GalleryArgs::plugins));
    c.push_back(command<BakeArgs>(app, "bake",
                                  "render a shader into a mesh's UV atlas (each triangle at its TEXCOORD_0) and write the\n"
                                  "mesh drawn with the baked texture",
                                  add_bake_options, cmd_bake, &BakeArgs::plugins));
    c.push_back(command<StudyArgs>(app, "study",
                                   "measure a shader's error against its run time under every derivative, anti-aliasing\n"
                                   "and precision mode, on the scene's camera and generated views; writes CSV and a report",
                                   [](CLI::App& sub, StudyArgs& a) { add_study_options(sub, a); }, cmd_study,
                                   &StudyArgs::plugins));
    c.push_back(command<TranslateArgs>(
        app, "translate",
        "write a GLSL shader as a C++ translation to read, edit and build as a plugin (with a\n"
        "CMakeLists.txt that builds it against the installed quadshade)",
        add_translate_options, cmd_translate));
    c.push_back(command<ShaderTestArgs>(
        app, "shader-test",
        "run piglit's .shader_test files with quadshade as the GL driver: a line per test, a\n"
        "summary by folder and skip reason (exit 3 when a test fails or crashes)",
        add_shader_test_options, cmd_shader_test));
    struct NoArgs {};
    c.push_back(command<NoArgs>(
        app, "help", "this help", [](CLI::App&, NoArgs&) {},
        [&app](NoArgs&) {
            std::fputs(app.get_formatter()->make_help(&app, "quadshade", CLI::AppFormatMode::Normal).c_str(), stdout);
            return 0;
        }));
    return c;
}

// A usage error (exit 2): options that contradict each other or name what the scene lacks.
bool is_usage_error(const std::exception& e) {
    return dynamic_cast<const UsageError*>(&e) || dynamic_cast<const UniformOptionError*>(&e) ||
           dynamic_cast<const CameraOptionError*>(&e) || dynamic_cast<const UnsupportedRequest*>(&e);
}

}  // namespace

int main(int argc, char** argv) {
    remove_temporaries_on_signals();
    CLI::App app("quadshade: CPU renderer of GLSL procedural shaders with GPU-exact derivatives", "quadshade");
    app.require_subcommand(1, 1);
    app.get_formatter()->column_width(26);
    const std::vector<Command> commands = add_commands(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "quadshade: %s\n\n%s", e.what(), app.help().c_str());
        return kExitUsage;
    }
    try {
        for (const Command& c : commands) {
            if (!c.app->parsed()) continue;
            for (const std::string& plugin : c.plugins ? *c.plugins : std::vector<std::string>{}) {
                for (const std::string& warning : load_plugin(plugin)) std::fprintf(stderr, "quadshade: warning: %s\n", warning.c_str());
            }
            return c.run();
        }
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "quadshade: %s\n", e.what());
        return is_usage_error(e) ? kExitUsage : kExitInput;
    }
}
