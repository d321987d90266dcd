#pragma once
// The mipmaps Mesa makes of a depth texture: what quadshade's float depth mipmaps (a depth
// comparison texture's, shading/glsl/texture_shadow.h) are checked against, texel for texel.

#include <vector>

namespace qs {

// Uploads `depths` (width x height floats, rows from t = 0) as a GL_DEPTH_COMPONENT32F texture in
// the current context, runs glGenerateMipmap and reads every level below the base back with
// glGetTexImage: the levels one after another, down to 1x1. Throws std::runtime_error on a GL
// error.
std::vector<float> generated_depth_mipmaps(int width, int height, const std::vector<float>& depths);

}  // namespace qs
