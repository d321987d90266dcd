#pragma once
// Helpers for vertex stages, in float as GL evaluates them.

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace qs {

// gl_ModelViewProjectionMatrix * gl_Vertex with w = 1, summed column by column left to right as
// Mesa lowers a matrix-vector product (((c0 x + c1 y) + c2 z) + c3), with no fused multiply-add.
inline glm::vec4 transform_point(const glm::mat4& m, const glm::vec3& p) {
    glm::vec4 r = m[0] * p.x;
    r = r + m[1] * p.y;
    r = r + m[2] * p.z;
    r = r + m[3];
    return r;
}

}  // namespace qs
