#include "raster/depth_buffer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

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

// Whether two triangles' pixel bounding boxes meet: where they do not, no pixel is shared.
bool boxes_meet(const TriangleSetup& a, const TriangleSetup& b) {
    return std::max(a.min_x, b.min_x) <= std::min(a.max_x, b.max_x) && std::max(a.min_y, b.min_y) <= std::min(a.max_y, b.max_y);
}

}  // namespace

bool interiors_overlap(const TriangleSetup& a, const TriangleSetup& b) {
    return !separated_by_an_edge_of(a, b) && !separated_by_an_edge_of(b, a);
}

bool may_reach_depth_one(const TriangleSetup& t) {
    const PlaneEquation& z = t.z;
    double largest = -HUGE_VAL;
    for (const int x : {t.min_x, t.max_x}) {
        for (const int y : {t.min_y, t.max_y}) {
            largest = std::max(largest, double(z.a0) + double(z.dadx) * x + double(z.dady) * y);
        }
    }
    // The rasterizer evaluates the plane in float, fused or not: two roundings, each within 2^-24
    // of a partial sum no larger in magnitude than `scale`.
    const double scale = std::abs(double(z.a0)) + std::abs(double(z.dadx)) * std::max(std::abs(t.min_x), std::abs(t.max_x)) +
                         std::abs(double(z.dady)) * std::max(std::abs(t.min_y), std::abs(t.max_y));
    return !(largest + 0x1p-22 * scale < 1.0);  // also true for a NaN plane
}

bool depth_buffer_matters(std::span<const TriangleSetup> triangles, int width, int height) {
    if (triangles.size() > kMaxTrianglesTested) return true;
    for (const TriangleSetup& t : triangles) {
        if (may_reach_depth_one(t)) return true;
    }
    // A few triangles (a quad, a handful of them): every pair, without building a grid.
    constexpr std::size_t kEveryPair = 16;
    if (triangles.size() <= kEveryPair) {
        for (std::size_t i = 0; i < triangles.size(); ++i) {
            for (std::size_t j = i + 1; j < triangles.size(); ++j) {
                if (boxes_meet(triangles[i], triangles[j]) && interiors_overlap(triangles[i], triangles[j])) return true;
            }
        }
        return false;
    }
    // Each triangle in the grid cells its pixel bounding box meets; only triangles sharing a
    // cell can share a pixel.
    constexpr int kCell = 64;
    const int cells_x = (width + kCell - 1) / kCell, cells_y = (height + kCell - 1) / kCell;
    std::vector<std::vector<std::uint32_t>> cells(std::size_t(cells_x) * std::size_t(cells_y));
    for (std::uint32_t i = 0; i < triangles.size(); ++i) {
        const TriangleSetup& t = triangles[i];
        for (int cy = t.min_y / kCell; cy <= t.max_y / kCell; ++cy) {
            for (int cx = t.min_x / kCell; cx <= t.max_x / kCell; ++cx) {
                cells[std::size_t(cy) * std::size_t(cells_x) + std::size_t(cx)].push_back(i);
            }
        }
    }
    // A pair is tested once, in the cell that holds the top-left pixel of where their boxes meet.
    std::size_t budget = (std::size_t(1) << 16) + 16 * triangles.size();
    for (int cy = 0; cy < cells_y; ++cy) {
        for (int cx = 0; cx < cells_x; ++cx) {
            const std::vector<std::uint32_t>& in = cells[std::size_t(cy) * std::size_t(cells_x) + std::size_t(cx)];
            for (std::size_t i = 0; i < in.size(); ++i) {
                const TriangleSetup& a = triangles[in[i]];
                for (std::size_t j = i + 1; j < in.size(); ++j) {
                    if (budget-- == 0) return true;
                    const TriangleSetup& b = triangles[in[j]];
                    const int x0 = std::max(a.min_x, b.min_x), x1 = std::min(a.max_x, b.max_x);
                    const int y0 = std::max(a.min_y, b.min_y), y1 = std::min(a.max_y, b.max_y);
                    if (x0 > x1 || y0 > y1 || x0 / kCell != cx || y0 / kCell != cy) continue;
                    if (interiors_overlap(a, b)) return true;
                }
            }
        }
    }
    return false;
}

}  // namespace qs
