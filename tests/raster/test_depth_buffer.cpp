// The depth buffer: what it stores (24-bit, as the reference's), and leaving it out only where it
// provably changes nothing (every overlap in painter's order, no depth reaches 1).
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "raster/depth_buffer.h"
#include "raster/fixed_point.h"
#include "tests/raster/test_program.h"

namespace qs::test {

namespace {

const ProgramOf<Flat> kFlat;
const ProgramOf<Position> kPosition;

// A triangle given in framebuffer pixels (x right, y down) and window depth, set up for a
// width x height image.
std::optional<TriangleSetup> setup_pixels(int width, int height, const std::array<glm::vec3, 3>& p, FillRule rule) {
    std::array<ClipVertex, 3> tri;
    for (std::size_t i = 0; i < 3; ++i) {
        tri[i].window = {p[i], 1.0f};
        tri[i].clip = {p[i].x * 2.0f / float(width) - 1.0f, 1.0f - p[i].y * 2.0f / float(height), p[i].z * 2.0f - 1.0f, 1.0f};
        tri[i].varyings = {};
    }
    return setup_triangle(tri, 0, width, height, rule, 0, tri[2]);
}

// The pixel centres t covers, as its rasterizer coverage test sees them.
std::vector<bool> coverage(const TriangleSetup& t, int width, int height) {
    std::vector<bool> c(std::size_t(width) * std::size_t(height), false);
    for (int y = t.min_y; y <= t.max_y; ++y) {
        for (int x = t.min_x; x <= t.max_x; ++x) {
            c[std::size_t(y * width + x)] = t.edges[0].inside(x, y) && t.edges[1].inside(x, y) && t.edges[2].inside(x, y);
        }
    }
    return c;
}

// Two pixel-space triangles: whether their interiors overlap (checked symmetric), and whether a
// pixel centre is covered by both under `rule`.
struct Pair {
    bool overlap, shared_pixel;
};
Pair compare(const std::array<glm::vec3, 3>& a, const std::array<glm::vec3, 3>& b, FillRule rule) {
    constexpr int W = 32, H = 32;
    const auto ta = setup_pixels(W, H, a, rule), tb = setup_pixels(W, H, b, rule);
    REQUIRE(ta);
    REQUIRE(tb);
    const bool overlap = interiors_overlap(*ta, *tb);
    CHECK(overlap == interiors_overlap(*tb, *ta));
    const std::vector<bool> ca = coverage(*ta, W, H), cb = coverage(*tb, W, H);
    bool shared = false;
    for (std::size_t i = 0; i < ca.size(); ++i) shared |= ca[i] && cb[i];
    return {overlap, shared};
}

}  // namespace

TEST_CASE("interiors_overlap: shared edges, shared vertices and T-junctions are not overlaps, overlaps are",
          "[raster][depth]") {
    for (FillRule rule : {FillRule::LeftBottom, FillRule::RightTop}) {
        // Two halves of a square through pixel centres: a shared diagonal.
        const Pair diagonal = compare({{{2.5f, 2.5f, 0}, {20.5f, 2.5f, 0}, {20.5f, 20.5f, 0}}},
                                      {{{2.5f, 2.5f, 0}, {20.5f, 20.5f, 0}, {2.5f, 20.5f, 0}}}, rule);
        CHECK_FALSE(diagonal.overlap);
        // A vertex of one in the middle of the other's edge (a T-junction), on a pixel centre.
        const Pair t_junction = compare({{{2.5f, 2.5f, 0}, {20.5f, 2.5f, 0}, {11.5f, 12.5f, 0}}},
                                        {{{8.5f, 2.5f, 0}, {14.5f, 2.5f, 0}, {11.5f, -6.5f, 0}}}, rule);
        CHECK_FALSE(t_junction.overlap);
        // Touching at one vertex only (an hourglass), the vertex on a pixel centre.
        const Pair hourglass = compare({{{4.5f, 4.5f, 0}, {12.5f, 4.5f, 0}, {8.5f, 10.5f, 0}}},
                                       {{{8.5f, 10.5f, 0}, {4.5f, 16.5f, 0}, {12.5f, 16.5f, 0}}}, rule);
        CHECK_FALSE(hourglass.overlap);
        // Crossing, nested and identical triangles overlap and do share pixels.
        for (const Pair& p : {compare({{{2, 2, 0}, {20, 3, 0}, {5, 20, 0}}}, {{{18, 18, 0}, {3, 10, 0}, {19, 4, 0}}}, rule),
                              compare({{{2, 2, 0}, {30, 3, 0}, {5, 30, 0}}}, {{{6, 6, 0}, {9, 6.5f, 0}, {7, 10, 0}}}, rule),
                              compare({{{2, 2, 0}, {30, 3, 0}, {5, 30, 0}}}, {{{2, 2, 0}, {30, 3, 0}, {5, 30, 0}}}, rule)}) {
            CHECK(p.overlap);
            CHECK(p.shared_pixel);
        }
    }
}

TEST_CASE("interiors_overlap is sound: triangles it calls disjoint never share a pixel centre, under either fill rule",
          "[raster][depth]") {
    // Vertices on a coarse grid of quarter pixels, many on pixel centres, so that shared edges,
    // collinear edges, T-junctions and vertices on edges are common.
    std::mt19937 rng(2024);
    std::uniform_int_distribution<int> coord(0, 16 * 4);
    auto vertex = [&] { return glm::vec3(float(coord(rng)) / 4.0f + 0.5f, float(coord(rng)) / 4.0f + 0.5f, 0.0f); };
    std::size_t disjoint = 0, touching = 0;
    for (int n = 0; n < 20000; ++n) {
        std::array<glm::vec3, 3> a = {vertex(), vertex(), vertex()}, b = {vertex(), vertex(), vertex()};
        if (n % 2) b[0] = a[1], b[1] = a[0];  // share an edge (either side of it)
        if (n % 5 == 0) b[2] = 0.5f * (a[0] + a[1]);  // a vertex on an edge's line
        const FillRule rule = n % 3 ? FillRule::LeftBottom : FillRule::RightTop;
        constexpr int W = 32, H = 32;
        const auto ta = setup_pixels(W, H, a, rule), tb = setup_pixels(W, H, b, rule);
        if (!ta || !tb) continue;  // zero area
        if (interiors_overlap(*ta, *tb)) continue;
        ++disjoint;
        const std::vector<bool> ca = coverage(*ta, W, H), cb = coverage(*tb, W, H);
        bool a_any = false, b_any = false;
        for (std::size_t i = 0; i < ca.size(); ++i) {
            INFO("case " << n << " pixel " << i % W << ", " << i / W);
            REQUIRE_FALSE((ca[i] && cb[i]));
            a_any |= ca[i], b_any |= cb[i];
        }
        touching += a_any && b_any && n % 2;
    }
    CHECK(disjoint > 5000);
    CHECK(touching > 1000);  // many of them did cover pixels on both sides of a shared edge
}

TEST_CASE("the depth buffer is left out only when every overlap is in painter's order and no depth reaches 1",
          "[raster][depth]") {
    constexpr int W = 64, H = 64;
    auto tri = [&](std::array<glm::vec3, 3> p) { return *setup_pixels(W, H, p, FillRule::LeftBottom); };
    const TriangleSetup lower = tri({{{1, 1, 0.5f}, {60, 1, 0.5f}, {60, 60, 0.5f}}});
    const TriangleSetup upper = tri({{{1, 1, 0.5f}, {60, 60, 0.5f}, {1, 60, 0.5f}}});
    const TriangleSetup across = tri({{{30, 2, 0.2f}, {40, 2, 0.2f}, {35, 50, 0.2f}}});
    const TriangleSetup behind = tri({{{30, 2, 0.7f}, {40, 2, 0.7f}, {35, 50, 0.7f}}});
    // Nearer than the square by two 24-bit steps: LESS could tie it after rounding.
    const TriangleSetup hair = tri({{{30, 2, 0.5f - 0x1p-23f}, {40, 2, 0.5f - 0x1p-23f}, {35, 50, 0.5f - 0x1p-23f}}});
    // Crossing the square's depth: in front at its base, behind at its tip.
    const TriangleSetup crossing = tri({{{30, 2, 0.3f}, {40, 2, 0.3f}, {35, 50, 0.7f}}});
    const TriangleSetup far = tri({{{1.5f, 1.5f, 1.0f}, {60, 1, 0.9f}, {60, 60, 0.9f}}});  // depth 1 on a pixel centre
    const TriangleSetup nearly_far = tri({{{1, 1, 1.0f}, {60, 1, 0.9f}, {60, 60, 0.9f}}});  // below 1 at every centre
    CHECK_FALSE(depth_buffer_matters(std::vector<TriangleSetup>{lower, upper}, W, H));
    CHECK_FALSE(depth_buffer_matters(std::vector<TriangleSetup>{lower, upper, across}, W, H));  // drawn over, nearer
    CHECK(depth_buffer_matters(std::vector<TriangleSetup>{across, lower, upper}, W, H));  // drawn over, farther
    CHECK(depth_buffer_matters(std::vector<TriangleSetup>{lower, upper, behind}, W, H));
    CHECK(depth_buffer_matters(std::vector<TriangleSetup>{lower, upper, hair}, W, H));
    CHECK(depth_buffer_matters(std::vector<TriangleSetup>{lower, upper, crossing}, W, H));
    CHECK(depth_buffer_matters(std::vector<TriangleSetup>{lower, upper, across, across}, W, H));  // a tie
    CHECK_FALSE(depth_buffer_matters(std::vector<TriangleSetup>{across}, W, H));
    CHECK(depth_buffer_matters(std::vector<TriangleSetup>{far}, W, H));  // LESS against 1 drops a corner
    CHECK(in_front(across, lower));
    CHECK_FALSE(in_front(lower, across));
    CHECK_FALSE(in_front(hair, lower));
    CHECK(may_reach_depth_one(far));
    CHECK_FALSE(may_reach_depth_one(lower));
    CHECK_FALSE(may_reach_depth_one(nearly_far));
}

TEST_CASE("DepthBufferDecision answers for the triangles it is given, not for the last frame's", "[raster][depth]") {
    constexpr int W = 64, H = 64;
    auto tri = [&](std::array<glm::vec3, 3> p) { return *setup_pixels(W, H, p, FillRule::LeftBottom); };
    const TriangleSetup lower = tri({{{1, 1, 0.5f}, {60, 1, 0.5f}, {60, 60, 0.5f}}});
    const TriangleSetup upper = tri({{{1, 1, 0.5f}, {60, 60, 0.5f}, {1, 60, 0.5f}}});
    const TriangleSetup behind = tri({{{30, 2, 0.7f}, {40, 2, 0.7f}, {35, 50, 0.7f}}});
    TriangleSetup moved = behind;  // the same corners, nearer: only its depth plane differs
    moved.z.a0 -= 0.5f;
    const std::vector<TriangleSetup> apart{lower, upper}, hidden{lower, upper, behind}, in_front_of{lower, upper, moved};
    DepthBufferDecision decision;
    for (int frame = 0; frame < 2; ++frame) {
        CHECK_FALSE(decision.matters(apart, W, H));
        CHECK_FALSE(decision.matters(apart, W, H));
        CHECK(decision.matters(hidden, W, H));
        CHECK(decision.matters(hidden, W, H));
        CHECK_FALSE(decision.matters(in_front_of, W, H));
        CHECK(decision.matters(hidden, W, H));
        CHECK_FALSE(decision.matters(in_front_of, 2 * W, 2 * H));  // another size
    }
}

namespace {

// A grid of n x n squares over [4, 60) pixels, each split into two triangles, its inner vertices
// moved by up to `jitter` pixels (a quarter-pixel lattice): beyond half a square, triangles fold
// over their neighbours.
std::vector<TriangleSetup> grid_mesh(int n, float jitter, std::mt19937& rng, FillRule rule) {
    constexpr int W = 64, H = 64;
    std::uniform_int_distribution<int> step(-int(4 * jitter), int(4 * jitter));
    std::vector<glm::vec3> p;
    const float size = 56.0f / float(n);
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            const bool inner = i > 0 && j > 0 && i < n && j < n;
            const float dx = inner ? float(step(rng)) / 4.0f : 0.0f, dy = inner ? float(step(rng)) / 4.0f : 0.0f;
            p.push_back({4.0f + size * float(i) + dx, 4.0f + size * float(j) + dy, 0.5f});
        }
    }
    std::vector<TriangleSetup> out;
    auto add = [&](int a, int b, int c) {
        if (auto t = setup_pixels(W, H, {p[std::size_t(a)], p[std::size_t(b)], p[std::size_t(c)]}, rule)) out.push_back(*t);
    };
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            add(a, b, d), add(a, d, c);
        }
    }
    return out;
}

}  // namespace

