// The rasterizer: coverage (watertight, fill rule), interpolation, helper lanes, quad pairing,
// clipping, robustness, determinism.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <tuple>

#include "core/block_rows.h"
#include "core/lanes16.h"
#include "core/tile_grid.h"
#include "raster/fragment_inputs.h"
#include "render/scene_render.h"
#include "scenes/gltf.h"
#include "tests/raster/test_program.h"

namespace qs::test {

namespace {

const ProgramOf<Flat> kFlat;
const ProgramOf<Position> kPosition;
const ProgramOf<Slopes> kSlopes;

// Writes dFdx and dFdy of gl_FragCoord.y squared.
struct SquareY {
    static constexpr ShaderInfo info{.name = "test_y2", .description = "a test shader", .needs = {.coordinates = Coordinates::Object3D, .derivatives = true, .frag_coord = true}};
    using VertexStage = PassThrough;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        F y = in.gl_FragCoord.y;
        return vec4<F>(dFdx(y * y), dFdy(y * y), y, 1.0f);
    }
};
const ProgramOf<SquareY> kSquareY;

// The same shader not saying that it reads gl_FragCoord.
struct UndeclaredSquareY : SquareY {
    static constexpr ShaderInfo info{.name = "test_y2_undeclared", .description = "a test shader", .needs = {.coordinates = Coordinates::Object3D, .derivatives = true}};
};
const ProgramOf<UndeclaredSquareY> kUndeclaredSquareY;

// Writes N smooth varyings (N = 1 to 5; the fifth in place of the third), each a different
// function of the vertex: the inputs of whole tiles (FragmentInputs::ColumnVaryings for one to
// four of them, fill for five) against the general path's.
template <int N>
struct SmoothVaryings {
    static constexpr ShaderInfo info{.name = "test_smooth_varyings", .description = "a test shader", .needs = {.coordinates = Coordinates::Object3D, .derivatives = false}};
    struct VertexStage {
        static constexpr GlslFiles glsl{};
        template <class T>
        struct Varyings {
            T a, b, c, d, e;
            auto fields() {
                if constexpr (N == 1) return std::tie(a);
                else if constexpr (N == 2) return std::tie(a, b);
                else if constexpr (N == 3) return std::tie(a, b, c);
                else if constexpr (N == 4) return std::tie(a, b, c, d);
                else return std::tie(a, b, c, d, e);
            }
        };
        static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<VertexStage>& out) {
            const float x = in.position.x, y = in.position.y;
            out.a = 1.3f * x + 0.2f * y + 5.0f;
            if constexpr (N > 1) out.b = 0.7f * y - 0.4f * x;
            if constexpr (N > 2) out.c = 0.01f * x * y + 0.125f;
            if constexpr (N > 3) out.d = 100.0f + 3.0f * y;
            if constexpr (N > 4) out.e = 1.0f / (1.0f + 0.001f * x * x);
            out.gl_Position = transform_point(u.model_view_projection, in.position);
        }
    };
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        const F zero(0.0f);
        return vec4<F>(in.a, N > 1 ? in.b : zero, N > 4 ? in.e : N > 2 ? in.c : zero, N > 3 ? in.d : zero);
    }
};

// Window-space triangles (x, y in pixels, y up; z in [-1, 1]) drawn with one program.
Framebuffer draw(int w, int h, const std::vector<glm::vec3>& corners, const Program& program,
                 RasterOptions options = {}, RenderStats* stats = nullptr) {
    std::vector<VertexIn> verts;
    std::vector<std::uint32_t> idx;
    for (const glm::vec3& c : corners) {
        idx.push_back(std::uint32_t(verts.size()));
        verts.push_back({c, {0.0f, 0.0f}});
    }
    DrawCall d;
    d.vertices = verts;
    d.indices = idx;
    d.program = &program;
    d.uniforms.model_view_projection = window_to_clip(w, h);
    return rasterize(w, h, glm::vec4(0.0f), std::span<const DrawCall>(&d, 1), options, stats);
}

// Coverage of GL window pixel (x, y): its alpha.
float covered(const Framebuffer& fb, int x, int y) { return fb.pixel(x, fb.height - 1 - y)[3]; }

}  // namespace

TEST_CASE("a block's colours go from lane order to framebuffer rows, each pixel where its lane lies", "[raster][layout]") {
    // Channel c of lane i holds 100 c + i: each output float names where it came from.
    alignas(64) float channels[4][kBatchLanes];
    for (int c = 0; c < 4; ++c) {
        for (int i = 0; i < kBatchLanes; ++i) channels[c][i] = float(100 * c + i);
    }
    lanes16::Floats rows[kBlock];
    block_to_rows({channels[0], channels[1], channels[2], channels[3]}, rows);
    for (int i = 0; i < kBatchLanes; ++i) {
        for (int c = 0; c < 4; ++c) CHECK(rows[kLaneDy[i]][4 * kLaneDx[i] + c] == float(100 * c + i));
    }
}

