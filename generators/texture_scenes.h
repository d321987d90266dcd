#pragma once
// The texture conformance scenes: what a texture lookup depends on (wraps with UVs far outside
// [0, 1], every filter under magnification and minification, mipmaps, non-square and odd images,
// the image as a file, a data: URI and a .glb bufferView), each a plane drawn with
// `single_texture`. Every catalogue shader that samples a texture is compared on them against
// OSMesa (tests/reference/test_texture_conformance.cpp).

#include <filesystem>

namespace qs {

// Writes DIR/conformance/texture-<name>.gltf (or .glb) for each scene, and their images in
// DIR/conformance/images/.
void write_texture_scenes(const std::filesystem::path& dir);

}  // namespace qs
