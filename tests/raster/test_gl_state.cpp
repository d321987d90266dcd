// The rasterizer as a GL pipeline beyond scenes: drawing over what a framebuffer holds without a
// depth test, user clip planes, noperspective varyings and gl_FrontFacing.

#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>

#include "frontend/compile.h"
#include "interpreter/glsl_program.h"
#include "raster/clipper.h"
#include "raster/rasterizer.h"

namespace {

using namespace qs;

// A program from GLSL text.
std::unique_ptr<interpreter::GlslProgram> linked(const std::string& vertex, const std::string& fragment) {
    return std::make_unique<interpreter::GlslProgram>(
        "test", frontend::compile_glsl({"test.frag", fragment}, frontend::GlslSource{"test.vert", vertex}));
}

// Clip-space rectangles [x0, x1] x [y0, y1] at depth z, as two counter-clockwise triangles.
struct Rects {
    std::vector<VertexIn> vertices;
    std::vector<std::uint32_t> indices;
    void add(float x0, float y0, float x1, float y1, float z) {
        const std::uint32_t n = std::uint32_t(vertices.size());
        for (const glm::vec2 c : {glm::vec2(x0, y0), glm::vec2(x1, y0), glm::vec2(x0, y1), glm::vec2(x1, y1)}) {
            vertices.push_back({glm::vec3(c, z), {0.0f, 0.0f}});
        }
        indices.insert(indices.end(), {n, n + 1, n + 2, n + 2, n + 1, n + 3});
    }
};

const char* const kPositionVertex = "#version 110\nvoid main() { gl_Position = gl_Vertex; }\n";

// Pixel (x, y) of GL's window (y up).
glm::vec4 at(const Framebuffer& fb, int x, int y) {
    const float* p = fb.pixel(x, fb.height - 1 - y);
    return {p[0], p[1], p[2], p[3]};
}

ClipVertex vertex(glm::vec4 clip, float varying, float distance) {
    ClipVertex v{clip, Viewport(64, 64).window(clip, false), {}, {}};
    v.varyings[0] = varying;
    v.clip_distances[0] = distance;
    return v;
}

}  // namespace

TEST_CASE("rasterize_over draws over what the framebuffer holds, a later draw over an earlier one", "[raster][gl]") {
    const auto red = linked(kPositionVertex, "#version 110\nvoid main() { gl_FragColor = vec4(1.0, 0.0, 0.0, 1.0); }\n");
    const auto green = linked(kPositionVertex, "#version 110\nvoid main() { gl_FragColor = vec4(0.0, 1.0, 0.0, 1.0); }\n");
    Rects left, right;
    left.add(-1.0f, -1.0f, 0.5f, 0.5f, 0.0f);
    right.add(-0.5f, -0.5f, 1.0f, 0.5f, 0.0f);  // the same depth: GL's depth test would keep the first
    DrawCall draws[2];
    draws[0].vertices = left.vertices, draws[0].indices = left.indices, draws[0].program = red.get();
    draws[1].vertices = right.vertices, draws[1].indices = right.indices, draws[1].program = green.get();
    Framebuffer fb;
    fb.hold(64, 64, {0, 64}, false, false);
    for (std::size_t i = 0; i < fb.rgba.size(); i += 4) std::copy_n(&glm::vec4(0.0f, 0.0f, 1.0f, 1.0f)[0], 4, &fb.rgba[i]);
    rasterize_over(fb, draws, {});
    CHECK(at(fb, 4, 4) == glm::vec4(1, 0, 0, 1));     // the first draw alone
    CHECK(at(fb, 30, 30) == glm::vec4(0, 1, 0, 1));   // both: the later
    CHECK(at(fb, 60, 30) == glm::vec4(0, 1, 0, 1));   // the second alone
    CHECK(at(fb, 60, 60) == glm::vec4(0, 0, 1, 1));   // neither: kept
    // One draw at a time gives the same image.
    Framebuffer one = fb;
    for (std::size_t i = 0; i < one.rgba.size(); i += 4) std::copy_n(&glm::vec4(0.0f, 0.0f, 1.0f, 1.0f)[0], 4, &one.rgba[i]);
    rasterize_over(one, std::span<const DrawCall>(draws, 1), {});
    rasterize_over(one, std::span<const DrawCall>(draws + 1, 1), {});
    CHECK(one.rgba == fb.rgba);
    // A frame rendered with GL's default depth test keeps the first where they overlap.
    const Framebuffer tested = rasterize(64, 64, glm::vec4(0.0f), draws, {});
    CHECK(at(tested, 30, 30) == glm::vec4(1, 0, 0, 1));
    Framebuffer band;
    band.hold(64, 64, {0, 32}, false, false);
    CHECK_THROWS_AS(rasterize_over(band, draws, {}), std::invalid_argument);
}

