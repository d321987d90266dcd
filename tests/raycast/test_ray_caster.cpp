// The ray caster against the rasterizer (which matches OSMesa llvmpipe, see tests/reference):
// same scenes, same shaders, quad derivatives from 2x2 ray quads and analytic ones from ray
// differentials. Coverage may differ only on silhouettes: Embree tests the ray through the exact
// pixel centre against the float triangle, the rasterizer snaps vertices to 1/256 pixel and
// breaks ties on edges with GL's fill rule.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "shading/catalogue.h"
#include "scenes/gltf.h"
#include "raster/rasterizer.h"
#include "raycast/ray_caster.h"
#include "render/scene_render.h"
#include "tests/test_paths.h"

namespace qs {

namespace {

using namespace test;

Framebuffer render(Scene& scene, Backend backend, Derivatives rule, const std::string& shader = "", int threads = 0) {
    FrameRequest r;
    r.backend = backend;
    r.shader_override = shader;
    r.shading.derivatives = rule;
    r.shading.threads = threads;
    return render_frame(scene, r);
}

bool covered(const Framebuffer& fb, int x, int y) { return fb.pixel(x, y)[3] != 0.0f; }

// A pixel on the boundary of either image's coverage: it or a 4-neighbour differs in coverage.
bool on_silhouette(const Framebuffer& a, const Framebuffer& b, int x, int y) {
    for (const Framebuffer* f : {&a, &b}) {
        const bool c = covered(*f, x, y);
        const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
        for (int k = 0; k < 4; ++k) {
            if (nx[k] >= 0 && ny[k] >= 0 && nx[k] < f->width && ny[k] < f->height && covered(*f, nx[k], ny[k]) != c) return true;
        }
    }
    return false;
}

// The largest difference of a pixel's RGB in 8-bit steps, after GL's unorm conversion.
int steps(const Framebuffer& a, const Framebuffer& b, int x, int y) {
    int d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(unorm8(a.pixel(x, y)[c])) - int(unorm8(b.pixel(x, y)[c]))));
    return d;
}

// Pixels over 1/255 allowed, as measured; zero for every plane shader but two. The ray caster
// interpolates in double from barycentric weights, the rasterizer (like llvmpipe) evaluates float
// plane equations: st differs by an ulp, and the two shaders with the finest features (5x Perlin's
// 40x and 80x octaves, Worley tiles' cell borders) put a few pixels in a neighbouring cell, as
// softpipe's own arithmetic does (tests/reference). Both stay far inside the reference bar of
// 0.1% of pixels (250 at 500x500). Measured: perlin5 116, worley_tiles 5.
// The aastep variants of worley_tiles and the halftone's un-anti-aliased step react the same way
// (measured: 5, 2 and 3). The "Noise is Beautiful" fBm and multifractal: its simplex noise jumps where
// luv.x == luv.y exactly, lines the rasterizer's st hits exactly at pixel centres of the finer
// octaves and the ray caster's, an ulp off, misses, as softpipe's does (tests/reference; measured:
// 650 and 533, beyond 0.1% as against softpipe, and only along those lines). Lawlor's Mandelbrot
// set iterates its texture coordinates up to 100 times, and near the set's boundary an ulp of them
// is a different escape time: 1110 pixels (0.44%; the ray caster is not held to the reference's
// bar, only to what was measured).
std::size_t bound_for(const std::string& shader) {
    if (shader == "perlin5") return 130;
    if (shader == "fbm_simplex2d") return 800;
    if (shader == "multifractal_simplex2d") return 700;
    if (shader == "lawlor_mandelbrot") return 1400;
    if (shader.starts_with("worley_tiles") || shader == "halftone_step") return 8;
    return 0;
}
// On Figure 1.1 differences outside the coverage mismatches come from pixel centres on a shared
// edge inside a sphere, which Embree gives to one triangle and the fill rule to the other: the
// neighbour's plane moves the pattern by a hair (measured: 1 pixel).
constexpr std::size_t kFigureOver1WhereCoverageAgrees = 3;

}  // namespace

