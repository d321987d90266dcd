#pragma once
// What the parts of the glTF reader share, private to them: the accessors' typed reads
// (gltf_accessors.cpp), a primitive's triangles (gltf_meshes.cpp), nodes, cameras and the scene's
// extras (gltf_nodes.cpp), materials' textures and uniforms (gltf_materials.cpp), all used by the
// scene's reader in gltf_load.cpp. tinygltf's types appear here: only those files include it.

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <tiny_gltf.h>

#include "scenes/gltf.h"

namespace qs::gltf_read {

[[noreturn]] inline void fail(const std::filesystem::path& file, const std::string& field, const std::string& what) {
    throw SceneError(file.string() + ": " + field + ": " + what);
}

inline std::string indexed(const std::string& array, std::size_t i) { return array + "[" + std::to_string(i) + "]"; }

// ---- buffers and accessors (gltf_accessors.cpp) ---------------------------------------------

// Buffer views lie inside their buffers and have strides glTF allows; checked once for all,
// before any accessor reads through them.
void check_buffer_views(const tinygltf::Model& m, const std::filesystem::path& file);

// An accessor's elements, tightly packed, sparse substitutions applied.
struct AccessorData {
    std::vector<unsigned char> bytes;
    std::size_t count = 0, element = 0;
    int component_type = 0;
    const unsigned char* at(std::size_t i) const { return bytes.data() + i * element; }
};

// The index at p, stored as an index accessor's component type.
std::uint32_t read_index(const unsigned char* p, int component_type);

// Accessor `index`, checked against the types and component types `field` may have and its
// count against max_count.
AccessorData read_accessor(const tinygltf::Model& m, int index, const std::filesystem::path& file,
                           const std::string& field, int want_type, std::initializer_list<int> want_components,
                           std::uint64_t max_count);

// A component type an attribute may have, and whether it is normalized.
struct Component {
    int type;
    bool normalized;
};
inline constexpr Component kFloat{TINYGLTF_COMPONENT_TYPE_FLOAT, false};
inline constexpr Component kByteNorm{TINYGLTF_COMPONENT_TYPE_BYTE, true}, kByte{TINYGLTF_COMPONENT_TYPE_BYTE, false};
inline constexpr Component kUByteNorm{TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, true},
    kUByte{TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, false};
inline constexpr Component kShortNorm{TINYGLTF_COMPONENT_TYPE_SHORT, true}, kShort{TINYGLTF_COMPONENT_TYPE_SHORT, false};
inline constexpr Component kUShortNorm{TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, true},
    kUShort{TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, false};

// What glTF 2.0 and KHR_mesh_quantization allow each attribute (and animation and instancing
// data) to be stored as.
inline const std::initializer_list<Component> kPositionTypes = {kFloat, kByte,      kByteNorm, kUByte,     kUByteNorm,
                                                                kShort, kShortNorm, kUShort,   kUShortNorm};
inline const std::initializer_list<Component> kNormalTypes = {kFloat, kByteNorm, kShortNorm};
inline const std::initializer_list<Component> kTexcoordTypes = {kFloat, kByte,      kByteNorm, kUByte,     kUByteNorm,
                                                                kShort, kShortNorm, kUShort,   kUShortNorm};
inline const std::initializer_list<Component> kColorTypes = {kFloat, kUByteNorm, kUShortNorm};
inline const std::initializer_list<Component> kRotationTypes = {kFloat, kByteNorm, kUByteNorm, kShortNorm, kUShortNorm};
inline const std::initializer_list<Component> kFloatOnly = {kFloat};

// An accessor's elements as floats: integer components as glTF converts them, normalized ones
// to [0, 1] (c / (2^b - 1)) or [-1, 1] (max(c / (2^(b-1) - 1), -1)), the others as they are.
struct Floats {
    std::vector<float> values;  // count * components
    std::size_t count = 0;
    int components = 0;
    glm::vec4 at(std::size_t i) const {
        glm::vec4 v(0.0f);
        for (int c = 0; c < components; ++c) v[c] = values[i * std::size_t(components) + std::size_t(c)];
        return v;
    }
};

// Accessor `index` as floats, checked as read_accessor checks it; `element` names its elements in
// messages.
Floats read_floats(const tinygltf::Model& m, int index, const std::filesystem::path& file, const std::string& field,
                   std::initializer_list<int> want_types, std::initializer_list<Component> want_components,
                   std::uint64_t max_count, const char* element = "element");

// ---- meshes (gltf_meshes.cpp) ---------------------------------------------------------------

// Whether a primitive's mode draws triangles (TRIANGLES, strips, fans; the default).
bool is_triangles(int mode);

// Primitive `pi` of mesh `mi` as triangles with its attributes. `texcoord1_set`: the TEXCOORD_n
// Vertex::texcoord1 holds (1, or the material's base colour set when that is 2 or more).
Mesh read_primitive(const tinygltf::Model& m, std::size_t mi, std::size_t pi, const std::filesystem::path& file,
                    std::uint64_t vertices_left, int texcoord1_set);

// ---- nodes, cameras and the scene's extras (gltf_nodes.cpp) ---------------------------------

// A node's local transform, every number checked: glTF gives them as doubles, kept as doubles
// (transforms are composed in double), and one that does not fit in float (a translation of
// 1e39) would place everything at infinity once rounded for drawing.
Node read_node(const tinygltf::Node& n, const std::filesystem::path& file, const std::string& field);

// Camera `index` of a node placed by `world`, its numbers checked.
Camera read_camera(const tinygltf::Model& m, int index, const glm::dmat4& world, const std::filesystem::path& file,
                   const std::string& node_field);

// For a file without a camera: a three-quarter view of glTF's front (+Z), from 30 degrees to the
// right (+X) and 20 degrees above, +Y up, at the bounding sphere of everything in the scene (where
// it stands before any animation), with a 45 degree field of view and an aspect ratio of 1, so
// that the sphere shows whole at any image size (Camera::projection). Seen straight from the
// front, a box shows one face and a flat part nothing of its depth.
Camera framing_camera(const Scene& scene);

// scenes[].extras: the clear colour, time, stretch and size.
void read_scene_extras(const tinygltf::Value& extras, const std::filesystem::path& path, const std::string& field,
                       Scene& scene);

// ---- materials and textures (gltf_materials.cpp) --------------------------------------------

// A material's extras.uniforms: {"uScale": 4.0, "uTint": [1, 0.5, 0.2], ...}, each a number or
// an array of 2 to 16 numbers (matrices column by column).
std::vector<UniformSetting> read_uniforms(const tinygltf::Value& v, const std::filesystem::path& file, const std::string& field);

// KHR_texture_transform on a textureInfo: glTF's translation * rotation * scale, and the texCoord
// it may override.
void read_texture_transform(const tinygltf::Value& t, const std::filesystem::path& file, const std::string& field,
                            Material& look);

// The textures the objects' materials bind to `teximage`, each made once.
class TextureReader {
public:
    TextureReader(const tinygltf::Model& m, const std::filesystem::path& file, const ScenePathPolicy& policy, Scene& scene)
        : m_(m), file_(file), policy_(policy), scene_(scene) {}

