// quadshade-bench-error: error against run time for every derivative, anti-aliasing and precision
// mode, on the anti-aliased shaders and views that stress them.
//
//   quadshade-bench-error [--out DIR] [--size N] [--truth K] [--repeat N] [--threads N] [--quick]
//
// For each case (a shader family on a view) every mode renders an image, timed (median of
// --repeat frames, 2 threads by default), and is measured against
//   (a) OSMesa llvmpipe rendering the same GLSL (supersampled modes: llvmpipe supersampled alike);
//   (b) the ground truth: the un-anti-aliased pattern box-filtered over each pixel by K x K
//       supersampling (default 32 x 32) in double precision.
// Writes DIR/study.csv (one row per case and mode: time, RMS and max error against both) and
// DIR/images/CASE/*.png (each mode, llvmpipe, the truth, heat maps); bench/report.py turns them
// into plots and an HTML report. Progress goes to stderr.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "render/frame_image.h"
#include "shading/catalogue.h"
#include "shading/glsl_export.h"
#include "reference/gl_renderer.h"
#include "scenes/gltf.h"
#include "render/scene_render.h"

namespace {

using namespace qs;
using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

const fs::path kSource = QUADSHADE_SOURCE_DIR;

// ---- views ---------------------------------------------------------------------------------

struct View {
    std::string name;
    std::string description;
    std::function<void(Scene&)> apply;
};

void scale_texcoords(Scene& s, float k) {
    for (Mesh& m : s.meshes) {
        for (Vertex& v : m.vertices) v.texcoord *= k;
    }
}

// The Table 1.1 plane (z = 0, x and y in [-1, 1], st in [0, 1]) seen three ways.
std::vector<View> plane_views() {
    return {
        {"magnified", "orthographic, 0.3 of the plane's width fills the image: pattern edges span many pixels",
         [](Scene& s) { s.camera.xmag = s.camera.ymag = 0.3f; }},
        {"minified", "orthographic, st scaled by 4: a dot period is under 10 pixels",
         [](Scene& s) { scale_texcoords(s, 4.0f); }},
        {"grazing", "perspective over a plane 8 units wide, st scaled by 8, eye 0.5 above it: minification grows to the horizon",
         [](Scene& s) {
             scale_texcoords(s, 8.0f);
             for (Object& o : s.objects) o.world_from_object = glm::scale(glm::mat4(1.0f), glm::vec3(4.0f, 4.0f, 1.0f));
             s.camera.kind = Camera::Kind::Perspective;
             s.camera.yfov = glm::radians(40.0f);
             s.camera.znear = 0.05f, s.camera.zfar = 50.0f;
             s.camera.view = glm::lookAt(glm::vec3(0.0f, -4.2f, 0.5f), glm::vec3(0.0f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f));
         }},
    };
}

// ---- modes ---------------------------------------------------------------------------------

struct Family {
    std::string shader;       // the book's anti-aliased shader
    std::string alternative;  // its other anti-aliasing width: fwidth for aastep, length for spots
    std::string alternative_mode;
    std::string step;         // its un-anti-aliased variant
    fs::path scene;
    std::vector<View> views;
};

struct Mode {
    std::string name, group;
    std::string shader;  // which variant
    Backend backend = Backend::Rasterizer;
    Derivatives rule = Derivatives::Fine;
    Precision precision = Precision::Float;
    int supersample = 1;
};

std::vector<Mode> modes_of(const Family& f) {
    std::vector<Mode> m = {
        {"fine", "derivatives", f.shader},
        {"coarse-lower", "derivatives", f.shader, Backend::Rasterizer, Derivatives::CoarseLower},
        {"coarse-upper", "derivatives", f.shader, Backend::Rasterizer, Derivatives::CoarseUpper},
        {"dual2", "derivatives", f.shader, Backend::Rasterizer, Derivatives::Analytic},
        {"raycast-quads", "derivatives", f.shader, Backend::RayCaster, Derivatives::Fine},
        {"ray-differentials", "derivatives", f.shader, Backend::RayCaster, Derivatives::Analytic},
        {"double", "precision", f.shader, Backend::Rasterizer, Derivatives::Fine, Precision::Double},
    };
    m.push_back({f.alternative_mode, "anti-aliasing", f.alternative});
    // No anti-aliasing, then supersampling the un-anti-aliased pattern.
    const std::string plain = f.step;
    m.push_back({"step", "anti-aliasing", plain});
    for (int k : {2, 4, 8}) {
        Mode s{"ss" + std::to_string(k) + "x" + std::to_string(k), "anti-aliasing", plain};
        s.supersample = k;
        m.push_back(s);
    }
    return m;
}

// ---- images --------------------------------------------------------------------------------

// Box filter of k x k pixel blocks.
Image downsample(std::span<const float> rgba, int width, int height, int k) {
    Image out{width / k, height / k, std::vector<float>(std::size_t(width / k) * std::size_t(height / k) * 4, 0.0f)};
    for (int y = 0; y < out.height; ++y) {
        for (int x = 0; x < out.width; ++x) {
            double sum[4] = {0, 0, 0, 0};
            for (int j = 0; j < k; ++j) {
                const float* row = &rgba[((std::size_t(y) * k + j) * std::size_t(width) + std::size_t(x) * k) * 4];
                for (int i = 0; i < k * 4; ++i) sum[i % 4] += row[i];
            }
            for (int c = 0; c < 4; ++c) out.rgba[(std::size_t(y) * out.width + x) * 4 + c] = float(sum[c] / (k * k));
        }
    }
    return out;
}

struct Error {
    double rms = 0.0, max = 0.0;
};
// Over RGB, in [0, 1] units; the images are clamped as an 8-bit target would clamp them.
Error error_of(const Image& a, const Image& b) {
    double sum = 0.0, worst = 0.0;
    const std::size_t n = std::size_t(a.width) * std::size_t(a.height);
    for (std::size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) {
            const double d = std::clamp(double(a.rgba[i * 4 + c]), 0.0, 1.0) - std::clamp(double(b.rgba[i * 4 + c]), 0.0, 1.0);
            sum += d * d, worst = std::max(worst, std::abs(d));
        }
    }
    return {std::sqrt(sum / double(n * 3)), worst};
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

struct Options {
    fs::path out = "study";
    int size = 256, truth = 32, repeat = 5, threads = 2;
    bool quick = false;
};

class Study {
public:
    explicit Study(const Options& o) : o_(o) {}

