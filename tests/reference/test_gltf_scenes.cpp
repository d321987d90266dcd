// The glTF feature scenes (generators/gltf_scenes.h) and the shipped real model, each drawn by default
// (materials that name no shader: the default material) by quadshade's rasterizer and by OSMesa
// llvmpipe running the default material's GLSL: the conformance bar (coverage identical, no
// pixel more than 1/255 off) on each feature, the animation at several times, each camera at
// sizes wider and narrower than it. Writes build/conformance/gltf-scenes.csv and, for a case that
// differs at all, a quadshade | OSMesa | difference image beside it.
#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>

#include "reference/gl_renderer.h"
#include "render/scene_render.h"
#include "scenes/gltf.h"
#include "tests/reference/comparison.h"
#include "tests/test_paths.h"

namespace qs {

namespace {

using namespace test;

struct Case {
    const char* name;    // for messages and files
    const char* file;    // under scenes/assets
    const char* camera;  // --camera, empty for the first
    double time;
    int width, height;  // 0: the scene's size
};

// Per case, what may differ: nothing (no documented cause has been needed yet).
void check(const Case& c) {
    SceneLoadOptions options;
    options.camera = c.camera;
    const std::filesystem::path file = kSource / "scenes/assets" / c.file;
    const Scene reference_scene = load_scene(file, options);
    Scene scene = load_scene(file, options);
    const int width = c.width ? c.width : scene.width, height = c.height ? c.height : scene.height;
    auto context = create_osmesa_context(width, height, GlDriver::Llvmpipe, 0);
    GlFrameRequest g;
    g.width = width, g.height = height, g.time = c.time;
    const Image ref = GlSceneRenderer(reference_scene, g, *context, QUADSHADE_GLSL_DIR).render();
    FrameRequest r;
    r.width = width, r.height = height, r.time = c.time;
    r.set(raster_options_as(GlDriver::Llvmpipe));
    const Framebuffer q = render_frame(scene, r);
    const Counts n = count(q, ref);
    const std::filesystem::path out = std::filesystem::path(QUADSHADE_BIN_DIR) / ".." / "conformance";
    std::filesystem::create_directories(out);
    std::ofstream(out / "gltf-scenes.csv", std::ios::app)
        << c.name << "," << width << "," << height << "," << n.covered << "," << n.coverage_mismatch << "," << n.over_1
        << "," << n.over_2 << "," << n.max_steps << "\n";
    if (n.coverage_mismatch || n.max_steps) write_comparison(q, ref, out / ("gltf-" + std::string(c.name) + ".png"));
    std::printf(
        "glTF scene %s at %dx%d vs llvmpipe: %zu covered, %zu coverage mismatches, %zu over 1/255, %zu over 2/255, "
        "max %d/255\n",
        c.name, width, height, n.covered, n.coverage_mismatch, n.over_1, n.over_2, n.max_steps);
    INFO(c.name << " at " << width << "x" << height << ": " << n.covered << " covered, " << n.coverage_mismatch
                << " coverage mismatches, " << n.over_1 << " over 1/255, max " << n.max_steps << "/255");
    CHECK(n.covered > n.pixels / 20);
    CHECK(n.coverage_mismatch == 0);
    CHECK(n.over_1 == 0);
}

}  // namespace

TEST_CASE("glTF scenes vs llvmpipe: the default material (factors, textures, COLOR_0, lit, flat, unlit, no material)",
          "[conformance][gltf]") {
    check({"default-material", "gltf/default-material.gltf", "", 0.0, 0, 0});
}

TEST_CASE("glTF scenes vs llvmpipe: alphaMode OPAQUE, MASK and BLEND (back to front)", "[conformance][gltf]") {
    check({"alpha-modes", "gltf/alpha-modes.gltf", "", 0.0, 0, 0});
}

TEST_CASE("glTF scenes vs llvmpipe: TEXCOORD_1 and _2, KHR_texture_transform", "[conformance][gltf]") {
    check({"texcoord-sets", "gltf/texcoord-sets.gltf", "", 0.0, 0, 0});
}

TEST_CASE("glTF scenes vs llvmpipe: triangle strips and fans, points and lines skipped", "[conformance][gltf]") {
    check({"primitive-modes", "gltf/primitive-modes.gltf", "", 0.0, 0, 0});
}

TEST_CASE("glTF scenes vs llvmpipe: animations (LINEAR, STEP, CUBICSPLINE, slerp, the camera) at four times",
          "[conformance][gltf]") {
    for (const double t : {0.0, 0.4, 1.25, 2.5}) {
        const std::string name = "animation-t" + std::to_string(t).substr(0, 4);
        check({name.c_str(), "gltf/animation.gltf", "", t, 0, 0});
    }
}

TEST_CASE("glTF scenes vs llvmpipe: EXT_mesh_gpu_instancing (125 cubes)", "[conformance][gltf]") {
    check({"instancing", "gltf/instancing.glb", "", 0.0, 0, 0});
}

TEST_CASE("glTF scenes vs llvmpipe: KHR_mesh_quantization and normalized attributes", "[conformance][gltf]") {
    check({"quantized", "gltf/quantized.gltf", "", 0.0, 0, 0});
}

TEST_CASE("glTF scenes vs llvmpipe: cameras by name and index, at sizes wider and narrower than each",
          "[conformance][gltf]") {
    check({"cameras-first", "gltf/cameras.gltf", "", 0.0, 0, 0});
    check({"cameras-wide-portrait", "gltf/cameras.gltf", "Wide", 0.0, 90, 160});
    check({"cameras-top-view", "gltf/cameras.gltf", "Top view", 0.0, 0, 0});
    check({"cameras-top-portrait", "gltf/cameras.gltf", "1", 0.0, 80, 150});
    check({"cameras-close-wide", "gltf/cameras.gltf", "2", 0.0, 200, 80});
}

TEST_CASE("glTF scenes vs llvmpipe: a modelling tool's export (interleaved, textured and not, blended)",
          "[conformance][gltf]") {
    check({"workshop", "gltf/workshop.gltf", "", 0.0, 0, 0});
}

TEST_CASE("glTF scenes vs llvmpipe: a CAD assembly in a .glb (matrices, mirrored, flat, no camera)",
          "[conformance][gltf]") {
    check({"assembly", "gltf/assembly.glb", "", 0.0, 0, 0});
}

TEST_CASE("glTF scenes vs llvmpipe: a real model, Khronos's Box Textured, by default (the default camera)",
          "[conformance][gltf]") {
    check({"box-textured", "models/box-textured/BoxTextured.gltf", "", 0.0, 256, 256});
}

}  // namespace qs
