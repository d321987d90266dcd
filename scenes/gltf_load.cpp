// load_scene and parse_scene: glTF 2.0 read through tinygltf into the scene model (save_scene, the
// other side, is gltf_save.cpp). What tinygltf does not check (file access, offsets, strides,
// sparse data, the node graph, transforms, counts) is checked before it is used, with the help of
// scenes/gltf_checks.h and scenes/scene_files.h. This file reads the file and walks the scene's
// nodes (instancing, materials, animation, the camera); the parts it reads through are in
// scenes/gltf_read.h: accessors, meshes, nodes and cameras, materials' textures.
#include "scenes/gltf.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <set>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "scenes/gltf_checks.h"
#include "scenes/gltf_read.h"
#include "scenes/limits.h"
#include "scenes/scene_files.h"

namespace qs {

namespace {

namespace checks = gltf_checks;
using namespace gltf_read;

// ---- files the scene refers to --------------------------------------------------------------

// tinygltf looks a URI up under each of its search folders (the base folder it is given, then
// "."), and reads what it finds through these callbacks. It is given a base folder that is no
// real folder, so that every lookup arrives here with the URI behind it, goes through
// resolve_scene_uri and read_scene_file, and the "." lookups (the working directory) are refused.
struct FileAccess {
    static constexpr std::string_view kBase = "<scene folder>";
    std::filesystem::path scene_file;
    ScenePathPolicy policy;

    std::optional<std::filesystem::path> resolve(const std::string& looked_up, std::string* err) const {
        if (looked_up.size() <= kBase.size() || looked_up.compare(0, kBase.size(), kBase) != 0 ||
            looked_up[kBase.size()] != '/') {
            return std::nullopt;
        }
        try {
            return resolve_scene_uri(scene_file, std::string_view(looked_up).substr(kBase.size() + 1), policy);
        } catch (const SceneError& e) {
            if (err) *err += e.what();
            return std::nullopt;
        }
    }

