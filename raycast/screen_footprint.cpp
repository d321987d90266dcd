#include "raycast/screen_footprint.h"

#include <cmath>
#include <limits>

#include "core/block_layout.h"

namespace qs {

std::optional<TriangleFootprint> footprint(const glm::dmat4& m, const glm::dvec3& a, const glm::dvec3& b,
                                           const glm::dvec3& c, double slack) {
    // Clip coordinate r over the triangle's bounding box grown by the slack: its value at the
    // box's centre, give or take the sum of each axis's share; widened by a relative 1e-9 for
    // this arithmetic's own rounding.
    const glm::dvec3 lo = glm::min(glm::min(a, b), c) - slack, hi = glm::max(glm::max(a, b), c) + slack;
    const glm::dvec3 centre = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    struct Range {
        double low, high;
    };
    auto range = [&](int r) {
        const double mid = m[0][r] * centre.x + m[1][r] * centre.y + m[2][r] * centre.z + m[3][r];
        const double shares = std::abs(m[0][r]) * half.x + std::abs(m[1][r]) * half.y + std::abs(m[2][r]) * half.z;
        const double spread = shares + 1e-9 * (std::abs(mid) + shares);
        return Range{mid - spread, mid + spread};
    };
    const Range w = range(3);
    if (!(w.low > 0.0)) return std::nullopt;  // at or behind the eye plane (or not a number)
    // A point P of the triangle moved by e (|e| <= slack per axis) moves in NDC x by
    // (Mx.e - ndc_x(P) Mw.e) / w(P + e), and w(P + e) >= w.low: at most
    // (|Mx|_1 + |ndc_x| |Mw|_1) slack / w.low, where |ndc_x| over the box (w > 0) is at most its
    // largest |x| over its least w. The same for y and z.
    auto reach = [&](int r) {
        const Range v = range(r);
        const double largest = std::max(std::abs(v.low), std::abs(v.high)) / w.low;
        auto norm = [&](int row) { return std::abs(m[0][row]) + std::abs(m[1][row]) + std::abs(m[2][row]); };
        return (norm(r) + largest * norm(3)) * (slack / w.low);
    };
    TriangleFootprint f;
    f.reach = glm::dvec2(reach(0), reach(1));
    // NDC depth over a triangle in front of the eye lies between its vertices' (the projection
    // maps the triangle onto the flat triangle of their images).
    const double depth_reach = reach(2);
    f.nearest = std::numeric_limits<double>::infinity(), f.farthest = -f.nearest;
    const glm::dvec3* p[3] = {&a, &b, &c};
    for (int i = 0; i < 3; ++i) {
        const glm::dvec4 h = m * glm::dvec4(*p[i], 1.0);
        f.vertex[i] = glm::dvec2(h.x / h.w, h.y / h.w);
        f.nearest = std::min(f.nearest, h.z / h.w - depth_reach), f.farthest = std::max(f.farthest, h.z / h.w + depth_reach);
    }
    for (double v : {f.reach.x, f.reach.y, f.vertex[0].x, f.vertex[0].y, f.vertex[1].x, f.vertex[1].y, f.vertex[2].x,
                     f.vertex[2].y, f.nearest, f.farthest}) {
        if (!std::isfinite(v)) return std::nullopt;
    }
    return f;
}

BlockCoverage::BlockCoverage(int width, int height, int top, int bottom)
    : width_(width), height_(height), top_(top), bottom_(bottom), columns_((width + kBlock - 1) / kBlock),
      rows_((bottom - top + kBlock - 1) / kBlock), blocks_(std::size_t(columns_) * std::size_t(rows_), Block{Rays::Miss, {}}) {}

std::uint64_t BlockCoverage::bytes(int width, int rows) {
    return std::uint64_t((width + kBlock - 1) / kBlock) * std::uint64_t((rows + kBlock - 1) / kBlock + 1) * sizeof(Block);
}

void BlockCoverage::cover(const TriangleFootprint& f) {
    // Window coordinates, y down the framebuffer's top-down rows: pixel (column, row) has its
    // centre at (column + 0.5, row + 0.5). One pixel of margin for the rounding of the rays' own
    // NDC and of this arithmetic.
    constexpr double kMargin = 1.0;
    auto window = [&](glm::dvec2 ndc) {
        return glm::dvec2((ndc.x + 1.0) * 0.5 * width_, height_ - (ndc.y + 1.0) * 0.5 * height_);
    };
    const glm::dvec2 v[3] = {window(f.vertex[0]), window(f.vertex[1]), window(f.vertex[2])};
    const glm::dvec2 grow = f.reach * (0.5 * glm::dvec2(width_, height_)) + kMargin;
    const glm::dvec2 corner0 = glm::min(glm::min(v[0], v[1]), v[2]) - grow, corner1 = glm::max(glm::max(v[0], v[1]), v[2]) + grow;
    // The blocks [first, last] holding pixel centres in [lo, hi] on an axis whose blocks start
    // at pixel `start`; false where none of the `count` blocks does.
    auto blocks = [](double lo, double hi, int start, int count, int& first, int& last) {
        const double a = std::floor((lo - 0.5 - start) / kBlock), b = std::floor((hi - 0.5 - start) / kBlock);
        if (!(b >= 0.0) || !(a < count)) return false;
        first = a < 0.0 ? 0 : int(a), last = b >= count ? count - 1 : int(b);
        return true;
    };
    int c0, c1, r0, r1;
    if (!blocks(corner0.x, corner1.x, 0, columns_, c0, c1) || !blocks(corner0.y, corner1.y, top_, rows_, r0, r1)) return;
    // Marks a block this footprint reaches: sure to hit this triangle while no other reaches it.
    auto mark = [&](int column, int row, bool sure) {
        Block& b = block(column, row);
        b = b.rays == Rays::Miss && sure ? Block{Rays::HitOne, f.id} : Block{Rays::Traced, {}};
    };
    // The projected triangle's edges as e(p) = n . p + d, positive inside; a block is out when
    // the rectangle of its pixel centres, grown as the triangle is, lies wholly outside one edge.
    // A triangle seen edge-on keeps its rectangle.
    const double area = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x);
    const double scale = glm::length(v[1] - v[0]) * glm::length(v[2] - v[0]);
    // Triangles of up to 2x2 blocks keep their rectangle too: their edges would spare few of its
    // blocks, at the cost of testing them all.
    const bool edges = std::abs(area) > 1e-6 * scale && (c1 - c0 + 1) * (r1 - r0 + 1) > 4;
    if (!edges) {
        for (int row = r0; row <= r1; ++row) {
            for (int column = c0; column <= c1; ++column) mark(column, row, false);
        }
        return;
    }
    struct Edge {
        glm::dvec2 n;
        double d;
    };
    Edge e[3] = {};
    for (int i = 0; i < 3; ++i) {
        const glm::dvec2 from = v[i], to = v[(i + 1) % 3];
        const double sign = area > 0.0 ? 1.0 : -1.0;
        e[i].n = sign * glm::dvec2(from.y - to.y, to.x - from.x);
        e[i].d = -glm::dot(e[i].n, from);
    }
    // A block's rays are sure to meet the triangle where the rectangle of its pixel centres,
    // grown as the triangle is, lies wholly inside every edge, and the triangle between the
    // near and far planes (Embree's t in [0, 1]; t = (1 + NDC depth) / 2 along these rays) with
    // some room for the rounding of Embree's t.
    constexpr double kDepthMargin = 0x1p-10;
    const bool between = f.nearest > -1.0 + kDepthMargin && f.farthest < 1.0 - kDepthMargin;
    const glm::dvec2 half = 0.5 * double(kBlock - 1) + grow;
    for (int row = r0; row <= r1; ++row) {
        for (int column = c0; column <= c1; ++column) {
            const glm::dvec2 centre(column * kBlock + 0.5 * kBlock, top_ + row * kBlock + 0.5 * kBlock);
            bool touches = true, inside = between;
            for (int i = 0; i < 3 && touches; ++i) {
                const double middle = glm::dot(e[i].n, centre) + e[i].d;
                const double spread = std::abs(e[i].n.x) * half.x + std::abs(e[i].n.y) * half.y;
                touches = middle + spread >= 0.0, inside = inside && middle - spread > 0.0;
            }
            if (touches) mark(column, row, inside);
        }
    }
}

