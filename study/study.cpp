#include "study/study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "core/tile_grid.h"
#include "files/output_file.h"
#include "files/temporary_file.h"
#include "images/image_io.h"
#include "render/frame_image.h"
#include "render/reference_process.h"
#include "scenes/gltf.h"
#include "shading/catalogue.h"
#include "shading/glsl_export.h"
#include "study/derivative_maps.h"
#include "study/expression_derivatives.h"
#include "study/file_name.h"
#include "study/image_error.h"
#include "study/stability.h"
#include "study/study_csv.h"
#include "study/study_memory.h"

namespace qs::study {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

#if defined(QUADSHADE_HAS_RAYCAST)
constexpr bool kRaycast = true;
#else
constexpr bool kRaycast = false;
#endif

// Writes a view's scene for the reference, its texture files copied beside it (a scene may only
// read files in its own folder): the glTF, its buffer and the copies committed together.
void save_view(const Scene& scene, const fs::path& file) {
    OutputSet out(file);
    Scene copy = scene;
    for (std::size_t i = 0; i < copy.textures.size(); ++i) {
        ImageSource& image = copy.textures[i].image;
        if (image.kind != ImageSource::Kind::File || image.file.empty()) continue;
        const std::string name =
            file.stem().string() + "-" + std::to_string(i) + "-" + file_name(image.file.filename().string());
        const fs::path local = out.staged(name);
        copy_to_output(image.file, local);
        image.file = local;
    }
    save_scene(copy, out.staged(file.filename().string()));
    out.commit(file.filename().string());
}

// Whether `file`'s entry is `folder` or lies inside it (both entries, their folders resolved).
bool inside(const fs::path& file, const fs::path& folder) {
    const fs::path f = entry_path(file), d = entry_path(folder);
    return std::mismatch(d.begin(), d.end(), f.begin(), f.end()).first == d.end();
}

struct Timing {
    double median = 0.0, min = 0.0, max = 0.0;
};

// The modes `request` names (all the shader has, when it names none).
std::vector<Mode> chosen_modes(const Request& r) {
    const std::vector<Mode> all = all_modes(r.shaders, kRaycast);
    if (r.modes.empty()) return all;
    std::vector<Mode> chosen;
    for (const std::string& name : r.modes) {
        auto it = std::find_if(all.begin(), all.end(), [&](const Mode& m) { return m.name == name; });
        if (it == all.end()) {
            throw std::invalid_argument("no mode '" + name +
                                        "' for this shader (its modes: " + mode_names(r.shaders, kRaycast) + ")");
        }
        chosen.push_back(*it);
    }
    return chosen;
}

void check_shaders(const Shaders& shaders) {
    for (const std::string& name : {shaders.shader, shaders.unfiltered, shaders.alternative}) {
        if (!name.empty() && !find_program(name)) {
            throw std::runtime_error("unknown shader '" + name +
                                     "' (quadshade shaders lists the catalogue; --plugin LIB adds a plugin's)");
        }
    }
}

// The scene a study draws: as loaded, only the objects that keep_shader names when it names one.
Scene study_scene(const Request& r) {
    Scene scene = load_scene(r.scene);
    if (!r.keep_shader.empty()) {
        std::erase_if(scene.objects, [&](const Object& o) { return o.shader != r.keep_shader; });
        if (scene.objects.empty()) {
            throw std::invalid_argument(r.scene.string() + ": no object's material names the shader '" + r.keep_shader +
                                        "'");
        }
    }
    return scene;
}

// The maps of the derivatives a study draws: the expressions it names, else the shader's inputs.
std::vector<DerivativeMap> maps_of(const Request& r) {
    if (!r.derivative_maps) return {};
    return r.expressions.empty() ? input_maps(r.shaders.shader)
                                 : expression_maps(r.shaders.shader, r.expressions, "--derivatives-of");
}

class Study {
public:
    explicit Study(const Request& r) : r_(r) {}

