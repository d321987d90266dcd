#pragma once
// Homogeneous clipping of a triangle against the near and far planes and the guard band.
//
// GL clips to the view volume; like llvmpipe, quadshade only clips x and y at a guard band far
// outside the viewport (fixed::kGuardBand pixels), so ordinary triangles reach the rasterizer
// untouched and exact, while huge ones cannot overflow the fixed-point edge functions. Near and
// far are always clipped (no depth clamp), which also removes everything at or behind the eye.
// New vertices interpolate clip position and varyings linearly in clip space, which is correct
// under perspective.

#include <array>
#include <vector>

#include <glm/vec4.hpp>

#include "shading/program.h"

namespace qs {

struct ClipVertex {
    glm::vec4 clip;
    std::array<float, kMaxVaryings> varyings;
};

// Appends the clipped polygon's triangles (a fan) to `out`. Returns false when nothing is left.
// Triangles with a non-finite coordinate are dropped whole.
bool clip_triangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, int varying_count,
                   float guard_x, float guard_y, std::vector<std::array<ClipVertex, 3>>& out);

}  // namespace qs