TEST_CASE("a block's rows land the same streamed or cached, on rows that start a cache line or not", "[raster][layout]") {
    lanes16::Floats rows[kBlock];
    for (int r = 0; r < kBlock; ++r) {
        for (int j = 0; j < 4 * kBlock; ++j) rows[r][j] = float(100 * r + j);
    }
    // Widths 8 and 12: every block's rows start a cache line (the colour is allocated on one);
    // 9, 10 and 11: they do not, and are stored as plain rows.
    for (int width : {8, 9, 10, 11, 12}) {
        for (RowStores stores : {RowStores::Cached, RowStores::Streamed}) {
            Framebuffer fb;
            fb.hold(width, 6, RowBand{0, 6}, false, false);
            REQUIRE(starts_cache_line(fb.rgba.data()));
            std::fill(fb.rgba.begin(), fb.rgba.end(), -1.0f);
            write_block_rows(fb, 4, 1, rows, stores);
            streaming_stores_done();
            INFO("width " << width << (stores == RowStores::Streamed ? ", streamed" : ", cached"));
            for (int y = 0; y < 6; ++y) {
                for (int x = 0; x < width; ++x) {
                    for (int c = 0; c < 4; ++c) {
                        const bool in_block = x >= 4 && x < 8 && y >= 1 && y < 5;
                        CHECK(fb.pixel(x, y)[c] == (in_block ? float(100 * (y - 1) + 4 * (x - 4) + c) : -1.0f));
                    }
                }
            }
        }
    }
}

TEST_CASE("lanes16's append, lowest_bits, compress_bits and equal are their lane-by-lane definitions", "[raster][layout]") {
    std::mt19937 random(5);
    std::uniform_int_distribution<std::uint32_t> bits(0, 0xFFFFu);
    std::uniform_int_distribution<int> small(-3, 3);
    for (int trial = 0; trial < 500; ++trial) {
        const std::uint32_t mask = trial % 10 == 0 ? 0u : trial % 10 == 1 ? 0xFFFFu : bits(random), other = bits(random);
        lanes16::Ints v, w, to;
        for (int i = 0; i < kBatchLanes; ++i) {
            v[i] = 1000 * i - 7000, w[i] = small(random) == 0 ? v[i] : v[i] + small(random), to[i] = -1 - i;
        }
        // Appended after `first` lanes, as many of mask's lanes as fit.
        const int first = trial % (kBatchLanes + 1);
        const std::uint32_t taken = lanes16::lowest_bits(mask, kBatchLanes - first);
        const lanes16::Ints appended = lanes16::append(to, first, taken, v);
        std::uint32_t packed = 0, equal = 0, expected_taken = 0;
        int k = 0;
        for (int i = 0; i < kBatchLanes; ++i) {
            equal |= std::uint32_t(v[i] == w[i]) << i;
            if (!(mask >> i & 1)) continue;
            if (k < kBatchLanes - first) expected_taken |= 1u << i;
            packed |= (other >> i & 1) << k++;
        }
        CHECK(taken == expected_taken);
        for (int i = 0, n = 0; i < kBatchLanes; ++i) {
            if (taken >> i & 1) CHECK(appended[first + n++] == v[i]);
            if (i < first || i >= first + std::popcount(taken)) CHECK(appended[i] == to[i]);
        }
        CHECK(lanes16::compress_bits(other, mask) == packed);
        CHECK(lanes16::equal(v, w) == equal);
    }
}

