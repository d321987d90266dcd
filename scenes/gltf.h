#pragma once
// glTF 2.0 scenes through tinygltf (the files that include it: gltf_save.cpp, gltf_load.cpp and the
// reader's parts in gltf_read.h).
//
// What is read, all of it standard glTF 2.0 (docs/scenes.md has the details):
//  - each mesh primitive of triangles (TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN; points and lines
//    are skipped with a warning) with POSITION, and NORMAL, COLOR_0 and TEXCOORD_n where given,
//    as floats or the normalized and quantized integers glTF and KHR_mesh_quantization allow;
//  - each primitive is drawn with the shader its material names, materials[i].extras =
//    { "shader": "flow_noise" }, or where it names none (or has no material) with the default
//    material (shading/shaders/gltf_material.h): glTF's base colour (baseColorFactor x the
//    baseColorTexture on its texCoord, with its sampler and KHR_texture_transform, x COLOR_0),
//    alphaMode and alphaCutoff, KHR_materials_unlit;
//  - the shaders' `teximage` is the material's pbrMetallicRoughness.baseColorTexture (an image
//    file, a data: URI or a bufferView, with its sampler), or the file extras.teximage names
//    (relative to the .gltf; it keeps the baseColorTexture's sampler, if any);
//  - a shader's other samplers (sampler2D, sampler3D or samplerCube uniforms) are bound by their
//    GLSL name in materials[i].extras.textures = { "NAME": BINDING, ... }, where BINDING is
//      3                         glTF textures[3] (its image and sampler), a sampler2D;
//      "images/wood.png"         an image file relative to the .gltf, glTF's default sampler;
//      { "texture": 3 | "image": "noise3d.png" | "faces": ["px.png", ...],   exactly one;
//                                faces: a samplerCube's six files, +X -X +Y -Y +Z -Z, square
//                                images of one size, each clamped to its edges whatever the wraps
//        "sampler": 1,           glTF samplers[1] instead of the texture's own (or the default)
//        "depth": 32,            a sampler3D of 32 slices (1..2048), stacked in the image from
//                                top to bottom: slice z (r = (z + 0.5) / 32) is rows
//                                [z H, (z + 1) H) of an image of 32 H rows, each slice's first
//                                row at t = 0 (a 32^3 volume is a 32x1024 image)
//        "wrapR": 33071,         the r axis's wrap (3D only; glTF has none): REPEAT by default;
//        "compare": "LEQUAL" }   a depth comparison texture for a sampler2DShadow (2D), or with
//                                faces a samplerCubeShadow: the image's (each face's) red
//                                channel is the depth (red / 255), compared by the
//                                function (GL's names without GL_: NEVER, LESS, EQUAL,
//                                LEQUAL, GREATER, NOTEQUAL, GEQUAL, ALWAYS), any sampler
//                                (its mipmaps are float depths);
//    "teximage" may be bound this way too (instead of baseColorTexture; not with extras.teximage).
//    Volumes are 8-bit images (PNG), as a GL_RGBA8 3D texture holds them;
//  - nodes with EXT_mesh_gpu_instancing draw their mesh once per instance; animations of node
//    translation, rotation and scale (LINEAR, STEP, CUBICSPLINE) are kept for Scene::pose;
//  - the camera is the one SceneLoadOptions::camera names, else the first node with a camera in
//    the default scene's node order; a file without one is seen from the front (+Z) turned 30
//    degrees to +X and raised 20 degrees, +Y up, framing its bounding sphere;
//  - scenes[i].extras = { "clear_color": [r, g, b, a], "time": t, "size": [w, h], "stretch": true }
//    (all optional; stretch: an orthographic camera's view box fills the image, Camera::stretch);
//  - extensions: KHR_texture_transform, KHR_materials_unlit, KHR_mesh_quantization and
//    EXT_mesh_gpu_instancing are implemented; a file that requires another is refused, and one
//    that merely uses another is drawn without it, with a warning (Scene::warnings).
// Bad materials, accessors and textures are reported together, up to 20 in one SceneError.
// Shaders see the untransformed POSITION as gl_Vertex, the node's world matrix in the MVP.

#include <filesystem>
#include <optional>
#include <span>
#include <string>

#include <glm/gtc/quaternion.hpp>

#include "scenes/scene.h"
#include "scenes/scene_files.h"

namespace qs {

struct SceneLoadOptions {
    ScenePathPolicy paths;  // which files the scene may read besides itself
    // The camera to render from: a camera node's name, a camera's name, or an index into the
    // file's cameras[] (the first node placing it); empty for the first camera node in the
    // scene's order, or the default camera of a file without one.
    std::string camera;
};

// A SceneLoadOptions::camera that names none of the file's cameras: the command line's fault (bad
// usage, exit 2), where a SceneError is the file's.
class CameraOptionError : public SceneError {
public:
    using SceneError::SceneError;
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
