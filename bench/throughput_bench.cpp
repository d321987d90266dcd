// quadshade-bench-throughput: Table 1.1's shaders on the Table 1.1 plane, quadshade next to OSMesa
// llvmpipe in one run on the same cores (LP_NUM_THREADS = quadshade's thread count), next to
// the book's 2011 GPU figures. Frames are timed after set-up (context creation and GLSL
// compilation are reported separately); llvmpipe frames end with glFinish. Both render into a
// float RGBA target, as the reference comparisons do.
//
//   quadshade-bench-throughput [--threads N] [--repeat N] [--sizes 1024,500] [--shaders a,b] [--out DIR]
// Writes DIR/throughput.csv and DIR/throughput.md and prints the Markdown table.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "shading/catalogue.h"
#include "shading/glsl_export.h"
#include "reference/gl_renderer.h"
#include "scenes/gltf.h"
#include "render/scene_render.h"

namespace {

using Clock = std::chrono::steady_clock;

struct Row {
    const char* shader;
    const char* book_name;
    int book[4];  // Mfrag/s on NVIDIA 9600M, AMD HD6310, AMD HD4850, NVIDIA GTX260 (seed 000)
};
const Row kRows[] = {
    {"constant_color", "Constant color", {422, 430, 2721, 3610}},
    {"single_texture", "Single texture", {412, 414, 2718, 3610}},
    {"dots", "Dots (Fig 1.2)", {360, 355, 2720, 3420}},
    {"perlin", "Perlin noise (Fig 1.4)", {63, 97, 1042, 697}},
    {"perlin5", "5x Perlin (Fig 1.4)", {11, 23, 271, 146}},
    {"worley", "Worley noise (Fig 1.5)", {82, 116, 1192, 787}},
    {"worley_tiles", "Worley tiles (Fig 1.5)", {26, 51, 580, 345}},
    {"halftone", "Halftone (Fig 1.6)", {34, 52, 597, 373}},
};

struct Stats {
    double median = 0, min = 0, max = 0;  // ms per frame
};
Stats stats_of(std::vector<double> ms) {
    std::sort(ms.begin(), ms.end());
    return {ms[ms.size() / 2], ms.front(), ms.back()};
}

template <class F>
Stats time_frames(int repeat, F&& frame) {
    frame();  // warm-up
    std::vector<double> ms;
    for (int i = 0; i < repeat; ++i) {
        const auto t0 = Clock::now();
        frame();
        ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    }
    return stats_of(ms);
}

// What the specialised pipeline keeps for a shader, in words; the depth buffer is the frame's
// (the plane's two triangles do not overlap: none).
std::string needs_of(const char* shader, const qs::RenderStats& frame) {
    const qs::Program* p = qs::find_program(shader);
    if (!p) return "?";
    const qs::Needs& n = p->info().needs;
    std::string s = n.derivatives ? "quads" : "per pixel";
    s += frame.depth_buffer ? ", depth" : ", no depth";
    s += n.texture ? ", texture" : "";
    return s;
}

// Figure 1.1, one frame: the rasterizer and the ray caster (quad derivatives and ray
// differentials) next to llvmpipe, with the ray caster's one-off BVH build apart.
std::string figure_frames(int threads, int repeat, const std::filesystem::path& glsl) {
    const std::filesystem::path file = std::filesystem::path(QUADSHADE_SOURCE_DIR) / "scenes/assets/figure-1.1.gltf";
    qs::Scene scene = qs::load_scene(file);
    std::ostringstream md;
    md << "| renderer | derivatives | ms per frame | set-up ms | of which BVH build ms |\n|---|---|---|---|---|\n";
    struct Mode {
        const char* name;
        qs::Backend backend;
        qs::Derivatives rule;
        const char* rule_name;
    };
    const Mode modes[] = {{"quadshade rasterizer", qs::Backend::Rasterizer, qs::Derivatives::Fine, "fine quads"},
                          {"quadshade rasterizer", qs::Backend::Rasterizer, qs::Derivatives::Analytic, "Dual2, plane derivatives"},
                          {"quadshade ray caster", qs::Backend::RayCaster, qs::Derivatives::Fine, "fine ray quads"},
                          {"quadshade ray caster", qs::Backend::RayCaster, qs::Derivatives::Analytic, "Dual2, ray differentials"}};
    for (const Mode& m : modes) {
        qs::FrameRequest req;
        req.backend = m.backend;
        req.shading.derivatives = m.rule;
        req.shading.threads = threads;
        const auto s0 = Clock::now();
        qs::SceneRenderer renderer(scene, req);
        const double setup = std::chrono::duration<double, std::milli>(Clock::now() - s0).count();
        qs::Framebuffer fb;
        const Stats t = time_frames(repeat, [&] { renderer.render_into(fb, std::nullopt); });
        char line[256];
        std::snprintf(line, sizeof line, "| %s | %s | %.1f (%.1f-%.1f) | %.1f | %.1f |\n", m.name, m.rule_name, t.median,
                      t.min, t.max, setup, 1e3 * renderer.bvh_build_seconds());
        md << line;
    }
    auto context = qs::create_osmesa_context(scene.width, scene.height, qs::GlDriver::Llvmpipe, threads);
    const auto s0 = Clock::now();
    qs::GlSceneRenderer gl(scene, {scene.width, scene.height, {}, "", {}}, *context, glsl);
    gl.draw();
    const double setup = std::chrono::duration<double, std::milli>(Clock::now() - s0).count();
    const Stats l = time_frames(repeat, [&] { gl.draw(); });
    char line[256];
    std::snprintf(line, sizeof line, "| OSMesa llvmpipe | fine quads | %.1f (%.1f-%.1f) | %.0f (context, GLSL compile) | - |\n", l.median, l.min, l.max, setup);
    md << line;
    return md.str();
}

}  // namespace

