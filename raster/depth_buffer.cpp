#include "raster/depth_buffer.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <compare>
#include <cstdint>
#include <vector>

#include "raster/fixed_point.h"

namespace qs {

namespace {

// Edge k of t at the fixed-point point (px, py), without the fill rule's bias: positive inside.
// Clipped vertices lie in the viewport (below 2^24 in fixed point), so the products fit easily.
std::int64_t edge_at(const TriangleSetup& t, int k, std::int64_t px, std::int64_t py) {
    const std::size_t a = std::size_t(k), b = std::size_t((k + 1) % 3);
    return (t.corner_x[b] - t.corner_x[a]) * (py - t.corner_y[a]) - (t.corner_y[b] - t.corner_y[a]) * (px - t.corner_x[a]);
}

// Whether an edge line of `a` has every corner of `b` on it or outside.
bool separated_by_an_edge_of(const TriangleSetup& a, const TriangleSetup& b) {
    for (int k = 0; k < 3; ++k) {
        bool outside = true;
        for (std::size_t v = 0; v < 3; ++v) outside &= edge_at(a, k, b.corner_x[v], b.corner_y[v]) <= 0;
        if (outside) return true;
    }
    return false;
}

// Plane z at pixel (x, y), exactly (in double).
double exactly_at(const PlaneEquation& z, double x, double y) { return double(z.a0) + double(z.dadx) * x + double(z.dady) * y; }

// Plane z at corner k of t (the snapped corner in pixel units). A plane is affine, so over the
// triangle (which holds every pixel centre it covers) it is largest and least at corners.
double at_corner(const PlaneEquation& z, const TriangleSetup& t, std::size_t k) {
    return exactly_at(z, double(t.corner_x[k]) / double(fixed::kOne), double(t.corner_y[k]) / double(fixed::kOne));
}

// How far the rasterizer's float evaluation of plane z (FragmentInputs::at) may be from the exact
// value at pixels x0..x1, y0..y1: at most four roundings (two fused), each within 2^-24 of a
// product or partial sum no larger in magnitude than `scale`.
double evaluation_error(const PlaneEquation& z, int x0, int x1, int y0, int y1) {
    const double scale = std::abs(double(z.a0)) + std::abs(double(z.dadx)) * std::max(std::abs(x0), std::abs(x1)) +
                         std::abs(double(z.dady)) * std::max(std::abs(y0), std::abs(y1));
    return 0x1p-22 * scale;
}

// Whether two triangles' pixel bounding boxes meet: where they do not, no pixel is shared.
bool boxes_meet(const TriangleSetup& a, const TriangleSetup& b) {
    return std::max(a.min_x, b.min_x) <= std::min(a.max_x, b.max_x) && std::max(a.min_y, b.min_y) <= std::min(a.max_y, b.max_y);
}

}  // namespace

bool interiors_overlap(const TriangleSetup& a, const TriangleSetup& b) {
    return !separated_by_an_edge_of(a, b) && !separated_by_an_edge_of(b, a);
}

bool may_reach_depth_one(const TriangleSetup& t) {
    // The covered centres lie in the triangle and in its pixel box: the lesser of the plane's
    // largest values over either bounds them (the box's for a triangle with a corner just off
    // the centres, the triangle's for a sliver whose box the plane climbs across).
    double in_triangle = -HUGE_VAL, in_box = -HUGE_VAL;
    for (std::size_t k = 0; k < 3; ++k) in_triangle = std::max(in_triangle, at_corner(t.z, t, k));
    for (const int x : {t.min_x, t.max_x}) {
        for (const int y : {t.min_y, t.max_y}) in_box = std::max(in_box, exactly_at(t.z, x, y));
    }
    const double largest = std::min(in_triangle, in_box);
    return !(largest + evaluation_error(t.z, t.min_x, t.max_x, t.min_y, t.max_y) < 1.0);  // also true for a NaN plane
}

namespace {

// A snapped corner, and the directed edge between two.
struct Point {
    std::int64_t x, y;
    auto operator<=>(const Point&) const = default;
};
struct Segment {
    Point from, to;
};
constexpr std::uint64_t kEmpty = ~std::uint64_t(0);  // no corner's key

// Twice the signed area of (o, a, b). Corners below 2^30 in magnitude keep it within 64 bits.
std::int64_t cross(const Point& o, const Point& a, const Point& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Whether p, on the line through a and b, lies on the closed segment between them.
bool within(const Point& a, const Point& b, const Point& p) {
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

// Whether two closed segments share a point.
bool touch(const Segment& s, const Segment& t) {
    const std::int64_t d1 = cross(s.from, s.to, t.from), d2 = cross(s.from, s.to, t.to);
    const std::int64_t d3 = cross(t.from, t.to, s.from), d4 = cross(t.from, t.to, s.to);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
    return (d1 == 0 && within(s.from, s.to, t.from)) || (d2 == 0 && within(s.from, s.to, t.to)) ||
           (d3 == 0 && within(t.from, t.to, s.from)) || (d4 == 0 && within(t.from, t.to, s.to));
}

// The outline of triangles set up with their interiors on the positive side: each edge k -> k + 1
// of each triangle, less the edges two of them share in opposite directions. Empty where some edge
// is left twice in one direction (two triangles on the same side of it: they overlap) or a corner
// lies beyond 2^30.
std::vector<Segment> outline(std::span<const TriangleSetup> triangles) {
    // A corner as one number; an edge as its two corners' in increasing order, counting +1 for
    // each triangle that runs from the lesser to the greater and -1 for each that runs back, in an
    // open-addressed table (a sort of the edges took five times as long). A mesh's triangles
    // share most edges, so it is about half full.
    constexpr std::int64_t kRange = std::int64_t(1) << 30;
    const auto key = [](std::int64_t x, std::int64_t y) { return std::uint64_t(x + kRange) << 32 | std::uint64_t(y + kRange); };
    const auto corner = [](std::uint64_t k) { return Point{std::int64_t(k >> 32) - kRange, std::int64_t(k & 0xffffffffu) - kRange}; };
    struct Slot {
        std::uint64_t a = kEmpty, b = 0;
        int count = 0;
    };
    const int bits = std::bit_width(3 * triangles.size());  // a slot always free
    std::vector<Slot> table(std::size_t(1) << bits);
    const std::size_t mask = table.size() - 1;
    for (const TriangleSetup& t : triangles) {
        for (std::size_t k = 0; k < 3; ++k) {
            if (std::max(std::abs(t.corner_x[k]), std::abs(t.corner_y[k])) >= kRange) return {};
        }
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint64_t p = key(t.corner_x[k], t.corner_y[k]), q = key(t.corner_x[(k + 1) % 3], t.corner_y[(k + 1) % 3]);
            const std::uint64_t a = std::min(p, q), b = std::max(p, q);
            std::size_t at = std::size_t((a * 0x9E3779B97F4A7C15u) ^ (b * 0xC2B2AE3D27D4EB4Fu)) >> (64 - bits);
            while (table[at].a != kEmpty && (table[at].a != a || table[at].b != b)) at = (at + 1) & mask;
            table[at].a = a, table[at].b = b;
            table[at].count += p < q ? 1 : -1;
        }
    }
    std::vector<Segment> out;
    for (const Slot& s : table) {
        if (s.count == 0) continue;  // empty or cancelled (tested first: either is common)
        if (s.count != 1 && s.count != -1) return {};
        out.push_back(s.count > 0 ? Segment{corner(s.a), corner(s.b)} : Segment{corner(s.b), corner(s.a)});
    }
    return out;
}

// Whether the segments form one closed loop: every corner on them starts one and ends one, and
// following them from the first comes back to it through all of them.
bool one_loop(std::vector<Segment>& segments) {
    std::sort(segments.begin(), segments.end(), [](const Segment& s, const Segment& t) { return s.from < t.from; });
    std::vector<Point> ends;
    ends.reserve(segments.size());
    for (std::size_t i = 0; i < segments.size(); ++i) {
        if (i > 0 && segments[i].from == segments[i - 1].from) return false;
        ends.push_back(segments[i].to);
    }
    std::sort(ends.begin(), ends.end());
    if (std::adjacent_find(ends.begin(), ends.end()) != ends.end()) return false;
    std::size_t at = 0, steps = 0;
    do {
        const Point next = segments[at].to;
        const auto found = std::lower_bound(segments.begin(), segments.end(), next,
                                            [](const Segment& s, const Point& p) { return s.from < p; });
        if (found == segments.end() || found->from != next) return false;
        at = std::size_t(found - segments.begin());
        ++steps;
    } while (at != 0 && steps <= segments.size());
    return steps == segments.size();
}

// Whether no two segments of a loop share a point, but consecutive ones their common corner, and
// none turns straight back along the one before it. Segments are swept in order of their least x;
// false past kMaxOutlineTests pairs whose boxes meet.
bool simple(const std::vector<Segment>& loop) {
    std::vector<std::size_t> order(loop.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    auto min_x = [&](std::size_t i) { return std::min(loop[i].from.x, loop[i].to.x); };
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return min_x(a) < min_x(b); });
    std::size_t tests = 0;
    for (std::size_t i = 0; i < order.size(); ++i) {
        const Segment& s = loop[order[i]];
        const std::int64_t s_max_x = std::max(s.from.x, s.to.x);
        for (std::size_t j = i + 1; j < order.size() && min_x(order[j]) <= s_max_x; ++j) {
            const Segment& t = loop[order[j]];
            if (std::max(s.from.y, s.to.y) < std::min(t.from.y, t.to.y) || std::max(t.from.y, t.to.y) < std::min(s.from.y, s.to.y)) continue;
            if (++tests > kMaxOutlineTests) return false;
            const bool s_then_t = s.to == t.from, t_then_s = t.to == s.from;
            if (s_then_t || t_then_s) {
                const Segment& first = s_then_t ? s : t;
                const Segment& second = s_then_t ? t : s;
                const Point back{first.to.x - first.from.x, first.to.y - first.from.y};
                const Point ahead{second.to.x - second.from.x, second.to.y - second.from.y};
                const bool straight_back = cross(first.from, first.to, second.to) == 0 && back.x * ahead.x + back.y * ahead.y < 0;
                if (straight_back) return false;
            } else if (touch(s, t)) {
                return false;
            }
        }
    }
    return true;
}

}  // namespace

bool covers_each_centre_once(std::span<const TriangleSetup> triangles) {
    if (triangles.empty()) return true;
    std::vector<Segment> loop = outline(triangles);
    return loop.size() >= 3 && one_loop(loop) && simple(loop);
}

bool in_front(const TriangleSetup& later, const TriangleSetup& earlier) {
    const int x0 = std::max(later.min_x, earlier.min_x), x1 = std::min(later.max_x, earlier.max_x);
    const int y0 = std::max(later.min_y, earlier.min_y), y1 = std::min(later.max_y, earlier.max_y);
    if (x0 > x1 || y0 > y1) return true;  // no pixel in common
    // depth24 is within one step of z (2^24 - 1) for each (the float product and the rounding),
    // so depths more than two steps apart never tie: four steps of margin.
    constexpr double kSteps = 4.0 / double(kDepthCleared);
    const double later_error = evaluation_error(later.z, x0, x1, y0, y1);
    const double margin = later_error + evaluation_error(earlier.z, x0, x1, y0, y1) + kSteps;
    for (std::size_t k = 0; k < 3; ++k) {
        const double near = at_corner(later.z, later, k), far = at_corner(earlier.z, later, k);
        if (!(near >= later_error && far - near > margin)) return false;  // also for NaN
    }
    return true;
}

bool depth_buffer_matters(std::span<const TriangleSetup> triangles, int width, int height) {
    if (triangles.size() > kMaxTrianglesTested) return true;
    for (const TriangleSetup& t : triangles) {
        if (may_reach_depth_one(t)) return true;
    }
    // Runs of consecutive triangles of one draw, and whether each was proven to cover every pixel
    // centre once (a handful of triangles are left to the pair tests).
    constexpr std::size_t kEveryPair = 16;
    std::vector<std::uint32_t> run(triangles.size());
    std::vector<char> once;
    for (std::size_t begin = 0; begin < triangles.size();) {
        std::size_t end = begin + 1;
        while (end < triangles.size() && triangles[end].draw == triangles[begin].draw) ++end;
        std::fill(run.begin() + std::ptrdiff_t(begin), run.begin() + std::ptrdiff_t(end), std::uint32_t(once.size()));
        once.push_back(end - begin > kEveryPair && covers_each_centre_once(triangles.subspan(begin, end - begin)));
        begin = end;
    }
    // Triangle j, drawn after i, may change the frame where their interiors overlap and j is
    // not in front of i there.
    const auto conflict = [&](std::uint32_t i, std::uint32_t j) {
        return !in_front(triangles[j], triangles[i]) && interiors_overlap(triangles[i], triangles[j]);
    };
    // A few triangles (a quad, a handful of them): every pair, without building a grid.
    if (triangles.size() <= kEveryPair) {
        for (std::uint32_t i = 0; i < triangles.size(); ++i) {
            for (std::uint32_t j = i + 1; j < triangles.size(); ++j) {
                if (boxes_meet(triangles[i], triangles[j]) && conflict(i, j)) return true;
            }
        }
        return false;
    }
    // Each triangle in the grid cells its pixel bounding box meets, listed cell after cell (a
    // count, then the lists); only triangles sharing a cell can share a pixel.
    constexpr int kCell = 64;
    const int cells_x = (width + kCell - 1) / kCell, cells_y = (height + kCell - 1) / kCell;
    const auto for_cells = [&](const TriangleSetup& t, auto&& f) {
        for (int cy = t.min_y / kCell; cy <= t.max_y / kCell; ++cy) {
            for (int cx = t.min_x / kCell; cx <= t.max_x / kCell; ++cx) f(std::size_t(cy) * std::size_t(cells_x) + std::size_t(cx));
        }
    };
    std::vector<std::uint32_t> first(std::size_t(cells_x) * std::size_t(cells_y) + 1, 0);
    for (const TriangleSetup& t : triangles) for_cells(t, [&](std::size_t c) { ++first[c + 1]; });
    for (std::size_t c = 1; c < first.size(); ++c) first[c] += first[c - 1];
    std::vector<std::uint32_t> listed(first.back()), next(first.begin(), first.end() - 1);
    for (std::uint32_t i = 0; i < triangles.size(); ++i) for_cells(triangles[i], [&](std::size_t c) { listed[next[c]++] = i; });
    // A pair is tested once, in the cell that holds the top-left pixel of where their boxes meet.
    // A cell lists its triangles in order, so a proven run's are consecutive there and skipped
    // as a block.
    std::size_t budget = (std::size_t(1) << 16) + 16 * triangles.size();
    std::vector<std::size_t> run_end;
    for (int cy = 0; cy < cells_y; ++cy) {
        for (int cx = 0; cx < cells_x; ++cx) {
            const std::size_t c = std::size_t(cy) * std::size_t(cells_x) + std::size_t(cx);
            const std::span<const std::uint32_t> in(listed.data() + first[c], first[c + 1] - first[c]);
            run_end.resize(in.size());
            for (std::size_t k = in.size(); k-- > 0;) {
                run_end[k] = k + 1 < in.size() && run[in[k + 1]] == run[in[k]] ? run_end[k + 1] : k + 1;
            }
            for (std::size_t i = 0; i < in.size(); ++i) {
                const TriangleSetup& a = triangles[in[i]];
                for (std::size_t j = once[run[in[i]]] ? run_end[i] : i + 1; j < in.size(); ++j) {
                    if (budget-- == 0) return true;
                    const TriangleSetup& b = triangles[in[j]];
                    const int x0 = std::max(a.min_x, b.min_x), x1 = std::min(a.max_x, b.max_x);
                    const int y0 = std::max(a.min_y, b.min_y), y1 = std::min(a.max_y, b.max_y);
                    if (x0 > x1 || y0 > y1 || x0 / kCell != cx || y0 / kCell != cy) continue;
                    if (conflict(in[i], in[j])) return true;
                }
            }
        }
    }
    return false;
}

bool DepthBufferDecision::matters(std::span<const TriangleSetup> triangles, int width, int height) {
    now_.clear();
    for (const TriangleSetup& t : triangles) {
        now_.push_back({t.corner_x, t.corner_y, {t.min_x, t.min_y, t.max_x, t.max_y},
                        {std::bit_cast<std::uint32_t>(t.z.a0), std::bit_cast<std::uint32_t>(t.z.dadx), std::bit_cast<std::uint32_t>(t.z.dady)},
                        t.draw});
    }
    if (now_ != last_ || width != width_ || height != height_) {
        answer_ = depth_buffer_matters(triangles, width, height);
        std::swap(now_, last_);
        width_ = width, height_ = height;
    }
    return answer_;
}

}  // namespace qs