    void run(Tables& tables) {
        const std::vector<Mode> modes = chosen_modes(r_);
        const std::vector<View> views = views_of(r_);
        check_shaders(r_.shaders);
        const std::vector<DerivativeMap> maps = maps_of(r_);
        const Scene original = study_scene(r_);
        const std::string label = r_.label.empty() ? r_.shaders.shader : r_.label;
        make_output_folder(r_.output / "images", FolderLink::Refused);
        // The reference's images and logs are this run's own (two runs may share the folder).
        std::optional<ScratchFolder> scratch;
        if (r_.reference) {
            reference_ = reference_executable("study");
            write_glsl();  // the reference sees the GLSL as any GL application would: the text only
            scratch.emplace(r_.output / "reference");
            scratch_ = scratch->path();
        }
        std::size_t total = views.size() * (modes.size() + 1), done = 0;
        for (const View& view : views) study_view(view, original, label, modes, maps, tables, done, total);
        std::fprintf(stderr, "\n");
    }

private:
    // One view: its scene (and the reference's copy of it where it differs from the file), its
    // row of views.csv, float against double and the derivative maps, then the truth and every
    // mode against it and against llvmpipe. `done` of `total` steps, for the progress line.
    void study_view(const View& view, const Scene& original, const std::string& label, const std::vector<Mode>& modes,
                    const std::vector<DerivativeMap>& maps, Tables& tables, std::size_t& done, std::size_t total) {
        const View* v = &view;
        const std::string id = file_name(label) + "-" + v->name;
        const fs::path dir = r_.output / "images" / id;
        make_output_folder(dir, FolderLink::Refused);
        Scene scene = original;
        time_ = v->time ? v->time : r_.time;
        apply_view(*v, scene);
        const bool offset = r_.offset != glm::dvec3(0.0);
        if (offset) offset_coordinates(scene, r_.offset);
        size_for(scene, r_.size);
        // The reference reads the view from a file, written unless the scene is as loaded.
        fs::path scene_file = r_.scene;
        if (r_.reference && (v->changes_scene() || offset || !r_.keep_shader.empty())) {
            make_output_folder(r_.output / "views", FolderLink::Refused);
            scene_file = r_.output / "views" / (id + ".gltf");
            save_view(scene, scene_file);
        }
        const std::string& truth_shader = r_.shaders.unfiltered.empty() ? r_.shaders.shader : r_.shaders.unfiltered;
        const std::string truth_text = truth_shader + " at " + std::to_string(r_.truth) + "x" +
                                       std::to_string(r_.truth) + " samples per pixel in double, box-filtered";
        tables.views += csv_line({label, v->name, v->description, std::to_string(scene.width),
                                  std::to_string(scene.height), truth_text,
                                  number(r_.offset.x) + " " + number(r_.offset.y) + " " + number(r_.offset.z),
                                  time_ ? number(*time_) : number(scene.time)});
        progress(done, total, id + ": float against double, undefined cases");
        const Stability st = stability(scene, r_.shaders.shader, time_, r_.threads, dir, "images/" + id);
        const auto& u = st.undefined;
        tables.stability += csv_line(
            {label, v->name, number(st.rms), number(st.max), std::to_string(st.over_1),
             std::to_string(std::size_t(scene.width) * std::size_t(scene.height)),
             st.checked ? std::to_string(u.pixels) : "", st.checked ? std::to_string(u.per_case[0]) : "",
             st.checked ? std::to_string(u.per_case[1]) : "", st.checked ? std::to_string(u.per_case[2]) : "",
             st.checked ? std::to_string(u.per_case[3]) : "", st.note, st.float_image, st.double_image,
             st.heat_image, st.mask_image});
        if (!maps.empty()) {
            progress(done, total, id + ": derivative maps");
            for (const DerivativeRow& d : derivative_maps(scene, maps, time_, r_.threads, dir, "images/" + id)) {
                tables.derivatives += csv_line({label, v->name, d.input, d.rule, number(d.rms_dx), number(d.max_dx),
                                                number(d.rms_dy), number(d.max_dy), number(d.scale),
                                                std::to_string(d.covered), d.map_image, d.heat_image,
                                                d.analytic_image});
            }
        }
        progress(++done, total, id + ": truth");
        const Image truth = ground_truth(scene, truth_shader);
        write_image(dir / "truth.png", truth);
        mode_rows(scene, scene_file, modes, truth, truth_shader, label, v->name, id, dir, tables.study, done, total);
    }

