#pragma once
// A scene's textures as the renderer samples them: the image decoded (images/image_io.h) and
// uploaded in glTF's orientation (UV (0, 0) is the image's first row, so rows are not flipped; a
// 3D texture's slices are the image's bands of rows, top first), the glTF sampler in the texture
// unit's terms, and mipmaps when its minification filter reads them, made as llvmpipe's
// glGenerateMipmap makes them (shading/glsl/texture.h).

#include <cstdint>
#include <memory>

#include "scenes/scene.h"
#include "shading/glsl/texture.h"

namespace qs {

// The sampler state of a texture: its glTF sampler, and its compare function where it is a depth
// comparison texture.
glsl::SamplerState sampler_state(const Texture& texture);

// A glsl::sampler2D or, for a texture with dims 3, a glsl::sampler3D, for a cube map a
// glsl::samplerCube (shading/glsl/texture_cube.h). Throws SceneError naming the scene file and the
// texture's field (a cube map's face by its index) when an image cannot be read, its rows do not
// divide into the texture's depth, or a cube map's faces are not square or not of one size.
// `loading_bytes`, when given, receives the most the loading held at once beside the texture it
// made (read_texture_image's decoding_bytes; a cube map's faces read before each one included).
std::unique_ptr<glsl::Texture> load_texture(const Scene& scene, const Texture& texture,
                                            std::uint64_t* loading_bytes = nullptr);

// A 1x1 (x1) opaque white texture of `dims` dimensions (a cube map of 1x1 faces for
// glsl::kCubeDims): what a sampler reads where the material binds no texture to it (a lookup
// gives (1, 1, 1, 1) at any coordinate, level and filter).
const glsl::Texture& white_texture(int dims);

}  // namespace qs
