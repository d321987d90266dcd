// The ProcTexGen articles' noises. Improved noise (shading/noise/improved_noise.h): its gradient table is
// Perlin's grad() bit logic, SIMD lanes equal scalar code, the looping variant with a period of
// 256 is the plain noise to the bit, and with a period of 8 it loops. Worley (worley3d.h): F1 and
// F2 are the distances to the feature positions it returns, in order, in either metric.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "shading/noise/improved_noise.h"
#include "shading/noise/worley3d.h"

namespace qs::glsl {

namespace {

// Ken Perlin's reference grad(hash, x, y, z) (2002), written from its statement.
float reference_grad(int hash, float x, float y, float z) {
    const int h = hash & 15;
    const float u = h < 8 ? x : y;
    const float v = h < 4 ? y : (h == 12 || h == 14 ? x : z);
    return ((h & 1) == 0 ? u : -u) + ((h & 2) == 0 ? v : -v);
}

}  // namespace

TEST_CASE("improved noise: the 16 gradients are the reference implementation's grad()", "[noise][proctexgen]") {
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> d(-1.0f, 1.0f);
    for (int hash = 0; hash < 256; ++hash) {
        const vec3<float> p(d(rng), d(rng), d(rng));
        INFO("hash " << hash);
        CHECK(noise::texgrad<float>(hash, p) == reference_grad(hash, p.x, p.y, p.z));
    }
}

TEST_CASE("improved noise: 16 SIMD lanes equal scalar code, and texShaderNoise with period 256 is inoise", "[noise][proctexgen]") {
    using L = Pixels<float, 16>;
    std::mt19937 rng(2);
    std::uniform_real_distribution<float> d(-300.0f, 300.0f);
    double largest = 0.0;
    for (int round = 0; round < 64; ++round) {
        float xs[16], ys[16], zs[16];
        for (int i = 0; i < 16; ++i) xs[i] = d(rng), ys[i] = d(rng), zs[i] = d(rng);
        const vec3<L> P(L::load(xs), L::load(ys), L::load(zs));
        const L n = noise::inoise(P), looped = noise::texShaderNoise(P, 256, 0), based = noise::texShaderNoise(P, 8, 8);
        for (int i = 0; i < 16; ++i) {
            const vec3<float> p(xs[i], ys[i], zs[i]);
            const float scalar = noise::inoise(p);
            CHECK(n[i] == scalar);
            CHECK(looped[i] == scalar);
            CHECK(based[i] == noise::texShaderNoise(p, 8, 8));
            largest = std::max(largest, std::abs(double(scalar)));
        }
    }
    CHECK(largest <= 1.0);
    CHECK(largest > 0.5);  // not a constant
}

TEST_CASE("texShaderNoise loops at its period, on every axis, and its base picks another noise", "[noise][proctexgen]") {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> d(0.0f, 8.0f);
    double other = 0.0;
    for (int k = 0; k < 2000; ++k) {
        const vec3<float> p(d(rng), d(rng), d(rng));
        const float n = noise::texShaderNoise(p, 8, 0);
        for (const vec3<float>& shift : {vec3<float>(8, 0, 0), vec3<float>(0, 16, 0), vec3<float>(0, 0, -8), vec3<float>(24, 8, 8)}) {
            // p + shift loses the low bits of p's fraction: the same noise within that rounding.
            CHECK(std::abs(noise::texShaderNoise(p + shift, 8, 0) - n) < 1e-4f);
        }
        other = std::max(other, double(std::abs(noise::texShaderNoise(p, 8, 8) - n)));
    }
    CHECK(other > 0.5);
}

TEST_CASE("3D Worley: F1 <= F2 are the distances to the two feature positions, on lanes as in scalar code", "[noise][proctexgen]") {
    using L = Pixels<float, 16>;
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> d(-40.0f, 40.0f);
    for (const bool manhattan : {false, true}) {
        for (int round = 0; round < 16; ++round) {
            float xs[16], ys[16], zs[16];
            for (int i = 0; i < 16; ++i) xs[i] = d(rng), ys[i] = d(rng), zs[i] = d(rng);
            const vec3<L> P(L::load(xs), L::load(ys), L::load(zs));
            L f1, f2;
            vec3<L> pos1, pos2;
            noise::voronoi(P, f1, pos1, f2, pos2, .9f, manhattan);
            for (int i = 0; i < 16; ++i) {
                const vec3<float> p(xs[i], ys[i], zs[i]);
                float g1, g2;
                vec3<float> q1, q2;
                noise::voronoi(p, g1, q1, g2, q2, .9f, manhattan);
                CHECK(f1[i] == g1);
                CHECK(f2[i] == g2);
                CHECK(pos2.z[i] == q2.z);
                auto distance = [&](const vec3<float>& q) {
                    const vec3<float> o = q - p;
                    return manhattan ? std::abs(o.x) + std::abs(o.y) + std::abs(o.z) : std::sqrt(dot(o, o));
                };
                CHECK(g1 <= g2);
                CHECK(g1 == Approx(distance(q1)).margin(1e-5));
                CHECK(g2 == Approx(distance(q2)).margin(1e-5));
                // Each feature point lies in its own cell, moved by at most jitter / 2 from its centre.
                for (const vec3<float>& q : {q1, q2}) {
                    const vec3<float> centre = floor(q) + 0.5f;
                    CHECK(std::abs(q.x - centre.x) <= 0.4501f);  // 0.9 (k/255 - 0.5), k = 0 or 255: 0.45, rounded
                    CHECK(std::abs(q.y - centre.y) <= 0.4501f);  // 0.9 (k/255 - 0.5), k = 0 or 255: 0.45, rounded
                    CHECK(std::abs(q.z - centre.z) <= 0.4501f);  // 0.9 (k/255 - 0.5), k = 0 or 255: 0.45, rounded
                }
            }
        }
    }
}

}  // namespace qs::glsl