TEST_CASE("ray caster: Figure 1.1 with quad derivatives matches the rasterizer, coverage differs only on silhouettes",
          "[raycast]") {
    Scene scene = load_scene(kFigure);
    const int w = scene.width, h = scene.height;
    // Coverage, object by object: alpha is 1 where an object is drawn, the clear colour's 0 elsewhere.
    std::vector<char> coverage_differs(std::size_t(w) * std::size_t(h), 0);
    std::size_t mismatches = 0, silhouette_pixels = 0;
    const std::vector<Object> all = scene.objects;
    for (const Object& o : all) {
        scene.objects = {o};
        const Framebuffer r = render(scene, Backend::Rasterizer, Derivatives::Fine);
        const Framebuffer c = render(scene, Backend::RayCaster, Derivatives::Fine);
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const bool silhouette = on_silhouette(r, r, x, y);
                silhouette_pixels += silhouette;
                if (covered(r, x, y) == covered(c, x, y)) continue;
                ++mismatches;
                coverage_differs[std::size_t(y) * std::size_t(w) + std::size_t(x)] = 1;
                INFO(o.name << ": coverage differs off the silhouette at (" << x << ", " << y << ")");
                CHECK(on_silhouette(r, c, x, y));
            }
        }
    }
    // Measured: 4 of 8268 silhouette pixels (the rasterizer's 1/256-pixel vertex snapping).
    std::printf("ray caster vs rasterizer, Figure 1.1: coverage differs at %zu of %zu silhouette pixels\n", mismatches,
                silhouette_pixels);
    CHECK(mismatches * 100 <= silhouette_pixels);

    scene.objects = all;
    const Framebuffer r = render(scene, Backend::Rasterizer, Derivatives::Fine);
    const Framebuffer c = render(scene, Backend::RayCaster, Derivatives::Fine);
    std::size_t over_1 = 0, over_1_inside = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (steps(r, c, x, y) <= 1) continue;
            ++over_1;
            over_1_inside += !coverage_differs[std::size_t(y) * std::size_t(w) + std::size_t(x)];
        }
    }
    std::printf("ray caster vs rasterizer, Figure 1.1: %zu pixels over 1/255, %zu of them where coverage agrees\n", over_1,
                over_1_inside);
    CHECK(over_1_inside <= kFigureOver1WhereCoverageAgrees);
}

TEST_CASE("ray caster: every Table 1.1 plane shader with quad derivatives matches the rasterizer", "[raycast]") {
    for (const Program* p : catalogue()) {
        const ShaderInfo& info = p->info();
        const bool object_space = info.needs.coordinates == Coordinates::Object2D || info.needs.coordinates == Coordinates::Object3D;
        if (object_space || info.name.find("probe") != std::string_view::npos) continue;  // Figure 1.1's, probes
        if (!plane_binds_samplers(info)) continue;
        const std::string name(info.name);
        Scene scene = load_scene(plane_for(name));
        scene.width = scene.height = 500;  // the book's benchmark size, as in tests/reference
        const Framebuffer r = render(scene, Backend::Rasterizer, Derivatives::Fine, name);
        const Framebuffer c = render(scene, Backend::RayCaster, Derivatives::Fine, name);
        std::size_t coverage = 0, over_1 = 0;
        for (int y = 0; y < r.height; ++y) {
            for (int x = 0; x < r.width; ++x) {
                coverage += covered(r, x, y) != covered(c, x, y);
                over_1 += steps(r, c, x, y) > 1;
            }
        }
        INFO(name << ": " << coverage << " coverage mismatches, " << over_1 << " pixels over 1/255");
        CHECK(coverage == 0);
        CHECK(over_1 <= bound_for(name));
    }
}