TEST_CASE("a closed fan covers every pixel inside exactly once and nothing outside", "[raster][coverage]") {
    std::mt19937 rng(1234);
    std::uniform_real_distribution<float> jitter(-0.5f, 0.5f);
    constexpr int W = 64, H = 64;
    for (int fan = 0; fan < 40; ++fan) {
        // A star-shaped polygon around a centre, vertices on the 1/256 grid, some on pixel centres.
        const glm::vec2 centre(32.0f + jitter(rng) * 8, 32.0f + jitter(rng) * 8);
        const int n = 3 + fan % 9;
        std::vector<glm::vec2> ring;
        for (int i = 0; i < n; ++i) {
            const float a = 6.2831853f * (float(i) + 0.3f * jitter(rng)) / float(n);
            const float r = 10.0f + 18.0f * (jitter(rng) + 0.5f);
            glm::vec2 p = centre + r * glm::vec2(std::cos(a), std::sin(a));
            if (i % 3 == 0) p = glm::floor(p) + 0.5f;  // exactly on a pixel centre
            ring.push_back(glm::round(p * 256.0f) / 256.0f);
        }
        std::vector<float> count(W * H, 0.0f);
        for (int i = 0; i < n; ++i) {
            const glm::vec2 a = ring[std::size_t(i)], b = ring[std::size_t((i + 1) % n)];
            // Alternate the winding: coverage must not depend on it.
            const std::vector<glm::vec3> tri = (i % 2) ? std::vector<glm::vec3>{{centre, 0}, {a, 0}, {b, 0}}
                                                       : std::vector<glm::vec3>{{centre, 0}, {b, 0}, {a, 0}};
            const Framebuffer fb = draw(W, H, tri, kFlat);
            for (int y = 0; y < H; ++y) {
                for (int x = 0; x < W; ++x) count[std::size_t(y * W + x)] += covered(fb, x, y);
            }
        }
        for (int y = 0; y < H; ++y) {
            for (int x = 0; x < W; ++x) {
                INFO("fan " << fan << " pixel " << x << ", " << y);
                REQUIRE(count[std::size_t(y * W + x)] <= 1.0f);
            }
        }
        // The centre's pixel and its neighbours are strictly inside.
        CHECK(count[std::size_t(int(centre.y) * W + int(centre.x))] == 1.0f);
    }
}

TEST_CASE("fill rule: pixel centres on left and bottom edges are in, on right and top edges out", "[raster][coverage]") {
    // Rectangle x in [2.5, 6.5], y in [1.5, 4.5]: every edge passes through pixel centres.
    const Framebuffer fb = draw(16, 16, {{2.5f, 1.5f, 0}, {6.5f, 1.5f, 0}, {6.5f, 4.5f, 0},
                                         {2.5f, 1.5f, 0}, {6.5f, 4.5f, 0}, {2.5f, 4.5f, 0}}, kFlat);
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 16; ++x) {
            const bool inside = x >= 2 && x <= 5 && y >= 1 && y <= 3;
            INFO("pixel " << x << ", " << y);
            CHECK(covered(fb, x, y) == (inside ? 1.0f : 0.0f));
        }
    }
}

TEST_CASE("two triangles sharing a diagonal through pixel centres cover each pixel once", "[raster][coverage]") {
    const std::vector<glm::vec3> lower = {{0.5f, 0.5f, 0}, {12.5f, 0.5f, 0}, {12.5f, 12.5f, 0}};
    const std::vector<glm::vec3> upper = {{0.5f, 0.5f, 0}, {12.5f, 12.5f, 0}, {0.5f, 12.5f, 0}};
    const Framebuffer a = draw(16, 16, lower, kFlat), b = draw(16, 16, upper, kFlat);
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 16; ++x) {
            const bool inside = x <= 11 && y <= 11;  // left/bottom in, right/top out
            CHECK(covered(a, x, y) + covered(b, x, y) == (inside ? 1.0f : 0.0f));
        }
    }
}

TEST_CASE("perspective-correct varyings equal the analytic value at pixel centres", "[raster][interpolation]") {
    // A tilted plane seen through a perspective camera; varyings are the object position.
    constexpr int W = 64, H = 48;
    const glm::mat4 proj = glm::perspective(glm::radians(50.0f), float(W) / H, 0.5f, 50.0f);
    const glm::mat4 view = glm::lookAt(glm::vec3(0, -3, 1.5f), glm::vec3(0, 2, 0), glm::vec3(0, 0, 1));
    const glm::mat4 mvp = proj * view;
    std::vector<VertexIn> verts = {{{-4, -1, 0}, {}}, {{4, -1, 0}, {}}, {{4, 9, 0}, {}}, {{-4, 9, 0}, {}}};
    std::vector<std::uint32_t> idx = {0, 1, 2, 0, 2, 3};
    DrawCall d{verts, idx, &kPosition, {}};
    d.uniforms.model_view_projection = mvp;
    const Framebuffer fb = rasterize(W, H, glm::vec4(0), std::span<const DrawCall>(&d, 1), {});
    const glm::dmat4 inv = glm::inverse(glm::dmat4(mvp));
    int checked = 0;
    for (int row = 0; row < H; ++row) {
        for (int x = 0; x < W; ++x) {
            const float* px = fb.pixel(x, row);
            if (px[3] == 0.0f) continue;
            // Ray through the pixel centre, intersected with z = 0 in double.
            const double nx = (x + 0.5) / W * 2 - 1, ny = (H - row - 0.5) / H * 2 - 1;
            glm::dvec4 a = inv * glm::dvec4(nx, ny, -1, 1), b = inv * glm::dvec4(nx, ny, 1, 1);
            a /= a.w, b /= b.w;
            const double t = a.z / (a.z - b.z);
            const glm::dvec3 hit = glm::dvec3(a) + t * (glm::dvec3(b) - glm::dvec3(a));
            // Float setup and interpolation over ~10 units: a few ulps of the plane equations.
            constexpr double kTolerance = 2e-4;
            CHECK(px[0] == Approx(hit.x).margin(kTolerance));
            CHECK(px[1] == Approx(hit.y).margin(kTolerance));
            ++checked;
        }
    }
    CHECK(checked > W * H / 3);
}