    // Each mode's image of the view, its error against the truth and against llvmpipe's image of
    // the same variant and supersampling (rendered once), a row of study.csv each.
    void mode_rows(Scene& scene, const fs::path& scene_file, const std::vector<Mode>& modes, const Image& truth,
                   const std::string& truth_shader, const std::string& label, const std::string& view_name,
                   const std::string& id, const fs::path& dir, std::string& csv, std::size_t& done, std::size_t total) {
        std::map<std::pair<std::string, int>, std::string> llvmpipe_files;  // (variant, supersample)
        std::map<std::pair<std::string, int>, Image> llvmpipe;
        for (const Mode& m : modes) {
            progress(++done, total, id + ": " + m.name);
            const auto [image, time] = render(scene, m);
            const std::string name = file_name(m.name) + ".png", heat = file_name(m.name) + "-heat.png";
            write_image(dir / name, image);
            write_image(dir / heat, difference_heat_map(image, truth, 0.25f));
            const Error vs_truth = error_of(image, truth);
            Error vs_gl{NAN, NAN};
            std::string gl_file;
            if (r_.reference) {
                const auto key = std::make_pair(m.shader, m.supersample);
                if (!llvmpipe.count(key)) {
                    gl_file = "llvmpipe-" + file_name(m.shader) + "-ss" + std::to_string(m.supersample) + ".png";
                    llvmpipe[key] = reference(scene_file, scene, m);
                    llvmpipe_files[key] = gl_file;
                    write_image(dir / gl_file, llvmpipe[key]);
                }
                gl_file = llvmpipe_files[key];
                vs_gl = error_of(image, llvmpipe[key]);
            }
            const std::string images = "images/" + id + "/";
            csv += csv_line({label, view_name, m.name, m.group, m.shader, number(time.median), number(time.min),
                             number(time.max), number(vs_gl.rms), number(vs_gl.max), number(vs_truth.rms),
                             number(vs_truth.max), std::to_string(image.width), std::to_string(image.height),
                             images + name, gl_file.empty() ? "" : images + gl_file, images + "truth.png",
                             images + heat, truth_shader});
        }
    }

    // Each variant's GLSL, for the reference: output/glsl/NAME.vert and NAME.frag.
    void write_glsl() const {
        const fs::path dir = r_.output / "glsl";
        make_output_folder(dir, FolderLink::Refused);
        for (const std::string& name : {r_.shaders.shader, r_.shaders.unfiltered, r_.shaders.alternative}) {
            if (name.empty()) continue;
            const Program& p = *find_program(name);
            for (const bool vertex : {true, false})
                write_output(dir / (name + (vertex ? ".vert" : ".frag")), glsl_source(p, vertex));
        }
    }

    FrameRequest request(const Scene& scene, const Mode& m, int k) const {
        FrameRequest f;
        f.width = scene.width * k, f.height = scene.height * k;
        f.time = time_;
        f.shader_override = m.shader;
        f.backend = m.backend;
        f.shading.derivatives = m.rule;
        f.shading.precision = m.precision;
        f.shading.threads = r_.threads;
        return f;
    }

    // The mode's image at the scene's size and its time per frame (supersampled modes include
    // the filter).
    std::pair<Image, Timing> render(Scene& scene, const Mode& m) const {
        SceneRenderer renderer(scene, request(scene, m, m.supersample));
        Framebuffer fb;
        Image image;
        std::vector<double> ms;
        constexpr int kWarmUp = 3;  // untimed: thread pool, caches, first touch of the framebuffer
        const int warm_up = r_.repeat > 1 ? kWarmUp : 0;
        for (int i = 0; i < r_.repeat + warm_up; ++i) {
            const auto t0 = Clock::now();
            renderer.render_into(fb, std::nullopt);
            image = m.supersample > 1 ? box_filter(fb.rgba, fb.width, fb.height, m.supersample) : colour_image(fb);
            if (i >= warm_up) ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
        }
        std::sort(ms.begin(), ms.end());
        return {image, {ms[ms.size() / 2], ms.front(), ms.back()}};
    }

    Image reference(const fs::path& scene_file, const Scene& scene, const Mode& m) const {
        const int k = m.supersample;
        const fs::path image = scratch_ / "reference.exr", log = scratch_ / "reference.log";
        std::vector<std::string> argv = {reference_.string(),
                                         scene_file.string(),
                                         "-o",
                                         image.string(),
                                         "--glsl",
                                         (r_.output / "glsl").string(),
                                         "--driver",
                                         "llvmpipe",
                                         "--shader",
                                         m.shader,
                                         "--size",
                                         std::to_string(scene.width * k) + "x" + std::to_string(scene.height * k),
                                         "--threads",
                                         std::to_string(r_.threads)};
        if (time_) argv.insert(argv.end(), {"--time", number(*time_)});
        if (const int status = run_process(argv, log); status != 0) {
            throw std::runtime_error("quadshade-reference failed on " + scene_file.string() + " with " + m.shader +
                                     " (exit " + std::to_string(status) + "): " + read_text(log));
        }
        ImageReadLimits limits;  // the size asked for, checked on the header
        limits.width = scene.width * k, limits.height = scene.height * k;
        Image gl = read_image(image, limits);
        return k > 1 ? box_filter(gl.rgba, gl.width, gl.height, k) : gl;
    }