TEST_CASE("user clip planes keep what has a clip distance of at least 0", "[raster][gl][clip]") {
    // A triangle across the plane d = x: the part at x < 0 goes, whatever the view volume says.
    const ClipVertex a = vertex({-0.5f, -0.5f, 0.0f, 1.0f}, 0.0f, -0.5f), b = vertex({0.5f, -0.5f, 0.0f, 1.0f}, 1.0f, 0.5f),
                     c = vertex({0.5f, 0.5f, 0.0f, 1.0f}, 1.0f, 0.5f);
    std::vector<std::array<ClipVertex, 3>> out;
    REQUIRE(clip_triangle(a, b, c, 1, Viewport(64, 64), out, {0, 0}));
    CHECK(out.size() == 1);  // plane off: unchanged
    out.clear();
    REQUIRE(clip_triangle(a, b, c, 1, Viewport(64, 64), out, {1u, 0}));
    for (const auto& t : out) {
        for (const ClipVertex& v : t) {
            CHECK(v.clip.x >= -1e-6f);
            CHECK(v.clip_distances[0] >= -1e-6f);
        }
    }
    // Wholly behind the plane: nothing.
    out.clear();
    const ClipVertex d = vertex({-0.5f, 0.5f, 0.0f, 1.0f}, 0.0f, -0.5f), e = vertex({-0.6f, 0.0f, 0.0f, 1.0f}, 0.0f, -0.1f);
    CHECK_FALSE(clip_triangle(a, d, e, 1, Viewport(64, 64), out, {1u, 0}));
}

TEST_CASE("a clipped edge's noperspective varying is interpolated in the window", "[raster][gl][clip]") {
    // An edge from w 1 to w 3 cut by the near plane: perspective varyings take the clip-space t,
    // noperspective ones the t of the new vertex's window position.
    const ClipVertex inside = vertex({0.0f, 0.0f, 0.0f, 1.0f}, 0.0f, 0.0f);
    const ClipVertex behind = vertex({3.0f, 3.0f, -6.0f, 3.0f}, 1.0f, 0.0f);  // z < -w
    const ClipVertex third = vertex({0.0f, 0.5f, 0.0f, 1.0f}, 0.0f, 0.0f);
    for (unsigned noperspective : {0u, 1u}) {
        std::vector<std::array<ClipVertex, 3>> out;
        REQUIRE(clip_triangle(inside, behind, third, 1, Viewport(64, 64), out, {0, noperspective}));
        bool seen = false;
        for (const auto& t : out) {
            for (const ClipVertex& v : t) {
                if (v.clip.w == 1.0f) continue;  // an original vertex
                seen = true;
                // On the near plane z = -w, on the line from inside: clip t = 1/4 (w = 1.5).
                const float x_ndc = v.clip.x / v.clip.w;
                CHECK(v.clip.w == Approx(1.5f));
                CHECK(v.varyings[0] == Approx(noperspective ? x_ndc / 1.0f : 0.25f).epsilon(1e-5));
            }
        }
        CHECK(seen);
    }
}

TEST_CASE("gl_FrontFacing is each triangle's winding in GL's window", "[raster][gl]") {
    const auto program = linked(kPositionVertex, "#version 110\nvoid main() { gl_FragColor = gl_FrontFacing ? vec4(1.0) : vec4(0.5); }\n");
    Rects r;
    r.add(-1.0f, -1.0f, 0.0f, 1.0f, 0.0f);  // counter-clockwise
    r.add(1.0f, -1.0f, 0.0f, 1.0f, 0.0f);   // mirrored: clockwise
    DrawCall d;
    d.vertices = r.vertices, d.indices = r.indices, d.program = program.get();
    for (Derivatives rule : {Derivatives::None, Derivatives::Fine}) {
        RasterOptions o;
        o.derivatives = rule;
        o.force_general_path = rule == Derivatives::Fine;
        const Framebuffer fb = rasterize(64, 64, glm::vec4(0.0f), std::span<const DrawCall>(&d, 1), o);
        CHECK(at(fb, 10, 10) == glm::vec4(1.0f));
        CHECK(at(fb, 50, 10) == glm::vec4(0.5f));
    }
}
