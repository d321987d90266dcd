#pragma once
// The uniforms both renderers set for each object from the scene alone, wherever the drawn
// shader declares them (the default material declares them all, shading/shaders/gltf_material.h):
//   vec4 uBaseColorFactor     the material's baseColorFactor
//   int  uBaseColorTexCoord   0: its base colour texture reads gl_MultiTexCoord0 (TEXCOORD_0),
//                             1: gl_MultiTexCoord1 (TEXCOORD_1, or the set n >= 2 it names)
//   mat3 uTextureTransform    its KHR_texture_transform
//   int  uAlphaMode           0: OPAQUE, 1: MASK, 2: BLEND
//   float uAlphaCutoff        its alphaCutoff
//   int  uLighting            0: unlit (KHR_materials_unlit), 1: Lambert per vertex on NORMAL,
//                             2: Lambert per fragment on flat normals (a mesh without NORMAL)
//   mat4 uModelView           view * world, the object's place before the projection
//   mat3 uNormalMatrix        the inverse transpose of uModelView's upper 3x3
//   vec4 uUnproject           1 / P[0][0], 1 / P[1][1], P[2][3], P[3][3] of the projection P: a
//                             view-space position from a window position and its view depth
// Each is computed in double and rounded to float once, as uniforms are. A material's
// extras.uniforms and the command line's --uniform replace them by name.

#include <cstddef>
#include <vector>

#include "scenes/scene.h"
#include "scenes/uniforms.h"

namespace qs {

// Object `i`'s values under `pose`, for a render of the given width / height.
std::vector<UniformSetting> object_uniforms(const Scene& scene, std::size_t i, const Pose& pose, double aspect);

}  // namespace qs
