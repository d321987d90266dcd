#include "raster/clipper.h"

#include <cmath>

namespace qs {

Viewport::Viewport(int width, int height)
    : scale{float(width) * 0.5f, -float(height) * 0.5f, 0.5f}, translate{float(width) * 0.5f, float(height) * 0.5f, 0.5f} {}

glm::vec4 Viewport::window(const glm::vec4& clip, bool fused) const {
    const float oow = 1.0f / clip.w;
    glm::vec4 r;
    for (int k = 0; k < 3; ++k) {
        r[k] = fused ? std::fma(clip[k] * oow, scale[k], translate[k]) : clip[k] * oow * scale[k] + translate[k];
    }
    r.w = oow;
    return r;
}

namespace {

// The view volume's planes in Mesa's order, as dot products with (x, y, z, w): inside when >= 0.
constexpr int kPlanes = 6;
constexpr float kPlane[kPlanes][4] = {
    {-1, 0, 0, 1},  // x <= w
    {1, 0, 0, 1},   // x >= -w
    {0, -1, 0, 1},  // y <= w
    {0, 1, 0, 1},   // y >= -w
    {0, 0, 1, 1},   // near: z >= -w
    {0, 0, -1, 1},  // far: z <= w
};

// Plane p's distance to v: a view volume plane's, or user plane p - kPlanes's.
float distance(int plane, const ClipVertex& v) {
    if (plane >= kPlanes) return v.clip_distances[std::size_t(plane - kPlanes)];
    const float* p = kPlane[plane];
    const glm::vec4& c = v.clip;
    return ((c.x * p[0] + c.y * p[1]) + c.z * p[2]) + c.w * p[3];
}

// Bit p set: the vertex is outside plane p (draw_llvm.c's clip mask), the user planes of
// `user` from bit kPlanes on.
unsigned outside_mask(const ClipVertex& v, unsigned user) {
    const glm::vec4& c = v.clip;
    unsigned m = unsigned(c.x > c.w) | unsigned(0.0f > c.x + c.w) << 1 | unsigned(c.y > c.w) << 2 |
                 unsigned(0.0f > c.y + c.w) << 3 | unsigned(0.0f > c.z + c.w) << 4 | unsigned(c.z > c.w) << 5;
    for (int i = 0; i < kMaxClipDistances; ++i) {
        if (user >> i & 1) m |= unsigned(v.clip_distances[std::size_t(i)] < 0.0f) << (kPlanes + i);
    }
    return m;
}

// The vertex at `from + t (to - from)`, with window coordinates computed from it (unfused).
// Noperspective varyings take the t of the window position (draw_pipe_clip.c's t_nopersp): along
// x, or along y where the endpoints' x agree.
ClipVertex interpolate(float t, const ClipVertex& from, const ClipVertex& to, int varying_count, const Viewport& viewport,
                       unsigned noperspective) {
    ClipVertex r;
    for (int k = 0; k < 4; ++k) r.clip[k] = from.clip[k] + t * (to.clip[k] - from.clip[k]);
    r.window = viewport.window(r.clip, false);
    float t_window = t;
    if (noperspective) {
        for (int k = 0; k < 2; ++k) {
            if (from.clip[k] == to.clip[k]) continue;
            const float to_k = to.clip[k] / to.clip.w, from_k = from.clip[k] / from.clip.w, at = r.clip[k] / r.clip.w;
            t_window = (at - from_k) / (to_k - from_k);
            break;
        }
    }
    for (int i = 0; i < varying_count; ++i) {
        const float s = noperspective >> i & 1 ? t_window : t;
        r.varyings[std::size_t(i)] = from.varyings[std::size_t(i)] + s * (to.varyings[std::size_t(i)] - from.varyings[std::size_t(i)]);
    }
    for (int i = 0; i < kMaxClipDistances; ++i) {
        r.clip_distances[std::size_t(i)] =
            from.clip_distances[std::size_t(i)] + t * (to.clip_distances[std::size_t(i)] - from.clip_distances[std::size_t(i)]);
    }
    return r;
}

}  // namespace

bool clip_triangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, int varying_count,
                   const Viewport& viewport, std::vector<std::array<ClipVertex, 3>>& out, ClipState state) {
    for (const ClipVertex* v : {&a, &b, &c}) {
        const glm::vec4& p = v->clip;
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || !std::isfinite(p.w)) return false;
    }
    const unsigned ma = outside_mask(a, state.user_planes), mb = outside_mask(b, state.user_planes),
                   mc = outside_mask(c, state.user_planes);
    if ((ma | mb | mc) == 0) {  // the common case: the triangle reaches setup bit-for-bit unchanged
        out.push_back({a, b, c});
        return true;
    }
    if (ma & mb & mc) return false;  // wholly outside one plane
    std::vector<ClipVertex> poly = {a, b, c}, next;
    for (int p = 0; p < kPlanes + kMaxClipDistances && poly.size() >= 3; ++p) {
        if (!((ma | mb | mc) >> p & 1)) continue;
        next.clear();
        const std::size_t n = poly.size();
        float d_prev = distance(p, poly[0]);
        for (std::size_t i = 1; i <= n; ++i) {
            const ClipVertex& prev = poly[i - 1];
            const ClipVertex& cur = poly[i % n];
            const float d = distance(p, cur);
            if (!std::isfinite(d) || !std::isfinite(d_prev)) return false;
            bool crossing;
            if (d_prev >= 0.0f) {
                next.push_back(prev);
                crossing = d < 0.0f;
            } else {
                crossing = !(d < 0.0f);
            }
            if (crossing) {
                // From the endpoint nearer the plane (on a tie the inside one), Mesa's expressions.
                const float denom = d - d_prev;
                const bool from_cur = d < 0.0f ? -d < d_prev : !(-d_prev < d);
                next.push_back(from_cur ? interpolate(d / denom, cur, prev, varying_count, viewport, state.noperspective)
                                        : interpolate(-d_prev / denom, prev, cur, varying_count, viewport, state.noperspective));
            }
            d_prev = d;
        }
        poly.swap(next);
    }
    if (poly.size() < 3) return false;
    for (std::size_t i = 2; i < poly.size(); ++i) out.push_back({poly[i - 1], poly[i], poly[0]});
    return true;
}

}  // namespace qs