TEST_CASE("covers_each_centre_once: a mesh whose outline is one simple loop, and nothing else", "[raster][depth]") {
    std::mt19937 rng(11);
    CHECK(covers_each_centre_once(grid_mesh(6, 0.0f, rng, FillRule::LeftBottom)));
    CHECK(covers_each_centre_once(grid_mesh(6, 1.5f, rng, FillRule::RightTop)));  // bent, not folded
    // A triangle drawn twice.
    std::vector<TriangleSetup> twice = grid_mesh(6, 0.0f, rng, FillRule::LeftBottom);
    twice.push_back(twice[20]);
    CHECK_FALSE(covers_each_centre_once(twice));
    // Two meshes side by side: they do not overlap, but two loops are not proven.
    std::vector<TriangleSetup> two = grid_mesh(3, 0.0f, rng, FillRule::LeftBottom);
    for (TriangleSetup t : grid_mesh(3, 0.0f, rng, FillRule::LeftBottom)) {
        for (std::int64_t& x : t.corner_x) x += 70 * fixed::kOne;  // only the corners matter here
        two.push_back(t);
    }
    CHECK_FALSE(covers_each_centre_once(two));
    // A fan of 9 triangles, 80 degrees each, winding twice round its centre: every inner edge
    // has a neighbour across it, and the pixel centres near the centre are covered twice. Its
    // outline is a star that crosses itself.
    std::vector<TriangleSetup> fan;
    for (int k = 0; k < 9; ++k) {
        auto at = [](int i) {
            const double a = 4.0 * std::numbers::pi * double(i % 9) / 9.0;
            return glm::vec3(32.0f + float(std::lround(80.0 * std::cos(a))) / 4.0f, 32.0f + float(std::lround(80.0 * std::sin(a))) / 4.0f, 0.5f);
        };
        fan.push_back(*setup_pixels(64, 64, {glm::vec3(32.0f, 32.0f, 0.5f), at(k), at(k + 1)}, FillRule::LeftBottom));
    }
    CHECK_FALSE(covers_each_centre_once(fan));
}

