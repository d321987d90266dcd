#include "raster/clipper.h"

#include <cmath>

namespace qs {

namespace {

// A clip plane as a dot product with (x, y, z, w): inside when >= 0.
struct Plane {
    glm::vec4 n;
    float distance(const glm::vec4& p) const { return n.x * p.x + n.y * p.y + n.z * p.z + n.w * p.w; }
};

ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, float t, int varying_count) {
    ClipVertex r;
    r.clip = a.clip + (b.clip - a.clip) * t;
    for (int i = 0; i < varying_count; ++i) r.varyings[i] = a.varyings[i] + (b.varyings[i] - a.varyings[i]) * t;
    return r;
}

}  // namespace

bool clip_triangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, int varying_count,
                   float guard_x, float guard_y, std::vector<std::array<ClipVertex, 3>>& out) {
    for (const ClipVertex* v : {&a, &b, &c}) {
        const glm::vec4& p = v->clip;
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || !std::isfinite(p.w)) return false;
    }
    const Plane planes[6] = {
        {{0, 0, 1, 1}},         // near:  z >= -w
        {{0, 0, -1, 1}},        // far:   z <= w
        {{1, 0, 0, guard_x}},   // x >= -gx w
        {{-1, 0, 0, guard_x}},  // x <= gx w
        {{0, 1, 0, guard_y}},   // y >= -gy w
        {{0, -1, 0, guard_y}},  // y <= gy w
    };
    unsigned outside_any = 0;
    for (int p = 0; p < 6; ++p) {
        for (const ClipVertex* v : {&a, &b, &c}) {
            if (planes[p].distance(v->clip) < 0.0f) outside_any |= 1u << p;
        }
    }
    if (outside_any == 0) {  // the common case: the triangle reaches setup bit-for-bit unchanged
        out.push_back({a, b, c});
        return true;
    }
    std::vector<ClipVertex> poly = {a, b, c}, next;
    for (int p = 0; p < 6 && !poly.empty(); ++p) {
        if (!(outside_any & (1u << p))) continue;
        next.clear();
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const ClipVertex& s = poly[i];
            const ClipVertex& e = poly[(i + 1) % poly.size()];
            const float ds = planes[p].distance(s.clip), de = planes[p].distance(e.clip);
            if (ds >= 0.0f) next.push_back(s);
            if ((ds >= 0.0f) != (de >= 0.0f)) {
                // Interpolate from the inside vertex, so that shared edges clip identically.
                next.push_back(ds >= 0.0f ? lerp(s, e, ds / (ds - de), varying_count)
                                          : lerp(e, s, de / (de - ds), varying_count));
            }
        }
        poly.swap(next);
    }
    if (poly.size() < 3) return false;
    for (std::size_t i = 1; i + 1 < poly.size(); ++i) out.push_back({poly[0], poly[i], poly[i + 1]});
    return true;
}

}  // namespace qs