TEST_CASE("ray differentials: d(st)/dx, d(st)/dy equal the rasterizer's plane derivatives to 1e-4", "[raycast][derivatives]") {
    // The Figure 1.1 ground plane alone, seen in perspective: st's derivatives vary over the image.
    Scene scene = load_scene(kFigure);
    scene.objects.resize(1);
    REQUIRE(scene.objects[0].name.find("ground") != std::string::npos);
    const Framebuffer r = render(scene, Backend::Rasterizer, Derivatives::Analytic, "st_derivative_probe");
    const Framebuffer c = render(scene, Backend::RayCaster, Derivatives::Analytic, "st_derivative_probe");
    double worst = 0.0;
    std::size_t interior = 0;
    auto filled = [](const Framebuffer& f, int x, int y) {
        const float* p = f.pixel(x, y);
        return p[0] != 0.0f || p[1] != 0.0f || p[2] != 0.0f || p[3] != 0.0f;
    };
    for (int y = 1; y + 1 < r.height; ++y) {
        for (int x = 1; x + 1 < r.width; ++x) {
            bool inside = true;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) inside &= filled(r, x + dx, y + dy) && filled(c, x + dx, y + dy);
            }
            if (!inside) continue;
            ++interior;
            double scale = 0.0, diff = 0.0;
            for (int k = 0; k < 4; ++k) {
                scale = std::max(scale, std::abs(double(r.pixel(x, y)[k])));
                diff = std::max(diff, std::abs(double(r.pixel(x, y)[k]) - double(c.pixel(x, y)[k])));
            }
            worst = std::max(worst, diff / scale);
        }
    }
    std::printf("ray differentials vs plane derivatives of st: largest relative difference %.3g over %zu interior pixels\n",
                worst, interior);
    CHECK(interior > 100000);
    CHECK(worst < 1e-4);
}

TEST_CASE("ray caster: self-occluding, overlapping and culled scenes match the depth-tested rasterizer", "[raycast][depth]") {
    // The ray caster takes the closest hit, the rasterizer the fragment that passes a 24-bit LESS
    // test: the same visible surface everywhere but along the edges where one surface passes
    // behind another (silhouettes over other objects, the torus's fold, the lines where objects
    // cross), which, like coverage, depend on the rasterizer's 1/256-pixel vertex snapping and
    // depth steps against Embree's exact float intersection at the pixel centre. Which surface a
    // pixel shows is read from st.s (pattern_s); colours are then compared where both show the
    // same one, with quad derivatives (dots_aa).
    for (const char* name : {"torus-rolled", "overlap", "overlap-reversed", "hierarchy", "culling"}) {
        Scene scene = load_scene(kSource / "scenes/assets/conformance" / (std::string(name) + ".gltf"));
        const Framebuffer rs = render(scene, Backend::Rasterizer, Derivatives::Fine, "pattern_s");
        const Framebuffer cs = render(scene, Backend::RayCaster, Derivatives::Fine, "pattern_s");
        const Framebuffer r = render(scene, Backend::Rasterizer, Derivatives::Fine, "dots_aa");
        const Framebuffer c = render(scene, Backend::RayCaster, Derivatives::Fine, "dots_aa");
        std::size_t covered_pixels = 0, coverage = 0, coverage_off_silhouette = 0, surface = 0, over_1 = 0;
        for (int y = 0; y < r.height; ++y) {
            for (int x = 0; x < r.width; ++x) {
                covered_pixels += covered(r, x, y);
                if (covered(r, x, y) != covered(c, x, y)) {
                    ++coverage;
                    coverage_off_silhouette += !on_silhouette(r, c, x, y);
                    continue;
                }
                if (!covered(r, x, y)) continue;
                if (std::abs(rs.pixel(x, y)[0] - cs.pixel(x, y)[0]) > 1e-3f) {
                    ++surface;
                    continue;
                }
                over_1 += steps(r, c, x, y) > 1;
            }
        }
        std::printf("ray caster vs rasterizer, %s: %zu covered pixels, coverage differs at %zu (%zu off silhouettes), "
                    "visible surface at %zu, %zu pixels over 1/255 where the surface agrees\n",
                    name, covered_pixels, coverage, coverage_off_silhouette, surface, over_1);
        INFO(name);
        CHECK(coverage_off_silhouette == 0);
        // Measured: 1 pixel (torus), 55 (culling), else 0. The culling scene's single-sided fan
        // keeps only its slivers, thinner than a pixel and all silhouette: one runs along a pixel
        // row, covered by one backend's edges and not the other's for 55 pixels.
        CHECK(coverage * (name == std::string("culling") ? 100 : 1000) <= covered_pixels);
        CHECK(surface * 1000 <= covered_pixels);   // allowed along occlusion edges; measured: 0 everywhere
        // Measured 3, 0, 0, 2: st an ulp apart (the ray caster's double-precision barycentric weights
        // against llvmpipe's float planes, as for perlin5 on the plane) where an aastep edge crosses
        // a pixel, and one silhouette pixel whose helper lanes differ.
        CHECK(over_1 <= 6);
    }
}

