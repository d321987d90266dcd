// The ray caster's rays on sixteen lanes (raycast/eye.h) against the scalar glm expressions they
// stand for, to the bit: each lane must round as the one-ray code, or the images change.
#include <catch2/catch.hpp>

#include <bit>
#include <cstdint>
#include <random>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "raycast/eye.h"

namespace qs {

namespace {

// The world point of NDC (x, y, z) and its derivative along NDC direction d, one ray at a time
// as glm computes them (h.xyz scaled by 1 / h.w).
glm::dvec3 unproject(const glm::dmat4& world_from_clip, double x, double y, double z, const glm::dvec4& d, glm::dvec3& dp) {
    const glm::dvec4 h = world_from_clip * glm::dvec4(x, y, z, 1.0);
    const double scale = 1.0 / h.w;
    const glm::dvec3 p = glm::dvec3(h) * scale;
    const glm::dvec4 dh = world_from_clip * d;
    dp = (glm::dvec3(dh) - p * dh.w) * scale;
    return p;
}

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

}  // namespace

TEST_CASE("the sixteen-lane rays and their differentials round as glm's one-ray code", "[raycast]") {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int checked = 0;
    for (int camera = 0; camera < 20; ++camera) {
        const glm::dvec3 eye(5.0 * unit(random), 5.0 * unit(random), 5.0 + 3.0 * unit(random));
        const glm::dmat4 view = glm::lookAt(eye, glm::dvec3(unit(random), unit(random), 0.0), glm::dvec3(0.0, 1.0, 0.0));
        const glm::dmat4 projection = camera % 3 == 0 ? glm::ortho(-2.0, 2.5, -1.5, 1.0, 0.1, 30.0)
                                                      : glm::perspective(0.4 + unit(random) * 0.2, 1.5, 0.1, 100.0);
        Eye e;
        e.clip_from_world = glm::dmat4(glm::mat4(projection * view));  // from float, as the renderer's
        e.world_from_clip = glm::inverse(e.clip_from_world);
        const int width = 317 + camera, height = 211;
        e.ndc_per_x = 2.0 / width, e.ndc_per_y = 2.0 / height;
        lanes16::Doubles xw, yw;
        for (int i = 0; i < kBatchLanes; ++i) xw[i] = (unit(random) + 1.0) * 0.5 * width, yw[i] = (unit(random) + 1.0) * 0.5 * height;
        const Eye::Rays rays = e.rays(xw, yw);
        const Eye::Differentials d = e.differentials(rays);
        for (int i = 0; i < kBatchLanes; ++i) {
            const double x = xw[i] * e.ndc_per_x - 1.0, y = yw[i] * e.ndc_per_y - 1.0;
            const glm::dvec4 dx(e.ndc_per_x, 0.0, 0.0, 0.0), dy(0.0, e.ndc_per_y, 0.0, 0.0);
            glm::dvec3 near_dx, far_dx, near_dy, far_dy;
            const glm::dvec3 near = unproject(e.world_from_clip, x, y, -1.0, dx, near_dx);
            const glm::dvec3 far = unproject(e.world_from_clip, x, y, 1.0, dx, far_dx);
            unproject(e.world_from_clip, x, y, -1.0, dy, near_dy), unproject(e.world_from_clip, x, y, 1.0, dy, far_dy);
            const glm::dvec3 expected[] = {near, far - near, near_dx, far_dx - near_dx, near_dy, far_dy - near_dy};
            const glm::dvec3 got[] = {rays.origin.at(i), rays.direction.at(i), d.origin_dx.at(i), d.direction_dx.at(i),
                                      d.origin_dy.at(i), d.direction_dy.at(i)};
            for (int k = 0; k < 6; ++k) {
                for (int c = 0; c < 3; ++c) {
                    INFO("camera " << camera << ", lane " << i << ", vector " << k << ", component " << c);
                    CHECK(same_bits(got[k][c], expected[k][c]));
                    ++checked;
                }
            }
        }
    }
    CHECK(checked == 20 * kBatchLanes * 18);
}

}  // namespace qs
