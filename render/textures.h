#pragma once
// A scene's textures as the renderer samples them: the image decoded (scenes/image_io.h) and
// uploaded in glTF's orientation (UV (0, 0) is the image's first row, so rows are not flipped),
// the glTF sampler in the texture unit's terms, and mipmaps when its minification filter reads
// them, made as llvmpipe's glGenerateMipmap makes them (shading/glsl/texture.h).

#include "scenes/scene.h"
#include "shading/glsl/texture.h"

namespace qs {

glsl::SamplerState sampler_state(const Sampler& sampler);

// Throws SceneError naming the scene file and the texture's field when the image cannot be read.
glsl::sampler2D load_texture(const Scene& scene, const Texture& texture);

}  // namespace qs
