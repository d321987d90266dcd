#pragma once
// Homogeneous clipping of a triangle against the view volume and the enabled user clip planes,
// and the viewport transform, in
// the order of operations and with the arithmetic of Mesa's draw module (draw_pipe_clip.c, which
// both llvmpipe and softpipe run; Mesa 22.3), so that clipped triangles reach setup with the
// reference's bits: its positions, its window coordinates and its varyings.
//
//  - Planes, and their order: x <= w, x >= -w, y <= w, y >= -w, near z >= -w, far z <= w, then
//    the user planes (GL_CLIP_PLANEi, gl_ClipDistance[i] >= 0) from the first. A
//    triangle with every vertex inside all six passes unchanged; one with all vertices outside
//    one plane is dropped; otherwise only the planes some vertex is outside of are clipped, in
//    that order (a vertex made by an earlier plane that rounds a hair outside a later one that
//    was not in the set stays). No guard band: llvmpipe has none with a depth buffer.
//  - A crossing edge's new vertex is interpolated from the endpoint nearer the plane (the inside
//    one on a tie), t = d_from / (d_from - d_to), each of clip x, y, z, w and every varying as
//    from + t (to - from) (noperspective varyings with the t of the window position instead, as
//    Mesa's interp computes it); its window coordinates are then computed from its clip position, in
//    float without fused multiply-adds (Mesa's C, built for baseline x86-64). The choice depends
//    on the two distances only, so an edge two triangles share is cut at the same point in both.
//  - The polygon is fanned as (p[i-1], p[i], p[0]): the original first vertex last.
// The original vertices' window coordinates come from the vertex stage (Viewport::window, fused
// on FMA hosts as the draw module's LLVM code). Triangles with a coordinate or plane distance
// that is not finite are dropped whole.

#include <array>
#include <vector>

#include <glm/vec4.hpp>

#include "shading/batches.h"
#include "shading/shader_info.h"

namespace qs {

// GL's viewport transform for a width x height framebuffer, in framebuffer orientation (y down,
// as OSMesa's buffer): x = ndc.x W/2 + W/2, y = ndc.y (-H/2) + H/2, z = ndc.z / 2 + 1/2.
struct Viewport {
    float scale[3], translate[3];
    Viewport(int width, int height);
    // (x, y, z, 1/w) in window coordinates: ndc = clip * (1/w), then ndc * scale + translate, as
    // one fused multiply-add when `fused` (the draw module's llvm.fmuladd on an FMA host).
    glm::vec4 window(const glm::vec4& clip, bool fused) const;
};

struct ClipVertex {
    glm::vec4 clip;
    glm::vec4 window;  // Viewport::window of clip
    std::array<float, kMaxVaryings> varyings;
    std::array<float, kMaxClipDistances> clip_distances{};  // VertexOut's
};

// How a draw's triangles are clipped beyond the view volume.
struct ClipState {
    unsigned user_planes = 0;    // bit i: clip at clip_distances[i] >= 0 (DrawCall::clip_distances)
    unsigned noperspective = 0;  // bit v: varying v is interpolated in the window (Needs)
};

// Appends the clipped polygon's triangles to `out`. Returns false when nothing is left.
bool clip_triangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, int varying_count,
                   const Viewport& viewport, std::vector<std::array<ClipVertex, 3>>& out, ClipState state = {});

}  // namespace qs
