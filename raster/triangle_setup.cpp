#include "raster/triangle_setup.h"

#include <algorithm>
#include <cmath>

#include "raster/fixed_point.h"

namespace qs {

std::optional<TriangleSetup> setup_triangle(const std::array<ClipVertex, 3>& tri, int varying_count, int width,
                                            int height, FillRule fill_rule, unsigned flat,
                                            const ClipVertex& provoking) {
    const float scale_x = float(width) * 0.5f, trans_x = float(width) * 0.5f;
    const float scale_y = -float(height) * 0.5f, trans_y = float(height) * 0.5f;
    float x[3], y[3], z[3], oow[3];
    std::int64_t fx[3], fy[3];
    for (int i = 0; i < 3; ++i) {
        const glm::vec4& c = tri[i].clip;
        oow[i] = 1.0f / c.w;
        x[i] = c.x * oow[i] * scale_x + trans_x;
        y[i] = c.y * oow[i] * scale_y + trans_y;
        z[i] = c.z * oow[i] * 0.5f + 0.5f;
        if (!std::isfinite(x[i]) || !std::isfinite(y[i]) || !std::isfinite(z[i])) return std::nullopt;
        fx[i] = fixed::snap(x[i]);
        fy[i] = fixed::snap(y[i]);
    }
    // Orient so that the interior is on the positive side of every edge.
    const std::int64_t area = (fx[1] - fx[0]) * (fy[2] - fy[0]) - (fx[2] - fx[0]) * (fy[1] - fy[0]);
    if (area == 0) return std::nullopt;
    int order[3] = {0, 1, 2};
    if (area < 0) std::swap(order[1], order[2]);

    TriangleSetup t;
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

    // Planes from the float positions in the vertices' original order, as llvmpipe's setup.
    const PlaneSetup s(x, y);
    if (!s.valid) return std::nullopt;
    t.z = PlaneEquation(s, z[0], z[1], z[2]);
    t.inv_w = PlaneEquation(s, oow[0], oow[1], oow[2]);
    for (int v = 0; v < varying_count; ++v) {
        if (flat >> v & 1) {
            t.varyings[v].a0 = provoking.varyings[v];  // constant, not divided by w
            continue;
        }
        t.varyings[v] = PlaneEquation(s, tri[0].varyings[v] * oow[0], tri[1].varyings[v] * oow[1],
                                      tri[2].varyings[v] * oow[2]);
    }
    return t;
}

}  // namespace qs
