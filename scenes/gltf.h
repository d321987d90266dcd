#pragma once
// glTF 2.0 scenes through tinygltf (the only file that includes it is gltf.cpp).
//
// quadshade's conventions, all inside standard glTF:
//  - each mesh primitive (TRIANGLES, POSITION required, TEXCOORD_0 optional) is drawn with the
//    shader its material names: materials[i].extras = { "shader": "flow_noise",
//    "teximage": "textures/image.png" (optional, relative to the .gltf) };
//  - the camera is the first node with a camera, in the default scene's node order; a file
//    without one is seen from the front (down -Z, +Y up), framing its bounding sphere;
//  - scenes[i].extras = { "clear_color": [r, g, b, a], "time": t, "size": [w, h] } (all optional).
// Shaders see the untransformed POSITION as gl_Vertex, the node's world matrix in the MVP.

#include <filesystem>

#include "scenes/scene.h"

namespace qs {

// Throws SceneError naming the file and the field at fault.
Scene load_scene(const std::filesystem::path& path);

// Writes `scene` as .gltf with its buffer in a .bin beside it (used by the scene generator).
void save_scene(const Scene& scene, const std::filesystem::path& path);

}  // namespace qs