TEST_CASE("covers_each_centre_once is sound: no pixel centre of a mesh it accepts is covered twice", "[raster][depth]") {
    // Grids bent and folded at random: folds overlap their neighbours, and outlines cross.
    std::mt19937 rng(2025);
    int accepted = 0, refused = 0, refused_overlapping = 0;
    for (int n = 0; n < 400; ++n) {
        const FillRule rule = n % 2 ? FillRule::LeftBottom : FillRule::RightTop;
        const std::vector<TriangleSetup> mesh = grid_mesh(2 + n % 5, float(n % 9) * 1.5f, rng, rule);
        std::vector<int> count(64 * 64, 0);
        int most = 0;
        for (const TriangleSetup& t : mesh) {
            const std::vector<bool> c = coverage(t, 64, 64);
            for (std::size_t i = 0; i < c.size(); ++i) most = std::max(most, count[i] += c[i]);
        }
        if (covers_each_centre_once(mesh)) {
            INFO("case " << n);
            REQUIRE(most <= 1);
            ++accepted;
        } else {
            ++refused;
            refused_overlapping += most > 1;
        }
    }
    CHECK(accepted > 100);
    CHECK(refused_overlapping > 50);  // folds the proof caught
    CHECK(refused > refused_overlapping - 1);
}

TEST_CASE("depth is stored in 24 bits as the reference's buffer: nearer by less than a step does not pass LESS",
          "[raster][depth]") {
    CHECK(depth24(0.0f) == 0.0f);
    CHECK(depth24(1.0f) == kDepthCleared);
    CHECK(depth24(2.0f) == kDepthCleared);
    CHECK(depth24(std::nextafter(1.0f, 0.0f)) < kDepthCleared);  // every depth below 1 passes the clear
    CHECK(depth24(std::numeric_limits<float>::quiet_NaN()) == 0.0f);
    // Two triangles over the same pixels, the second nearer by a hair: its window depth is the
    // next float below the first's, which a float comparison would let through, but both are
    // 5439172 in 24 bits and LESS keeps the first. Nearer by 2^-12, the second wins. The colour's
    // blue is the NDC z.
    const float z1 = -0x1.6809d8p-2f;
    for (const float z2 : {-0x1.6809dcp-2f, z1 - 0x1p-12f}) {
        const std::vector<VertexIn> v = {{{0, 0, z1}, {}}, {{16, 0, z1}, {}}, {{0, 16, z1}, {}},
                                         {{0, 0, z2}, {}}, {{16, 0, z2}, {}}, {{0, 16, z2}, {}}};
        const std::vector<std::uint32_t> idx = {0, 1, 2, 3, 4, 5};
        DrawCall d{v, idx, &kPosition, {}};
        d.uniforms.model_view_projection = window_to_clip(16, 16);
        const Framebuffer fb = rasterize(16, 16, glm::vec4(0.0f), std::span<const DrawCall>(&d, 1), {});
        const bool hair = z2 == -0x1.6809dcp-2f;
        CHECK(fb.depth.empty() == !hair);  // nearer by 2^-12, painter's order is proven and no buffer needed
        CHECK(z2 * 0.5f + 0.5f < z1 * 0.5f + 0.5f);
        CHECK((depth24(z2 * 0.5f + 0.5f) == depth24(z1 * 0.5f + 0.5f)) == hair);
        CHECK(fb.pixel(2, 13)[2] == (hair ? z1 : z2));
    }
}

