// quadshade bake's atlas draw (each triangle at its TEXCOORD_0, the shader's own varyings)
// against the same draw through OSMesa: quadshade-reference --atlas compiles each shader's
// vertex GLSL with gl_Position replaced by the texcoord, as a GL application baking would.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>

#include "render/atlas_bake.h"
#include "render/normal_bake.h"
#include "scenes/gltf.h"
#include "shading/height_field.h"
#include "tests/reference/comparison.h"
#include "tests/test_paths.h"

namespace qs {

namespace {

using namespace test;

const std::filesystem::path kAtlasCube = kSource / "scenes/assets/bake/atlas-cube.gltf";
const std::filesystem::path kAtlasSphere = kSource / "scenes/assets/bake/atlas-sphere.gltf";

Image reference_atlas(const std::filesystem::path& scene_file, const std::string& shader, int size) {
    const auto out = scene_file.parent_path() / (scene_file.stem().string() + "." + shader + ".exr");
    const std::string cmd = (kBin / "quadshade-reference").string() + " " + scene_file.string() + " --atlas -o " +
                            out.string() + " --glsl " + QUADSHADE_GLSL_DIR + " --driver llvmpipe --size " +
                            std::to_string(size) + "x" + std::to_string(size) + " --time 0.5 --shader " + shader +
                            " 2> /dev/null";
    if (std::system(cmd.c_str()) != 0) throw std::runtime_error("reference render failed: " + cmd);
    return read_image(out);
}

}  // namespace

TEST_CASE("bake: the atlas of a shader is OSMesa's draw of each triangle at its texcoords", "[reference][bake]") {
    const auto dir = temp_dir("atlas-bake");
    // Odd sizes: quads stick out of the frame; spots takes derivatives (per texel), turbulence none.
    // With skirts (drawn after the charts, at the same depth) the depth test decides the gutter.
    struct Bake {
        std::filesystem::path mesh;
        int size, skirt;
    };
    for (const auto& [mesh, size, skirt] : {Bake{kAtlasCube, 199, 0}, Bake{kAtlasSphere, 256, 0}, Bake{kAtlasCube, 128, 3},
                                            Bake{kAtlasSphere, 160, 2}}) {
        for (const std::string shader : {"spots", "turbulence"}) {
            const Scene scene = load_scene(mesh);
            // The reference draws the very scene quadshade draws: the atlas's clear colour, size
            // and skirts.
            const auto file = dir / (mesh.stem().string() + "-" + shader + "-" + std::to_string(skirt) + ".gltf");
            save_scene(atlas_scene(scene, size, skirt), file);
            AtlasRequest req;
            req.size = size;
            req.skirt = skirt;
            req.frame.time = 0.5;
            req.frame.shader_override = shader;
            req.frame.set(raster_options_as(GlDriver::Llvmpipe));
            const Framebuffer ours = render_atlas_frame(scene, req);
            const Image ref = reference_atlas(file, shader, size);
            const Counts c = count(ours, ref);
            INFO(mesh.filename().string() << " " << shader << " at " << size << " skirt " << skirt << ": covered " << c.covered << ", coverage "
                                          << c.coverage_mismatch << ", over 1/255 " << c.over_1 << ", over 2/255 "
                                          << c.over_2 << ", max " << c.max_steps);
            if (c.coverage_mismatch || c.over_1) write_comparison(ours, ref, dir / (file.stem().string() + "-diff.png"));
            CHECK(c.covered > std::size_t(size * size) / 4);  // the charts cover most of the atlas
            CHECK(c.covered < std::size_t(size * size));      // and leave gutters
            CHECK(c.coverage_mismatch == 0);
            CHECK(c.over_1 * 1000 <= c.covered);
            CHECK(c.over_2 == 0);
        }
    }
}

TEST_CASE("bake: the mesh drawn with its baked atlas (trilinear, mipmaps) is OSMesa's render of the baked scene", "[reference][bake]") {
    // The baked cube as `quadshade bake` writes it, seen minified (mipmaps) and magnified.
    const auto dir = temp_dir("atlas-baked");
    const Scene scene = load_scene(kAtlasCube);
    AtlasRequest req;
    req.size = 128, req.skirt = 2;
    req.frame.time = 0.5;
    req.frame.shader_override = "spots";
    write_image(dir / "baked-color.png", bake_atlas(scene, req), {}, true);
    save_scene(baked_scene(scene, dir / "baked-color.png"), dir / "baked.gltf");
    for (const int size : {61, 301}) {
        Scene baked = load_scene(dir / "baked.gltf");
        FrameRequest r;
        r.width = r.height = size;
        r.set(raster_options_as(GlDriver::Llvmpipe));
        const Framebuffer ours = render_frame(baked, r);
        const auto out = dir / ("baked-" + std::to_string(size) + ".exr");
        const std::string cmd = (kBin / "quadshade-reference").string() + " " + (dir / "baked.gltf").string() + " -o " +
                                out.string() + " --glsl " + QUADSHADE_GLSL_DIR + " --driver llvmpipe --size " +
                                std::to_string(size) + "x" + std::to_string(size) + " 2> /dev/null";
        REQUIRE(std::system(cmd.c_str()) == 0);
        const Image ref = read_image(out);
        const Counts c = count(ours, ref);
        INFO("baked cube at " << size << ": covered " << c.covered << ", coverage " << c.coverage_mismatch << ", over 1/255 "
                              << c.over_1 << ", over 2/255 " << c.over_2);
        CHECK(c.covered > std::size_t(size * size) / 8);
        CHECK(c.coverage_mismatch == 0);
        CHECK(c.over_1 * 1000 <= c.covered);
        CHECK(c.over_2 == 0);
    }
}

TEST_CASE("bake: the mesh drawn lit by its baked colour and normal map (baked_lit) is OSMesa's render of the baked scene",
          "[reference][bake][normals]") {
    // noise_bumps baked with its normal map as `quadshade bake --maps color,normal` writes it,
    // both meshes, minified and magnified: baked_lit's two trilinear lookups, normalize and
    // Lambert against llvmpipe's, at the bar of every catalogue shader.
    const auto dir = temp_dir("atlas-baked-lit");
    const HeightField* field = find_height_field("noise_bumps");
    REQUIRE(field);
    for (const auto& mesh : {kAtlasCube, kAtlasSphere}) {
        const Scene scene = load_scene(mesh);
        AtlasRequest req;
        req.size = 128, req.skirt = 2;
        req.frame.shader_override = "noise_bumps";
        NormalBakeRequest n;
        n.size = 128, n.skirt = 2;
        const std::string stem = mesh.stem().string();
        write_image(dir / (stem + "-color.png"), bake_atlas(scene, req), {}, true);
        write_image(dir / (stem + "-normal.png"), bake_normal_map(scene, *field, n), {}, true);
        save_scene(baked_scene(scene, dir / (stem + "-color.png"), dir / (stem + "-normal.png"), {}), dir / (stem + ".gltf"));
        for (const int size : {61, 301}) {
            Scene baked = load_scene(dir / (stem + ".gltf"));
            REQUIRE(baked.objects.at(0).shader == "baked_lit");
            FrameRequest r;
            r.width = r.height = size;
            r.set(raster_options_as(GlDriver::Llvmpipe));
            const Framebuffer ours = render_frame(baked, r);
            const auto out = dir / (stem + "-" + std::to_string(size) + ".exr");
            const std::string cmd = (kBin / "quadshade-reference").string() + " " + (dir / (stem + ".gltf")).string() +
                                    " -o " + out.string() + " --glsl " + QUADSHADE_GLSL_DIR + " --driver llvmpipe --size " +
                                    std::to_string(size) + "x" + std::to_string(size) + " 2> /dev/null";
            REQUIRE(std::system(cmd.c_str()) == 0);
            const Image ref = read_image(out);
            const Counts c = count(ours, ref);
            INFO("lit baked " << stem << " at " << size << ": covered " << c.covered << ", coverage " << c.coverage_mismatch
                              << ", over 1/255 " << c.over_1 << ", over 2/255 " << c.over_2 << ", max " << c.max_steps);
            if (c.coverage_mismatch || c.over_1) write_comparison(ours, ref, dir / (stem + "-" + std::to_string(size) + "-diff.png"));
            CHECK(c.covered > std::size_t(size * size) / 8);
            CHECK(c.coverage_mismatch == 0);
            CHECK(c.over_1 * 1000 <= c.covered);
            CHECK(c.over_2 == 0);
        }
    }
}

}  // namespace qs
