#pragma once
// A shader evaluated on an N^3 grid of object-space positions, as a 3D texture (the ProcTexGen
// fast noise reads such a volume). Each z slice is a frame: the square [-1, 1]^2 at the slice's depth
// seen by an orthographic camera at N x N pixels, whose pixel centres are the slice's texel
// centres. So a volume is made exactly as a GL application would bake it (a full-screen square
// per slice, quads and helper lanes for shaders that take derivatives: dFdx is then the change
// per texel along x), and the same scenes drawn by OSMesa check it (tests/reference).

#include <optional>
#include <string>
#include <vector>

#include "images/image_io.h"
#include "render/scene_render.h"
#include "scenes/scene.h"

namespace qs {

// Sides a volume may have: its stacked image (N x N^2) must load back as a texture
// (scenes/limits.h: 16384 rows).
inline constexpr int kMaxVolumeSide = 128;

struct VolumeRequest {
    std::string shader;
    int size = 32;  // N: N^3 texels
    // Materials for the shader: the first object's textures and uniforms of this scene, if any.
    const Scene* material_scene = nullptr;
    FrameRequest frame;  // time, uniforms, derivative rule, threads; its size and shader are set here
};

// Texel (i, j, k)'s centre is object position p = -1 + 2 ((i, j, k) + 0.5) / N, so that a
// sampler3D read at (p + 1) / 2 returns the shader's colour at p.
float volume_texel_centre(int index, int size);

// The scene whose frame is slice `k` of `request`'s volume (its rows top-down, y = +1 first).
Scene volume_slice_scene(const VolumeRequest& request, int k);

// The volume as the 3D texture layout of scenes/scene.h (Texture::depth): slice k is rows
// [k N, (k + 1) N), row j of a slice is y texel j (t = 0 first). Throws std::invalid_argument for
// a size outside [1, kMaxVolumeSide], SceneError for an unknown shader or a missing texture.
Image bake_volume(const VolumeRequest& request);

}  // namespace qs
