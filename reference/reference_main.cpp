// quadshade-reference: renders a scene through OSMesa (Mesa llvmpipe or softpipe) from the glTF
// alone and the shaders' GLSL (written by `quadshade shaders --export-glsl DIR`), the reference
// quadshade's images are compared with.
//
// Exit codes: 0 success, 1 bad input or GL failure, 2 bad usage.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "files/temporary_file.h"
#include "reference/gl_renderer.h"
#include "scenes/gltf.h"

namespace {

struct Options {
    std::string scene, shader, glsl, size;
    std::vector<std::string> outputs, uniforms;
    std::string driver_name = "llvmpipe";
    qs::GlDriver driver = qs::GlDriver::Llvmpipe;
    std::optional<double> time;
    std::string camera;
    int threads = 0, repeat = 1;
    bool atlas = false;
};

void add_options(CLI::App& app, Options& o) {
    app.add_option("scene", o.scene, "the glTF scene (.gltf or .glb)")->required();
    app.add_option("-o,--output", o.outputs,
                   "an image to write: .exr/.tif keep float, .png is GL's 8-bit conversion (glReadPixels); repeatable")
        ->required();
    app.add_option("--glsl", o.glsl, "folder of NAME.vert / NAME.frag (quadshade shaders --export-glsl DIR)")
        ->required()
        ->check(CLI::ExistingDirectory);
    app.add_option("--driver", o.driver_name, "llvmpipe (default) or softpipe")->check(CLI::IsMember({"llvmpipe", "softpipe"}));
    app.add_option("--size", o.size, "image size WxH (default: the scene's)");
    app.add_option("--time", o.time, "the `time` uniform and the time animations are posed at (default: the scene's)");
    app.add_option("--camera", o.camera,
                   "the camera to render from: a camera node's or camera's name, or an index into "
                   "the file's cameras[] (default: the first camera node)")
        ->option_text("NAME|INDEX");
    app.add_option("--shader", o.shader, "draw every object with this shader's GLSL");
    app.add_option("--uniform", o.uniforms,
                   "NAME=VALUE: a shader's own uniform for every program that has it, replacing the material's "
                   "extras.uniforms (4.0, 1,0.5,0.2 or [1,0.5,0.2]; matrices column by column); repeatable")
        ->take_all()
        ->allow_extra_args(false);
    app.add_flag("--atlas", o.atlas,
                 "draw each triangle at its TEXCOORD_0, as `quadshade bake` does: each vertex shader's main() runs, "
                 "then gl_Position = vec4(gl_MultiTexCoord0.st * 2.0 - 1.0, 0.0, 1.0)");
    app.add_option("--threads", o.threads, "LP_NUM_THREADS for llvmpipe")->check(CLI::Range(0, 1024));
    app.add_option("--repeat", o.repeat, "render N times and report the median frame time (glFinish per frame)")
        ->check(CLI::Range(1, 100000));
}

// --size WxH, each within 1..16384; false when it is not that.
bool parse_size(const std::string& size, int& width, int& height) {
    const std::size_t x = size.find('x');
    try {
        if (x == std::string::npos) return false;
        std::size_t used = 0;
        width = std::stoi(size.substr(0, x), &used);
        if (used != x) return false;
        height = std::stoi(size.substr(x + 1), &used);
        if (used != size.size() - x - 1) return false;
    } catch (const std::exception&) {
        return false;
    }
    return width > 0 && height > 0 && width <= 16384 && height <= 16384;
}

// Renders the scene, writes the outputs and prints the frame times; the exit code.
int render(const Options& o, const std::vector<qs::UniformSetting>& uniforms, int width, int height) {
    try {
        qs::SceneLoadOptions load;
        load.camera = o.camera;
        const qs::Scene scene = qs::load_scene(o.scene, load);
        for (const std::string& w : scene.warnings) {
            std::fprintf(stderr, "quadshade-reference: warning: %s\n", w.c_str());
        }
        if (width == 0) width = scene.width, height = scene.height;
        const auto t0 = std::chrono::steady_clock::now();
        auto context = qs::create_osmesa_context(width, height, o.driver, o.threads);
        const qs::GlContextInfo info = context->info();
        // The first frame includes GLSL compilation (and llvmpipe's JIT): timed separately.
        qs::GlSceneRenderer gl(scene, {width, height, o.time, o.shader, uniforms, o.atlas}, *context, o.glsl);
        const qs::Image img = gl.render();
        const double first = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const qs::Metadata metadata = {
            {"quadshade:reference_driver", o.driver == qs::GlDriver::Softpipe ? "softpipe" : "llvmpipe"},
            {"quadshade:gl_renderer", info.renderer},
            {"quadshade:gl_version", info.version},
            {"quadshade:scene", o.scene}};
        for (const std::string& output : o.outputs) {
            if (qs::is_float_format(output)) qs::write_image(output, img, metadata, true);
            else qs::write_image(output, gl.read_unorm8(), metadata, true);
        }
        std::vector<double> frames;
        for (int r = 1; r < o.repeat; ++r) {
            const auto f0 = std::chrono::steady_clock::now();
            gl.draw();
            frames.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - f0).count());
        }
        std::fprintf(stderr, "quadshade-reference: %s | %s | first frame (context, compile, render) %.1f ms",
                     info.renderer.c_str(), info.version.c_str(), first * 1e3);
        if (!frames.empty()) {
            std::sort(frames.begin(), frames.end());
            std::fprintf(stderr, " | median frame %.3f ms over %zu", frames[frames.size() / 2] * 1e3, frames.size());
        }
        std::fputc('\n', stderr);
    } catch (const qs::UniformOptionError& e) {  // a --uniform no program has
        std::fprintf(stderr, "quadshade-reference: %s\n", e.what());
        return 2;
    } catch (const qs::CameraOptionError& e) {  // a --camera the scene does not have
        std::fprintf(stderr, "quadshade-reference: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "quadshade-reference: %s\n", e.what());
        return 1;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    qs::remove_temporaries_on_signals();
    Options o;
    CLI::App app("quadshade-reference: renders a glTF scene through OSMesa from the shaders' original GLSL, as any "
                 "OpenGL application would. The outputs record the driver, renderer string and Mesa version in their "
                 "metadata.",
                 "quadshade-reference");
    add_options(app, o);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    o.driver = o.driver_name == "softpipe" ? qs::GlDriver::Softpipe : qs::GlDriver::Llvmpipe;
    std::vector<qs::UniformSetting> uniforms;
    try {
        for (const std::string& u : o.uniforms) uniforms.push_back(qs::parse_uniform_option(u));
    } catch (const qs::UniformOptionError& e) {
        std::fprintf(stderr, "quadshade-reference: %s\n", e.what());
        return 2;
    }
    int width = 0, height = 0;
    if (!o.size.empty() && !parse_size(o.size, width, height)) {
        std::fprintf(stderr, "quadshade-reference: --size expects WxH within 1..16384, got '%s'\n", o.size.c_str());
        return 2;
    }
    return render(o, uniforms, width, height);
}