TEST_CASE("a plane at sixteen lanes is PlaneEquation's own value on each, fused or not, in one step or two",
          "[raster][interpolation]") {
    std::mt19937 rng(48);
    std::uniform_real_distribution<float> coefficient(-1000.0f, 1000.0f), position(0.0f, 4096.0f);
    for (int trial = 0; trial < 500; ++trial) {
        PlaneEquation p;
        p.a0 = coefficient(rng), p.dadx = coefficient(rng) * 1e-3f, p.dady = coefficient(rng) * 1e-2f;
        lanes16::Floats x, y;
        for (int i = 0; i < kBatchLanes; ++i) x[i] = std::floor(position(rng)) + 0.5f, y[i] = std::floor(position(rng)) + 0.5f;
        const lanes16::Floats fused = FragmentInputs::at<true>(p, x, y), separate = FragmentInputs::at<false>(p, x, y);
        const lanes16::Floats fused2 = FragmentInputs::at_row<true>(p.dady, FragmentInputs::at_column<true>(p, x), y);
        const lanes16::Floats separate2 = FragmentInputs::at_row<false>(p.dady, FragmentInputs::at_column<false>(p, x), y);
        for (int i = 0; i < kBatchLanes; ++i) {
            CHECK(std::bit_cast<std::uint32_t>(fused[i]) == std::bit_cast<std::uint32_t>(p.at_fused(x[i], y[i])));
            CHECK(std::bit_cast<std::uint32_t>(separate[i]) == std::bit_cast<std::uint32_t>(p.at(x[i], y[i])));
            CHECK(std::bit_cast<std::uint32_t>(fused2[i]) == std::bit_cast<std::uint32_t>(fused[i]));
            CHECK(std::bit_cast<std::uint32_t>(separate2[i]) == std::bit_cast<std::uint32_t>(separate[i]));
        }
    }
}

TEMPLATE_TEST_CASE_SIG("whole tiles get the same varyings as the general path, bit for bit, whatever their count",
                       "[raster][interpolation]", ((int N), N), 1, 2, 3, 4, 5) {
    const ProgramOf<SmoothVaryings<N>> program;
    // 200 x 150: whole 64 x 64 tiles and partial ones; two triangles over it all.
    constexpr int W = 200, H = 150;
    const std::vector<std::uint32_t> idx = {0, 1, 2, 0, 2, 3};
    const bool affine = GENERATE(true, false);
    const bool fused = GENERATE(true, false);
    DrawCall d;
    std::vector<VertexIn> verts;
    if (affine) {  // window coordinates: w is 1 everywhere, the tiles' column path
        verts = {{{-3, -2, 0}, {}}, {{W + 5.0f, -2, 0}, {}}, {{W + 5.0f, H + 4.0f, 0}, {}}, {{-3, H + 4.0f, 0}, {}}};
        d.uniforms.model_view_projection = window_to_clip(W, H);
    } else {  // a plane in perspective: the tiles' general fill
        verts = {{{-6, -1, 0}, {}}, {{6, -1, 0}, {}}, {{6, 9, 0}, {}}, {{-6, 9, 0}, {}}};
        d.uniforms.model_view_projection = glm::perspective(glm::radians(60.0f), float(W) / H, 0.5f, 50.0f) *
                                           glm::lookAt(glm::vec3(0, -2, 1.0f), glm::vec3(0, 3, 0), glm::vec3(0, 0, 1));
    }
    d.vertices = verts;
    d.indices = idx;
    d.program = &program;
    RasterOptions options;
    options.fused_interpolation = fused;
    RenderStats stats;
    const Framebuffer tiles = rasterize(W, H, glm::vec4(0.0f), std::span<const DrawCall>(&d, 1), options, &stats);
    options.force_general_path = true;
    const Framebuffer general = rasterize(W, H, glm::vec4(0.0f), std::span<const DrawCall>(&d, 1), options);
    INFO("varyings " << N << (affine ? ", affine" : ", perspective") << (fused ? ", fused" : ", separate"));
    REQUIRE(tiles.rgba.size() == general.rgba.size());
    CHECK(std::memcmp(tiles.rgba.data(), general.rgba.data(), tiles.rgba.size() * sizeof(float)) == 0);
    // The varyings are not all alike (a shader reading one twice would pass the comparison).
    const float* p = tiles.pixel(100, 75);
    CHECK(p[0] != 0.0f);
    if (N > 1) CHECK(p[1] != p[0]);
    if (N > 3) CHECK(p[3] != p[2]);
}