TEST_CASE("the stored depth is each pixel's own, in every block of an odd-sized frame", "[raster][depth]") {
    // Two crossing triangles whose depth changes by about 0.02 from one pixel to the next, on a
    // frame whose last block column and row are partial, and whose corners no triangle covers.
    // A pixel's stored depth is the window depth of the fragment it shows (blue is its NDC z),
    // to the 24-bit step; the clear depth, 1, where it shows none. A block's depths stored in
    // the wrong order or place would be off by whole steps of the slope.
    constexpr int W = 37, H = 23;
    const std::vector<VertexIn> v = {{{-2, 2, -0.9f}, {}}, {{36, 4, 0.8f}, {}}, {{10, 22, 0.1f}, {}},
                                     {{1, 20, 0.7f}, {}},  {{35, 21, -0.6f}, {}}, {{20, 1, 0.2f}, {}}};
    const std::vector<std::uint32_t> idx = {0, 1, 2, 3, 4, 5};
    DrawCall d{v, idx, &kPosition, {}};
    d.uniforms.model_view_projection = window_to_clip(W, H);
    const Framebuffer fb = rasterize(W, H, glm::vec4(0.0f), std::span<const DrawCall>(&d, 1), {});
    REQUIRE(!fb.depth.empty());
    int covered = 0, clear = 0;
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x) {
            const float* p = fb.pixel(x, y);
            const float depth = fb.depth[fb.index(x, y)];
            if (p[3] == 0.0f) {
                CHECK(depth == 1.0f);
                ++clear;
            } else {
                CHECK(std::abs(depth - (p[2] * 0.5f + 0.5f)) < 0x1p-20f);
                ++covered;
            }
        }
    }
    CHECK(covered > W * H / 2);
    CHECK(clear > 0);
}

