#pragma once
// What quadshade accepts from a scene before it does any work. Each limit is checked where the
// data is read, before anything is allocated for it, and a violation is a SceneError naming the
// file and the field. docs/reliability.md lists them with their reasons.

#include <cstdint>

namespace qs::limits {

// A .gltf or .glb file, and each file it refers to (buffers, images).
inline constexpr std::uint64_t kSceneFileBytes = std::uint64_t(1) << 30;     // 1 GiB
inline constexpr std::uint64_t kResourceFileBytes = std::uint64_t(1) << 31;  // 2 GiB
// Objects and arrays nested in the JSON (glTF itself needs about 6; extras may add a few). Checked
// on the text before any parser sees it: a parser that recurses would overflow its stack.
inline constexpr int kJsonDepth = 64;
// Nodes below a scene's root (a chain of parents).
inline constexpr int kNodeDepth = 128;
// Vertices over all meshes, triangles drawn (a mesh placed by n nodes counts n times), and
// objects (draw calls). A triangle costs about 300 bytes per frame in setup.
inline constexpr std::uint64_t kVertices = std::uint64_t(1) << 24;
inline constexpr std::uint64_t kTriangles = std::uint64_t(1) << 24;
inline constexpr std::uint64_t kObjects = std::uint64_t(1) << 16;
// Rendered images: 1..32768 on each side (the rasterizer's fixed point guard band).
inline constexpr int kImageSide = 1 << 15;
// Textures: GL's largest size on llvmpipe on each side, and 64 Mtexels in all (1 GiB as the
// float RGBA the shaders sample), checked on the file's header before it is decoded.
inline constexpr int kTextureSide = 1 << 14;
inline constexpr std::uint64_t kTextureTexels = std::uint64_t(1) << 26;

}  // namespace qs::limits