TEST_CASE("flat varyings take the provoking (last) vertex's value over the whole triangle", "[raster][interpolation]") {
    static const ProgramOf<FlatX> flat;
    // -0 too, sign and all: spreading it over the lanes by adding +0 would make it +0, which a
    // shader can tell (1/x, atan, sign tests).
    for (const float last_x : {12.0f, -0.0f}) {
        CAPTURE(last_x);
        const Framebuffer fb = draw(32, 32, {{1.0f, 1.0f, 0}, {30.0f, 2.0f, 0}, {last_x, 29.0f, 0}}, flat);
        int drawn = 0;
        for (int row = 0; row < 32; ++row) {
            for (int x = 0; x < 32; ++x) {
                const float* px = fb.pixel(x, row);
                if (px[3] == 0.0f) continue;
                ++drawn;
                CHECK(px[0] == last_x);  // flat: the last vertex's x
                CHECK(std::signbit(px[0]) == std::signbit(last_x));
                CHECK(std::abs(px[1] - (31 - row + 0.5f)) < 1e-3f);  // smooth: the pixel centre's y
            }
        }
        CHECK(drawn > 100);
    }
    CHECK(std::signbit(lanes16::broadcast(-0.0f)[7]));
}

TEST_CASE("dFdx of an interpolated varying on helper lanes equals the interior value", "[raster][helpers]") {
    // v = x / 4 in window space: every quad difference is exactly 0.25, and 0 in y, including
    // quads along the sliver's edges where most lanes are helpers extrapolating the plane.
    const std::vector<glm::vec3> sliver = {{1.3f, 2.1f, 0}, {60.7f, 9.4f, 0}, {3.2f, 5.9f, 0}};
    std::vector<VertexIn> verts;
    for (const glm::vec3& c : sliver) verts.push_back({c, {}});
    // varying 0 is position.x; scale it by 1/4 through the object position itself.
    for (VertexIn& v : verts) v.position.x *= 1.0f, v.texcoord = {0, 0};
    RenderStats stats;
    const Framebuffer fb = draw(64, 16, sliver, kSlopes, {}, &stats);
    int written = 0;
    for (int row = 0; row < 16; ++row) {
        for (int x = 0; x < 64; ++x) {
            const float* px = fb.pixel(x, row);
            if (px[3] == 0.0f) continue;
            ++written;
            CHECK(px[0] == Approx(1.0f).margin(1e-5));  // d(position.x)/dx = 1 pixel per pixel
            CHECK(px[1] == Approx(0.0f).margin(1e-5));
        }
    }
    CHECK(written > 0);
    CHECK(stats.lanes_shaded > std::uint64_t(written));  // helper lanes ran
}

TEST_CASE("odd image sizes: quads pair rows from the top (OSMesa) or from the bottom (FBO)", "[raster][helpers]") {
    // 17x15, v = y^2 on a full-window rectangle: dFdy on GL row 0 pairs it with row -1 (a helper
    // below the image) top-down, with row 1 bottom-up.
    constexpr int W = 17, H = 15;
    const ProgramOf<SquareY>& program = kSquareY;
    const std::vector<glm::vec3> full = {{0, 0, 0}, {W, 0, 0}, {W, H, 0}, {0, 0, 0}, {W, H, 0}, {0, H, 0}};
    RasterOptions top, bottom;
    bottom.pairing = QuadPairing::BottomUp;
    const Framebuffer a = draw(W, H, full, program, top), b = draw(W, H, full, program, bottom);
    auto dy_at = [](const Framebuffer& fb, int y) { return fb.pixel(16, fb.height - 1 - y)[1]; };
    CHECK(dy_at(a, 0) == 0.5f * 0.5f - (-0.5f) * (-0.5f));  // rows 0 and -1
    CHECK(dy_at(b, 0) == 1.5f * 1.5f - 0.5f * 0.5f);        // rows 0 and 1
    CHECK(dy_at(a, 14) == 14.5f * 14.5f - 13.5f * 13.5f);   // rows 13 and 14
    CHECK(dy_at(b, 14) == 15.5f * 15.5f - 14.5f * 14.5f);   // rows 14 and 15 (helper above)
    // Column 16 pairs with the helper column 17 in both.
    CHECK(a.pixel(16, 0)[0] == 0.0f);
    for (int i = 0; i < W * H; ++i) CHECK(a.rgba[std::size_t(i) * 4 + 3] == 1.0f);  // every pixel drawn
}

