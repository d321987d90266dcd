#pragma once
// What the rasterizer draws: triangles of one mesh, one program, one set of uniforms.

#include <cstdint>
#include <span>

#include "shading/program.h"

namespace qs {

struct DrawCall {
    std::span<const VertexIn> vertices;
    std::span<const std::uint32_t> indices;  // three per triangle
    const Program* program = nullptr;
    Uniforms uniforms;
    // The bound texture picks a mipmap level or a filter from the level of detail: shade in quads
    // even if the shader takes no derivatives of its own, as a GL driver does for texture2D.
    bool texture_lod = false;
};

}  // namespace qs