    void run(const std::vector<Family>& families) {
        std::size_t total = 0, done = 0;
        for (const Family& f : families) total += f.views.size() * (modes_of(f).size() + 2);
        fs::create_directories(o_.out / "images");
        export_glsl(o_.out / "glsl");  // what the reference compiles: the catalogue's GLSL text
        std::ofstream csv(o_.out / "study.csv");
        csv << "shader,view,mode,group,variant,ms,rms_vs_llvmpipe,max_vs_llvmpipe,rms_vs_truth,max_vs_truth,"
               "width,height,image,llvmpipe_image,truth_image,heat_image\n";
        std::ofstream views(o_.out / "views.csv");
        views << "shader,view,description\n";
        for (const Family& f : families) {
            for (const View& v : f.views) {
                const std::string id = f.shader + "-" + v.name;
                const fs::path dir = o_.out / "images" / id;
                fs::create_directories(dir);
                views << f.shader << "," << v.name << ",\"" << v.description << "\"\n";
                Scene scene = load_scene(f.scene);
                v.apply(scene);
                size_for(scene);
                progress(++done, total, id + ": ground truth");
                const Image truth = ground_truth(scene, f);
                write_image(dir / "truth.png", truth);
                progress(++done, total, id + ": llvmpipe");
                std::map<std::pair<std::string, int>, Image> llvmpipe;  // (variant, supersample)
                for (const Mode& m : modes_of(f)) {
                    progress(++done, total, id + ": " + m.name);
                    const auto [image, ms] = render(scene, m);
                    auto key = std::make_pair(m.shader, m.supersample);
                    if (!llvmpipe.count(key)) {
                        llvmpipe[key] = reference(scene, m);
                        write_image(dir / ("llvmpipe-" + m.shader + "-ss" + std::to_string(m.supersample) + ".png"), llvmpipe[key]);
                    }
                    const Error vs_gl = error_of(image, llvmpipe[key]), vs_truth = error_of(image, truth);
                    const std::string name = m.name + ".png", heat = m.name + "-heat.png";
                    write_image(dir / name, image);
                    write_image(dir / heat, difference_heat_map(image, truth, 0.25f));
                    csv << f.shader << "," << v.name << "," << m.name << "," << m.group << "," << m.shader << "," << ms
                        << "," << vs_gl.rms << "," << vs_gl.max << "," << vs_truth.rms << "," << vs_truth.max << ","
                        << image.width << "," << image.height << ",images/" << id << "/" << name << ",images/" << id
                        << "/llvmpipe-" << m.shader << "-ss" << m.supersample << ".png,images/" << id
                        << "/truth.png,images/" << id << "/" << heat << "\n";
                    csv.flush();
                }
            }
        }
        std::fprintf(stderr, "\n");
    }

private:
    // Plane views are square; Figure 1.1 keeps its aspect at a quarter of its size.
    void size_for(Scene& scene) const {
        if (scene.width == scene.height) scene.width = scene.height = o_.size;
        else scene.width /= 4, scene.height /= 4;
    }

