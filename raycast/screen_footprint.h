#pragma once
// Where on the screen the scene's triangles may be seen, so that the ray caster writes the clear
// colour into blocks that no ray can hit without tracing them (Figure 1.1's sky: about a
// quarter of its blocks, whose rays took about 6% of a frame's time in Embree).
//
// A triangle's footprint is its projection grown by the rounding of what Embree traces: float
// vertices and float rays. Where Embree reports a hit, the exact ray through the pixel centre
// passes within that slack of the triangle, so the pixel centre lies in the footprint. A
// triangle that comes near the eye plane (w <= 0 within the slack) projects without bound: it
// covers the whole screen.

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace qs {

// A triangle's footprint in NDC: the triangle of its projected vertices, grown by `reach` on
// each axis.
struct TriangleFootprint {
    glm::dvec2 vertex[3];
    glm::dvec2 reach;
};

// The footprint of triangle a, b, c (world space) where each point may be off by up to `slack`
// on each axis, or none where that reaches the eye plane.
std::optional<TriangleFootprint> footprint(const glm::dmat4& clip_from_world, const glm::dvec3& a,
                                           const glm::dvec3& b, const glm::dvec3& c, double slack);

// The 4x4 blocks of one frame (core/block_layout.h) that some triangle may cover.
class BlockMask {
public:
    // The blocks of framebuffer rows [top, bottom) of a width x height frame, whose block rows
    // start at `top` (a tile's top: TileGrid::y0), none covered.
    BlockMask(int width, int height, int top, int bottom);
    void cover_all() { std::fill(covered_.begin(), covered_.end(), std::uint8_t(1)); }
    // Covers the blocks with a pixel centre that may lie in `f`.
    void cover(const TriangleFootprint& f);
    int width() const { return width_; }
    int height() const { return height_; }
    int top() const { return top_; }
    int bottom() const { return bottom_; }
    // Whether the block whose top-left pixel is (bx, by) in framebuffer coordinates is covered.
    bool covered(int bx, int by) const {
        return covered_[std::size_t((by - top_) / 4) * std::size_t(columns_) + std::size_t(bx / 4)] != 0;
    }

private:
    int width_, height_, top_, bottom_, columns_, rows_;
    std::vector<std::uint8_t> covered_;  // per block, row by row
};

// The footprints of a scene's triangles seen by one camera.
class ScreenFootprint {
public:
    ScreenFootprint(const glm::dmat4& clip_from_world, const glm::dmat4& world_from_clip);
    // Adds the triangle with world vertices a, b, c (finite), as Embree holds it in float.
    void add(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);
    // The blocks of rows [top, bottom) of a width x height frame (BlockMask) that the triangles
    // may cover; kept for the next frame of the same rows.
    const BlockMask& blocks(int width, int height, int top, int bottom);

private:
    glm::dmat4 clip_from_world_;
    double origin_extent_ = 0.0;  // the largest coordinate (in magnitude) of a ray's origin
    std::vector<TriangleFootprint> triangles_;
    bool everywhere_ = false;
    std::optional<BlockMask> mask_;
};

}  // namespace qs
