#pragma once
// What the scene and the frame give every shader (Uniforms): transforms, time, textures, its own
// uniforms' values, generic attributes and clip planes.

#include <array>
#include <cstdint>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "shading/batches.h"
#include "shading/glsl/texture.h"
#include "shading/shader_info.h"

namespace qs {

// GL_MAX_VERTEX_ATTRIBS: the generic vertex attributes a draw can feed (glVertexAttribPointer).
inline constexpr int kMaxGenericAttributes = 16;
// A generic attribute's value at one vertex: four 32-bit words, floats' bits or integers.
using AttributeValue = std::array<std::uint32_t, 4>;

// What the scene and the frame give every shader: its transforms (a GLSL 1.30 vertex stage reads
// them as the uniforms mvp, model, view, projection and normalMatrix: scenes/shader_inputs.h),
// time, its textures, and its own uniforms' values.
struct Uniforms {
    glm::mat4 model_view_projection{1.0f};  // gl_ModelViewProjectionMatrix, mvp
    glm::mat4 model{1.0f};                  // world from object
    glm::mat4 view{1.0f};                   // view from world
    glm::mat4 projection{1.0f};             // clip from view
    glm::mat3 normal_matrix{1.0f};          // transpose(inverse(mat3(view * model)))
    float time = 0.0f;
    const glsl::sampler2D* teximage = nullptr;  // set when Needs::texture
    // ShaderInfo::uniforms' values, kUniformWords 32-bit words each in their order: floats' bits
    // or 32-bit integers. Read through glsl::uniform (glsl/uniform.h).
    const std::uint32_t* user = nullptr;
    // Needs::samplers' textures, in their order, each of the kind the shader declares.
    std::array<const glsl::Texture*, kMaxSamplers> samplers{};
    // Per generic attribute location, its value at each vertex of the draw (VertexIn::id); null:
    // GL's current value, (0, 0, 0, 1), at every vertex.
    std::array<const AttributeValue*, kMaxGenericAttributes> attributes{};
    // glClipPlane's planes in eye space: a vertex stage that writes gl_ClipVertex clips at
    // dot(plane, gl_ClipVertex) >= 0 (VertexOut::clip_distances).
    std::array<glm::vec4, kMaxClipDistances> clip_planes{};

    const glsl::sampler2D& sampler2D(int i) const { return static_cast<const glsl::sampler2D&>(*samplers[std::size_t(i)]); }
    const glsl::sampler3D& sampler3D(int i) const { return static_cast<const glsl::sampler3D&>(*samplers[std::size_t(i)]); }
};

}  // namespace qs