    // Material `mi`'s texture: extras.teximage if it names a file (with the baseColorTexture's
    // sampler, if any), else pbrMetallicRoughness.baseColorTexture; -1 for neither.
    int of_material(int mi);

    // Material `mi`'s extras.textures (gltf.h): each uniform's texture. One named `teximage`
    // replaces `teximage` (the material's baseColorTexture) as extras.teximage does, which it
    // may not accompany.
    void named_of_material(int mi, Object& o);

private:
    // An image file a material names (extras.teximage, extras.textures): a file name, not a URI,
    // so not percent-decoded; resolved as every file a scene names (the file need not exist: a
    // texture is read only when a shader samples it).
    ImageSource named_file(const std::string& name, const std::string& field);

    // One binding of extras.textures: a glTF texture index, an image file, or an object of them
    // with a sampler, a depth and wrapR.
    int binding(const tinygltf::Value& v, const std::string& field);

    int texture_index(const tinygltf::Value& v, const std::string& field, const Sampler& sampler, bool own_sampler, int dims,
                      int depth, std::optional<CompareFunc> compare = std::nullopt);

    int file_texture(const std::string& uri, const std::string& field, const Sampler& sampler, int dims, int depth,
                     std::optional<CompareFunc> compare = std::nullopt);

    // A cube map from six image files in GL's face order (+X, -X, +Y, -Y, +Z, -Z); their sizes
    // are checked when the images are read.
    int cube_texture(const tinygltf::Value& v, const std::string& field, const Sampler& sampler,
                     std::optional<CompareFunc> compare);

    // The same image, sampler and shape: one texture (its first field names it).
    int add_once(Texture t);

    const tinygltf::Texture& texture_at(int index, const std::string& field) const;

    Texture read_texture(int index, const std::string& field) const;

    // The texture's sampler, glTF's defaults where it gives none, its values checked.
    Sampler sampler_of(const tinygltf::Texture& gt, const std::string& field) const;

    Wrap wrap_of(int v, const std::string& field) const;

    // samplers[index], `field` naming where the index came from.
    Sampler sampler_at(int index, const std::string& field) const;

    int add(Texture t);

    const tinygltf::Model& m_;
    const std::filesystem::path& file_;
    const ScenePathPolicy& policy_;
    Scene& scene_;
    std::map<int, int> gltf_textures_;  // glTF texture index -> Scene::textures
};

}  // namespace qs::gltf_read