    // `shader` at truth x truth samples per pixel in double, box-filtered; rendered in bands of
    // rows so that a large rate never holds the whole supersampled frame.
    Image ground_truth(Scene& scene, const std::string& shader) const {
        Mode m{"truth", "", shader};
        m.precision = Precision::Double;
        const int k = r_.truth;
        const FrameRequest f = request(scene, m, k);
        SceneRenderer renderer(scene, f);
        std::vector<double> sum(std::size_t(scene.width) * std::size_t(scene.height) * 4, 0.0);
        constexpr int kBandPixels = 1 << 22;
        const int max_rows = std::max(1, kBandPixels / f.width);
        Framebuffer fb;
        for (const RowBand band : image_bands(f.height, f.shading.pairing, max_rows)) {
            renderer.render_into(fb, std::nullopt, nullptr, band);
            for (int row = 0; row < fb.rows; ++row) {
                const int y = (fb.first_row + row) / k;
                const float* in = &fb.rgba[std::size_t(row) * std::size_t(fb.width) * 4];
                for (int x = 0; x < fb.width; ++x) {
                    for (int c = 0; c < 4; ++c)
                        sum[(std::size_t(y) * std::size_t(scene.width) + std::size_t(x / k)) * 4 + c] += in[x * 4 + c];
                }
            }
        }
        Image out{scene.width, scene.height, std::vector<float>(sum.size())};
        for (std::size_t i = 0; i < sum.size(); ++i) out.rgba[i] = float(sum[i] / double(k * k));
        return out;
    }

    static void progress(std::size_t done, std::size_t total, const std::string& what) {
        const int width = 30, filled = int(done * width / total);
        std::fprintf(stderr, "\r[%s%s] %3zu/%zu %-48.48s", std::string(std::size_t(filled), '#').c_str(),
                     std::string(std::size_t(width - filled), '.').c_str(), done, total, what.c_str());
        std::fflush(stderr);
    }

    const Request& r_;
    fs::path reference_, scratch_;  // quadshade-reference; where its images and logs go
    std::optional<double> time_;    // the view's time (its frame's, or the request's), as r_.time
};

}  // namespace

std::vector<View> views_of(const Request& r) {
    std::vector<View> views;
    const std::vector<std::string> none = r.frames.empty()
                                              ? std::vector<std::string>{"camera", "magnified", "minified", "grazing"}
                                              : std::vector<std::string>{"camera"};
    for (const std::string& v : r.views.empty() ? none : r.views) views.push_back(view_named(v));
    return at_frames(views, r.frames, r.fps);
}

std::uint64_t check_study(const Request& r, std::uint64_t memory_limit) {
    if (r.size < 1 || r.truth < 1 || r.repeat < 1) {
        throw std::invalid_argument("size, truth and repeat must be positive");
    }
    if (!r.frames.empty() && !(r.fps > 0.0)) throw std::invalid_argument("frames need a positive fps");
    const std::vector<Mode> modes = chosen_modes(r);
    (void)views_of(r);
    check_shaders(r.shaders);
    (void)maps_of(r);
    Scene scene = study_scene(r);
    size_for(scene, r.size);
    const MemoryPlan plan = plan_memory(r, scene, modes);
    check_memory(plan, memory_limit);
    return plan.peak;
}

void run_study(const Request& request, Tables& tables) {
    if (request.size < 1 || request.truth < 1 || request.repeat < 1)
        throw std::invalid_argument("size, truth and repeat must be positive");
    Study(request).run(tables);
}

std::vector<fs::path> study_inputs(const Request& request) {
    std::vector<fs::path> inputs = load_scene(request.scene).inputs;
    inputs.push_back(request.scene);
    for (const View& view : views_of(request)) {
        if (view.camera_file.empty()) continue;
        const std::vector<fs::path> theirs = load_scene(view.camera_file).inputs;
        inputs.insert(inputs.end(), theirs.begin(), theirs.end());
        inputs.push_back(view.camera_file);
    }
    return inputs;
}

void refuse_outputs_over(const fs::path& output, const std::vector<fs::path>& inputs) {
    InputFiles files;
    for (const fs::path& input : inputs) files.add(input);
    for (const char* name : {"study.csv", "views.csv", "derivatives.csv", "stability.csv", "report.html"}) {
        if (files.contains(output / name))
            throw std::invalid_argument((output / name).string() + ": an input of this study; it would be overwritten");
    }
    for (const fs::path& input : inputs) {
        std::error_code ec;
        const fs::path target = fs::is_symlink(input, ec) ? fs::weakly_canonical(input, ec) : input;
        for (const char* folder : {"images", "plots", "glsl", "views"}) {
            if (inside(input, output / folder) || inside(target, output / folder)) {
                throw std::invalid_argument(input.string() + ": an input of this study, in " +
                                            (output / folder).string() + ", which the study fills");
            }
        }
    }
}

}  // namespace qs::study