    static bool exists(const std::string& path, void* self) {
        const auto p = static_cast<const FileAccess*>(self)->resolve(path, nullptr);
        return p && std::filesystem::exists(*p);
    }
    static std::string expand(const std::string& path, void*) { return path; }
    static bool read(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* self) {
        const auto p = static_cast<const FileAccess*>(self)->resolve(path, err);
        if (!p) return false;
        try {
            *out = read_scene_file(*p, limits::kResourceFileBytes);
            return true;
        } catch (const SceneError& e) {
            if (err) *err += e.what();
            return false;
        }
    }
    static bool write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
        if (err) *err += "loading a scene writes no files";
        return false;
    }
};

// Every buffer and image URI resolved before tinygltf reads anything, so that a message names
// the field, and the scene's list of input files. `json` has passed the depth check.
void check_uris(std::string_view json, const std::filesystem::path& file, const ScenePathPolicy& policy,
                std::vector<std::filesystem::path>& inputs) {
    const nlohmann::json doc = nlohmann::json::parse(json, nullptr, /*allow_exceptions=*/false);
    if (!doc.is_object()) return;  // tinygltf reports what is wrong with it
    for (const char* array : {"buffers", "images"}) {
        const auto list = doc.find(array);
        if (list == doc.end() || !list->is_array()) continue;
        for (std::size_t i = 0; i < list->size(); ++i) {
            const nlohmann::json& item = (*list)[i];
            if (!item.is_object() || !item.contains("uri") || !item["uri"].is_string()) continue;
            const std::string& uri = item["uri"].get_ref<const std::string&>();
            if (uri.rfind("data:", 0) == 0) continue;  // embedded
            std::filesystem::path resolved;
            try {
                resolved = resolve_scene_uri(file, checks::percent_decoded(uri), policy);
            } catch (const SceneError& e) {
                fail(file, indexed(array, i) + ".uri", e.what());
            }
            if (std::filesystem::is_directory(resolved)) fail(file, indexed(array, i) + ".uri", "'" + uri + "' is a folder");
            inputs.push_back(resolved);
        }
    }
}

// tinygltf's image callback: keep the encoded bytes of a data: URI (the only place they are
// kept), decode nothing. Files are read, and bufferViews sliced, when a texture is first used.
bool keep_embedded_image(tinygltf::Image* image, int, std::string*, std::string*, int, int, const unsigned char* bytes,
                         int size, void*) {
    if (image->uri.empty() && image->bufferView < 0) image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

// ---- the scene ------------------------------------------------------------------------------

// The glTF extensions quadshade implements; a file that requires another is refused.
const std::set<std::string> kImplementedExtensions = {"KHR_texture_transform", "KHR_materials_unlit",
                                                      "KHR_mesh_quantization", "EXT_mesh_gpu_instancing"};

// The problems of a file, reported together (up to kShown of them) rather than one per run.
class Problems {
public:
    explicit Problems(const std::filesystem::path& file) : file_(file) {}
    // Runs f; a SceneError it throws is recorded, and false returned.
    template <class F>
    bool attempt(F&& f) {
        try {
            f();
            return true;
        } catch (const SceneError& e) {
            add(e.what());
            return false;
        }
    }
    void add(std::string message) {
        if (messages_.size() < kShown) messages_.push_back(std::move(message));
        ++count_;
    }
    // Throws one SceneError holding them all, a line each; nothing when there are none.
    void throw_if_any() const {
        if (count_ == 0) return;
        std::string all;
        for (const std::string& m : messages_) all += (all.empty() ? "" : "\n") + m;
        if (count_ > messages_.size()) {
            all +=
                "\n" + file_.string() + ": " + std::to_string(count_ - messages_.size()) + " more problems not shown";
        }
        throw SceneError(all);
    }

private:
    static constexpr std::size_t kShown = 20;
    std::filesystem::path file_;
    std::vector<std::string> messages_;
    std::size_t count_ = 0;
};

// One kind of warning counted over the primitives it concerns, said once:
// "<what> on 65 primitives of 12 meshes; first: meshes[3].primitives[0]".
class Tally {
public:
    void add(std::size_t mesh, const std::string& primitive) {
        if (count_++ == 0) first_ = primitive;
        meshes_.insert(mesh);
    }
    std::size_t count() const { return count_; }
    std::string on() const {
        return std::to_string(count_) + (count_ == 1 ? " primitive" : " primitives") + " of " +
               std::to_string(meshes_.size()) + (meshes_.size() == 1 ? " mesh" : " meshes") + "; first: " + first_;
    }

private:
    std::size_t count_ = 0;
    std::set<std::size_t> meshes_;
    std::string first_;
};

// What the objects of one glTF material share, read once for all of them.
struct MaterialRead {
    bool ok = false;
    Object proto;  // material, look, shader, textures, uniforms, double_sided
};

class SceneLoader {
public:
    SceneLoader(const tinygltf::Model& m, const std::filesystem::path& path, const SceneLoadOptions& options,
                Scene& scene)
        : m_(m),
          path_(path),
          options_(options),
          scene_(scene),
          problems_(path),
          textures_(m, path, options.paths, scene) {}

    void load() {
        check_extensions();
        const int scene_index = m_.defaultScene >= 0 ? m_.defaultScene : 0;
        if (m_.scenes.empty() || std::size_t(scene_index) >= m_.scenes.size()) {
            fail(path_, "scenes", "no scene to render");
        }
        const tinygltf::Scene& gs = m_.scenes[std::size_t(scene_index)];
        read_scene_extras(gs.extras, path_, indexed("scenes", std::size_t(scene_index)) + ".extras", scene_);
        reached_.assign(m_.nodes.size(), -1);
        materials_.resize(m_.materials.size());
        material_read_.assign(m_.materials.size(), false);
        for (int ni : gs.nodes) visit(ni, -1, glm::dmat4(1.0), 0);
        read_animations();
        problems_.throw_if_any();
        if (scene_.objects.empty()) fail(path_, "nodes", "no node carries a mesh");
        choose_camera();
        warn();
    }

private:
    void check_extensions() {
        std::string unimplemented;
        for (std::size_t i = 0; i < m_.extensionsRequired.size(); ++i) {
            if (!kImplementedExtensions.count(m_.extensionsRequired[i])) {
                problems_.add(path_.string() + ": extensionsRequired[" + std::to_string(i) + "]: '" +
                              m_.extensionsRequired[i] + "' is required but not implemented (quadshade implements " +
                              implemented_list() + ")");
            }
        }
        problems_.throw_if_any();
        for (const std::string& e : m_.extensionsUsed) {
            if (!kImplementedExtensions.count(e)) unimplemented += (unimplemented.empty() ? "" : ", ") + e;
        }
        if (!unimplemented.empty()) {
            scene_.warnings.push_back(path_.string() +
                                      ": extensionsUsed: drawn without what these extensions add, which "
                                      "quadshade does not implement: " +
                                      unimplemented);
        }
    }

    static std::string implemented_list() {
        std::string list;
        for (const std::string& e : kImplementedExtensions) list += (list.empty() ? "" : ", ") + e;
        return list;
    }

    void visit(int ni, int parent, const glm::dmat4& parent_world, int depth) {
        if (ni < 0 || std::size_t(ni) >= m_.nodes.size()) {
            fail(path_, "nodes", "node index " + std::to_string(ni) + " out of range");
        }
        const std::string node_field = indexed("nodes", std::size_t(ni));
        if (reached_[std::size_t(ni)] >= 0) {
            fail(path_, node_field, "is reached twice (a cycle, or a child of two parents): glTF nodes form trees");
        }
        if (depth > limits::kNodeDepth) {
            fail(path_, node_field,
                 "lies deeper than " + std::to_string(limits::kNodeDepth) + " levels below the scene's root");
        }
        const tinygltf::Node& n = m_.nodes[std::size_t(ni)];
        Node node = read_node(n, path_, node_field);
        node.parent = parent;
        const int index = int(scene_.nodes.size());
        reached_[std::size_t(ni)] = index;
        scene_.nodes.push_back(node);
        const glm::dmat4 world = parent_world * node.local();
        if (!checks::is_finite(glm::mat4(world))) {
            fail(path_, node_field, "its world transform is not finite (too large for float)");
        }
        if (n.camera >= 0) cameras_.push_back({ni, index, n.camera, world});
        if (n.skin >= 0) ++skinned_nodes_;
        if (n.mesh >= 0) place_mesh(n, ni, index, world);
        for (int child : n.children) visit(child, index, world, depth + 1);
    }

    // The objects node `ni` draws: one per primitive, or per primitive and instance.
    void place_mesh(const tinygltf::Node& n, int ni, int node, const glm::dmat4& world) {
        const std::string node_field = indexed("nodes", std::size_t(ni));
        if (std::size_t(n.mesh) >= m_.meshes.size()) fail(path_, node_field + ".mesh", "index out of range");
        std::vector<glm::dmat4> instances = {glm::dmat4(1.0)};
        if (const auto it = n.extensions.find("EXT_mesh_gpu_instancing"); it != n.extensions.end()) {
            if (!problems_.attempt([&] {
                    instances = read_instances(it->second, node_field + ".extensions.EXT_mesh_gpu_instancing");
                })) {
                return;
            }
        }
        const tinygltf::Mesh& gm = m_.meshes[std::size_t(n.mesh)];
        for (std::size_t pi = 0; pi < gm.primitives.size(); ++pi) {
            const tinygltf::Primitive& p = gm.primitives[pi];
            const std::string field = "meshes[" + std::to_string(n.mesh) + "].primitives[" + std::to_string(pi) + "]";
            if (!is_triangles(p.mode)) {
                if (p.mode >= TINYGLTF_MODE_POINTS && p.mode <= TINYGLTF_MODE_LINE_STRIP) {
                    points_and_lines_.add(std::size_t(n.mesh), field + " (mode " + std::to_string(p.mode) + ")");
                } else {
                    problems_.add(path_.string() + ": " + field + ".mode: unknown primitive mode " +
                                  std::to_string(p.mode));
                }
                continue;
            }
            if (!p.targets.empty()) morphed_.add(std::size_t(n.mesh), field);
            const MaterialRead* material = material_of(p.material, field);
            if (!material) continue;
            const auto key = std::make_pair(std::size_t(n.mesh), pi);
            if (!mesh_of_.count(key)) {
                const int set1 = material->proto.look.texcoord >= 2 ? material->proto.look.texcoord : 1;
                Mesh mesh;
                if (!problems_.attempt([&] {
                        mesh = read_primitive(m_, std::size_t(n.mesh), pi, path_, limits::kVertices - vertices_, set1);
                    })) {
                    mesh_of_[key] = -1;
                    continue;
                }
                mesh_of_[key] = int(scene_.meshes.size());
                vertices_ += mesh.vertices.size();
                scene_.meshes.push_back(std::move(mesh));
            }
            if (mesh_of_[key] < 0) continue;
            for (std::size_t i = 0; i < instances.size(); ++i) {
                Object o = material->proto;
                o.name = n.name.empty() ? node_field : n.name;
                if (instances.size() > 1) o.name += " instance " + std::to_string(i);
                o.mesh = std::size_t(mesh_of_[key]);
                o.node = node;
                o.instance = instances[i];
                o.world_from_object = world * instances[i];
                if (!checks::places_things(glm::mat4(o.world_from_object))) {
                    fail(path_, node_field,
                         "its world transform is degenerate (determinant " +
                             std::to_string(checks::determinant(glm::mat4(o.world_from_object))) +
                             (instances.size() > 1 ? ") for instance " + std::to_string(i) : ")") +
                             ": its mesh would be invisible");
                }
                triangles_ += scene_.meshes[o.mesh].indices.size() / 3;
                if (triangles_ > limits::kTriangles || scene_.objects.size() >= limits::kObjects) {
                    fail(path_, node_field,
                         "the scene draws more than " + std::to_string(limits::kTriangles) + " triangles or " +
                             std::to_string(limits::kObjects) + " objects");
                }
                scene_.objects.push_back(std::move(o));
            }
        }
    }

    // EXT_mesh_gpu_instancing: each instance's T * R * S from its attributes (any may be absent).
    std::vector<glm::dmat4> read_instances(const tinygltf::Value& ext, const std::string& field) {
        if (!ext.IsObject() || !ext.Has("attributes") || !ext.Get("attributes").IsObject()) {
            fail(path_, field, "expected an object with attributes");
        }
        const tinygltf::Value& attributes = ext.Get("attributes");
        std::optional<std::size_t> count;
        auto read = [&](const char* name, int type, std::initializer_list<Component> kinds) -> Floats {
            if (!attributes.Has(name)) return {};
            const tinygltf::Value& a = attributes.Get(name);
            if (!a.IsInt()) fail(path_, field + ".attributes." + name, "expected an accessor index");
            Floats f =
                read_floats(m_, a.Get<int>(), path_, field + ".attributes." + name, {type}, kinds, limits::kObjects);
            if (count && *count != f.count) {
                fail(path_, field + ".attributes." + name, "count differs from the other attributes'");
            }
            count = f.count;
            return f;
        };
        const Floats t = read("TRANSLATION", TINYGLTF_TYPE_VEC3, kPositionTypes);
        const Floats r = read("ROTATION", TINYGLTF_TYPE_VEC4, kRotationTypes);
        const Floats s = read("SCALE", TINYGLTF_TYPE_VEC3, kPositionTypes);
        if (!count) fail(path_, field + ".attributes", "none of TRANSLATION, ROTATION, SCALE");
        std::vector<glm::dmat4> instances(*count, glm::dmat4(1.0));
        for (std::size_t i = 0; i < *count; ++i) {
            Node local;
            if (t.count) local.translation = glm::dvec3(glm::vec3(t.at(i)));
            if (r.count) {
                const glm::vec4 q = r.at(i);
                const glm::dquat dq(q.w, q.x, q.y, q.z);
                if (glm::length(dq) == 0.0) {
                    fail(path_, field + ".attributes.ROTATION",
                         "instance " + std::to_string(i) + " is a zero quaternion");
                }
                local.rotation = glm::normalize(dq);
            }
            if (s.count) local.scale = glm::dvec3(glm::vec3(s.at(i)));
            instances[i] = local.local();
        }
        return instances;
    }

    // Material `mi` as its objects share it, read once; nullptr where it is bad (recorded). A
    // primitive without a material gets glTF's default one (white, opaque, single-sided).
    const MaterialRead* material_of(int mi, const std::string& primitive) {
        if (mi < 0) {
            no_material_.ok = true;
            no_material_.proto.material = primitive + " (no material)";
            return &no_material_;
        }
        if (std::size_t(mi) >= m_.materials.size()) {
            problems_.add(path_.string() + ": " + primitive + ".material: index " + std::to_string(mi) +
                          " out of range");
            return nullptr;
        }
        MaterialRead& r = materials_[std::size_t(mi)];
        if (!material_read_[std::size_t(mi)]) {
            material_read_[std::size_t(mi)] = true;
            r.ok = problems_.attempt([&] { r.proto = read_material(mi); });
        }
        return r.ok ? &r : nullptr;
    }

    // extras.glsl: "FRAG" or {"fragment": "FRAG", "vertex": "VERT"}, files beside the scene.
    void read_glsl_files(const tinygltf::Value& v, const std::string& field, Object& o) {
        if (!o.shader.empty()) fail(path_, field, "the material names a shader too (extras.shader): give one of them");
        auto file = [&](const tinygltf::Value& name, const std::string& f) {
            if (!name.IsString() || name.Get<std::string>().empty()) fail(path_, f, "expected a GLSL file name");
            std::filesystem::path resolved;
            try {
                resolved = resolve_scene_uri(path_, name.Get<std::string>(), options_.paths);
            } catch (const SceneError& e) {
                fail(path_, f, e.what());
            }
            scene_.inputs.push_back(resolved);
            return resolved;
        };
        if (v.IsString()) {
            o.glsl_fragment = file(v, field);
            return;
        }
        if (!v.IsObject() || !v.Has("fragment")) fail(path_, field, "expected a file name or {\"fragment\": FRAG, \"vertex\": VERT}");
        for (const std::string& key : v.Keys()) {
            if (key != "fragment" && key != "vertex") fail(path_, field + "." + key, "unknown field (fragment, vertex)");
        }
        o.glsl_fragment = file(v.Get("fragment"), field + ".fragment");
        if (v.Has("vertex")) o.glsl_vertex = file(v.Get("vertex"), field + ".vertex");
    }

    Object read_material(int mi) {
        const tinygltf::Material& gmat = m_.materials[std::size_t(mi)];
        const std::string mf = indexed("materials", std::size_t(mi));
        Object o;
        o.material = gmat.name.empty() ? mf : "'" + gmat.name + "' (" + mf + ")";
        o.double_sided = gmat.doubleSided;
        if (gmat.extras.IsObject() && gmat.extras.Has("shader")) {
            if (!gmat.extras.Get("shader").IsString()) fail(path_, mf + ".extras.shader", "expected a shader name");
            o.shader = gmat.extras.Get("shader").Get<std::string>();
        }
        if (gmat.extras.IsObject() && gmat.extras.Has("glsl")) read_glsl_files(gmat.extras.Get("glsl"), mf + ".extras.glsl", o);
        Material& look = o.look;
        const tinygltf::PbrMetallicRoughness& pbr = gmat.pbrMetallicRoughness;
        if (pbr.baseColorFactor.size() != 4) {
            fail(path_, mf + ".pbrMetallicRoughness.baseColorFactor", "expected 4 numbers");
        }
        for (int i = 0; i < 4; ++i) {
            const double f = pbr.baseColorFactor[std::size_t(i)];
            if (!std::isfinite(float(f))) fail(path_, mf + ".pbrMetallicRoughness.baseColorFactor", "not finite");
            look.base_color_factor[i] = f;
        }
        const tinygltf::TextureInfo& base = pbr.baseColorTexture;
        if (base.index >= 0) {
            const std::string bf = mf + ".pbrMetallicRoughness.baseColorTexture";
            if (base.texCoord < 0) fail(path_, bf + ".texCoord", "expected a TEXCOORD_n set, n >= 0");
            look.texcoord = base.texCoord;
            if (const auto t = base.extensions.find("KHR_texture_transform"); t != base.extensions.end()) {
                read_texture_transform(t->second, path_, bf + ".extensions.KHR_texture_transform", look);
            }
        }
        if (gmat.alphaMode == "MASK") {
            look.alpha_mode = AlphaMode::Mask;
        } else if (gmat.alphaMode == "BLEND") {
            look.alpha_mode = AlphaMode::Blend;
        } else if (gmat.alphaMode != "OPAQUE") {
            fail(path_, mf + ".alphaMode", "'" + gmat.alphaMode + "' is none of OPAQUE, MASK, BLEND");
        }
        if (!std::isfinite(float(gmat.alphaCutoff)) || gmat.alphaCutoff < 0.0) {
            fail(path_, mf + ".alphaCutoff", "expected a number >= 0");
        }
        look.alpha_cutoff = gmat.alphaCutoff;
        look.unlit = gmat.extensions.count("KHR_materials_unlit") > 0;
        o.texture = textures_.of_material(mi);
        textures_.named_of_material(mi, o);
        if (gmat.extras.IsObject() && gmat.extras.Has("uniforms")) {
            o.uniforms = read_uniforms(gmat.extras.Get("uniforms"), path_, mf + ".extras.uniforms");
        }
        return o;
    }

    void read_animations() {
        for (std::size_t ai = 0; ai < m_.animations.size(); ++ai) {
            const tinygltf::Animation& a = m_.animations[ai];
            for (std::size_t ci = 0; ci < a.channels.size(); ++ci) {
                problems_.attempt([&] { read_channel(a, ai, ci); });
            }
        }
        if (scene_.channels.empty()) return;
        // Only what moves needs the node graph at each frame; the camera's node too, if it moves.
    }

    void read_channel(const tinygltf::Animation& a, std::size_t ai, std::size_t ci) {
        const tinygltf::AnimationChannel& ch = a.channels[ci];
        const std::string cf = "animations[" + std::to_string(ai) + "].channels[" + std::to_string(ci) + "]";
        if (ch.target_path == "weights") {
            ++weight_channels_;
            return;
        }
        Channel c;
        if (ch.target_path == "translation") {
            c.path = Channel::Path::Translation;
        } else if (ch.target_path == "rotation")
            c.path = Channel::Path::Rotation;
        else if (ch.target_path == "scale") {
            c.path = Channel::Path::Scale;
        } else {
            fail(path_, cf + ".target.path",
                 "'" + ch.target_path + "' is none of translation, rotation, scale, weights");
        }
        // An extension's target (KHR_animation_pointer): warned as an unimplemented extension.
        if (ch.target_node < 0) return;
        if (std::size_t(ch.target_node) >= m_.nodes.size()) fail(path_, cf + ".target.node", "index out of range");
        const int node = reached_[std::size_t(ch.target_node)];
        if (node < 0) return;  // a node the scene does not show
        if (scene_.nodes[std::size_t(node)].has_matrix) {
            fail(path_, cf + ".target.node",
                 "nodes[" + std::to_string(ch.target_node) +
                     "] has a matrix: glTF animates only "
                     "nodes given by translation, rotation and scale");
        }
        c.node = node;
        if (ch.sampler < 0 || std::size_t(ch.sampler) >= a.samplers.size()) {
            fail(path_, cf + ".sampler", "index out of range");
        }
        const tinygltf::AnimationSampler& s = a.samplers[std::size_t(ch.sampler)];
        const std::string sf = "animations[" + std::to_string(ai) + "].samplers[" + std::to_string(ch.sampler) + "]";
        if (s.interpolation == "LINEAR") {
            c.interpolation = Channel::Interpolation::Linear;
        } else if (s.interpolation == "STEP")
            c.interpolation = Channel::Interpolation::Step;
        else if (s.interpolation == "CUBICSPLINE") {
            c.interpolation = Channel::Interpolation::CubicSpline;
        } else {
            fail(path_, sf + ".interpolation", "'" + s.interpolation + "' is none of LINEAR, STEP, CUBICSPLINE");
        }
        const Floats times =
            read_floats(m_, s.input, path_, sf + ".input", {TINYGLTF_TYPE_SCALAR}, kFloatOnly, limits::kVertices);
        if (times.count == 0) fail(path_, sf + ".input", "no keyframes");
        for (std::size_t k = 0; k < times.count; ++k) {
            if (k > 0 && !(times.values[k] > times.values[k - 1])) {
                fail(path_, sf + ".input", "keyframe times must increase (time " + std::to_string(k) + ")");
            }
            c.times.push_back(times.values[k]);
        }
        const bool cubic = c.interpolation == Channel::Interpolation::CubicSpline;
        if (cubic && times.count < 2) fail(path_, sf, "CUBICSPLINE needs at least two keyframes");
        const Floats values =
            read_floats(m_, s.output, path_, sf + ".output",
                        {c.path == Channel::Path::Rotation ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3},
                        c.path == Channel::Path::Rotation ? kRotationTypes : kPositionTypes, 3 * limits::kVertices);
        if (values.count != times.count * (cubic ? 3 : 1)) {
            fail(path_, sf + ".output",
                 std::to_string(values.count) + " values for " + std::to_string(times.count) + " keyframes (" +
                     (cubic ? "CUBICSPLINE keeps 3 per keyframe" : "one per keyframe") + ")");
        }
        c.values.assign(values.values.begin(), values.values.end());
        scene_.channels.push_back(std::move(c));
    }

    // The camera --camera names (a camera node's name, a camera's name, or an index into
    // cameras[]), else the first camera node in the scene's order, else the default camera.
    void choose_camera() {
        const bool stretch = scene_.camera.stretch;  // the scene's extras
        choose_camera_node();
        scene_.camera.stretch = stretch;
    }

    void choose_camera_node() {
        const std::string& wanted = options_.camera;
        const CameraNode* chosen = cameras_.empty() ? nullptr : &cameras_.front();
        if (!wanted.empty()) {
            chosen = nullptr;
            const bool is_index = !wanted.empty() && std::all_of(wanted.begin(), wanted.end(), [](char ch) {
                return std::isdigit(static_cast<unsigned char>(ch));
            });
            for (const CameraNode& c : cameras_) {
                const tinygltf::Node& n = m_.nodes[std::size_t(c.gltf_node)];
                const bool match = is_index ? wanted.size() < 10 && c.camera == std::stoi(wanted)
                                            : n.name == wanted || m_.cameras[std::size_t(c.camera)].name == wanted;
                if (match) {
                    chosen = &c;
                    break;
                }
            }
            if (!chosen) {
                std::string list;
                for (const CameraNode& c : cameras_) {
                    const std::string& name = m_.nodes[std::size_t(c.gltf_node)].name;
                    list += (list.empty() ? "" : ", ") + std::to_string(c.camera) +
                            (name.empty() ? "" : " '" + name + "'") + " (nodes[" + std::to_string(c.gltf_node) + "])";
                }
                throw CameraOptionError(path_.string() + ": --camera " + wanted +
                                 ": no camera node of that name or cameras[] index" +
                                 (list.empty() ? " (the file has no camera)" : "; the file's cameras: " + list));
            }
        }
        if (!chosen) {
            scene_.camera = framing_camera(scene_);
            if (!checks::is_finite(glm::mat4(scene_.camera.projection(1.0) * scene_.camera.view))) {
                fail(path_, "nodes", "the scene has no camera and its bounds are too large to frame in float");
            }
            return;
        }
        const std::string node_field = indexed("nodes", std::size_t(chosen->gltf_node));
        scene_.camera = read_camera(m_, chosen->camera, chosen->world, path_, node_field);
        const tinygltf::Node& n = m_.nodes[std::size_t(chosen->gltf_node)];
        scene_.camera.name = n.name.empty() ? node_field : n.name;
        scene_.camera_node = chosen->node;
    }

    void warn() {
        const std::string file = path_.string() + ": ";
        if (points_and_lines_.count()) {
            scene_.warnings.push_back(file + "points and lines are not drawn: skipped " + points_and_lines_.on());
        }
        if (morphed_.count()) {
            scene_.warnings.push_back(file + "morph targets are not applied (drawn as the base mesh): " +
                                      morphed_.on());
        }
        if (skinned_nodes_) {
            scene_.warnings.push_back(file + std::to_string(skinned_nodes_) +
                                      " skinned nodes are drawn unskinned, as their meshes stand without their joints");
        }
        if (weight_channels_) {
            scene_.warnings.push_back(file + std::to_string(weight_channels_) +
                                      " animation channels of morph target weights are not played");
        }
    }

    struct CameraNode {
        int gltf_node;  // nodes[]
        int node;       // Scene::nodes
        int camera;     // cameras[]
        glm::dmat4 world;
    };

    const tinygltf::Model& m_;
    const std::filesystem::path& path_;
    const SceneLoadOptions& options_;
    Scene& scene_;
    Problems problems_;
    TextureReader textures_;
    std::vector<int> reached_;  // per glTF node: its Scene::nodes index, -1 until reached
    std::vector<MaterialRead> materials_;
    std::vector<bool> material_read_;
    MaterialRead no_material_;
    std::map<std::pair<std::size_t, std::size_t>, int> mesh_of_;  // (mesh, primitive) -> Scene::meshes, -1 if bad
    std::vector<CameraNode> cameras_;
    std::uint64_t vertices_ = 0, triangles_ = 0;
    Tally points_and_lines_, morphed_;
    std::size_t skinned_nodes_ = 0, weight_channels_ = 0;
};

// The JSON of a .gltf file or of a .glb's JSON chunk, its nesting checked before anything parses it.
std::string_view json_of(std::span<const unsigned char> bytes, bool binary, const std::filesystem::path& path) {
    std::string_view json;
    try {
        json = binary ? checks::glb_json_chunk(bytes)
                      : std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    } catch (const SceneError& e) {
        fail(path, "header", e.what());
    }
    if (checks::json_nesting_depth(json, limits::kJsonDepth) > limits::kJsonDepth) {
        fail(path, "JSON", "objects and arrays nest deeper than " + std::to_string(limits::kJsonDepth) + " levels");
    }
    return json;
}

// tinygltf's model of the file: the files it names read through FileAccess (as `policy` allows),
// its images kept encoded.
tinygltf::Model read_model(std::span<const unsigned char> bytes, std::string_view json, bool binary,
                           const std::filesystem::path& path, const ScenePathPolicy& policy) {
    tinygltf::Model m;
    tinygltf::TinyGLTF loader;
    FileAccess access{path, policy};
    loader.SetFsCallbacks({&FileAccess::exists, &FileAccess::expand, &FileAccess::read, &FileAccess::write, &access});
    loader.SetImageLoader(keep_embedded_image, nullptr);
    std::string err, warn;
    const std::string base(FileAccess::kBase);
    const bool ok = binary ? loader.LoadBinaryFromMemory(&m, &err, &warn, bytes.data(), unsigned(bytes.size()), base)
                           : loader.LoadASCIIFromString(&m, &err, &warn, json.data(), unsigned(json.size()), base);
    if (!ok) {
        // tinygltf names the files it looked for under the base it was given: show the folder.
        std::string what = err.empty() ? warn : err;
        const std::string folder = path.parent_path().empty() ? "." : path.parent_path().string();
        for (std::size_t at; (at = what.find(FileAccess::kBase)) != std::string::npos;) {
            what.replace(at, FileAccess::kBase.size(), folder);
        }
        throw SceneError(path.string() + ": not a valid glTF file: " + what);
    }
    return m;
}

}  // namespace

Scene load_scene(const std::filesystem::path& path, const SceneLoadOptions& options) {
    return parse_scene(read_scene_file(path, limits::kSceneFileBytes, /*follow_symlink=*/true), path, options);
}

Scene parse_scene(std::span<const unsigned char> bytes, const std::filesystem::path& path, const SceneLoadOptions& options) {
    const bool binary = checks::has_glb_magic(bytes);
    if (path.extension() == ".glb" && !binary) fail(path, "header", "a .glb file without the binary glTF magic");
    const std::string_view json = json_of(bytes, binary, path);
    Scene scene;
    scene.file = path;
    std::error_code ec;
    scene.inputs.push_back(std::filesystem::weakly_canonical(path, ec));
    check_uris(json, path, options.paths, scene.inputs);
    const tinygltf::Model m = read_model(bytes, json, binary, path, options.paths);
    check_buffer_views(m, path);
    SceneLoader(m, path, options, scene).load();
    return scene;
}

}  // namespace qs
