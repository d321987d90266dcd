#include "apps/study_command.h"

#include <filesystem>

#include "apps/command_line.h"

namespace qs::app {

namespace fs = std::filesystem;

void add_study_options(CLI::App& cmd, StudyArgs& a) {
    study::Request& r = a.request;
    cmd.add_option("scene", a.scene, "the glTF scene (.gltf or .glb)")->required()->option_text("SCENE");
    cmd.add_option("--shader", r.shaders.shader, "the catalogue shader to study (quadshade shaders lists them)")
        ->option_text("NAME");
    add_glsl_options(cmd, a.glsl, a.vertex_glsl);
    add_plugin_option(cmd, a.plugins);
    cmd.add_option("-o,--output", a.output, "the folder for study.csv, the images, the plots and report.html")
        ->required()->option_text("DIR");
    cmd.add_option("--unfiltered", r.shaders.unfiltered,
                   "the shader's unfiltered variant: the truth and the supersampled modes\nrender it "
                   "(default: the shader itself)")->option_text("NAME");
    cmd.add_option("--alternative", r.shaders.alternative, "a variant filtered another way, measured as a mode")
        ->option_text("NAME");
    cmd.add_option("--alternative-mode", r.shaders.alternative_mode, "that mode's name (default: alternative)")
        ->option_text("MODE");
    cmd.add_option("--views", r.views, "camera, magnified, minified, grazing (default: all four)")
        ->delimiter(',')->option_text("VIEW,...");
    cmd.add_option("--modes", r.modes,
                   "fine, coarse-lower, coarse-upper, dual2, raycast-quads,\nray-differentials, double, step, ss2x2, "
                   "ss4x4, ss8x8, the\nalternative's (default: all the shader has)")
        ->delimiter(',')->option_text("MODE,...");
    cmd.add_option("--keep-objects", r.keep_shader, "draw only the objects whose material names this shader")
        ->option_text("NAME");
    cmd.add_option("--size", r.size, "the image's longer side in pixels, the scene's aspect kept (default 256)")
        ->check(CLI::Range(8, 4096))->option_text("N");
    cmd.add_option("--truth", r.truth, "the truth's samples per pixel along each axis (default 32)")
        ->check(CLI::Range(2, 64))->option_text("K");
    cmd.add_option("--repeat", r.repeat, "timed frames per mode, after 3 untimed ones (default 5)")
        ->check(CLI::Range(1, 1000))->option_text("N");
    cmd.add_option("--threads", r.threads, "worker threads, quadshade's and llvmpipe's (default 2)")
        ->check(CLI::Range(1, 1024))->option_text("N");
    cmd.add_option("--time", r.time, "the `time` uniform in seconds (default: the scene's)")->check(kFinite)->option_text("T");
    cmd.add_option_function<std::vector<double>>(
           "--offset", [&r](const std::vector<double>& v) { r.offset = {v[0], v[1], v[2]}; },
           "add X,Y,Z to the shader's coordinates (TEXCOORD_0's x, y and the\nobject positions; the geometry "
           "stays where it was): the pattern far\nfrom its origin")
        ->delimiter(',')->expected(3)->check(kFinite)->option_text("X,Y,Z");
    cmd.add_flag("--no-reference", a.no_reference, "do not render llvmpipe's images (no OSMesa needed)");
    cmd.add_flag("--no-derivative-maps", a.no_derivative_maps, "do not map the inputs' derivatives under each rule");
}

int cmd_study(StudyArgs& a) {
    study::Request& r = a.request;
    use_glsl_options(a.glsl, a.vertex_glsl, r.shaders.shader);
    if (r.shaders.shader.empty()) throw UsageError("study: name the shader with --shader NAME or --glsl FRAG");
    if (!r.shaders.alternative.empty() && r.shaders.alternative_mode.empty()) r.shaders.alternative_mode = "alternative";
    if (r.shaders.alternative.empty() && !r.shaders.alternative_mode.empty()) {
        throw UsageError("--alternative-mode: name the variant with --alternative");
    }
    std::error_code ec;
    if (fs::exists(a.output, ec) && !fs::is_directory(a.output, ec)) {
        throw UsageError("-o " + a.output + ": exists and is not a folder");
    }
    if (r.size * r.truth > (1 << 16)) throw UsageError("--size times --truth is over 65536 pixels on a side");
    r.scene = a.scene;
    r.output = a.output;
    r.reference = !a.no_reference;
    r.derivative_maps = !a.no_derivative_maps;
    try {
        study::run_study(r);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("study: ") + e.what());
    }
    study::write_report(r.output);
    std::printf("quadshade study: %s\n", (fs::path(r.output) / "report.html").string().c_str());
    return 0;
}

}  // namespace qs::app
