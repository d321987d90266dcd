#include "apps/render_command.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "apps/command_line.h"
#include "images/image_io.h"
#include "render/frame_pattern.h"
#include "render/memory_plan.h"
#include "render/plugins.h"
#include "render/undefined_mask.h"
#include "scenes/scene_files.h"
#include "scenes/uniforms.h"

namespace qs::app {

namespace fs = std::filesystem;

namespace {

// Options only the rasterizer has: the ray caster refuses them, even at their default values,
// rather than render something the command line did not describe.
const char* const kRasterOnly[] = {"--fill-rule", "--interpolation", "--general-path"};

// What is drawn: the scene and its output, when, from which camera, with which shaders.
void add_scene_options(CLI::App& cmd, RenderArgs& a) {
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
    cmd.add_option("--time", r.time, "the `time` uniform and the animations' time, in seconds (default: the scene's)")
        ->check(kFinite)
        ->option_text("T");
    cmd.add_option("--frames", a.frames, "render frames A..B (inclusive) at time = frame / fps")
        ->delimiter(':')->check(CLI::Range(0, 1000000))->option_text("A:B");
    cmd.add_option("--fps", a.fps, "frames per second for --frames (default 30)")
        ->check(kFinite & CLI::PositiveNumber)->option_text("N");
    cmd.add_option("--shader", r.shader_override, "draw every object with this catalogue shader")->option_text("NAME");
    add_glsl_options(cmd, a.glsl, a.vertex_glsl, a.compile_glsl);
    cmd.add_option("--camera", a.load.camera,
                   "the camera to render from: a camera node's or camera's name, or an\n"
                   "index into the file's cameras[] (default: the first camera node)")
        ->option_text("NAME|INDEX");
    add_plugin_option(cmd, a.plugins);
    cmd.add_option("--uniform", a.uniforms,
                   "a shader's own uniform, for every object whose shader declares it\n"
                   "(replaces the material's extras.uniforms): 4.0, 1,0.5,0.2 or [1,0.5,0.2];\n"
                   "matrices column by column; repeatable")
        ->option_text("NAME=VALUE")->allow_extra_args(false);
}

// How it is drawn: the backend and the rules of derivatives, precision, quads, fill and
// interpolation.
void add_rule_options(CLI::App& cmd, RenderArgs& a) {
    FrameRequest& r = a.request;
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
}

// What the image keeps beside the colour: time reduced exactly, alpha, the undefined-case mask.
void add_output_options(CLI::App& cmd, RenderArgs& a) {
    FrameRequest& r = a.request;
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
}

// What the render may use: threads, files outside the scene's folder, memory.
void add_resource_options(CLI::App& cmd, RenderArgs& a) {
    FrameRequest& r = a.request;
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

}  // namespace

void add_render_options(CLI::App& cmd, RenderArgs& a) {
    add_scene_options(cmd, a);
    add_rule_options(cmd, a);
    add_output_options(cmd, a);
    add_resource_options(cmd, a);
}

void note_raster_only(const CLI::App& cmd, RenderArgs& a) {
    for (const char* option : kRasterOnly) {
        if (cmd.count(option) > 0) a.raster_only.emplace_back(option);
    }
}

namespace {

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

struct RenderPlan {
    std::vector<RowBand> bands;
    std::uint64_t peak_bytes = 0;  // the most the render holds at once, by the plan
};

// The bands a render of the whole frame, or of bands of it, is made in, within `limit` beside
// what the render holds throughout (the scene, its textures, kRenderOverheadBytes), and the
// render's planned peak.
RenderPlan plan_render(const SceneRenderer& renderer, const RenderArgs& a, std::uint64_t limit) {
    const int w = renderer.width();
    const SceneRenderer::HeldBytes held = renderer.held_bytes();
    MemoryPlanInput in;
    in.height = renderer.height();
    in.pairing = a.request.shading.pairing;
    in.limit = limit;
    in.held = kRenderOverheadBytes + held.scene + held.textures;
    in.can_band = writes_in_bands(a.output) && (a.mask_output.empty() || writes_in_bands(a.mask_output));
    in.bytes_for_rows = [&](int rows) {
        std::uint64_t bytes = renderer.frame_bytes(rows) + ImageWriter::conversion_bytes(a.output, w, rows, a.alpha);
        if (!a.mask_output.empty()) {
            bytes += std::uint64_t(w) * std::uint64_t(rows) * 4 * sizeof(float) +
                     ImageWriter::conversion_bytes(a.mask_output, w, rows, false);
        }
        return bytes;
    };
    RenderPlan plan{plan_bands(in)};
    int rows = 0;
    for (const RowBand& b : plan.bands) rows = std::max(rows, b.end - b.begin);
    // Loading a texture held its decoding beside the scene; the frames come after.
    plan.peak_bytes = in.held + std::max(held.texture_loading, in.bytes_for_rows(rows));
    return plan;
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
                                      "red: NaN produced, green: division by zero, blue: built-in outside its domain, "
                                      "grey: integer overflow");
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

// The file of frame `f` under `pattern` (-o or --undefined-mask): the pattern itself for a still.
std::string frame_file(const RenderArgs& a, const std::string& pattern, int f) {
    try {
        return a.animated() ? frame_path(pattern, f) : pattern;
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
}

// Refuses a bad -o or --undefined-mask pattern before anything is read, and a mask that would be
// written over any frame's image.
void check_frame_names(const RenderArgs& a, int first, int last) {
    frame_file(a, a.output, first);
    if (!a.mask_output.empty()) frame_file(a, a.mask_output, first);
    if (!a.mask_output.empty() && a.animated()) {
        // Every frame's name under both patterns.
        const std::string image = resolved_pattern(a.output), mask = resolved_pattern(a.mask_output);
        for (int f = first; f <= last; ++f) {
            if (const std::optional<int> g = frame_named(mask, frame_path(image, f), first, last)) {
                throw UsageError("--undefined-mask: frame " + std::to_string(*g) +
                                 "'s mask would be written over frame " + std::to_string(f) + "'s image " +
                                 frame_file(a, a.output, f));
            }
        }
    }
}

// The line that ends a render: frames, size, time, speed, work, bands, depth and memory.
void print_render_summary(const RenderArgs& a, const SceneRenderer& renderer, const FrameTotals& totals,
                          int nframes, double total, std::size_t bands, std::uint64_t peak, std::uint64_t planned) {
    const int w = renderer.width(), h = renderer.height();
    const double render_seconds = totals.render_seconds;
    const int renders = totals.renders;
    const RenderStats& stats = totals.stats;
    std::fprintf(stderr,
                 "quadshade: %d frame%s %dx%d in %.3f s (render %.1f ms/frame, %.1f Mpixel/s), %llu triangles, "
                 "%llu lanes shaded",
                 nframes, nframes == 1 ? "" : "s", w, h, total, 1e3 * render_seconds / renders,
                 double(w) * h * renders / render_seconds * 1e-6, (unsigned long long)stats.triangles_setup,
                 (unsigned long long)stats.lanes_shaded);
    if (renders < nframes) std::fputs(", rendered once (no drawn shader reads time)", stderr);
    if (bands > 1) std::fprintf(stderr, ", in %zu bands of rows", bands);
    if (a.request.backend == Backend::RayCaster) {
        std::fprintf(stderr, ", BVH built once in %.1f ms", 1e3 * renderer.bvh_build_seconds());
    } else {
        std::fputs(stats.depth_buffer ? ", depth tested"
                                      : ", no depth buffer (drawn in order, each pixel's nearest surface comes last)",
                   stderr);
    }
    std::fprintf(stderr, ", peak memory %s (planned %s)\n", byte_size_text(peak).c_str(),
                 byte_size_text(planned).c_str());
}

void print_undefined(const UndefinedCounts& undefined) {
    std::fprintf(stderr,
                 "quadshade: undefined GLSL cases on %llu pixels: NaN produced %llu, division by zero %llu, "
                 "built-in outside its domain %llu, integer overflow %llu\n",
                 (unsigned long long)undefined.pixels, (unsigned long long)undefined.per_case[0],
                 (unsigned long long)undefined.per_case[1], (unsigned long long)undefined.per_case[2],
                 (unsigned long long)undefined.per_case[3]);
}

}  // namespace

int cmd_render(RenderArgs& a) {
    FrameRequest& req = a.request;
    if (a.animated() && a.frames.second < a.frames.first) throw UsageError("--frames: B must not be less than A");
    req.shading.check_undefined = !a.mask_output.empty();
    if (req.shading.check_undefined && !a.animated() && resolved(a.mask_output) == resolved(a.output)) {
        throw UsageError("--undefined-mask: the same file as -o");
    }
    refuse_unsupported(a);
    for (const std::string& u : a.uniforms) req.uniforms.push_back(parse_uniform_option(u));
    if (!a.memory_limit.empty()) memory_limit(a.memory_limit);  // a bad size is refused before anything loads
    const int first = a.animated() ? a.frames.first : 0, last = a.animated() ? a.frames.second : 0;
    check_frame_names(a, first, last);

    for (const std::string& plugin : a.plugins) {
        for (const std::string& warning : load_plugin(plugin)) std::fprintf(stderr, "quadshade: warning: %s\n", warning.c_str());
    }
    const Program* glsl = use_glsl_options(a.glsl, a.vertex_glsl, a.compile_glsl, req.shader_override, {shade_request(req)});
    // The libraries first: the render's memory is measured from here, and its plan is checked
    // against what is left.
    if (needs_image_library(a.output) || (!a.mask_output.empty() && needs_image_library(a.mask_output))) {
        load_image_library();
    }
    load_libraries(req);
    const std::uint64_t limit = memory_limit(a.memory_limit);
    reset_peak_resident();
    std::uint64_t resident_before = resident_bytes();
    Scene scene = load_scene(a.scene, a.load);
    resident_before += load_image_library_for(scene);
    for (const std::string& w : scene.warnings) std::fprintf(stderr, "quadshade: warning: %s\n", w.c_str());
    check_programs(scene, req.shader_override, glsl_way(a.compile_glsl), {shade_request(req)});  // fail before any work
    for (int f = first; f <= last; ++f) {
        check_output(frame_file(a, a.output, f), scene.inputs, "-o");
        if (!a.mask_output.empty()) check_output(frame_file(a, a.mask_output, f), scene.inputs, "--undefined-mask");
    }
    SceneRenderer renderer(scene, req);
    for (const std::string& note : renderer.notes()) std::fprintf(stderr, "quadshade: warning: %s\n", note.c_str());
    const RenderPlan plan = plan_render(renderer, a, limit);
    const std::vector<RowBand>& bands = plan.bands;

    const bool progress = last > first && ::isatty(STDERR_FILENO);
    const auto start = std::chrono::steady_clock::now();
    FrameTotals totals;
    Framebuffer fb;
    // Frames that cannot differ (no drawn shader reads time) are rendered once, when one band
    // holds the whole frame.
    const bool render_once = !renderer.depends_on_time() && bands.size() == 1;
    for (int f = first; f <= last; ++f) {
        const double time = a.animated() ? double(f) / double(a.fps) : req.time.value_or(double(scene.time));
        const std::string mask = a.mask_output.empty() ? "" : frame_file(a, a.mask_output, f);
        write_frame(renderer, bands, time, a, frame_file(a, a.output, f), mask, fb, totals, render_once && f > first);
        if (progress) print_progress(f - first + 1, last - first + 1);
    }
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::uint64_t peak = peak_resident_bytes();
    print_render_summary(a, renderer, totals, last - first + 1, total, bands.size(),
                         peak > resident_before ? peak - resident_before : 0, plan.peak_bytes);
    warn_after_render(glsl);
    if (!a.mask_output.empty()) print_undefined(totals.undefined);
    return 0;
}

}  // namespace qs::app
