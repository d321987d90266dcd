// The noise translations: SIMD lanes equal scalar code bit for bit, the analytic gradient of
// flow noise is right, and Listing 1.3's printed typo breaks the noise along simplex edges.
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>

#include <glm/vec2.hpp>

#include "shading/noise/cellular.h"
#include "shading/noise/flow_noise.h"
#include "shading/noise/simplex2d.h"
#include "shading/noise/simplex3d.h"

// Inside qs::glsl, as shader code is: unqualified built-ins resolve as they do in shaders.
namespace qs::glsl {

TEST_CASE("noise on 16 SIMD lanes equals the scalar float code bit for bit", "[noise]") {
    using L = Pixels<float, 16>;
    float xs[16], ys[16], zs[16];
    for (int i = 0; i < 16; ++i) xs[i] = 1.37f * float(i) - 9.0f, ys[i] = 0.61f * float(i), zs[i] = 60.0f - 0.5f * float(i);
    const vec3<L> P(L::load(xs), L::load(ys), L::load(zs));
    const L n3 = noise::snoise3<noise::Simplex3dDemo>(P);
    const vec2<L> c3 = noise::cellular(P);
    const vec2<L> c2 = noise::cellular(P.xy());
    vec2<L> grad;
    const L flow = noise::srdnoise(P.xy(), L(0.7f), grad);
    for (int i = 0; i < 16; ++i) {
        const vec3<float> p(xs[i], ys[i], zs[i]);
        vec2<float> g;
        CHECK(n3[i] == noise::snoise3<noise::Simplex3dDemo>(p));
        CHECK(c3.x[i] == noise::cellular(p).x);
        CHECK(c3.y[i] == noise::cellular(p).y);
        CHECK(c2.y[i] == noise::cellular(p.xy()).y);
        CHECK(flow[i] == noise::srdnoise(p.xy(), 0.7f, g));
        CHECK(grad.x[i] == g.x);
    }
}

// cellular_vectors hashes the cells of lanes that lie close together once per batch
// (noise/cellular_nearby.h, on AVX-512): blocks of pixels at several scales (so that their cells are
// close together, or not), across the hash's wrap at 289 and below zero, on 16 and 32 lanes of
// pixels and quads, give every lane the scalar code's F1, F2 and vectors to the bit.
template <class L>
void check_cellular_lanes(int& nearby, int& batches) {
    constexpr int N = L::size;
    for (const float scale : {64.0f / 500.0f, 8.0f / 500.0f, 0.9f, 1.7f, 40.0f}) {
        for (const glm::vec2 origin : {glm::vec2(0.3f, 0.7f), glm::vec2(287.6f, 40.2f), glm::vec2(-3.1f, -288.7f),
                                       glm::vec2(1000.25f, 12.5f)}) {
            for (int block = 0; block < 24; ++block) {
                float xs[N], ys[N];
                for (int i = 0; i < N; ++i) {
                    const int x = 4 * block + (i / 16) * 4 + (i % 4 % 2) + 2 * (i % 16 / 4 % 2);
                    const int y = (i % 4 / 2) + 2 * (i % 16 / 8);
                    xs[i] = origin.x + scale * (float(x) + 0.5f), ys[i] = origin.y + scale * (float(y) + 0.5f);
                }
                const vec2<L> P(L::load(xs), L::load(ys));
                vec4<L> d1d2;
                const vec2<L> F = noise::cellular_vectors(P, d1d2);
                vec2<L> Fs(1e6f);
                vec4<L> unused(0.0f);
                nearby += noise::cellular_search_nearby(mod(floor(P), 289.0f), fract(P), [&](const L& d, const vec2<L>& v) {
                    noise::insert(d, v, Fs, unused);
                }), ++batches;
                for (int i = 0; i < N; ++i) {
                    vec4<float> d;
                    const vec2<float> f = noise::cellular_vectors(vec2<float>(xs[i], ys[i]), d);
                    INFO("scale " << scale << ", origin " << origin.x << " " << origin.y << ", lane " << i);
                    CHECK(std::bit_cast<std::uint32_t>(lane(F.x, i)) == std::bit_cast<std::uint32_t>(f.x));
                    CHECK(std::bit_cast<std::uint32_t>(lane(F.y, i)) == std::bit_cast<std::uint32_t>(f.y));
                    for (int c = 0; c < 4; ++c) {
                        CHECK(std::bit_cast<std::uint32_t>(lane(d1d2[c], i)) == std::bit_cast<std::uint32_t>(d[c]));
                    }
                }
            }
        }
    }
}

TEST_CASE("cellular noise on lanes whose cells lie close together equals the scalar code bit for bit", "[noise]") {
    int nearby = 0, batches = 0;
    check_cellular_lanes<Pixels<float, 16>>(nearby, batches);
    check_cellular_lanes<Pixels<float, 32>>(nearby, batches);
    check_cellular_lanes<Quads<float, 4>>(nearby, batches);
    check_cellular_lanes<Quads<float, 8>>(nearby, batches);
    if (simd::register_floats == 16) {
        // Both ways are taken: the table where the cells lie close together, each lane's own
        // hashes elsewhere (the largest scale, and where the cells wrap at 289).
        CHECK(nearby > batches / 4);
        CHECK(nearby < batches);
    } else {
        CHECK(nearby == 0);
    }
}

TEST_CASE("flow noise's analytic gradient matches central differences", "[noise]") {
    constexpr double h = 1e-6;
    constexpr double kTolerance = 1e-5;  // O(h^2) truncation plus rounding of the noise sum
    for (double x : {0.1, 1.3, 5.7, -3.2}) {
        for (double y : {0.4, -2.6, 8.1}) {
            vec2<double> g, unused;
            noise::srdnoise(vec2<double>(x, y), 0.4, g);
            const double cx = (noise::srdnoise(vec2<double>(x + h, y), 0.4, unused) -
                               noise::srdnoise(vec2<double>(x - h, y), 0.4, unused)) / (2 * h);
            const double cy = (noise::srdnoise(vec2<double>(x, y + h), 0.4, unused) -
                               noise::srdnoise(vec2<double>(x, y - h), 0.4, unused)) / (2 * h);
            CHECK(g.x == Approx(cx).margin(kTolerance));
            CHECK(g.y == Approx(cy).margin(kTolerance));
        }
    }
}

TEST_CASE("Listing 1.3 with its printed C.xxxx jumps across simplex edges, with C.xxzz it is continuous", "[noise]") {
    // March along a line in small steps; the largest step-to-step change shows a discontinuity.
    auto largest_jump = [](auto noise) {
        double worst = 0.0, prev = noise(vec2<double>(0.0, 0.05));
        for (int i = 1; i <= 200000; ++i) {
            const double t = i * 5e-5;
            const double v = noise(vec2<double>(t, 0.05 + 0.31 * t));
            worst = std::max(worst, std::abs(v - prev));
            prev = v;
        }
        return worst;
    };
    const double correct = largest_jump([](const vec2<double>& p) { return noise::snoise(p); });
    const double typo = largest_jump(
        [](const vec2<double>& p) { return noise::snoise<double, noise::Simplex2dCorner::ListingTypo>(p); });
    // A continuous function with slope below ~3 moves less than 1e-3 per 5e-5 step.
    CHECK(correct < 1e-3);
    CHECK(typo > 0.05);
}

TEST_CASE("noise values stay in their documented ranges", "[noise]") {
    double lo3 = 0, hi3 = 0, f1max = 0;
    for (int i = 0; i < 20000; ++i) {
        const vec3<double> p(std::sin(i * 0.7) * 9.0, std::cos(i * 1.3) * 7.0, i * 0.013);
        const double n = noise::snoise3<noise::Simplex3dDemo>(p);
        lo3 = std::min(lo3, n), hi3 = std::max(hi3, n);
        const vec2<double> F = noise::cellular(p);
        CHECK(F.x <= F.y);
        f1max = std::max(f1max, F.x);
    }
    CHECK(lo3 > -1.05);
    CHECK(hi3 < 1.05);
    CHECK(hi3 - lo3 > 1.0);  // and it uses most of the range
    CHECK(f1max < 1.5);
}

}  // namespace qs::glsl
