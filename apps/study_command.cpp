#include "apps/study_command.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "apps/command_line.h"
#include "core/tile_grid.h"
#include "images/image_io.h"
#include "render/memory_plan.h"
#include "render/plugins.h"
#include "scenes/scene_files.h"

namespace qs::app {

namespace fs = std::filesystem;

namespace {

// What is studied: the scene, the shader and its variants, and where the results go.
void add_subject_options(CLI::App& cmd, StudyArgs& a, bool line) {
    study::Request& r = a.request;
    a.app = &cmd;
    cmd.add_option("scene", a.scene, "the glTF scene (.gltf or .glb)")->option_text("SCENE");
    cmd.add_option("--shader", r.shaders.shader, "the catalogue shader to study (quadshade shaders lists them)")
        ->option_text("NAME");
    add_glsl_options(cmd, a.glsl, a.vertex_glsl, a.compile_glsl);
    add_plugin_option(cmd, a.plugins);
    if (!line) {
        cmd.add_option("-o,--output", a.output, "the folder for study.csv, the images, the plots and report.html")
            ->required()
            ->option_text("DIR");
        cmd.add_option("--study", a.study_file,
                       "a study file: on each line a scene and its options as this command\ntakes them (paths relative "
                       "to the file; # starts a comment, \\ at\nthe end goes on on the next line); the options "
                       "given here\napply to every line; one report")
            ->option_text("FILE");
    }
    cmd.add_option("--unfiltered", r.shaders.unfiltered,
                   "the shader's unfiltered variant: the truth and the supersampled modes\nrender it "
                   "(default: the shader itself)")
        ->option_text("NAME");
    cmd.add_option("--alternative", r.shaders.alternative, "a variant filtered another way, measured as a mode")
        ->option_text("NAME");
    cmd.add_option("--alternative-mode", r.shaders.alternative_mode, "that mode's name (default: alternative)")
        ->option_text("MODE");
}

// The views each mode renders: the camera's and generated ones, at chosen frames.
void add_view_options(CLI::App& cmd, StudyArgs& a) {
    study::Request& r = a.request;
    cmd.add_option("--views", r.views,
                   "camera, magnified, minified, grazing (default: all four; the camera\nalone with --frames), or "
                   "scene files whose camera is a view\n(CAMERA.gltf)")
        ->delimiter(',')
        ->option_text("VIEW,...");
    cmd.add_option("--frames", a.frames,
                   "frames of an animated scene as views, each view at each frame\n(time = frame / fps): "
                   "0,12,24 or A:B (inclusive), as render takes them")
        ->delimiter(',')
        ->option_text("F,...");
    cmd.add_option("--fps", r.fps, "frames per second for --frames (default 30)")
        ->check(kFinite & CLI::PositiveNumber)
        ->option_text("N");
}

// The modes measured and how: image size, truth, timing, the shader's time and offset.
void add_mode_options(CLI::App& cmd, StudyArgs& a) {
    study::Request& r = a.request;
    cmd.add_option("--modes", r.modes,
                   "fine, coarse-lower, coarse-upper, dual2, raycast-quads,\nray-differentials, double, step, ss2x2, "
                   "ss4x4, ss8x8, the\nalternative's (default: all the shader has)")
        ->delimiter(',')
        ->option_text("MODE,...");
    cmd.add_option("--label", r.label, "the study's name in the CSV and the report (default: the shader's)")
        ->option_text("NAME");
    cmd.add_option("--keep-objects", r.keep_shader, "draw only the objects whose material names this shader")
        ->option_text("NAME");
    cmd.add_option("--size", r.size, "the image's longer side in pixels, the scene's aspect kept (default 256)")
        ->check(CLI::Range(8, 4096))
        ->option_text("N");
    cmd.add_option("--truth", r.truth, "the truth's samples per pixel along each axis (default 32)")
        ->check(CLI::Range(2, 64))
        ->option_text("K");
    cmd.add_option("--repeat", r.repeat, "timed frames per mode, after 3 untimed ones (default 5)")
        ->check(CLI::Range(1, 1000))
        ->option_text("N");
    cmd.add_option("--threads", r.threads, "worker threads, quadshade's and llvmpipe's (default 2)")
        ->check(CLI::Range(1, 1024))
        ->option_text("N");
    cmd.add_option("--time", r.time, "the `time` uniform in seconds (default: the scene's)")
        ->check(kFinite)
        ->option_text("T");
    cmd.add_option_function<std::vector<double>>(
           "--offset",
           [&r](const std::vector<double>& v) {
               r.offset = {v[0], v[1], v[2]};
           },
           "add X,Y,Z to the shader's coordinates (TEXCOORD_0's x, y and the\nobject positions; the geometry "
           "stays where it was): the pattern far\nfrom its origin")
        ->delimiter(',')
        ->expected(3)
        ->check(kFinite)
        ->option_text("X,Y,Z");
}

// What the study makes beside the measurements: llvmpipe's images, derivative maps, memory.
void add_output_options(CLI::App& cmd, StudyArgs& a, bool line) {
    study::Request& r = a.request;
    cmd.add_flag("--no-reference", a.no_reference, "do not render llvmpipe's images (no OSMesa needed)");
    cmd.add_flag("--no-derivative-maps", a.no_derivative_maps, "do not map the inputs' derivatives under each rule");
    cmd.add_option("--derivatives-of", r.expressions,
                   "map the derivatives of this GLSL expression in place of the inputs':\nover the fragment "
                   "shader's inputs, uniforms, globals and main's\noutermost variables where main ends (e.g. the "
                   "argument of an\nfwidth); evaluated in the shader's GLSL (a catalogue or plugin\nshader's own "
                   "exported GLSL) by the interpreter; repeatable")
        ->option_text("EXPR");
    if (!line) {
        cmd.add_option("--memory-limit", a.memory_limit,
                       "memory the study may use, llvmpipe's process included, e.g. 4G\n(default: what the system "
                       "has available); planned before any work")
            ->option_text("SIZE");
    }
}

}  // namespace

void add_study_options(CLI::App& cmd, StudyArgs& a, bool line) {
    add_subject_options(cmd, a, line);
    add_view_options(cmd, a);
    add_mode_options(cmd, a);
    add_output_options(cmd, a, line);
}

namespace {

// --frames' items (N or A:B, inclusive) as frames, in the order given.
std::vector<int> frame_list(const std::vector<std::string>& items) {
    constexpr int kMaxFrame = 1000000, kMaxFrames = 1000;
    auto frame = [&](const std::string& text) {
        std::size_t end = 0;
        int f = -1;
        try {
            f = std::stoi(text, &end);
        } catch (const std::exception&) {
            end = 0;
        }
        if (end == 0 || end != text.size() || f < 0 || f > kMaxFrame) {
            throw UsageError("--frames: '" + text + "' is not a frame (0 to " + std::to_string(kMaxFrame) + ")");
        }
        return f;
    };
    std::vector<int> frames;
    for (const std::string& item : items) {
        const std::size_t colon = item.find(':');
        const int first = frame(item.substr(0, colon));
        const int last = colon == std::string::npos ? first : frame(item.substr(colon + 1));
        if (last < first) throw UsageError("--frames: " + item + ": B must not be less than A");
        if (frames.size() + std::size_t(last - first) + 1 > std::size_t(kMaxFrames)) {
            throw UsageError("--frames: more than " + std::to_string(kMaxFrames) + " frames");
        }
        for (int f = first; f <= last; ++f) {
            if (std::find(frames.begin(), frames.end(), f) != frames.end()) {
                throw UsageError("--frames: frame " + std::to_string(f) + " is named twice");
            }
            frames.push_back(f);
        }
    }
    return frames;
}

// A study's request from its arguments, paths resolved against `base`.
study::Request prepared(StudyArgs& a, const fs::path& base) {
    study::Request r = a.request;
    auto resolve = [&](std::string& p) {
        if (!p.empty() && fs::path(p).is_relative()) p = (base / p).string();
    };
    resolve(a.scene), resolve(a.glsl), resolve(a.vertex_glsl);
    for (std::string& view : r.views) {
        if (view.ends_with(".gltf") || view.ends_with(".glb")) resolve(view);  // a camera's scene file
    }
    use_glsl_options(a.glsl, a.vertex_glsl, a.compile_glsl, r.shaders.shader);
    if (a.scene.empty()) throw UsageError("study: give the scene (or a study file with --study)");
    if (r.shaders.shader.empty()) throw UsageError("study: name the shader with --shader NAME or --glsl FRAG");
    if (!r.shaders.alternative.empty() && r.shaders.alternative_mode.empty())
        r.shaders.alternative_mode = "alternative";
    if (r.shaders.alternative.empty() && !r.shaders.alternative_mode.empty()) {
        throw UsageError("--alternative-mode: name the variant with --alternative");
    }
    if (r.size * r.truth > kMaxDimension) {
        throw UsageError("--size times --truth is over " + std::to_string(kMaxDimension) +
                         " pixels on a side, the most a frame has");
    }
    r.frames = frame_list(a.frames);
    if (!r.frames.empty() && r.time) throw UsageError("--frames and --time: each frame is a time; give one of them");
    if (a.no_derivative_maps && !r.expressions.empty()) {
        throw UsageError("--derivatives-of and --no-derivative-maps: give one of them");
    }
    r.scene = a.scene;
    r.reference = !a.no_reference;
    r.derivative_maps = !a.no_derivative_maps;
    return r;
}

// The lines of a study file, each parsed as the command's options, those given on the command
// line (`given`) in place of the line's.
std::vector<study::Request> study_file(const StudyArgs& given) {
    const fs::path file = given.study_file, base = file.parent_path();
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file.string() + ": cannot read the study file");
    std::vector<study::Request> requests;
    std::string text;
    for (int number = 1, first = 1; std::getline(in, text); first = ++number) {
        if (const std::size_t hash = text.find('#'); hash != std::string::npos) text.erase(hash);
        // A line that ends in a backslash goes on on the next.
        for (std::string more; !text.empty() && text.back() == '\\' && std::getline(in, more); ++number) {
            text.back() = ' ';
            if (const std::size_t hash = more.find('#'); hash != std::string::npos) more.erase(hash);
            text += more;
        }
        const std::string where = file.string() + ":" + std::to_string(first) + ": ";
        if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
        StudyArgs line;
        CLI::App app("a study file's line", "study");
        add_study_options(app, line, true);
        try {
            app.parse(text, false);
        } catch (const CLI::ParseError& e) {
            throw UsageError(where + e.what());
        }
        study::Request& r = line.request;
        const study::Request& g = given.request;
        auto from_command_line = [&](const char* option) { return given.app->count(option) > 0; };
        if (from_command_line("--size")) r.size = g.size;
        if (from_command_line("--truth")) r.truth = g.truth;
        if (from_command_line("--repeat")) r.repeat = g.repeat;
        if (from_command_line("--threads")) r.threads = g.threads;
        if (from_command_line("--time")) r.time = g.time;
        if (from_command_line("--offset")) r.offset = g.offset;
        if (from_command_line("--views")) r.views = g.views;
        if (from_command_line("--frames")) line.frames = given.frames;
        if (from_command_line("--fps")) r.fps = g.fps;
        if (from_command_line("--modes")) r.modes = g.modes;
        if (from_command_line("--derivatives-of")) r.expressions = g.expressions;
        line.no_reference = line.no_reference || given.no_reference;
        line.no_derivative_maps = line.no_derivative_maps || given.no_derivative_maps;
        for (std::string& plugin : line.plugins) {
            load_plugin(fs::path(plugin).is_relative() ? base / plugin : fs::path(plugin));
        }
        try {
            requests.push_back(prepared(line, base));
        } catch (const UsageError& e) {
            throw UsageError(where + e.what());
        }
    }
    if (requests.empty()) throw UsageError(file.string() + ": no study in the file");
    return requests;
}

}  // namespace