TEST_CASE("the lane-wide depth test is the per-lane one: depth24, LESS and the edge sums on a whole batch",
          "[raster][depth]") {
    // What the rasterizer's block test uses (raster/rasterizer.cpp), lane by lane against the
    // scalar definitions: clamps, NaN, ties of the rounding (k + 0.5 steps), both signs, and edge
    // values at the 64-bit range the fixed-point edge functions reach.
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<float> z = {0.0f, -0.0f, 1.0f, 2.0f, -1.0f, nan, std::nextafter(1.0f, 0.0f), 0x1p-25f, 0x1p-24f,
                            std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()};
    for (const float steps : {0.5f, 1.5f, 2.5f, 1000.5f, 4194303.5f}) z.push_back(steps / kDepthCleared);
    std::mt19937 random(7);
    std::uniform_real_distribution<float> near_unit(-0.1f, 1.1f);
    while (z.size() % kBatchLanes != 0 || z.size() < 8 * std::size_t(kBatchLanes)) z.push_back(near_unit(random));
    for (std::size_t at = 0; at < z.size(); at += kBatchLanes) {
        const lanes16::Floats lanes = lanes16::load(&z[at]);
        const lanes16::Floats d = depth24(lanes);
        lanes16::Floats stored;
        for (int i = 0; i < kBatchLanes; ++i) {
            CHECK(std::bit_cast<std::uint32_t>(d[i]) == std::bit_cast<std::uint32_t>(depth24(z[at + std::size_t(i)])));
            stored[i] = depth24(z[(at + std::size_t(i) * 7) % z.size()]);  // another lane's depth, often equal
        }
        const std::uint32_t pass = lanes16::less(d, stored);
        for (int i = 0; i < kBatchLanes; ++i) CHECK((pass >> i & 1) == std::uint32_t(d[i] < stored[i]));
    }
    const std::int64_t big = std::int64_t(1) << 62;
    lanes16::Longs offsets;
    for (int i = 0; i < kBatchLanes; ++i) offsets[i] = (i % 2 ? -1 : 1) * (std::int64_t(i) << 40) + (i % 3) - 1;
    for (const std::int64_t base : {std::int64_t(0), std::int64_t(1), std::int64_t(-1), big, -big, std::int64_t(15) << 40}) {
        const std::uint32_t positive = lanes16::sum_positive(base, offsets);
        for (int i = 0; i < kBatchLanes; ++i) CHECK((positive >> i & 1) == std::uint32_t(base + offsets[i] > 0));
    }
}

