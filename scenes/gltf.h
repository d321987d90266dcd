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
#include <span>

#include "scenes/scene.h"
#include "scenes/scene_files.h"

namespace qs {

struct SceneLoadOptions {
    ScenePathPolicy paths;  // which files the scene may read besides itself
};

// Throws SceneError naming the file and the field at fault. Everything scenes/limits.h bounds is
// checked before it is allocated; buffer and image URIs, and extras.teximage, are resolved by
// resolve_scene_uri (scene_files.h) and must lie in the scene's folder unless
// options.paths.allow_outside; images are not decoded here.
Scene load_scene(const std::filesystem::path& path, const SceneLoadOptions& options = {});
// The same from the file's bytes (JSON or binary glTF, told apart by the binary magic); `path`
// names the file in messages and its folder is where URIs lead.
Scene parse_scene(std::span<const unsigned char> bytes, const std::filesystem::path& path,
                  const SceneLoadOptions& options = {});

// Writes `scene` as .gltf with its buffer in a .bin beside it (used by the scene generator).
void save_scene(const Scene& scene, const std::filesystem::path& path);

}  // namespace qs
