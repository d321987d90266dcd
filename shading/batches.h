#pragma once
// What the stages take and give: a vertex's attributes and outputs, and a batch of kBatchLanes
// fragments' inputs and colours (structures of arrays, 4 quads when a quad mode is used).

#include <array>
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace qs {

inline constexpr int kBatchLanes = 16;   // 4 quads: one AVX-512 register of floats
inline constexpr int kBatchQuads = kBatchLanes / 4;
inline constexpr int kMaxVaryings = 8;
inline constexpr int kMaxClipDistances = 8;  // GL_MAX_CLIP_DISTANCES: user clip planes

struct VertexIn {
    glm::vec3 position;           // object space (gl_Vertex.xyz)
    glm::vec2 texcoord;           // gl_MultiTexCoord0.st
    glm::vec3 normal{0.0f};       // gl_Normal: glTF's NORMAL, (0, 0, 0) where the mesh has none
    glm::vec4 color{1.0f};        // gl_Color: COLOR_0, (1, 1, 1, 1) where none; a vec3 colour has alpha 1
    glm::vec2 texcoord1{0.0f};    // gl_MultiTexCoord1.st: TEXCOORD_1
    std::uint32_t id = 0;         // gl_VertexID: its index in the draw's vertex arrays
};
struct VertexOut {
    glm::vec4 clip;  // gl_Position
    std::array<float, kMaxVaryings> varyings{};
    // gl_ClipDistance, or each clip plane's distance to gl_ClipVertex: what a draw that clips
    // against user planes (DrawCall::clip_distances) keeps where it is >= 0.
    std::array<float, kMaxClipDistances> clip_distances{};
};

// Inputs of kBatchLanes fragments, structure of arrays. In quad modes lanes 4q..4q+3 are quad q
// in the layout of number/lanes.h; helper lanes carry extrapolated values like the others.
struct FragmentBatch {
    alignas(64) float frag_coord[4][kBatchLanes];  // gl_FragCoord: x, y, z, 1/w
    alignas(64) float varying[kMaxVaryings][kBatchLanes];
    // d(varying)/dx and /dy in window space; filled only for Derivatives::Analytic.
    alignas(64) float varying_dx[kMaxVaryings][kBatchLanes];
    alignas(64) float varying_dy[kMaxVaryings][kBatchLanes];
    // d/dx and d/dy of gl_FragCoord.z and .w (1/w), per lane: planes for the rasterizer, ray
    // differentials for the ray caster. Filled only for Derivatives::Analytic.
    alignas(64) float frag_coord_dx[2][kBatchLanes];
    alignas(64) float frag_coord_dy[2][kBatchLanes];
    // gl_FrontFacing: bit i set when lane i's primitive faces front (counter-clockwise in GL's
    // window, glFrontFace's default).
    std::uint32_t front_facing = ~0u;
};

struct ColorBatch {
    alignas(64) float rgba[4][kBatchLanes];
    // Bit i: lane i executed GLSL's discard. Its fragment writes neither colour nor depth; it
    // was shaded to the end all the same, as a helper for its quad's derivatives. Always written.
    std::uint32_t discarded = 0;
    // Per lane, the Undefined bits (number/checked.h) of its colour; written only when
    // ShadeMode::check_undefined.
    std::uint8_t undefined[kBatchLanes];
};

}  // namespace qs