TEST_CASE("leaving the depth buffer out changes no pixel of a non-overlapping mesh with T-junctions", "[raster][depth]") {
    // A strip of squares, each split into two triangles, next to one long triangle whose edge
    // carries the strip's vertices: T-junctions along it. Drawn with and without a forced depth
    // buffer, both fill rules.
    std::vector<VertexIn> v;
    std::vector<std::uint32_t> idx;
    auto add = [&](glm::vec3 p) {
        v.push_back({p, {}});
        return std::uint32_t(v.size() - 1);
    };
    for (int i = 0; i < 6; ++i) {
        const float x0 = 3.25f + 9.5f * float(i), x1 = x0 + 9.5f;
        const std::uint32_t a = add({x0, 20.5f, 0}), b = add({x1, 20.5f, 0}), c = add({x1, 40.5f, 0}), d = add({x0, 40.5f, 0});
        idx.insert(idx.end(), {a, b, c, a, c, d});
    }
    const std::uint32_t l = add({3.25f, 20.5f, 0}), r = add({60.25f, 20.5f, 0}), bottom = add({31.0f, 1.5f, 0});
    idx.insert(idx.end(), {l, bottom, r});
    for (FillRule rule : {FillRule::LeftBottom, FillRule::RightTop}) {
        DrawCall d{v, idx, &kPosition, {}};
        d.uniforms.model_view_projection = window_to_clip(64, 64);
        RasterOptions lean, depth;
        lean.fill_rule = depth.fill_rule = rule;
        depth.force_general_path = true;
        RenderStats stats;
        const Framebuffer a = rasterize(64, 64, glm::vec4(0.0f), std::span<const DrawCall>(&d, 1), lean, &stats);
        const Framebuffer b = rasterize(64, 64, glm::vec4(0.0f), std::span<const DrawCall>(&d, 1), depth);
        CHECK_FALSE(stats.depth_buffer);
        CHECK(a.depth.empty());
        CHECK(a.rgba == b.rgba);
    }
}