TEST_CASE("ray caster: bit-identical for 1 and 2 threads, BVH built once for many frames", "[raycast]") {
    Scene scene = load_scene(kFigure);
    FrameRequest req;
    req.backend = Backend::RayCaster;
    req.width = 317, req.height = 101;  // odd: quads stick out of the image
    req.shading.threads = 1;
    Framebuffer one, two;
    SceneRenderer single(scene, req);
    single.render_into(one, 0.5f);
    req.shading.threads = 2;
    SceneRenderer dual(scene, req);
    dual.render_into(two, 0.5f);
    CHECK(one.rgba == two.rgba);
    const double built = dual.bvh_build_seconds();
    for (float t : {1.0f, 2.0f, 3.0f}) dual.render_into(two, t);
    CHECK(dual.bvh_build_seconds() == built);  // time moves the shading, not the geometry
}

TEST_CASE("both backends refuse a triangle indexing a missing vertex, the ray caster a blended draw", "[raycast]") {
    const std::vector<VertexIn> vertices = {
        {{-1.0f, -1.0f, 0.0f}, {}}, {{1.0f, -1.0f, 0.0f}, {}}, {{-1.0f, 1.0f, 0.0f}, {}}};
    const std::vector<std::uint32_t> good = {0, 1, 2}, bad = {0, 1, 2, 2, 1, 3};
    DrawCall draw;
    draw.vertices = vertices, draw.program = find_program("constant_color"), draw.indices = bad;
    REQUIRE(draw.program);
    const std::string message = "triangle 1 indexes vertex 3 of 3";
    CHECK_THROWS_WITH(rasterize(8, 8, glm::vec4(0.0f), std::span<const DrawCall>(&draw, 1), {}), message);
    CHECK_THROWS_WITH(RayCaster(std::span<const DrawCall>(&draw, 1), glm::mat4(1.0f)), message);
    draw.indices = good;
    RayCaster caster(std::span<const DrawCall>(&draw, 1), glm::mat4(1.0f));
    Framebuffer fb;
    caster.render_into(fb, 8, 8, glm::vec4(0.0f), std::span<const DrawCall>(&draw, 1), {});
    draw.indices = bad;  // the same vertices, so the same BVH: refused each frame all the same
    CHECK_THROWS_WITH(caster.render_into(fb, 8, 8, glm::vec4(0.0f), std::span<const DrawCall>(&draw, 1), {}), message);
    draw.indices = good, draw.blend = true;
    CHECK_THROWS_AS(caster.render_into(fb, 8, 8, glm::vec4(0.0f), std::span<const DrawCall>(&draw, 1), {}),
                    UnsupportedRequest);
}

}  // namespace qs
