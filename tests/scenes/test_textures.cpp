// Textures in the renderer, without a reference: the image from any source gives the same bits,
// Dual2's level of detail, and the ray caster's quads for a texture that needs a level of detail.
// (Against OSMesa: tests/reference/test_texture_conformance.cpp.)
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "core/framebuffer.h"
#include "render/scene_render.h"
#include "scenes/gltf.h"
#include "tests/test_paths.h"

namespace qs {

namespace {

using namespace test;

Scene conformance_scene(const std::string& name) { return load_scene(kSource / "scenes/assets/conformance" / ("texture-" + name)); }

// Pixels whose 8-bit RGBA differs by more than one step.
std::size_t over_one_step(const Framebuffer& a, const Framebuffer& b) {
    std::size_t n = 0;
    for (std::size_t p = 0; p < a.rgba.size(); p += 4) {
        int worst = 0;
        for (std::size_t c = 0; c < 4; ++c) worst = std::max(worst, std::abs(int(unorm8(a.rgba[p + c])) - int(unorm8(b.rgba[p + c]))));
        n += worst > 1;
    }
    return n;
}

}  // namespace

TEST_CASE("a texture's image from a file, a data: URI and a .glb's bufferView renders the same", "[textures]") {
    decltype(Framebuffer::rgba) first;
    for (const char* file : {"source-file.gltf", "source-data-uri.gltf", "source-buffer-view.glb"}) {
        Scene s = conformance_scene(file);
        REQUIRE(s.textures.size() == 1);
        const Framebuffer f = render_frame(s, {});
        if (first.empty()) first = f.rgba;
        INFO(file);
        CHECK(f.rgba == first);
    }
}

TEST_CASE("Dual2's level of detail from its partials: on an affine mapping, the quads' levels", "[textures][derivatives]") {
    // The minified orthographic plane (st over 80 periods of a 16x8 image), made trilinear: quad
    // differences of an affine st are its derivatives, up to the rounding of st's values. (One
    // lookup: the halftone's aastep takes derivatives of non-affine values, where quads and Dual2
    // differ by design.)
    Scene s = conformance_scene("wrap-repeat-pot.gltf");
    s.textures[0].sampler.min_filter = Filter::LinearMipmapLinear;
    FrameRequest quads, dual2;
    dual2.shading.derivatives = Derivatives::Analytic;
    const Framebuffer a = render_frame(s, quads), b = render_frame(s, dual2);
    const std::size_t n = over_one_step(a, b);
    std::printf("Dual2 against quads, single_texture, trilinear, minified orthographic plane: %zu of %d pixels over "
                "1/255\n", n, a.width * a.height);
    CHECK(n <= std::size_t(a.width * a.height) / 100);
    s.textures[0].sampler.min_filter = Filter::Linear;  // without mipmaps it is another image
    CHECK(over_one_step(a, render_frame(s, quads)) > std::size_t(a.width * a.height) / 2);
}

#if defined(QUADSHADE_HAS_RAYCAST)
TEST_CASE("the ray caster shades a texture that needs a level of detail in quads, as the rasterizer",
          "[textures][raycast]") {
    for (const char* file : {"min-linear-mipmap-linear.gltf", "mirrored-mipmaps.gltf"}) {
        Scene s = conformance_scene(file);
        for (const char* shader : {"single_texture", "halftone"}) {
            FrameRequest raster, raycast;
            raster.shader_override = raycast.shader_override = shader;
            raycast.backend = Backend::RayCaster;
            const Framebuffer a = render_frame(s, raster), b = render_frame(s, raycast);
            const std::size_t n = over_one_step(a, b);
            std::printf("ray caster against rasterizer, %s, %s: %zu of %d pixels over 1/255\n", file, shader, n,
                        a.width * a.height);
            INFO(file << " " << shader);
            CHECK(n <= std::size_t(a.width * a.height) / 200);
        }
    }
}
#endif

TEST_CASE("a texture that needs a level of detail turns a derivative-free shader's draw into quads", "[textures]") {
    // single_texture takes no derivatives; with mipmaps its lookups need the quad's.
    Scene s = conformance_scene("min-linear-mipmap-linear.gltf");
    RenderStats with_mipmaps, without;
    render_frame(s, {}, &with_mipmaps);
    s.textures[0].sampler.min_filter = Filter::Linear;
    render_frame(s, {}, &without);
    CHECK(with_mipmaps.quads > 0);
    CHECK(without.quads == 0);
}

}  // namespace qs