TEST_CASE("a shader that reads gl_FragCoord without declaring it reads NaN, never another draw's numbers",
          "[raster][specialisation]") {
    // Two draws over the same pixels: the first interpolates gl_FragCoord, the second, nearer (it
    // passes the depth test), leaves it out.
    constexpr int W = 8, H = 8;
    const std::vector<VertexIn> verts = {{{0, 0, 0}, {}}, {{W, 0, 0}, {}}, {{W, H, 0}, {}}, {{0, H, 0}, {}}};
    const std::vector<VertexIn> nearer = {{{0, 0, -0.5f}, {}}, {{W, 0, -0.5f}, {}}, {{W, H, -0.5f}, {}}, {{0, H, -0.5f}, {}}};
    const std::vector<std::uint32_t> idx = {0, 1, 2, 0, 2, 3};
    DrawCall declared{verts, idx, &kSquareY, {}}, undeclared{nearer, idx, &kUndeclaredSquareY, {}};
    declared.uniforms.model_view_projection = undeclared.uniforms.model_view_projection = window_to_clip(W, H);
    const DrawCall both[] = {declared, undeclared};
    const Framebuffer fb = rasterize(W, H, glm::vec4(0.0f), both, {});
    for (int i = 0; i < W * H; ++i) CHECK(std::isnan(fb.rgba[std::size_t(i) * 4 + 2]));  // blue: gl_FragCoord.y
    const Framebuffer first = rasterize(W, H, glm::vec4(0.0f), std::span(both, 1), {});
    CHECK(first.pixel(3, H - 1 - 5)[2] == 5.5f);
}

TEST_CASE("varyings are counted from the vertex stage's fields, flat ones included", "[raster][specialisation]") {
    // A fragment stage reads its vertex stage's varyings by name (shading/varyings.h), so it
    // cannot read one the stage does not write (tests/shading/varyings_misread.cpp must not
    // compile); the renderers interpolate exactly the floats the fields hold.
    static_assert(varying_count<PassThrough>() == 5 && flat_varying_mask<PassThrough>() == 0u);
    static_assert(varying_count<FlatX::VertexStage>() == 2 && flat_varying_mask<FlatX::VertexStage>() == 1u);
    CHECK(kPosition.info().needs.varyings == 5);
    static const ProgramOf<FlatX> flat;
    CHECK(flat.info().needs.varyings == 2);
    CHECK(flat.info().needs.flat_varyings == 1u);
    // The vertex stage's fields in declaration order: P.xyz, then st.
    VertexOut out;
    kPosition.vertex(VertexIn{{1.0f, 2.0f, 3.0f}, {4.0f, 5.0f}}, Uniforms{}, out);
    CHECK(std::vector<float>(out.varyings.begin(), out.varyings.begin() + 5) == std::vector<float>{1, 2, 3, 4, 5});
}

TEST_CASE("degenerate, sliver and non-finite triangles are dropped without harm", "[raster][robustness]") {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    RenderStats stats;
    const Framebuffer fb = draw(32, 32,
                                {{1, 1, 0}, {20, 20, 0}, {10, 10, 0},       // collinear
                                 {5, 5, 0}, {5, 5, 0}, {5, 5, 0},          // a point
                                 {nan, 1, 0}, {3, 4, 0}, {9, 2, 0},        // NaN
                                 {inf, 1, 0}, {3, 4, 0}, {9, 2, 0},        // infinity
                                 {0.1f, 0.1f, 0}, {31.9f, 0.1f, 0}, {0.1f, 0.1004f, 0}},  // sub-pixel sliver
                                kFlat, {}, &stats);
    CHECK(stats.triangles_in == 5);
    for (float v : fb.rgba) CHECK(std::isfinite(v));
    float sum = 0.0f;
    for (std::size_t i = 3; i < fb.rgba.size(); i += 4) sum += fb.rgba[i];
    CHECK(sum == 0.0f);
}

