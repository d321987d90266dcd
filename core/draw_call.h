#pragma once
// What the rasterizer draws: triangles of one mesh, one program, one set of uniforms.

#include <cstdint>
#include <span>

#include "shading/program.h"

namespace qs {

// Which way a triangle's vertices turn in GL's window (y up), as glFrontFace names it.
enum class Winding { CounterClockwise, Clockwise };

// Which triangles a draw keeps, as GL's GL_CULL_FACE with glCullFace(GL_BACK) and glFrontFace:
// with `cull_back`, only those that wind as `front` in the window. The facing is the visible
// part's, after clipping, so a triangle crossing the near plane is judged by what is drawn of it.
struct FaceCulling {
    bool cull_back = false;
    Winding front = Winding::CounterClockwise;
    bool keeps(Winding w) const { return !cull_back || w == front; }
    bool operator==(const FaceCulling&) const = default;
};

struct DrawCall {
    std::span<const VertexIn> vertices;
    std::span<const std::uint32_t> indices;  // three per triangle
    const Program* program = nullptr;
    Uniforms uniforms;
    // The bound texture picks a mipmap level or a filter from the level of detail: shade in quads
    // even if the shader takes no derivatives of its own, as a GL driver does for texture2D.
    bool texture_lod = false;
    FaceCulling culling = {};  // none by default: a bake draws every triangle
    // GL's blending with glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA) into the float buffer,
    // every channel alpha included: src * a + dst * (1 - a), each product rounded (llvmpipe's
    // arithmetic, measured), and no depth writes (the depth test still applies).
    bool blend = false;
    // Bit i: keep only what has VertexOut::clip_distances[i] >= 0 (GL_CLIP_PLANEi enabled).
    unsigned clip_distances = 0;
};

}  // namespace qs
