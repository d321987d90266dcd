#include "raster/triangle_setup.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "raster/fixed_point.h"

namespace qs {

std::optional<TriangleSetup> setup_triangle(const std::array<ClipVertex, 3>& tri, int varying_count, int width,
                                            int height, FillRule fill_rule, unsigned flat,
                                            const ClipVertex& provoking, FaceCulling culling, unsigned noperspective) {
    std::int64_t fx[3], fy[3];
    for (int i = 0; i < 3; ++i) {
        const glm::vec4& w = tri[std::size_t(i)].window;
        if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z) || !std::isfinite(w.w)) return std::nullopt;
        // The clipper leaves vertices in the viewport; one its arithmetic would leave far outside
        // (the triangle fuzzer found an intersection near w = 0 at 2.6e9 pixels with the guard-band
        // clipper before it) would overflow the 64-bit edge functions, so it is dropped like one
        // that is not finite. Within 2^19 pixels, edge products stay below 2^56.
        constexpr float kLimit = float(1 << 19);
        if (!(std::abs(w.x) <= kLimit && std::abs(w.y) <= kLimit)) return std::nullopt;
        fx[i] = fixed::snap(w.x);
        fy[i] = fixed::snap(w.y);
    }
    // Orient so that the interior is on the positive side of every edge.
    const std::int64_t area = (fx[1] - fx[0]) * (fy[2] - fy[0]) - (fx[2] - fx[0]) * (fy[1] - fy[0]);
    if (area == 0) return std::nullopt;
    // y runs down here, so a negative area turns counter-clockwise in GL's window.
    if (!culling.keeps(area < 0 ? Winding::CounterClockwise : Winding::Clockwise)) return std::nullopt;
    int order[3] = {0, 1, 2};
    if (area < 0) std::swap(order[1], order[2]);

    TriangleSetup t;
    t.front = area < 0;
    for (int e = 0; e < 3; ++e) {
        const int a = order[e], b = order[(e + 1) % 3];
        t.edges[e] = EdgeFunction::from_edge(fx[a], fy[a], fx[b], fy[b], fixed::kSubpixelBits, fill_rule);
        t.corner_x[std::size_t(e)] = fx[a], t.corner_y[std::size_t(e)] = fy[a];
    }
    // Pixel centres i << 8 inside the fixed-point bounds.
    auto lo = [](std::int64_t v) { return int((v + fixed::kOne - 1) >> fixed::kSubpixelBits); };
    auto hi = [](std::int64_t v) { return int(v >> fixed::kSubpixelBits); };
    t.min_x = std::max(lo(std::min({fx[0], fx[1], fx[2]})), 0);
    t.min_y = std::max(lo(std::min({fy[0], fy[1], fy[2]})), 0);
    t.max_x = std::min(hi(std::max({fx[0], fx[1], fx[2]})), width - 1);
    t.max_y = std::min(hi(std::max({fy[0], fy[1], fy[2]})), height - 1);
    if (t.min_x > t.max_x || t.min_y > t.max_y) return std::nullopt;

    // Planes from the float window positions as llvmpipe's setup takes them: in the vertices'
    // order when their winding is counter-clockwise in GL's window (front facing; area < 0 here,
    // y down), else with the first two swapped (lp_setup_tri.c: triangle_both).
    std::array<const ClipVertex*, 3> v = {&tri[0], &tri[1], &tri[2]};
    if (area > 0) std::swap(v[0], v[1]);
    const float x[3] = {v[0]->window.x, v[1]->window.x, v[2]->window.x};
    const float y[3] = {v[0]->window.y, v[1]->window.y, v[2]->window.y};
    const PlaneSetup s(x, y);
    if (!s.valid) return std::nullopt;
    t.z = PlaneEquation(s, v[0]->window.z, v[1]->window.z, v[2]->window.z);
    t.inv_w = PlaneEquation(s, v[0]->window.w, v[1]->window.w, v[2]->window.w);
    for (int k = 0; k < varying_count; ++k) {
        if (flat >> k & 1) {
            t.varyings[std::size_t(k)].a0 = provoking.varyings[std::size_t(k)];  // constant, not divided by w
            continue;
        }
        if (noperspective >> k & 1) {
            t.varyings[std::size_t(k)] = PlaneEquation(s, v[0]->varyings[std::size_t(k)], v[1]->varyings[std::size_t(k)],
                                                       v[2]->varyings[std::size_t(k)]);
            continue;
        }
        t.varyings[std::size_t(k)] = PlaneEquation(s, v[0]->varyings[std::size_t(k)] * v[0]->window.w,
                                                   v[1]->varyings[std::size_t(k)] * v[1]->window.w,
                                                   v[2]->varyings[std::size_t(k)] * v[2]->window.w);
    }
    return t;
}

}  // namespace qs
