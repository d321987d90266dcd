// quadshade-bench-bake: the chapter's trade-off measured. A shader baked into a mesh's atlas and
// drawn as a texture (trilinear, mipmaps built on load) against the live procedural render:
// error and frame time, magnified (an atlas smaller than the mesh on screen) and minified, and
// the seams the gutter leaves, with skirts of 0, 2, 4 and 8 texels.
//
//   quadshade-bench-bake [--out DIR] [--repeat N] [--threads N]
//
// Prints two tables and writes them to DIR/bake.md and DIR/bake-seams.md (bench/results.py puts
// them into docs/results.md), with every image compared in DIR.
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

#include "render/atlas_bake.h"
#include "scenes/gltf.h"
#include "scenes/image_io.h"

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

// The median of `repeat` renders' wall time, and the last frame.
Framebuffer timed(Scene& scene, const FrameRequest& request, int repeat, double& ms) {
    std::vector<double> t;
    Framebuffer fb;
    SceneRenderer renderer(scene, request);
    for (int r = 0; r < repeat; ++r) {
        const auto t0 = Clock::now();
        renderer.render_into(fb, request.time);
        t.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    }
    std::sort(t.begin(), t.end());
    ms = t[t.size() / 2];
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

        Table bake_md(o.out / "bake.md");
        bake_md.line("## Baked against live: %s on %s, time 0.5, %d threads, median of %d frames\n\n", shader.c_str(),
                    mesh.filename().c_str(), o.threads, o.repeat);
        bake_md.line("| view | frame | atlas | live ms | baked ms | baked/live | mean error (8-bit steps) | pixels over 8/255 |\n");
        bake_md.line("|---|---|---|---|---|---|---|---|\n");
        struct View { const char* name; int frame, atlas; };
        for (const View v : {View{"magnified", 1024, 256}, View{"matched", 512, 1024}, View{"minified", 128, 1024}}) {
            AtlasRequest bake;
            bake.size = v.atlas, bake.skirt = 4, bake.frame = frame;
            bake.frame.shader_override = shader;
            const auto b0 = Clock::now();
            const Image atlas = bake_atlas(live, bake);
            const double bake_ms = std::chrono::duration<double, std::milli>(Clock::now() - b0).count();
            Scene baked = baked_in(live, atlas, o.out, std::string("atlas-") + v.name);
            Scene live_copy = live;
            FrameRequest r = frame;
            r.width = r.height = v.frame;
            double live_ms = 0, baked_ms = 0;
            const Framebuffer L = timed(live_copy, r, o.repeat, live_ms);
            const Framebuffer B = timed(baked, r, o.repeat, baked_ms);
            double sum = 0;
            std::size_t n = 0, over8 = 0;
            for (std::size_t i = 0; i < std::size_t(v.frame) * std::size_t(v.frame); ++i) {
                if (L.rgba[i * 4 + 3] < 0.5f) continue;
                const float e = rgb_error(L, B, i);
                sum += e, ++n, over8 += e > 8.0f;
            }
            bake_md.line("| %s | %dx%d | %d^2 (bake %.0f ms) | %.2f | %.2f | %.2f | %.2f | %zu of %zu |\n", v.name, v.frame, v.frame,
                        v.atlas, bake_ms, live_ms, baked_ms, baked_ms / live_ms, sum / double(n), over8, n);
            write_image(o.out / (std::string("live-") + v.name + ".png"), Image{L.width, L.height, L.rgba});
            write_image(o.out / (std::string("baked-") + v.name + ".png"), Image{B.width, B.height, B.rgba});
        }

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
            write_image(o.out / ("baked-skirt-" + std::to_string(skirt) + ".png"), Image{B.width, B.height, B.rgba});
        }
        write_image(o.out / "live.png", Image{L.width, L.height, L.rgba});
    } catch (const std::exception& e) {
        std::fprintf(stderr, "quadshade-bench-bake: %s\n", e.what());
        return 1;
    }
    return 0;
}