TEST_CASE("triangles crossing the near plane and vertices at 1e6 in clip space are clipped, not lost", "[raster][clipping]") {
    constexpr int W = 32, H = 32;
    // A ground plane reaching behind the eye: the lower half of the image must be covered.
    const glm::mat4 mvp = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f) *
                          glm::lookAt(glm::vec3(0, 0, 1), glm::vec3(0, 1, 1), glm::vec3(0, 0, 1));
    std::vector<VertexIn> plane = {{{-50, -50, 0}, {}}, {{50, -50, 0}, {}}, {{50, 50, 0}, {}}, {{-50, 50, 0}, {}}};
    std::vector<std::uint32_t> idx = {0, 1, 2, 0, 2, 3};
    DrawCall d{plane, idx, &kFlat, {}};
    d.uniforms.model_view_projection = mvp;
    const Framebuffer a = rasterize(W, H, glm::vec4(0), std::span<const DrawCall>(&d, 1), {});
    for (int row = H / 2 + 1; row < H; ++row) {
        for (int x = 0; x < W; ++x) CHECK(a.pixel(x, row)[3] == 1.0f);
    }
    for (int x = 0; x < W; ++x) CHECK(a.pixel(x, 0)[3] == 0.0f);  // sky stays clear
    // A triangle with clip coordinates of +-1e6 (w = 1) covers the whole window.
    std::vector<VertexIn> huge = {{{-1e6f, -1e6f, 0}, {}}, {{1e6f, -1e6f, 0}, {}}, {{0, 1e6f, 0}, {}}};
    std::vector<std::uint32_t> tri = {0, 1, 2};
    DrawCall h{huge, tri, &kFlat, {}};
    const Framebuffer b = rasterize(W, H, glm::vec4(0), std::span<const DrawCall>(&h, 1), {});
    for (std::size_t i = 3; i < b.rgba.size(); i += 4) CHECK(b.rgba[i] == 1.0f);
}

TEST_CASE("back faces are culled by their winding in the window, after clipping, for either front winding", "[raster][culling]") {
    constexpr int W = 32, H = 32;
    auto draw_culled = [](const std::vector<VertexIn>& verts, const std::vector<std::uint32_t>& idx, const glm::mat4& mvp,
                          FaceCulling culling) {
        DrawCall d{verts, idx, &kFlat, {}};
        d.uniforms.model_view_projection = mvp;
        d.culling = culling;
        return rasterize(W, H, glm::vec4(0), std::span<const DrawCall>(&d, 1), {});
    };
    auto alpha = [](const Framebuffer& fb) {
        std::vector<float> a;
        for (std::size_t i = 3; i < fb.rgba.size(); i += 4) a.push_back(fb.rgba[i]);
        return a;
    };
    const FaceCulling none, back{true, Winding::CounterClockwise}, back_mirrored{true, Winding::Clockwise};
    // In the window (y up): counter-clockwise on the left, clockwise on the right.
    const std::vector<VertexIn> pair = {{{2, 2, 0}, {}},  {{14, 2, 0}, {}}, {{2, 30, 0}, {}},
                                        {{18, 2, 0}, {}}, {{18, 30, 0}, {}}, {{30, 2, 0}, {}}};
    const std::vector<std::uint32_t> both = {0, 1, 2, 3, 4, 5};
    const glm::mat4 window = window_to_clip(W, H);
    for (const auto& [culling, left, right] : {std::tuple{none, 1.0f, 1.0f}, std::tuple{back, 1.0f, 0.0f},
                                               std::tuple{back_mirrored, 0.0f, 1.0f}}) {
        const Framebuffer fb = draw_culled(pair, both, window, culling);
        CHECK(covered(fb, 5, 5) == left);
        CHECK(covered(fb, 21, 5) == right);
    }
    // A ground plane reaching behind the eye, counter-clockwise seen from above: its clipped
    // pieces are judged by what is seen of them, so culling keeps all of it or none.
    const glm::mat4 mvp = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f) *
                          glm::lookAt(glm::vec3(0, 0, 1), glm::vec3(0, 1, 1), glm::vec3(0, 0, 1));
    const std::vector<VertexIn> plane = {{{-50, -50, 0}, {}}, {{50, -50, 0}, {}}, {{50, 50, 0}, {}}, {{-50, 50, 0}, {}}};
    const std::vector<std::uint32_t> ccw = {0, 1, 2, 0, 2, 3}, cw = {0, 2, 1, 0, 3, 2};
    const std::vector<float> drawn = alpha(draw_culled(plane, ccw, mvp, none));
    REQUIRE(std::count(drawn.begin(), drawn.end(), 1.0f) >= W * H / 3);  // the ground below the horizon
    const std::vector<float> nothing(drawn.size(), 0.0f);
    CHECK(alpha(draw_culled(plane, ccw, mvp, back)) == drawn);
    CHECK(alpha(draw_culled(plane, ccw, mvp, back_mirrored)) == nothing);
    CHECK(alpha(draw_culled(plane, cw, mvp, back)) == nothing);
    CHECK(alpha(draw_culled(plane, cw, mvp, back_mirrored)) == drawn);
}

