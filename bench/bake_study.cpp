// quadshade-bench-bake: the chapter's trade-off measured. A shader baked into a mesh's atlas and
// drawn as a texture (trilinear, mipmaps built on load) against the live procedural render:
// error and frame time, magnified (an atlas smaller than the mesh on screen) and minified, and
// the seams the gutter leaves, with skirts of 0, 2, 4 and 8 texels; normal maps from a height,
// by finite differences against Dual2 (angle error against the step, float and double, and
// cost); and the lit bake (colour and normal map drawn by baked_lit) against the lit live render
// (noise_bumps_lit).
//
//   quadshade-bench-bake [--out DIR] [--repeat N] [--threads N]
//
// Prints four tables and writes them to DIR/bake.md, DIR/bake-seams.md, DIR/bake-normals.md and
// DIR/bake-lit.md (bench/results.py puts them into docs/results.md), with every image compared
// in DIR.
//
// Seam pixels: pixels of the mesh whose texture lookups, without skirts, reach gutter texels
// (the baked render's alpha, the atlas's coverage filtered as the colour is, is below 1 there).
// For each skirt width: how many of them still read gutter, how many differ from the live render
// by more than 1/255 and 8/255, and their mean error beside that of the other mesh pixels.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "images/image_io.h"
#include "render/atlas_bake.h"
#include "render/frame_image.h"
#include "render/normal_bake.h"
#include "scenes/gltf.h"
#include "shading/height_field.h"

