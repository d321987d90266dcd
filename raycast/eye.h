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
        // The far-plane point, and 1 / w of both points' homogeneous coordinates (their
        // derivatives are scaled by it).
        lanes16::Doubles3 far;
        lanes16::Doubles near_scale, far_scale;
    };
    // d(origin)/dx, d(direction)/dx and the same for y.
    struct Differentials {
        lanes16::Doubles3 origin_dx, direction_dx, origin_dy, direction_dy;
    };

    // The rays through window points (xw, yw): the world points of NDC (x, y, -1) and (x, y, 1),
    // h.xyz scaled by 1 / h.w, one division per point instead of three, since sixteen-lane
    // double divisions dominate the block loop (the shipped scenes' ray-cast images are the same).
    Rays rays(const lanes16::Doubles& xw, const lanes16::Doubles& yw) const {
        using namespace lanes16;
        const Doubles x = xw * ndc_per_x - 1.0, y = yw * ndc_per_y - 1.0;
        const Doubles4 near = transform(world_from_clip, x, y, -1.0, 1.0);
        const Doubles4 far = transform(world_from_clip, x, y, 1.0, 1.0);
        Rays r;
        r.near_scale = 1.0 / near.w, r.far_scale = 1.0 / far.w;
        r.origin = {near.x * r.near_scale, near.y * r.near_scale, near.z * r.near_scale};
        r.far = {far.x * r.far_scale, far.y * r.far_scale, far.z * r.far_scale};
        r.direction = r.far - r.origin;
        return r;
    }

    // A point p = h.xyz / h.w with h linear in NDC moves along NDC direction d by
    // dp = (dh.xyz - p dh.w) / h.w, dh = world_from_clip d: the same for every pixel.
    Differentials differentials(const Rays& r) const {
        using namespace lanes16;
        auto along = [](const glm::dvec4& dh, const Doubles3& p, const Doubles& scale) {
            return Doubles3{(dh.x - p.x * dh.w) * scale, (dh.y - p.y * dh.w) * scale, (dh.z - p.z * dh.w) * scale};
        };
        const glm::dvec4 dx = world_from_clip * glm::dvec4(ndc_per_x, 0.0, 0.0, 0.0);
        const glm::dvec4 dy = world_from_clip * glm::dvec4(0.0, ndc_per_y, 0.0, 0.0);
        Differentials d;
        d.origin_dx = along(dx, r.origin, r.near_scale), d.direction_dx = along(dx, r.far, r.far_scale) - d.origin_dx;
        d.origin_dy = along(dy, r.origin, r.near_scale), d.direction_dy = along(dy, r.far, r.far_scale) - d.origin_dy;
        return d;
    }
};

}  // namespace qs
