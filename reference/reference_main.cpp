// quadshade-reference: renders a scene's original GLSL through OSMesa (Mesa llvmpipe or
// softpipe) into a float image, the reference quadshade's images are compared with.
//
//   quadshade-reference SCENE.gltf -o OUT.exr [-o OUT.png ...] [--driver llvmpipe|softpipe] [--size WxH]
//                       [--time T] [--shader NAME] [--threads N] [--repeat N]
// Exit codes: 0 success, 1 bad input or GL failure, 2 bad usage.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "reference/gl_renderer.h"
#include "scenes/gltf.h"

namespace {

const char* kUsage =
    "usage: quadshade-reference SCENE.gltf -o OUT.exr [-o OUT.png ...] [options]\n"
    "  -o FILE          an output; .exr/.tif keep float, .png is GL's 8-bit conversion (repeatable)\n"
    "  --driver D       llvmpipe (default) or softpipe\n"
    "  --size WxH       image size (default: the scene's)\n"
    "  --time T         the `time` uniform (default: the scene's)\n"
    "  --shader NAME    draw every object with this catalogue shader's GLSL\n"
    "  --threads N      LP_NUM_THREADS for llvmpipe\n"
    "  --repeat N       render N times and report the median frame time (glFinish per frame)\n"
    "The output records the driver, renderer string and Mesa version in its metadata.\n";

}  // namespace

int main(int argc, char** argv) {
    std::string scene_path, shader;
    std::vector<std::string> outputs;
    qs::GlDriver driver = qs::GlDriver::Llvmpipe;
    int width = 0, height = 0, threads = 0, repeat = 1;
    std::optional<float> time;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "quadshade-reference: %s needs a value\n%s", a.c_str(), kUsage);
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--help" || a == "-h") {
            std::fputs(kUsage, stdout);
            return 0;
        } else if (a == "-o") {
            outputs.push_back(value());
        } else if (a == "--driver") {
            const std::string d = value();
            if (d == "llvmpipe") driver = qs::GlDriver::Llvmpipe;
            else if (d == "softpipe") driver = qs::GlDriver::Softpipe;
            else { std::fprintf(stderr, "quadshade-reference: unknown driver '%s'\n", d.c_str()); return 2; }
        } else if (a == "--size") {
            if (std::sscanf(value().c_str(), "%dx%d", &width, &height) != 2 || width <= 0 || height <= 0 ||
                width > 16384 || height > 16384) {
                std::fprintf(stderr, "quadshade-reference: --size expects WxH within 1..16384\n");
                return 2;
            }
        } else if (a == "--time") {
            time = std::strtof(value().c_str(), nullptr);
        } else if (a == "--shader") {
            shader = value();
        } else if (a == "--threads") {
            threads = std::atoi(value().c_str());
        } else if (a == "--repeat") {
            repeat = std::max(1, std::atoi(value().c_str()));
        } else if (scene_path.empty() && a[0] != '-') {
            scene_path = a;
        } else {
            std::fprintf(stderr, "quadshade-reference: unexpected argument '%s'\n%s", a.c_str(), kUsage);
            return 2;
        }
    }
    if (scene_path.empty() || outputs.empty()) {
        std::fputs(kUsage, stderr);
        return 2;
    }
    try {
        qs::Scene scene = qs::load_scene(scene_path);
        if (width == 0) width = scene.width, height = scene.height;
        const auto t0 = std::chrono::steady_clock::now();
        auto context = qs::create_osmesa_context(width, height, driver, threads);
        const qs::GlContextInfo info = context->info();
        const std::filesystem::path shading_dir = std::filesystem::path(QUADSHADE_SOURCE_DIR) / "shading";
        qs::GlFrameRequest req{width, height, time, shader};
        // The first frame includes GLSL compilation (and llvmpipe's JIT): timed separately.
        qs::GlSceneRenderer gl(scene, req, *context, shading_dir);
        qs::Image img = gl.render();
        const double first = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::vector<double> frames;
        for (int r = 1; r < repeat; ++r) {
            const auto f0 = std::chrono::steady_clock::now();
            gl.draw();
            frames.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - f0).count());
        }
        for (const std::string& output : outputs) {
            qs::write_image(output, img,
                            {{"quadshade:reference_driver", driver == qs::GlDriver::Softpipe ? "softpipe" : "llvmpipe"},
                             {"quadshade:gl_renderer", info.renderer},
                             {"quadshade:gl_version", info.version},
                             {"quadshade:scene", scene_path}},
                            true);
        }
        std::fprintf(stderr, "quadshade-reference: %s | %s | first frame (context, compile, render) %.1f ms", info.renderer.c_str(),
                     info.version.c_str(), first * 1e3);
        if (!frames.empty()) {
            std::sort(frames.begin(), frames.end());
            std::fprintf(stderr, " | median frame %.3f ms over %zu", frames[frames.size() / 2] * 1e3, frames.size());
        }
        std::fputc('\n', stderr);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "quadshade-reference: %s\n", e.what());
        return 1;
    }
    return 0;
}