namespace {

using namespace qs;
using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

const fs::path kSource = QUADSHADE_SOURCE_DIR;

struct Options {
    fs::path out = "bake-study";
    int repeat = 5;
    int threads = 2;
};

// The median of `repeat` runs of f, in ms.
template <class F>
double median_ms(int repeat, F&& f) {
    std::vector<double> t;
    for (int r = 0; r < repeat; ++r) {
        const auto t0 = Clock::now();
        f();
        t.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}

// The median of `repeat` renders' wall time, and the last frame.
Framebuffer timed(Scene& scene, const FrameRequest& request, int repeat, double& ms) {
    Framebuffer fb;
    SceneRenderer renderer(scene, request);
    ms = median_ms(repeat, [&] { renderer.render_into(fb, request.time); });
    return fb;
}

// The scene drawn with its baked atlas, written to `dir` (the texture is read back from there).
Scene baked_in(const Scene& live, const Image& atlas, const fs::path& dir, const std::string& name) {
    const fs::path png = dir / (name + ".png");
    write_image(png, atlas, {}, true);
    return baked_scene(live, png);
}

// printf to stdout and to a file.
struct Table {
    std::ofstream file;
    explicit Table(const fs::path& path) : file(path) {
        if (!file) throw std::runtime_error(path.string() + ": cannot write");
    }
    [[gnu::format(printf, 2, 3)]] void line(const char* format, ...) {
        char buffer[1024];
        va_list args;
        va_start(args, format);
        std::vsnprintf(buffer, sizeof buffer, format, args);
        va_end(args);
        std::fputs(buffer, stdout);
        file << buffer;
    }
};

float rgb_error(const Framebuffer& a, const Framebuffer& b, std::size_t i) {
    float e = 0.0f;
    for (int c = 0; c < 3; ++c) {
        const float x = std::clamp(a.rgba[i * 4 + std::size_t(c)], 0.0f, 1.0f), y = std::clamp(b.rgba[i * 4 + std::size_t(c)], 0.0f, 1.0f);
        e = std::max(e, std::abs(std::round(x * 255.0f) - std::round(y * 255.0f)));
    }
    return e;  // 8-bit steps
}

// A baked frame B against the live frame L over the pixels L covers: the mean RGB error in 8-bit
// steps and how many pixels are over 8 steps.
struct LiveError {
    double mean = 0;
    std::size_t over8 = 0, covered = 0;
};
LiveError error_against_live(const Framebuffer& L, const Framebuffer& B) {
    LiveError r;
    double sum = 0;
    for (std::size_t i = 0; i < std::size_t(L.width) * std::size_t(L.height); ++i) {
        if (L.rgba[i * 4 + 3] < 0.5f) continue;
        const float e = rgb_error(L, B, i);
        sum += e, ++r.covered, r.over8 += e > 8.0f;
    }
    r.mean = sum / double(r.covered);
    return r;
}

// The three views of both live-against-baked tables: the atlas magnified, matched, minified.
struct View {
    const char* name;
    int frame, atlas;
};
constexpr View kViews[] = {{"magnified", 1024, 256}, {"matched", 512, 1024}, {"minified", 128, 1024}};

void live_against_baked_header(Table& md) {
    md.line("| view | frame | atlas | live ms | baked ms | baked/live | mean error (8-bit steps) | pixels over 8/255 |\n");
    md.line("|---|---|---|---|---|---|---|---|\n");
}
// One view's row: the live and the baked frame timed and compared, both written as PREFIXlive-
// and PREFIXbaked-VIEW.png.
void live_against_baked_row(Table& md, const View& v, double bake_ms, Scene live, const FrameRequest& live_request,
                            Scene baked, const FrameRequest& baked_request, const Options& o, const std::string& prefix) {
    double live_ms = 0, baked_ms = 0;
    const Framebuffer L = timed(live, live_request, o.repeat, live_ms);
    const Framebuffer B = timed(baked, baked_request, o.repeat, baked_ms);
    const LiveError e = error_against_live(L, B);
    md.line("| %s | %dx%d | %d^2 (bake %.0f ms) | %.2f | %.2f | %.2f | %.2f | %zu of %zu |\n", v.name, v.frame, v.frame,
            v.atlas, bake_ms, live_ms, baked_ms, baked_ms / live_ms, e.mean, e.over8, e.covered);
    write_image(o.out / (prefix + "live-" + v.name + ".png"), colour_image(L));
    write_image(o.out / (prefix + "baked-" + v.name + ".png"), colour_image(B));
}

// Finite differences against the analytic normal (Dual2 in double is the reference), per step
// and precision, over every covered texel of a 512^2 atlas of the sphere.
void normals_study(const Options& o) {
    const fs::path mesh = kSource / "scenes/assets/bake/atlas-sphere.gltf";
    const Scene scene = load_scene(mesh);
    const HeightField& field = *find_height_field("noise_bumps");
    constexpr int kSize = 512;
    const auto w0 = Clock::now();
    const AtlasTexels texels = atlas_texels(scene, kSize);
    const double walk_ms = std::chrono::duration<double, std::milli>(Clock::now() - w0).count();
    NormalBakeRequest r;
    r.size = kSize, r.threads = o.threads;
    r.precision = Precision::Double;
    const std::vector<glm::dvec3> truth = surface_normals(field, texels, r);
    Table md(o.out / "bake-normals.md");
    md.line("\n## Normal maps: finite differences against Dual2, noise_bumps on %s, atlas %d^2 (%zu texels), %d threads, "
            "median of %d runs\n\n",
            mesh.filename().c_str(), kSize, texels.texel.size(), o.threads, o.repeat);
    md.line("Angles against the analytic normal in double; e in object units (the sphere's radius is 1, a texel about "
            "%.1e); the texel walk (positions and frames) takes %.1f ms once.\n\n",
            2.0 * 3.14159265 / kSize, walk_ms);
    md.line("| method | precision | e | max angle (deg) | RMS angle (deg) | ms |\n|---|---|---|---|---|---|\n");
    auto row = [&](NormalMethod method, Precision precision, double e) {
        r.method = method, r.precision = precision, r.step = e;
        std::vector<glm::dvec3> n;
        const double ms = median_ms(o.repeat, [&] { n = surface_normals(field, texels, r); });
        double worst = 0.0, sum2 = 0.0;
        for (std::size_t k = 0; k < n.size(); ++k) {
            const double a = std::atan2(glm::length(glm::cross(n[k], truth[k])), glm::dot(n[k], truth[k])) * 180.0 / 3.14159265358979;
            worst = std::max(worst, a), sum2 += a * a;
        }
        const char* p = precision == Precision::Double ? "double" : "float";
        if (method == NormalMethod::Analytic) {
            md.line("| analytic (Dual2) | %s | - | %.2e | %.2e | %.1f |\n", p, worst, std::sqrt(sum2 / double(n.size())), ms);
        } else {
            md.line("| finite differences | %s | %.0e | %.2e | %.2e | %.1f |\n", p, e, worst, std::sqrt(sum2 / double(n.size())), ms);
        }
    };
    row(NormalMethod::Analytic, Precision::Float, 0.0);
    row(NormalMethod::Analytic, Precision::Double, 0.0);
    for (Precision precision : {Precision::Float, Precision::Double}) {
        for (double e : {1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6}) row(NormalMethod::FiniteDifferences, precision, e);
    }
}

// noise_bumps baked (colour and analytic normal map) and drawn by baked_lit, against
// noise_bumps_lit live, as the first table.
void lit_study(const Options& o, const FrameRequest& frame) {
    const fs::path mesh = kSource / "scenes/assets/bake/atlas-sphere.gltf";
    const Scene live = load_scene(mesh);
    const HeightField& field = *find_height_field("noise_bumps");
    Table md(o.out / "bake-lit.md");
    md.line("\n## Lit: noise_bumps baked (colour, normal map) and drawn by baked_lit against noise_bumps_lit live, on %s, "
            "%d threads, median of %d frames\n\n",
            mesh.filename().c_str(), o.threads, o.repeat);
    live_against_baked_header(md);
    for (const View& v : kViews) {
        AtlasRequest bake;
        bake.size = v.atlas, bake.skirt = 4, bake.frame = frame;
        bake.frame.shader_override = "noise_bumps";
        NormalBakeRequest n;
        n.size = v.atlas, n.skirt = 4, n.threads = o.threads;
        const auto b0 = Clock::now();
        const Image color = bake_atlas(live, bake), normals = bake_normal_map(live, field, n);
        const double bake_ms = std::chrono::duration<double, std::milli>(Clock::now() - b0).count();
        const fs::path color_png = o.out / (std::string("lit-color-") + v.name + ".png"),
                       normal_png = o.out / (std::string("lit-normal-") + v.name + ".png");
        write_image(color_png, color, {}, true);
        write_image(normal_png, normals, {}, true);
        FrameRequest r = frame;
        r.width = r.height = v.frame;
        FrameRequest lr = r;
        lr.shader_override = "noise_bumps_lit";
        live_against_baked_row(md, v, bake_ms, live, lr, baked_scene(live, color_png, normal_png, {}), r, o, "lit-");
    }
}

// bake.md: each view's frame of the live shader against the frame drawn from its baked atlas,
// with the bake's time.
void baked_against_live_study(const Options& o, const Scene& live, const fs::path& mesh, const std::string& shader,
                              const FrameRequest& frame) {
    Table bake_md(o.out / "bake.md");
    bake_md.line("## Baked against live: %s on %s, time 0.5, %d threads, median of %d frames\n\n", shader.c_str(),
                mesh.filename().c_str(), o.threads, o.repeat);
    live_against_baked_header(bake_md);
    for (const View& v : kViews) {
        AtlasRequest bake;
        bake.size = v.atlas, bake.skirt = 4, bake.frame = frame;
        bake.frame.shader_override = shader;
        const auto b0 = Clock::now();
        const Image atlas = bake_atlas(live, bake);
        const double bake_ms = std::chrono::duration<double, std::milli>(Clock::now() - b0).count();
        FrameRequest r = frame;
        r.width = r.height = v.frame;
        live_against_baked_row(bake_md, v, bake_ms, live, r, baked_in(live, atlas, o.out, std::string("atlas-") + v.name), r, o, "");
    }
}

// bake-seams.md: the pixels along the atlas' seams against the others, with skirts of 0 to 8
// texels: how many read the gutter, and their error against the live frame.
void seams_study(const Options& o, const Scene& live, const std::string& shader, const FrameRequest& frame) {
    Table seams_md(o.out / "bake-seams.md");
    seams_md.line("\n## Seams: atlas 256^2, frame 512x512, skirts of 0, 2, 4, 8 texels\n\n");
    seams_md.line("| skirt | seam pixels reading gutter | seam pixels over 1/255 | over 8/255 | mean error at seams | mean error elsewhere |\n");
    seams_md.line("|---|---|---|---|---|---|\n");
    FrameRequest r = frame;
    r.width = r.height = 512;
    Scene live_copy = live;
    const Framebuffer L = render_frame(live_copy, r);
    std::vector<char> seam;
    for (int skirt : {0, 2, 4, 8}) {
        AtlasRequest bake;
        bake.size = 256, bake.skirt = skirt, bake.frame = frame;
        bake.frame.shader_override = shader;
        Scene baked = baked_in(live, bake_atlas(live, bake), o.out, "atlas-skirt-" + std::to_string(skirt));
        const Framebuffer B = render_frame(baked, r);
        const std::size_t pixels = std::size_t(512) * 512;
        if (seam.empty()) {  // without skirts: where lookups reach the gutter
            seam.resize(pixels);
            for (std::size_t i = 0; i < pixels; ++i) seam[i] = L.rgba[i * 4 + 3] > 0.5f && B.rgba[i * 4 + 3] < 254.5f / 255.0f;
        }
        std::size_t gutter = 0, over1 = 0, over8 = 0, n_seam = 0, n_rest = 0;
        double sum_seam = 0, sum_rest = 0;
        for (std::size_t i = 0; i < pixels; ++i) {
            if (L.rgba[i * 4 + 3] < 0.5f) continue;
            const float e = rgb_error(L, B, i);
            if (seam[i]) {
                ++n_seam, sum_seam += e, over1 += e > 1.0f, over8 += e > 8.0f;
                gutter += B.rgba[i * 4 + 3] < 254.5f / 255.0f;
            } else {
                ++n_rest, sum_rest += e;
            }
        }
        seams_md.line("| %d | %zu of %zu | %zu | %zu | %.2f | %.2f |\n", skirt, gutter, n_seam, over1, over8, sum_seam / double(n_seam),
                    sum_rest / double(n_rest));
        write_image(o.out / ("baked-skirt-" + std::to_string(skirt) + ".png"), colour_image(B));
    }
    write_image(o.out / "live.png", colour_image(L));
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--out" && i + 1 < argc) o.out = argv[++i];
        else if (a == "--repeat" && i + 1 < argc) o.repeat = std::max(1, std::atoi(argv[++i]));
        else if (a == "--threads" && i + 1 < argc) o.threads = std::max(1, std::atoi(argv[++i]));
        else {
            std::fprintf(stderr, "usage: quadshade-bench-bake [--out DIR] [--repeat N] [--threads N]\n");
            return 2;
        }
    }
    try {
        fs::create_directories(o.out);
        const fs::path mesh = kSource / "scenes/assets/bake/atlas-cube.gltf";
        const std::string shader = "spots";
        const Scene live = load_scene(mesh);
        FrameRequest frame;
        frame.time = 0.5;
        frame.shading.threads = o.threads;

        baked_against_live_study(o, live, mesh, shader, frame);
        seams_study(o, live, shader, frame);
        normals_study(o);
        lit_study(o, frame);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "quadshade-bench-bake: %s\n", e.what());
        return 1;
    }
    return 0;
}
