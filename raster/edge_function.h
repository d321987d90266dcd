#pragma once
// Integer edge functions with llvmpipe's fill rule, in framebuffer coordinates (y down).
//
// For an edge a -> b of a triangle whose interior is on the positive side,
//     E(p) = (b.x - a.x) (p.y - a.y) - (b.y - a.y) (p.x - a.x),
// and a pixel centre p is covered when E(p) > 0 for all three edges, or E(p) == 0 on an edge the
// rule includes: a left edge (interior to its right: dE/dx > 0) or a bottom edge (horizontal,
// interior above it on screen: dE/dx == 0, dE/dy < 0 with y down). That is "left and bottom" in
// GL's window coordinates too, which is what llvmpipe does in OSMesa's buffer (measured with a
// rectangle whose edges pass through pixel centres; softpipe takes right and top instead, which
// FillRule::RightTop reproduces).
// Shared edges are covered exactly once.

#include <algorithm>
#include <cstdint>

namespace qs {

// Which edges own the pixel centres that lie exactly on them (GL window coordinates).
enum class FillRule {
    LeftBottom,  // llvmpipe (default)
    RightTop,    // softpipe
};

struct EdgeFunction {
    std::int64_t c = 0;     // E at pixel (0, 0), plus the fill-rule bias (E + bias > 0 inside)
    std::int64_t dcdx = 0;  // change per pixel step in x
    std::int64_t dcdy = 0;  // change per pixel step in y (down)

    // a, b: fixed-point vertex positions (pixel centres on multiples of fixed::kOne).
    static EdgeFunction from_edge(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by,
                                  int subpixel_bits, FillRule rule) {
        EdgeFunction e;
        const std::int64_t dx = bx - ax, dy = by - ay;
        const std::int64_t dEdx = -dy, dEdy = dx;
        const bool left_or_bottom = dEdx > 0 || (dEdx == 0 && dEdy < 0);
        const bool right_or_top = dEdx < 0 || (dEdx == 0 && dEdy > 0);
        const bool included = rule == FillRule::LeftBottom ? left_or_bottom : right_or_top;
        // E(0, 0) = dx * (0 - ay) - dy * (0 - ax)
        e.c = dx * (-ay) - dy * (-ax) + (included ? 1 : 0);
        e.dcdx = dEdx << subpixel_bits;
        e.dcdy = dEdy << subpixel_bits;
        return e;
    }

    std::int64_t at(int x, int y) const { return c + dcdx * x + dcdy * y; }
    bool inside(int x, int y) const { return at(x, y) > 0; }

    // The smallest and largest of at(x + i, y + j) - at(x, y) over an n x n square of pixels
    // (0 <= i, j < n): E is linear, so they lie at the corners its gradient points away from
    // and towards.
    std::int64_t least_offset(int n) const {
        return std::min<std::int64_t>(dcdx * (n - 1), 0) + std::min<std::int64_t>(dcdy * (n - 1), 0);
    }
    std::int64_t most_offset(int n) const {
        return std::max<std::int64_t>(dcdx * (n - 1), 0) + std::max<std::int64_t>(dcdy * (n - 1), 0);
    }
};

}  // namespace qs
