#pragma once
// The glTF feature scenes: one small scene for each part of glTF 2.0 that exporters write and the
// default material draws (base colour factors, textures and vertex colours, lit and flat and
// unlit; alpha modes; texture coordinate sets and KHR_texture_transform; strips, fans, points
// and lines; animations; EXT_mesh_gpu_instancing; KHR_mesh_quantization; cameras), and two files
// written as exporters write them (a modelling tool's scene, a CAD assembly in a .glb). Each is
// compared with OSMesa drawing the default material's GLSL (tests/reference/test_gltf_scenes.cpp).

#include <filesystem>

namespace qs {

// Writes DIR/gltf/<name>.gltf (+ .bin) or .glb for each scene, and the images they use.
void write_gltf_scenes(const std::filesystem::path& dir);

}  // namespace qs
