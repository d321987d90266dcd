// EmbreeScene traces a batch as packets of the width the CPU traces natively; the width must
// change nothing but ties: the same rays find the same triangles at the same t in packets of 4,
// 8 and 16, except through an edge or vertex that triangles share.
#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "core/block_layout.h"
#include "raycast/embree_scene.h"

namespace qs {

namespace {

using Triangle = std::array<std::uint32_t, 3>;

// An n x n grid of squares, two triangles each, over [-1, 1]^2 at height z.
void add_grid(EmbreeScene& scene, int n, float z) {
    std::vector<glm::vec3> positions;
    std::vector<Triangle> triangles;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) positions.push_back({-1.0f + 2.0f * float(i) / float(n), -1.0f + 2.0f * float(j) / float(n), z});
    }
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const std::uint32_t v = std::uint32_t(j * (n + 1) + i), up = v + std::uint32_t(n + 1);
            triangles.push_back({v, v + 1, up + 1});
            triangles.push_back({v, up + 1, up});
        }
    }
    scene.add_mesh(positions, triangles);
}

}  // namespace

TEST_CASE("Embree packets of 4, 8 and 16 rays find the same hits", "[raycast]") {
    // Two overlapping grids: the lower one hidden where the upper, smaller one covers it.
    const std::unique_ptr<EmbreeScene> s4 = EmbreeScene::create(4), s8 = EmbreeScene::create(8),
                                       s16 = EmbreeScene::create(16);
    const std::array<EmbreeScene*, 3> by_width = {s4.get(), s8.get(), s16.get()};
    for (EmbreeScene* s : by_width) {
        add_grid(*s, 6, 0.0f);
        add_grid(*s, 3, 0.5f);
        s->commit();
    }
    CHECK_THROWS_AS(EmbreeScene::create(12), std::invalid_argument);

    std::mt19937 random(7);
    std::uniform_real_distribution<float> coordinate(-1.3f, 1.3f);
    int hits = 0, misses = 0, upper = 0;
    for (int packet = 0; packet < 400; ++packet) {
        RayPacket rays;
        const bool on_edges = packet % 4 == 0;
        rays.active = std::uint32_t(random()) & 0xFFFFu;
        for (int i = 0; i < kBatchLanes; ++i) {
            // Every fourth packet through inner vertices and edges of both grids, where their
            // triangles meet (not the grids' borders, where a ray may hit or miss).
            float x = coordinate(random), y = coordinate(random);
            if (on_edges) x = float(int(x * 2.0f)) / 3.0f, y = (i & 1) ? y * 0.7f : float(int(y * 2.0f)) / 3.0f;
            rays.origin[0][i] = x, rays.origin[1][i] = y, rays.origin[2][i] = 2.0f;
            rays.direction[0][i] = 0.0f, rays.direction[1][i] = 0.0f, rays.direction[2][i] = -4.0f;
            rays.tnear[i] = (i % 3 == 0) ? 0.4f : 0.0f;  // some start below the upper grid
        }
        RayHits h[3];
        for (int w = 0; w < 3; ++w) by_width[std::size_t(w)]->intersect(rays, h[w]);
        for (int i = 0; i < kBatchLanes; ++i) {
            INFO("packet " << packet << ", lane " << i);
            for (int w = 1; w < 3; ++w) {
                CHECK(h[w].geometry[i] == h[0].geometry[i]);
                if (on_edges) {
                    // Where triangles meet, the packets' traversal orders may settle the tie
                    // either way: a neighbour of the same mesh, at (nearly) the same t.
                    CHECK(h[w].t[i] == Approx(h[0].t[i]).epsilon(1e-6));
                } else {
                    CHECK(h[w].primitive[i] == h[0].primitive[i]);
                    CHECK(h[w].t[i] == h[0].t[i]);
                }
            }
            if (!(rays.active >> i & 1)) {
                CHECK(h[0].geometry[i] == kNoHit);
                continue;
            }
            if (h[0].geometry[i] == kNoHit) {
                ++misses;
            } else {
                ++hits;
                upper += h[0].geometry[i] == 1;
            }
        }
    }
    // Every kind of outcome occurred: hits on both grids, and misses.
    CHECK(hits > 1000);
    CHECK(upper > 300);
    CHECK(misses > 100);
}

}  // namespace qs
