#pragma once
// The camera's primary rays, sixteen pixels at a time: through pixel centres in GL window
// coordinates (y up), from the near plane (origin, t = 0) to the far plane (t = 1), and their
// derivatives in window x and y. Double precision, each lane as glm computes one ray.

#include <glm/mat4x4.hpp>

#include "raycast/double_lanes.h"

namespace qs {

struct Eye {
    glm::dmat4 clip_from_world, world_from_clip;
    double ndc_per_x = 0.0, ndc_per_y = 0.0;  // 2/W, 2/H

    struct Rays {
        lanes16::Doubles3 origin, direction;  // the near-plane point, and far minus near
        // The far-plane point, and both points' homogeneous w (their derivatives divide by it).
        lanes16::Doubles3 far;
        lanes16::Doubles near_w, far_w;
    };
    // d(origin)/dx, d(direction)/dx and the same for y.
    struct Differentials {
        lanes16::Doubles3 origin_dx, direction_dx, origin_dy, direction_dy;
    };

    // The rays through window points (xw, yw): the world points of NDC (x, y, -1) and (x, y, 1).
    Rays rays(const lanes16::Doubles& xw, const lanes16::Doubles& yw) const {
        using namespace lanes16;
        const Doubles x = xw * ndc_per_x - 1.0, y = yw * ndc_per_y - 1.0;
        const Doubles4 near = transform(world_from_clip, x, y, -1.0, 1.0);
        const Doubles4 far = transform(world_from_clip, x, y, 1.0, 1.0);
        Rays r;
        r.origin = {near.x / near.w, near.y / near.w, near.z / near.w};
        r.far = {far.x / far.w, far.y / far.w, far.z / far.w};
        r.direction = r.far - r.origin;
        r.near_w = near.w, r.far_w = far.w;
        return r;
    }

    // A point p = h.xyz / h.w with h linear in NDC moves along NDC direction d by
    // dp = (dh.xyz - p dh.w) / h.w, dh = world_from_clip d: the same for every pixel.
    Differentials differentials(const Rays& r) const {
        using namespace lanes16;
        auto along = [](const glm::dvec4& dh, const Doubles3& p, const Doubles& w) {
            return Doubles3{(dh.x - p.x * dh.w) / w, (dh.y - p.y * dh.w) / w, (dh.z - p.z * dh.w) / w};
        };
        const glm::dvec4 dx = world_from_clip * glm::dvec4(ndc_per_x, 0.0, 0.0, 0.0);
        const glm::dvec4 dy = world_from_clip * glm::dvec4(0.0, ndc_per_y, 0.0, 0.0);
        Differentials d;
        d.origin_dx = along(dx, r.origin, r.near_w), d.direction_dx = along(dx, r.far, r.far_w) - d.origin_dx;
        d.origin_dy = along(dy, r.origin, r.near_w), d.direction_dy = along(dy, r.far, r.far_w) - d.origin_dy;
        return d;
    }
};

}  // namespace qs