TEST_CASE("depth test LESS keeps the nearest surface whatever the draw order", "[raster][depth]") {
    // Two tiles wide (kTileSize 64): each triangle covers one tile whole (the near one the lower
    // left, the far one the lower right), where, drawn first, it is shaded without tests and its
    // depths written for the other to be tested against. A third, small and farther still, drawn
    // last over both, keeps the depth buffer in either order (drawn in painter's order alone,
    // it would show).
    static_assert(kTileSize == 64);
    constexpr int S = 2 * kTileSize;
    const std::vector<glm::vec3> near_tri = {{0, 0, -0.5f}, {S, 0, -0.5f}, {0, S, -0.5f}};
    const std::vector<glm::vec3> far_tri = {{0, 0, 0.5f}, {S, 0, 0.5f}, {S, S, 0.5f}};
    const std::vector<glm::vec3> hidden = {{30, 30, 0.9f}, {50, 30, 0.9f}, {30, 50, 0.9f}};
    for (bool near_first : {true, false}) {
        std::vector<glm::vec3> all = near_first ? near_tri : far_tri;
        const auto& second = near_first ? far_tri : near_tri;
        all.insert(all.end(), second.begin(), second.end());
        all.insert(all.end(), hidden.begin(), hidden.end());
        const Framebuffer fb = draw(S, S, all, kPosition);
        CHECK(!fb.depth.empty());
        // Covered by both: the near one's z, in either triangle's whole tile.
        CHECK(fb.pixel(80, S - 1 - 20)[2] == -0.5f);
        CHECK(fb.pixel(40, S - 1 - 12)[2] == -0.5f);
        CHECK(fb.pixel(34, S - 1 - 34)[2] == -0.5f);
    }
    // On the far plane (window depth 1), drawn first over whole tiles: LESS against the cleared 1
    // drops every fragment, so the tile's first triangle is not written untested.
    const std::vector<glm::vec3> on_far_plane = {{0, 0, 1.0f}, {S, 0, 1.0f}, {0, S, 1.0f}, {1, 1, 0}, {3, 1, 0}, {1, 3, 0}};
    const Framebuffer dropped = draw(S, S, on_far_plane, kPosition);
    CHECK(!dropped.depth.empty());
    CHECK(covered(dropped, 40, 12) == 0.0f);
    CHECK(covered(dropped, 1, 1) == 1.0f);
    CHECK(draw(8, 8, near_tri, kFlat).depth.empty());  // one triangle occludes nothing: no depth buffer
}

TEST_CASE("derivative-free shaders run per pixel with no helper lanes, derivative shaders in quads", "[raster][specialisation]") {
    const std::vector<glm::vec3> tri = {{0.5f, 0.5f, 0}, {30.2f, 3.1f, 0}, {7.7f, 29.9f, 0}};
    RenderStats flat, slopes, general;
    draw(32, 32, tri, kFlat, {}, &flat);
    draw(32, 32, tri, kSlopes, {}, &slopes);
    RasterOptions force;
    force.force_general_path = true;
    draw(32, 32, tri, kFlat, force, &general);
    CHECK(flat.quads == 0);
    CHECK(flat.lanes_shaded == flat.pixels_written);
    CHECK(slopes.quads > 0);
    CHECK(slopes.lanes_shaded == slopes.quads * 4);
    CHECK(slopes.lanes_shaded > slopes.pixels_written);
    CHECK(general.pixels_written == flat.pixels_written);
    CHECK(general.lanes_shaded > general.pixels_written);
}

TEST_CASE("the Figure 1.1 frame is bit-identical on 1 and 2 threads", "[raster][determinism]") {
    Scene scene = load_scene(std::filesystem::path(QUADSHADE_SOURCE_DIR) / "scenes/assets/figure-1.1.gltf");
    FrameRequest one, two;
    one.width = two.width = 316, one.height = two.height = 100;
    one.shading.threads = 1, two.shading.threads = 2;
    const Framebuffer a = render_frame(scene, one), b = render_frame(scene, two);
    REQUIRE(a.rgba.size() == b.rgba.size());
    CHECK(std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(float)) == 0);
}

TEST_CASE("absurd image sizes are refused with a message", "[raster][robustness]") {
    CHECK_THROWS_WITH(draw(0, 10, {}, kFlat), Catch::Contains("outside"));
    CHECK_THROWS_WITH(draw(100000, 10, {}, kFlat), Catch::Contains("outside"));
}

}  // namespace qs::test
