#pragma once
// The depth buffer: what it holds, and whether a frame needs one, decided from the set-up
// triangles, not the shaders.
//
// GL tests every fragment against the depth buffer (LESS, cleared to 1; quadshade's reference
// always does). Drawn without it, in submission order, every fragment overwrites the pixel; that
// is the same image exactly when every fragment would pass the test. So the depth buffer may be
// left out when
//  - no fragment's window depth can reach 1 (LESS against the cleared 1 drops it), and
//  - wherever two triangles cover the same pixel centre, the later one is nearer there by more
//    than the 24-bit buffer could tie (the painter's order). Triangles whose interiors are
//    disjoint cover no centre twice; a large run of one draw's triangles is proven to cover each
//    centre at most once as a whole (a convex mesh with its back faces culled: Figure 1.1's
//    spheres), so that only pairs from different runs, or from runs not so proven, are tested.
// Everything is tested exactly or conservatively on the numbers the rasterizer uses; anything not
// proven keeps the depth buffer. The ray caster needs none: it shades the closest hit.

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include "core/lanes16.h"
#include "raster/triangle_setup.h"

namespace qs {

// A window depth as the reference's 24-bit depth buffer stores it (OSMesa, 24 depth bits, as
// llvmpipe converts: lp_build_clamped_float_to_unsigned_norm): clamped to [0, 1] (NaN to 0, as
// llvmpipe's max and min drop it), scaled by 2^24 - 1 in float and rounded to nearest even. The
// integer is exact in a float. Depths closer than 2^-24 compare equal, so the first drawn stays.
inline constexpr float kDepthCleared = 16777215.0f;  // the clear value 1
inline float depth24(float z) {
    // max(z, 0) then min(.., 1) as maxss and minss take them (NaN goes to 0), written as
    // comparisons: std::fmax and std::fmin were calls into libm.
    const float above = z > 0.0f ? z : 0.0f;
    return std::nearbyint((above < 1.0f ? above : 1.0f) * kDepthCleared);
}

// depth24 on every lane of a batch, to the bit (always inlined, as core/lanes16.h says why).
[[gnu::always_inline]] inline lanes16::Floats depth24(const lanes16::Floats& z) {
    // max(z, 0) takes 0 where z is NaN (its second operand), as maxss; rounding to nearest even is
    // std::nearbyint in the rounding mode shading threads keep.
    // A register at a time (one on AVX-512: as two halves, they met again through memory, a load
    // spanning two stores waits for both to be written, a stall on every block's depth test).
    return simd::by_pieces<lanes16::Floats>(
        [](const auto& part) [[gnu::always_inline]] {
            using Part = std::remove_cvref_t<decltype(part)>;
            const Part above = simd::extremum_or_second<simd::Extremum::Max>(part, Part{});
            const Part clamped = simd::extremum_or_second<simd::Extremum::Min>(above, simd::splat<Part>(1.0f));
            return simd::round<simd::Rounding::NearestEven>(clamped * simd::splat<Part>(kDepthCleared));
        },
        z);
}

// Whether the open interiors of two set-up triangles intersect, exactly, on their snapped
// fixed-point vertices. When they do not, no pixel centre is covered by both, under either fill
// rule: coverage is E + bias > 0 per edge (edge_function.h), which is the same as the pixel
// centre moved by an infinitesimal (e, -e^2) (left-bottom; (-e, e^2) for right-top) lying
// strictly inside, so a centre covered by both would be a point inside both. Shared edges,
// shared vertices and T-junctions therefore never count as overlap. Two convex polygons have
// disjoint interiors exactly when an edge line of one has every vertex of the other on or
// outside it (the edges of their Minkowski difference are theirs).
bool interiors_overlap(const TriangleSetup& a, const TriangleSetup& b);

// Whether a fragment of t may have window depth >= 1: its depth plane's largest value over the
// pixel centres it may cover (bounded by the plane at its snapped corners and at its pixel
// bounding box's), with a margin for the float evaluation, is not below 1.
bool may_reach_depth_one(const TriangleSetup& t);

// Whether the triangles, all set up with their interiors on the positive side of their edges,
// cover every pixel centre at most once, proven on their snapped corners; false where not
// proven. Each triangle's coverage is the winding number of its boundary around the pixel centre
// moved by the fill rule's infinitesimal step, so the number of triangles covering a centre is
// the winding number of the sum of their boundaries; edges two triangles share in opposite
// directions cancel from it. What remains must be one simple closed polygon (every corner on it
// starts one edge and ends one, no two edges touch but consecutive ones at their common corner),
// around which no point winds more than once. Bounded: false past kMaxOutlineTests tests of
// edge pairs.
bool covers_each_centre_once(std::span<const TriangleSetup> triangles);

// Whether, at every pixel centre `later` covers, `later`'s depth is below `earlier`'s plane by more
// than the rounding of both planes' float evaluation and of the 24-bit conversion could make up,
// with `later`'s depth at least 0 there: a fragment of `later` then passes LESS against one of
// `earlier` drawn before it. Both depths are affine in the pixel, so their difference is least at
// a corner of `later`; the evaluation error is bounded over the pixels the two boxes share.
bool in_front(const TriangleSetup& later, const TriangleSetup& earlier);

// Whether a depth buffer could change the frame these triangles draw, in this (submission) order.
// False only when proven (above); true as well when the proof would cost too much: more than
// kMaxTrianglesTested triangles, or more tested pairs than a budget linear in their number. Pairs
// are only those whose pixel bounding boxes meet: all of them for a handful of triangles,
// otherwise found through a grid of 64-pixel cells, each pair tested once; pairs within a run of
// one draw proven by covers_each_centre_once are not tested.
bool depth_buffer_matters(std::span<const TriangleSetup> triangles, int width, int height);

// depth_buffer_matters, remembering its last answer: a frame that sets up the same triangles as
// the last (an animation whose geometry stands still, a benchmark's loop) gets it without the
// proof, which is about a twentieth of a two-thread Figure 1.1 frame and all of it serial.
// "The same" is everything the proof reads, compared exactly.
class DepthBufferDecision {
public:
    bool matters(std::span<const TriangleSetup> triangles, int width, int height);

private:
    struct Read {  // what depth_buffer_matters reads of a triangle
        std::array<std::int64_t, 3> corner_x, corner_y;
        std::array<int, 4> box;
        std::array<std::uint32_t, 3> z;  // the depth plane's bits
        int draw;
        bool operator==(const Read&) const = default;
    };
    std::vector<Read> last_, now_;
    int width_ = 0, height_ = 0;
    bool answer_ = true;
};

inline constexpr std::size_t kMaxTrianglesTested = std::size_t(1) << 16;
inline constexpr std::size_t kMaxOutlineTests = std::size_t(1) << 16;

}  // namespace qs