ScreenFootprint::ScreenFootprint(const glm::dmat4& clip_from_world, const glm::dmat4& world_from_clip)
    : clip_from_world_(clip_from_world) {
    // The rays leave the near plane inside the world image of its NDC square, whose corners
    // hold its largest coordinates.
    for (int corner = 0; corner < 4; ++corner) {
        const glm::dvec4 h = world_from_clip * glm::dvec4(corner & 1 ? 1.0 : -1.0, corner & 2 ? 1.0 : -1.0, -1.0, 1.0);
        const glm::dvec3 p = glm::dvec3(h) / h.w;
        for (int c = 0; c < 3; ++c) origin_extent_ = std::max(origin_extent_, std::abs(p[c]));
        if (!(h.w > 0.0) || !std::isfinite(origin_extent_)) everywhere_ = true;
    }
}

void ScreenFootprint::add(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, TriangleId id) {
    if (everywhere_) return;
    double extent = 0.0;
    for (const glm::dvec3& p : {a, b, c}) extent = std::max({extent, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    // Embree holds the vertices and the rays in float (each off by up to a relative 2^-24) and
    // intersects in float, a few roundings more, all bounded by the largest coordinate in play;
    // 2^-18 of it leaves room to spare.
    const std::optional<TriangleFootprint> f = footprint(clip_from_world_, a, b, c, 0x1p-18 * (origin_extent_ + extent));
    if (!f) {
        everywhere_ = true, triangles_.clear();
        return;
    }
    triangles_.push_back(*f);
    triangles_.back().id = id;
}

const BlockCoverage& ScreenFootprint::blocks(int width, int height, int top, int bottom) {
    if (!coverage_ || coverage_->width() != width || coverage_->height() != height || coverage_->top() != top ||
        coverage_->bottom() != bottom) {
        coverage_.emplace(width, height, top, bottom);
        if (everywhere_) coverage_->cover_all();
        for (const TriangleFootprint& f : triangles_) coverage_->cover(f);
    }
    return *coverage_;
}

}  // namespace qs