int main(int argc, char** argv) {
    int threads = 2, repeat = 15;
    std::vector<int> sizes = {1024, 500};
    std::string out = "bench-results";
    std::vector<std::string> only;  // --shaders: these rows only, and no Figure 1.1 frame
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&] { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
        if (a == "--threads") threads = std::max(1, std::atoi(value().c_str()));
        else if (a == "--repeat") repeat = std::max(3, std::atoi(value().c_str()));
        else if (a == "--out") out = value();
        else if (a == "--shaders") {
            std::stringstream ss(value());
            for (std::string sh; std::getline(ss, sh, ',');) only.push_back(sh);
        }
        else if (a == "--sizes") {
            sizes.clear();
            std::stringstream ss(value());
            for (std::string s; std::getline(ss, s, ',');) sizes.push_back(std::atoi(s.c_str()));
        } else {
            std::fprintf(stderr, "usage: quadshade-bench-throughput [--threads N] [--repeat N] [--sizes 1024,500] "
                                 "[--shaders a,b] [--out DIR]\n");
            return a == "--help" ? 0 : 2;
        }
    }
    try {
        const std::filesystem::path plane = std::filesystem::path(QUADSHADE_SOURCE_DIR) / "scenes/assets/table-1.1-plane.gltf";
        std::filesystem::create_directories(out);
        const std::filesystem::path glsl = std::filesystem::path(out) / "glsl";  // what llvmpipe compiles
        qs::export_glsl(glsl);
        std::ofstream csv(std::filesystem::path(out) / "throughput.csv");
        csv << "shader,size,threads,quadshade_ms_median,quadshade_ms_min,quadshade_ms_max,llvmpipe_ms_median,"
               "llvmpipe_ms_min,llvmpipe_ms_max,llvmpipe_setup_ms,quadshade_mfrags,llvmpipe_mfrags,speedup\n";
        std::ostringstream md;
        md << "| shader | size | quadshade Mfrag/s | llvmpipe Mfrag/s | speedup (goal >= 2) | llvmpipe set-up ms | "
              "2011 GPUs: 9600M / HD6310 / HD4850 / GTX260 |\n|---|---|---|---|---|---|---|\n";
        std::ostringstream special;
        special << "| shader | size | what the shader needs | specialised ms | general path ms | saving |\n"
                   "|---|---|---|---|---|---|\n";
        for (int size : sizes) {
            auto context = qs::create_osmesa_context(size, size, qs::GlDriver::Llvmpipe, threads);
            for (const Row& row : kRows) {
                if (!only.empty() && std::find(only.begin(), only.end(), row.shader) == only.end()) continue;
                std::fprintf(stderr, "\r%-16s %4dx%-4d ...", row.shader, size, size);
                qs::Scene scene = qs::load_scene(plane);
                qs::FrameRequest req;
                req.width = req.height = size;
                req.shader_override = row.shader;
                req.shading.threads = threads;
                qs::Framebuffer fb;
                qs::SceneRenderer renderer(scene, req);
                const Stats q = time_frames(repeat, [&] { renderer.render_into(fb, std::nullopt); });
                qs::RenderStats frame;
                renderer.render_into(fb, std::nullopt, &frame);
                // The same frame through the general path: quads with helper lanes and a depth
                // buffer whatever the shader needs.
                qs::FrameRequest general_req = req;
                general_req.raster.force_general_path = true;
                qs::SceneRenderer general(scene, general_req);
                const Stats g = time_frames(repeat, [&] { general.render_into(fb, std::nullopt); });
                char saving[256];
                std::snprintf(saving, sizeof saving, "| %s | %d | %s | %.2f | %.2f | %.0f%% |\n", row.book_name, size,
                              needs_of(row.shader, frame).c_str(), q.median, g.median, 100.0 * (1.0 - q.median / g.median));
                special << saving;
                const auto s0 = Clock::now();
                qs::GlSceneRenderer gl(scene, {size, size, {}, row.shader, {}}, *context, glsl);
                gl.draw();  // the first frame compiles llvmpipe's code
                const double setup = std::chrono::duration<double, std::milli>(Clock::now() - s0).count();
                const Stats l = time_frames(repeat, [&] { gl.draw(); });
                const double frags = double(size) * size * 1e-3;  // per ms -> Mfrag/s
                const double qm = frags / q.median, lm = frags / l.median;
                csv << row.shader << "," << size << "," << threads << "," << q.median << "," << q.min << "," << q.max << ","
                    << l.median << "," << l.min << "," << l.max << "," << setup << "," << qm << "," << lm << ","
                    << qm / lm << "\n";
                char line[512];
                std::snprintf(line, sizeof line, "| %s | %d | %.0f (%.0f-%.0f) | %.0f (%.0f-%.0f) | %.2fx | %.0f | %d / %d / %d / %d |\n",
                              row.book_name, size, qm, frags / q.max, frags / q.min, lm, frags / l.max, frags / l.min,
                              qm / lm, setup, row.book[0], row.book[1], row.book[2], row.book[3]);
                md << line;
            }
        }
        std::fprintf(stderr, "\r%40s\r", "");
        std::ofstream(std::filesystem::path(out) / "throughput.md") << md.str();
        std::printf("%d threads, median of %d frames (min-max in brackets), float RGBA target\n\n%s", threads, repeat,
                    md.str().c_str());
        std::ofstream(std::filesystem::path(out) / "specialisation.md") << special.str();
        std::printf("\nLeaving out what a shader does not need (median ms per frame, %d threads): the specialised "
                    "pipeline against the general one (quads with helper lanes, depth buffer)\n\n%s",
                    threads, special.str().c_str());
        if (!only.empty()) return 0;
        const std::string figure = figure_frames(threads, repeat, glsl);
        std::ofstream(std::filesystem::path(out) / "figure-1.1-frame.md") << figure;
        std::printf("\nFigure 1.1 at 1264x400, %d threads, median of %d frames (min-max)\n\n%s", threads, repeat,
                    figure.c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "quadshade-bench-throughput: %s\n", e.what());
        return 1;
    }
    return 0;
}