TEST_CASE("a convex mesh with its back faces culled, drawn over a backdrop, needs no depth buffer, drawn under, it does",
          "[raster][depth]") {
    // An ellipsoid of 16 x 10 facets (in window pixels, NDC depth -0.5..0.5),
    // and a backdrop square behind it at depth 0.9, on a 64 x 64 frame.
    constexpr int W = 64, H = 64, kAround = 16, kRings = 10;
    std::vector<VertexIn> ellipsoid;
    for (int r = 0; r <= kRings; ++r) {
        const double polar = std::numbers::pi * double(r) / kRings;
        for (int a = 0; a <= kAround; ++a) {
            const double azimuth = 2.0 * std::numbers::pi * double(a) / kAround;
            ellipsoid.push_back({{32.0f + 21.0f * float(std::sin(polar) * std::cos(azimuth)),
                                  31.0f + 19.0f * float(std::sin(polar) * std::sin(azimuth)), -0.5f * float(std::cos(polar))},
                                 {}});
        }
    }
    std::vector<std::uint32_t> facets;
    for (int r = 0; r < kRings; ++r) {
        for (int a = 0; a < kAround; ++a) {
            const std::uint32_t p = std::uint32_t(r * (kAround + 1) + a), q = p + 1, u = p + kAround + 1, v = u + 1;
            facets.insert(facets.end(), {p, u, q, q, u, v});
        }
    }
    const std::vector<VertexIn> square = {{{0, 0, 0.9f}, {}}, {{W, 0, 0.9f}, {}}, {{W, H, 0.9f}, {}}, {{0, H, 0.9f}, {}}};
    const std::vector<std::uint32_t> two = {0, 1, 2, 0, 2, 3};
    DrawCall backdrop{square, two, &kPosition, {}}, mesh{ellipsoid, facets, &kPosition, {}};
    backdrop.uniforms.model_view_projection = mesh.uniforms.model_view_projection = window_to_clip(W, H);
    auto render = [&](std::vector<DrawCall> draws, bool force, RenderStats* stats = nullptr) {
        RasterOptions options;
        options.force_general_path = force;
        return rasterize(W, H, glm::vec4(0.0f), draws, options, stats);
    };
    for (const bool culled : {true, false}) {
        // The near half's facets wind counter-clockwise in GL's window (y up).
        mesh.culling = culled ? FaceCulling{true, Winding::CounterClockwise} : FaceCulling{};
        for (const bool mesh_last : {true, false}) {
            INFO("culled " << culled << ", mesh drawn " << (mesh_last ? "last" : "first"));
            const std::vector<DrawCall> draws = mesh_last ? std::vector{backdrop, mesh} : std::vector{mesh, backdrop};
            RenderStats stats;
            const Framebuffer lean = render(draws, false, &stats), tested = render(draws, true);
            CHECK(stats.depth_buffer == !(culled && mesh_last));
            CHECK(lean.rgba == tested.rgba);
            CHECK(lean.pixel(32, 32)[2] == Approx(-0.5f).margin(0.02f));  // the near pole shows
            CHECK(lean.pixel(2, 2)[2] == 0.9f);                           // the backdrop round it
        }
    }
}

}  // namespace qs::test