    FrameRequest request(const Scene& scene, const Mode& m, int k) const {
        FrameRequest r;
        r.width = scene.width * k, r.height = scene.height * k;
        r.shader_override = m.shader;
        r.backend = m.backend;
        r.shading.derivatives = m.rule;
        r.shading.precision = m.precision;
        r.shading.threads = o_.threads;
        return r;
    }

    // The mode's image at the scene's size and its time per frame (median; supersampled modes
    // include the filter).
    std::pair<Image, double> render(Scene& scene, const Mode& m) {
        SceneRenderer renderer(scene, request(scene, m, m.supersample));
        Framebuffer fb;
        Image image;
        std::vector<double> ms;
        constexpr int kWarmUp = 3;  // untimed: thread pool, caches, first-touch of the framebuffer
        for (int i = 0; i < o_.repeat + kWarmUp; ++i) {
            const auto t0 = Clock::now();
            renderer.render_into(fb, std::nullopt);
            image = m.supersample > 1 ? downsample(fb.rgba, fb.width, fb.height, m.supersample)
                                      : colour_image(fb);
            if (i >= kWarmUp) ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
        }
        return {image, median(ms)};
    }

    Image reference(Scene& scene, const Mode& m) {
        const int k = m.supersample;
        auto context = create_osmesa_context(scene.width * k, scene.height * k, GlDriver::Llvmpipe, o_.threads);
        const Image gl = GlSceneRenderer(scene, {scene.width * k, scene.height * k, {}, m.shader, {}}, *context, o_.out / "glsl").render();
        return k > 1 ? downsample(gl.rgba, gl.width, gl.height, k) : gl;
    }

    // The un-anti-aliased pattern, K x K samples per pixel in double precision, box-filtered.
    Image ground_truth(Scene& scene, const Family& f) {
        Mode m{"truth", "", f.step};
        m.precision = Precision::Double;
        SceneRenderer renderer(scene, request(scene, m, o_.truth));
        Framebuffer fb;
        renderer.render_into(fb, std::nullopt);
        return downsample(fb.rgba, fb.width, fb.height, o_.truth);
    }

    static void progress(std::size_t done, std::size_t total, const std::string& what) {
        const int width = 30, filled = int(done * width / total);
        std::fprintf(stderr, "\r[%s%s] %3zu/%zu %-48s", std::string(std::size_t(filled), '#').c_str(),
                     std::string(std::size_t(width - filled), '.').c_str(), done, total, what.c_str());
        std::fflush(stderr);
    }

    Options o_;
};

}  // namespace

int main(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&] {
            if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
            return std::string(argv[++i]);
        };
        try {
            if (a == "--out") o.out = value();
            else if (a == "--size") o.size = std::clamp(std::stoi(value()), 16, 2048);
            else if (a == "--truth") o.truth = std::clamp(std::stoi(value()), 2, 64);
            else if (a == "--repeat") o.repeat = std::clamp(std::stoi(value()), 1, 100);
            else if (a == "--threads") o.threads = std::clamp(std::stoi(value()), 1, 256);
            else if (a == "--quick") o.quick = true;
            else throw std::runtime_error("unknown option " + a);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "quadshade-bench-error: %s\nusage: quadshade-bench-error [--out DIR] [--size N] "
                                 "[--truth K] [--repeat N] [--threads N] [--quick]\n", e.what());
            return 2;
        }
    }
    const fs::path plane = kSource / "scenes/assets/table-1.1-plane.gltf";
    const fs::path figure = kSource / "scenes/assets/figure-1.1.gltf";
    // Figure 1.1's spots sphere alone, from the scene's camera.
    const View spots_view{"figure", "Figure 1.1's camera, the spots sphere alone, at a quarter of 1264x400", [](Scene& s) {
                              std::erase_if(s.objects, [](const Object& o) { return o.shader != "spots"; });
                          }};
    std::vector<Family> families = {
        {"dots_aa", "dots_aa_fwidth", "aastep-fwidth", "dots_aa_step", plane, plane_views()},
        {"bricks_aa", "bricks_aa_fwidth", "aastep-fwidth", "bricks_aa_step", plane, plane_views()},
        {"worley_tiles", "worley_tiles_fwidth", "aastep-fwidth", "worley_tiles_step", plane, plane_views()},
        {"halftone", "halftone_fwidth", "aastep-fwidth", "halftone_step", plane, plane_views()},
        // The book's spots blend over fwidth; the alternative is the gradient's true length.
        {"spots", "spots_length", "width-length", "spots_step", figure, {spots_view}},
    };
    if (o.quick) {  // one family, one view: a smoke run
        families.resize(1);
        families[0].views.resize(1);
    }
    try {
        Study(o).run(families);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "\nquadshade-bench-error: %s\n", e.what());
        return 1;
    }
    std::fprintf(stderr, "quadshade-bench-error: wrote %s\n", (o.out / "study.csv").c_str());
    return 0;
}
