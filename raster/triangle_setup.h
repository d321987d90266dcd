#pragma once
// A clipped triangle prepared for rasterization: viewport transform, fixed-point edge functions,
// its pixel bounding box, and the plane equations of depth, 1/w and every varying (premultiplied
// by 1/w for perspective correction, divided by the interpolated 1/w per fragment).

#include <array>
#include <cstdint>
#include <optional>

#include "core/draw_call.h"
#include "raster/clipper.h"
#include "raster/edge_function.h"
#include "raster/plane_equation.h"

namespace qs {

struct TriangleSetup {
    std::array<EdgeFunction, 3> edges;
    // The snapped vertices (fixed point, pixel centres on multiples of fixed::kOne), in edge
    // order: edge k runs from corner k to corner k + 1, the interior on its positive side.
    std::array<std::int64_t, 3> corner_x, corner_y;
    int min_x, min_y, max_x, max_y;  // inclusive pixel bounds, clamped to the framebuffer
    PlaneEquation z;                 // window depth, linear in screen space
    PlaneEquation inv_w;             // 1/w_clip, linear in screen space
    std::array<PlaneEquation, kMaxVaryings> varyings;  // varying / w_clip (noperspective: varying)
    int draw = 0;                    // index of the draw call it came from
    bool front = true;               // counter-clockwise in GL's window: gl_FrontFacing
};

// From the vertices' window coordinates (ClipVertex::window: framebuffer pixels, y down as
// OSMesa's buffer, depth, 1/w), snapped to fixed point for the edges. Returns nothing for a
// triangle that covers no pixel centre of the framebuffer, has zero area, or that `culling`
// drops by its winding on the snapped vertices (the sign llvmpipe's setup culls by). Flat
// varyings (bits of `flat`) take the value of `provoking`, the last vertex of the triangle before
// clipping, in the plane's a0; noperspective ones (bits of `noperspective`) are planes of their
// values, not divided by w.
std::optional<TriangleSetup> setup_triangle(const std::array<ClipVertex, 3>& tri, int varying_count, int width,
                                            int height, FillRule fill_rule, unsigned flat,
                                            const ClipVertex& provoking, FaceCulling culling = {},
                                            unsigned noperspective = 0);

}  // namespace qs