int cmd_study(StudyArgs& a) {
    std::vector<study::Request> requests;
    if (!a.study_file.empty()) {
        for (const char* option : {"scene", "--shader", "--glsl", "--vert", "--unfiltered", "--alternative",
                                   "--alternative-mode", "--keep-objects"}) {
            if (a.app->count(option)) throw UsageError(std::string("--study: ") + option + " goes on the file's lines");
        }
        requests = study_file(a);
    } else {
        requests.push_back(prepared(a, "."));
    }
    std::error_code ec;
    if (fs::exists(a.output, ec) && !fs::is_directory(a.output, ec)) {
        throw UsageError("-o " + a.output + ": exists and is not a folder");
    }
    // Every study's inputs, refused as outputs before any is run.
    std::vector<fs::path> inputs;
    for (const std::string& file : {a.study_file, a.glsl, a.vertex_glsl}) {
        if (!file.empty()) inputs.push_back(file);
    }
    if (!a.memory_limit.empty()) memory_limit(a.memory_limit);  // a bad size is refused before anything loads
    std::uint64_t planned = 0;
    try {
        for (const study::Request& r : requests) {
            const std::vector<fs::path> theirs = study::study_inputs(r);
            inputs.insert(inputs.end(), theirs.begin(), theirs.end());
        }
        study::refuse_outputs_over(a.output, inputs);
        // Every study's views, modes, shaders, expressions and memory, before any writes a file.
        load_image_library();
        const std::uint64_t limit = memory_limit(a.memory_limit);
        for (const study::Request& r : requests) planned = std::max(planned, study::check_study(r, limit));
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("study: ") + e.what());
    }
    make_output_folder(a.output, FolderLink::Followed);
    reset_peak_resident();
    const std::uint64_t resident_before = resident_bytes();
    study::Tables tables;
    for (study::Request& r : requests) {
        r.output = a.output;
        try {
            study::run_study(r, tables);
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("study: ") + e.what());
        }
    }
    study::write_tables(a.output, tables);
    study::write_report(a.output);
    const std::uint64_t peak = peak_resident_bytes();
    std::fprintf(stderr, "quadshade study: peak memory %s (planned %s with llvmpipe's process beside it)\n",
                 byte_size_text(peak > resident_before ? peak - resident_before : 0).c_str(),
                 byte_size_text(planned).c_str());
    std::printf("quadshade study: %s\n", (fs::path(a.output) / "report.html").string().c_str());
    return 0;
}

}  // namespace qs::app
