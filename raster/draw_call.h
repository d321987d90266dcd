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
};

}  // namespace qs
