#pragma once
// glTF 2.0 scenes through tinygltf (the only file that includes it is gltf.cpp).
//
// quadshade's conventions, all inside standard glTF:
//  - each mesh primitive (TRIANGLES, POSITION required, TEXCOORD_0 optional) is drawn with the
//    shader its material names: materials[i].extras = { "shader": "flow_noise" };
//  - the shaders' `teximage` is the material's pbrMetallicRoughness.baseColorTexture (an image
//    file, a data: URI or a bufferView, with its sampler), or the file extras.teximage names
//    (relative to the .gltf; it keeps the baseColorTexture's sampler, if any);
//  - a shader's other samplers (sampler2D or sampler3D uniforms) are bound by their GLSL name in
//    materials[i].extras.textures = { "NAME": BINDING, ... }, where BINDING is
//      3                         glTF textures[3] (its image and sampler), a sampler2D;
//      "images/wood.png"         an image file relative to the .gltf, glTF's default sampler;
//      { "texture": 3 | "image": "noise3d.png",   exactly one of the two
//        "sampler": 1,           glTF samplers[1] instead of the texture's own (or the default)
//        "depth": 32,            a sampler3D of 32 slices (1..2048), stacked in the image from
//                                top to bottom: slice z (r = (z + 0.5) / 32) is rows
//                                [z H, (z + 1) H) of an image of 32 H rows, each slice's first
//                                row at t = 0 (a 32^3 volume is a 32x1024 image)
//        "wrapR": 33071 }        the r axis's wrap (3D only; glTF has none): REPEAT by default;
//    "teximage" may be bound this way too (instead of baseColorTexture; not with extras.teximage).
//    Volumes are 8-bit images (PNG), as a GL_RGBA8 3D texture holds them;
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
