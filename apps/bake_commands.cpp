#include "apps/bake_commands.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "apps/command_line.h"
#include "core/framebuffer.h"
#include "files/temporary_file.h"
#include "images/image_io.h"
#include "render/atlas_bake.h"
#include "render/memory_plan.h"
#include "render/volume_bake.h"
#include "scenes/gltf.h"
#include "scenes/scene_files.h"
#include "scenes/uniforms.h"
#include "shading/catalogue.h"
#include "shading/height_field.h"

namespace qs::app {

namespace fs = std::filesystem;

void add_volume_options(CLI::App& cmd, VolumeArgs& a) {
    cmd.add_option("--shader", a.shader, "the catalogue shader to evaluate (its object-space position is the grid's)")
        ->option_text("NAME");
    add_glsl_options(cmd, a.glsl, a.vertex_glsl, a.compile_glsl);
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

void add_bake_options(CLI::App& cmd, BakeArgs& a) {
    cmd.add_option("mesh", a.mesh, "a glTF scene whose meshes have a UV atlas in TEXCOORD_0 (in [0, 1], no overlaps)")
        ->required()->option_text("MESH.gltf");
    cmd.add_option("--shader", a.shader, "the catalogue shader to bake (its own vertex stage gives its varyings)")
        ->option_text("NAME");
    add_glsl_options(cmd, a.glsl, a.vertex_glsl, a.compile_glsl);
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
        "three heights and a cross product (finite: the ProcTexGen articles' way)");
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
    cmd.add_option("--memory-limit", a.memory_limit,
                   "memory the bake may use, e.g. 4G (default: what the system has available); checked\n"
                   "before any work, map by map (each is written before the next is made)")
        ->option_text("SIZE");
}

namespace {

// The atlas frame written as the texture it is: rows in the opposite order (row 0 is t = 0), a
// row at a time, so that no flipped copy of the frame is made.
void write_atlas(const fs::path& file, const Framebuffer& frame, const Metadata& metadata) {
    ImageWriter writer(file, frame.width, frame.height, true, metadata);
    const std::size_t row = std::size_t(frame.width) * 4;
    for (int y = frame.height - 1; y >= 0; --y) writer.write_rows(1, frame.rgba.data() + std::size_t(y) * row);
    writer.commit();
}

}  // namespace

int cmd_bake_volume(VolumeArgs a) {
    const Program* glsl = use_glsl_options(a.glsl, a.vertex_glsl, a.compile_glsl, a.shader);
    if (a.shader.empty()) throw UsageError("bake-volume: give the shader to evaluate: --shader NAME or --glsl FRAG");
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
    warn_after_render(glsl);
    return 0;
}

namespace {

struct BakeMaps {
    bool color = false, height = false, normal = false;
};

// The maps --maps names, and the normal map's options only where it is asked for.
BakeMaps maps_asked(const BakeArgs& a) {
    BakeMaps maps;
    for (const std::string& map : a.maps) {
        if (map != "color" && map != "height" && map != "normal") {
            throw UsageError("--maps: '" + map + "' is not a map bake makes (color, height, normal)");
        }
        bool& wanted = map == "color" ? maps.color : map == "height" ? maps.height : maps.normal;
        if (wanted) throw UsageError("--maps: '" + map + "' is named twice");
        wanted = true;
    }
    if (!maps.color) throw UsageError("--maps: color is required (the baked scene is drawn with it)");
    if (!maps.normal && (a.normals_option->count() || a.normal_step || a.precision_option->count())) {
        throw UsageError("--normals, --normal-step and --normal-precision make the normal map: add normal to --maps");
    }
    if (a.normal_step && a.normals != NormalMethod::FiniteDifferences) {
        throw UsageError("--normal-step is the finite differences' step: it needs --normals finite");
    }
    return maps;
}

// The shader's height, where a height or normal map is asked for (nullptr otherwise).
const HeightField* height_field_for(const std::string& shader, const BakeMaps& maps) {
    if (!maps.height && !maps.normal) return nullptr;
    const HeightField* field = find_height_field(shader);
    if (!field) {
        std::string with;
        for (const HeightField* f : height_fields()) with += (with.empty() ? "" : ", ") + std::string(f->shader());
        throw UsageError("--maps " + std::string(maps.normal ? "normal" : "height") + ": shader '" + shader +
                         "' has no height (shaders with one: " + (with.empty() ? "none in this build" : with) + ")");
    }
    return field;
}

// The files beside OUT.gltf, each checked against the scene's inputs.
struct BakeFiles {
    std::string bin, color, height, normal;
};

BakeFiles bake_files(const fs::path& output, const Scene& scene, const BakeMaps& maps) {
    const std::string stem = output.stem().string();
    const BakeFiles files{stem + ".bin", stem + "-color.png", stem + "-height.png", stem + "-normal.png"};
    check_output(output, scene.inputs, "-o");
    check_output(output.parent_path() / files.bin, scene.inputs, "-o (its buffer)");
    check_output(output.parent_path() / files.color, scene.inputs, "-o (its texture)");
    if (maps.height) check_output(output.parent_path() / files.height, scene.inputs, "-o (its height map)");
    if (maps.normal) check_output(output.parent_path() / files.normal, scene.inputs, "-o (its normal map)");
    return files;
}

AtlasRequest atlas_request(const BakeArgs& a) {
    AtlasRequest req;
    req.size = a.size;
    req.skirt = a.skirt;
    req.frame.shader_override = a.shader;
    if (a.time) req.frame.time = *a.time;
    req.frame.shading.derivatives = a.derivatives;
    req.frame.shading.threads = a.threads;
    for (const std::string& u : a.uniforms) req.frame.uniforms.push_back(parse_uniform_option(u));
    return req;
}

NormalBakeRequest normal_request(const BakeArgs& a) {
    NormalBakeRequest n;
    n.size = a.size, n.skirt = a.skirt, n.method = a.normals, n.precision = a.normal_precision, n.threads = a.threads;
    if (a.normal_step) n.step = *a.normal_step;
    return n;
}

// The memory of the largest map (each map is written, and its memory freed, before the next)
// beside what the bake holds throughout: the scene as loaded and kRenderOverheadBytes. Throws
// MemoryError when a map would not fit in --memory-limit; returns the most the bake will hold.
std::uint64_t plan_bake_memory(const BakeArgs& a, const Scene& scene, const AtlasRequest& req,
                               const NormalBakeRequest& n, const BakeMaps& maps, const BakeFiles& files) {
    const std::uint64_t limit = memory_limit(a.memory_limit);
    const std::uint64_t held = kRenderOverheadBytes + scene_bytes(scene);
    const std::string side = std::to_string(a.size) + "x" + std::to_string(a.size);
    // An atlas is written a row at a time; the normal map as a whole image once it is made.
    const std::uint64_t atlas =
        atlas_bake_bytes(scene, req) + ImageWriter::conversion_bytes(files.color, a.size, 1, true);
    std::vector<std::pair<std::string, std::uint64_t>> needs = {{"the colour atlas", atlas}};
    if (maps.height) needs.emplace_back("the height map", atlas);
    if (maps.normal) {
        const std::uint64_t image = std::uint64_t(a.size) * std::uint64_t(a.size) * 4 * sizeof(float);
        needs.emplace_back("the normal map",
                           std::max(normal_bake_bytes(scene, n),
                                    image + ImageWriter::conversion_bytes(files.normal, a.size, a.size, true)));
    }
    std::uint64_t planned = 0;
    for (const auto& [map, bytes] : needs) {
        if (held + bytes > limit) {
            throw MemoryError("bake: " + map + " at " + side + " needs " + byte_size_text(held + bytes) +
                              ", more than the " + byte_size_text(limit) +
                              " available (--memory-limit sets it; a smaller --size needs less)");
        }
        planned = std::max(planned, held + bytes);
    }
    return planned;
}

struct BakeTimes {
    double color_ms = 0.0, height_ms = 0.0, normal_ms = 0.0;
};

// Bakes the maps asked for into `out`'s staging folder, each with metadata saying what it holds.
BakeTimes bake_maps(const BakeArgs& a, const Scene& scene, const AtlasRequest& req, const NormalBakeRequest& n,
                    const HeightField* field, const BakeMaps& maps, const BakeFiles& files, OutputSet& out) {
    auto clock = std::chrono::steady_clock::now;
    auto ms_since = [](auto t0) {
        return 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    };
    const Metadata common = {{"quadshade:shader", a.shader},
                             {"quadshade:time", std::to_string(req.frame.time.value_or(double(scene.time)))},
                             {"quadshade:skirt", std::to_string(a.skirt)}};
    BakeTimes times;
    Metadata meta = common;
    meta.push_back({"quadshade:atlas", "the shader at each texel's surface point (TEXCOORD_0); row 0 is t = 0"});
    meta.push_back({"quadshade:derivatives", rule_name(a.derivatives)});
    auto t0 = clock();
    write_atlas(out.staged(files.color), render_atlas_frame(scene, req), meta);
    times.color_ms = ms_since(t0);
    if (maps.height) {
        AtlasRequest h = req;
        h.frame.shader_override = std::string(field->height_shader());
        meta = common;
        meta.push_back({"quadshade:atlas", "the height of " + a.shader + " (" + std::string(field->height_shader()) +
                                               "), 0 to 1 for 0 to " + std::to_string(field->amplitude()) +
                                               " object units of relief; row 0 is t = 0"});
        t0 = clock();
        write_atlas(out.staged(files.height), render_atlas_frame(scene, h), meta);
        times.height_ms = ms_since(t0);
    }
    if (maps.normal) {
        meta = common;
        meta.push_back({"quadshade:atlas", "object-space unit normals as 0.5 + 0.5 n (not tangent-space), alpha 0 in the "
                                           "gutter; row 0 is t = 0"});
        meta.push_back({"quadshade:normals", n.method == NormalMethod::Analytic
                                                 ? "analytic (Dual2)"
                                                 : "finite differences, step " + std::to_string(n.step) + " object units"});
        meta.push_back({"quadshade:precision", n.precision == Precision::Double ? "double" : "float"});
        t0 = clock();
        write_image(out.staged(files.normal), bake_normal_map(scene, *field, n), meta, true);
        times.normal_ms = ms_since(t0);
    }
    return times;
}

}  // namespace

int cmd_bake(BakeArgs a) {
    const Program* glsl = use_glsl_options(a.glsl, a.vertex_glsl, a.compile_glsl, a.shader);
    if (a.shader.empty()) throw UsageError("bake: give the shader to bake: --shader NAME or --glsl FRAG");
    const fs::path output(a.output);
    if (output.extension() != ".gltf") throw UsageError("-o " + a.output + ": the baked scene is written as .gltf");
    const BakeMaps maps = maps_asked(a);
    const HeightField* field = height_field_for(a.shader, maps);
    if (!a.memory_limit.empty()) memory_limit(a.memory_limit);  // a bad size is refused before anything loads
    reset_peak_resident();  // the bake's memory is measured from here; its maps are PNG
    std::uint64_t resident_before = resident_bytes();
    SceneLoadOptions load;
    load.paths.allow_outside = a.allow_outside;
    Scene scene = load_scene(a.mesh, load);
    resident_before += load_image_library_for(scene);
    const BakeFiles files = bake_files(output, scene, maps);
    const Program* program = find_program(a.shader);
    if (!program) throw UsageError("--shader: no shader named '" + a.shader + "' (quadshade shaders lists them)");
    const AtlasRequest req = atlas_request(a);
    const NormalBakeRequest n = normal_request(a);

    // Before any work: the folder the files go to (their staging folder is made in it now), and
    // the memory.
    OutputSet out(output);
    const std::uint64_t planned = plan_bake_memory(a, scene, req, n, maps, files);
    const BakeTimes times = bake_maps(a, scene, req, n, field, maps, files, out);
    const Scene baked = baked_scene(scene, out.staged(files.color), maps.normal ? out.staged(files.normal) : fs::path(),
                                    maps.height ? out.staged(files.height) : fs::path());
    save_scene(baked, out.staged(output.filename().string()));
    out.commit(output.filename().string());
    std::fprintf(stderr, "quadshade: %s: %s baked into a %dx%d atlas in %.1f ms (%s)", a.output.c_str(), a.shader.c_str(),
                 a.size, a.size, times.color_ms, files.color.c_str());
    if (maps.height) std::fprintf(stderr, ", its height in %.1f ms (%s)", times.height_ms, files.height.c_str());
    if (maps.normal) std::fprintf(stderr, ", its normal map in %.1f ms (%s)", times.normal_ms, files.normal.c_str());
    const std::uint64_t peak = peak_resident_bytes();
    std::fprintf(stderr, ", peak memory %s (planned %s)\n",
                 byte_size_text(peak > resident_before ? peak - resident_before : 0).c_str(),
                 byte_size_text(planned).c_str());
    warn_after_render(glsl);
    return 0;
}

}  // namespace qs::app
