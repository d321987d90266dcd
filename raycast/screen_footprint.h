#pragma once
// Where on the screen the scene's triangles may be seen, so that the ray caster writes the clear
// colour into blocks that no ray can hit without tracing them (Figure 1.1's sky: a quarter of
// its blocks), and knows without tracing what the rays of a block that lies well inside the only
// triangle seen there hit (most of Figure 1.1's ground).
//
// A triangle's footprint is its projection grown by the rounding of what Embree traces: float
// vertices and float rays. Where Embree reports a hit, the exact ray through the pixel centre
// passes within that slack of the triangle, so the pixel centre lies in the footprint. The same
// bound read the other way: where the exact ray passes through the triangle farther than the
// slack from its edges, between the near and far planes by more than the slack, Embree's float
// ray meets Embree's float triangle. A triangle that comes near the eye plane (w <= 0 within the
// slack) projects without bound: it covers the whole screen.

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace qs {

// A triangle as Embree names it: its mesh (geometry) and its index there (primitive).
struct TriangleId {
    std::uint32_t geometry, primitive;
};

// A triangle's footprint in NDC: the triangle of its projected vertices, grown by `reach` on
// each axis, and the NDC depths its points may take, each off by as much.
struct TriangleFootprint {
    glm::dvec2 vertex[3];
    glm::dvec2 reach;
    double nearest, farthest;
    TriangleId id;
};

// The footprint of triangle a, b, c (world space) where each point may be off by up to `slack`
// on each axis, or none where that reaches the eye plane.
std::optional<TriangleFootprint> footprint(const glm::dmat4& clip_from_world, const glm::dvec3& a,
                                           const glm::dvec3& b, const glm::dvec3& c, double slack);

// Which triangles the rays through the pixel centres of each 4x4 block of one frame
// (core/block_layout.h) may hit.
class BlockCoverage {
public:
    // The blocks of framebuffer rows [top, bottom) of a width x height frame, whose block rows
    // start at `top` (a tile's top: TileGrid::y0), none covered.
    BlockCoverage(int width, int height, int top, int bottom);
    // What the blocks of `rows` framebuffer rows of a frame `width` wide take (one block row more:
    // a band's top may fall inside a block row).
    static std::uint64_t bytes(int width, int rows);
    void cover_all() { std::fill(blocks_.begin(), blocks_.end(), Block{Rays::Traced, {}}); }
    // Covers the blocks with a pixel centre that may lie in `f`.
    void cover(const TriangleFootprint& f);
    int width() const { return width_; }
    int height() const { return height_; }
    int top() const { return top_; }
    int bottom() const { return bottom_; }
    // Whether some triangle may be hit in the block whose top-left pixel is (bx, by) in
    // framebuffer coordinates.
    bool covered(int bx, int by) const { return at(bx, by).rays != Rays::Miss; }
    // The triangle that every ray of that block hits, where one is sure to: the only one whose
    // footprint reaches the block, which holds all sixteen pixel centres well inside it.
    const TriangleId* only(int bx, int by) const {
        const Block& b = at(bx, by);
        return b.rays == Rays::HitOne ? &b.triangle : nullptr;
    }

private:
    enum class Rays : std::uint8_t {
        Miss,    // no footprint reaches the block
        HitOne,  // every ray hits `triangle`
        Traced,  // Embree decides
    };
    struct Block {
        Rays rays;
        TriangleId triangle;
    };
    // The block in block column `column` and block row `row`.
    const Block& block(int column, int row) const {
        return blocks_[std::size_t(row) * std::size_t(columns_) + std::size_t(column)];
    }
    Block& block(int column, int row) { return blocks_[std::size_t(row) * std::size_t(columns_) + std::size_t(column)]; }
    const Block& at(int bx, int by) const { return block(bx / 4, (by - top_) / 4); }

    int width_, height_, top_, bottom_, columns_, rows_;
    std::vector<Block> blocks_;  // row by row
};

// The footprints of a scene's triangles seen by one camera.
class ScreenFootprint {
public:
    ScreenFootprint(const glm::dmat4& clip_from_world, const glm::dmat4& world_from_clip);
    // Adds Embree's triangle `id`, with world vertices a, b, c (finite), as Embree holds it in
    // float.
    void add(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, TriangleId id);
    // The blocks of rows [top, bottom) of a width x height frame and what their rays may hit;
    // kept for the next frame of the same rows.
    const BlockCoverage& blocks(int width, int height, int top, int bottom);

private:
    glm::dmat4 clip_from_world_;
    double origin_extent_ = 0.0;  // the largest coordinate (in magnitude) of a ray's origin
    std::vector<TriangleFootprint> triangles_;
    bool everywhere_ = false;
    std::optional<BlockCoverage> coverage_;
};

}  // namespace qs
