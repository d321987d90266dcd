#pragma once
// glTF 2.0 scenes through tinygltf (the only file that includes it is gltf.cpp).
//
// quadshade's conventions, all inside standard glTF:
//  - each mesh primitive (TRIANGLES, POSITION required, TEXCOORD_0 optional) is drawn with the
//    shader its material names: materials[i].extras = { "shader": "flow_noise" };
//  - the shaders' `teximage` is the material's pbrMetallicRoughness.baseColorTexture (an image
//    file, a data: URI or a bufferView, with its sampler), or the file extras.teximage names
//    (relative to the .gltf; it keeps the baseColorTexture's sampler, if any);
//  - the camera is the first node with a camera, in the default scene's node order; a file
//    without one is seen from the front (down -Z, +Y up), framing its bounding sphere;
//  - scenes[i].extras = { "clear_color": [r, g, b, a], "time": t, "size": [w, h] } (all optional).
// Shaders see the untransformed POSITION as gl_Vertex, the node's world matrix in the MVP.

#include <filesystem>
#include <optional>
#include <span>
#include <string>

#include <glm/gtc/quaternion.hpp>

#include "scenes/scene.h"

namespace qs {

// Throws SceneError naming the file and the field at fault.
Scene load_scene(const std::filesystem::path& path);

// A node for save_scene to write, for scenes that exercise glTF's node hierarchy: its parent (an
// earlier node, or -1 for a root), its local transform as a matrix or else as translation,
// rotation and scale (glTF's T * R * S), and the object it carries (-1 for none).
struct SavedNode {
    std::string name;
    int parent = -1;
    std::optional<glm::mat4> matrix;
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // w, x, y, z
    glm::vec3 scale{1.0f};
    int object = -1;
};

// Writes `scene` as .gltf with its buffer in a .bin beside it, or as one .glb (used by the scene
// generator). Textures become images (a URI relative to the file, a data: URI or a bufferView, as
// their ImageSource says), samplers and baseColorTextures.
// Without `nodes` each object is a root node with its world matrix; with them, the objects sit
// where the nodes put them (each object on exactly one node; its world_from_object is not
// written, the loader composes it from the hierarchy). Throws SceneError otherwise.
void save_scene(const Scene& scene, const std::filesystem::path& path, std::span<const SavedNode> nodes = {});

}  // namespace qs
