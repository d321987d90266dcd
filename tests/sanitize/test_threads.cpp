// Run in the ThreadSanitizer build (tools/ci-sanitizers) with the probe shaders, translated and
// run by the GLSL interpreter (whose registers and masks are the thread's): multi-threaded
// renders of both backends, whole and in row bands, many frames through one renderer, and the
// result the same bits as one thread's.
#include <catch2/catch.hpp>

#include <cstring>

#include "render/glsl_shaders.h"
#include "render/scene_render.h"
#include "scenes/gltf.h"
#include "tests/test_paths.h"

namespace qs {

TEST_CASE("threads: renders on 1 to 7 threads are race-free and bit-identical, both backends", "[threads]") {
    using namespace test;
    Scene figure = load_scene(kFigure), plane = load_scene(kPlane);
    std::vector<Backend> backends = {Backend::Rasterizer};
#if defined(QUADSHADE_HAS_RAYCAST)
    backends.push_back(Backend::RayCaster);
#endif
    const std::string interpreted = interpreted_twin("st_derivative_probe");
    for (Backend backend : backends) {
        for (Scene* scene : {&figure, &plane}) {
            for (const std::string& shader : {std::string("st_derivative_probe"), std::string("float_env_probe"),
                                              std::string("position_derivative_probe"), interpreted}) {
                INFO(shader << " backend " << int(backend));
                FrameRequest r;
                r.width = 150, r.height = 131;
                r.shader_override = shader;
                r.backend = backend;
                r.shading.check_undefined = true;
                r.shading.threads = 1;
                Framebuffer one;
                SceneRenderer(*scene, r).render_into(one, 0.0);
                for (int threads : {2, 4, 7}) {
                    r.shading.threads = threads;
                    SceneRenderer renderer(*scene, r);
                    Framebuffer fb;
                    for (int frame = 0; frame < 3; ++frame) {
                        renderer.render_into(fb, 0.0);
                        CHECK(std::memcmp(fb.rgba.data(), one.rgba.data(), fb.rgba.size() * sizeof(float)) == 0);
                        CHECK(fb.undefined == one.undefined);
                    }
                    for (const RowBand& b : image_bands(r.height, r.shading.pairing, 64)) {
                        renderer.render_into(fb, 0.0, nullptr, b);
                        CHECK(std::memcmp(fb.rgba.data(), one.pixel(0, b.begin), fb.rgba.size() * sizeof(float)) == 0);
                    }
                }
            }
        }
    }
}

}  // namespace qs
