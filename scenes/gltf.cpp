// The one file that includes tinygltf. What tinygltf does not check (file access, offsets,
// strides, sparse data, the node graph, transforms, counts) is checked here before it is used,
// with the help of scenes/gltf_checks.h and scenes/scene_files.h.
#include "scenes/gltf.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "scenes/gltf_checks.h"
#include "scenes/limits.h"
#include "scenes/scene_files.h"

namespace qs {

namespace {

namespace checks = gltf_checks;

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& field, const std::string& what) {
    throw SceneError(file.string() + ": " + field + ": " + what);
}

std::string indexed(const std::string& array, std::size_t i) { return array + "[" + std::to_string(i) + "]"; }

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

// ---- buffers and accessors ------------------------------------------------------------------

// Buffer views lie inside their buffers and have strides glTF allows; checked once for all,
// before any accessor reads through them.
void check_buffer_views(const tinygltf::Model& m, const std::filesystem::path& file) {
    for (std::size_t i = 0; i < m.bufferViews.size(); ++i) {
        const tinygltf::BufferView& v = m.bufferViews[i];
        const std::string field = indexed("bufferViews", i);
        if (v.buffer < 0 || std::size_t(v.buffer) >= m.buffers.size()) fail(file, field + ".buffer", "index out of range");
        const auto end = checks::checked_add(v.byteOffset, v.byteLength);
        const std::size_t size = m.buffers[std::size_t(v.buffer)].data.size();
        if (!end || *end > size) {
            fail(file, field, "bytes " + std::to_string(v.byteOffset) + " + " + std::to_string(v.byteLength) +
                                  " reach past the end of buffers[" + std::to_string(v.buffer) + "] (" +
                                  std::to_string(size) + " bytes)");
        }
        if (v.byteStride != 0 && (v.byteStride < 4 || v.byteStride > 252 || v.byteStride % 4 != 0)) {
            fail(file, field + ".byteStride", std::to_string(v.byteStride) + " is not a multiple of 4 in 4..252");
        }
    }
}

// An accessor's elements, tightly packed, sparse substitutions applied.
struct AccessorData {
    std::vector<unsigned char> bytes;
    std::size_t count = 0, element = 0;
    int component_type = 0;
    const unsigned char* at(std::size_t i) const { return bytes.data() + i * element; }
};

// Bytes [offset, offset + (count - 1) stride + element) of buffer view `view`, checked.
const unsigned char* view_range(const tinygltf::Model& m, int view, std::uint64_t offset, std::uint64_t count,
                                std::uint64_t stride, std::uint64_t element, const std::filesystem::path& file,
                                const std::string& field) {
    if (view < 0 || std::size_t(view) >= m.bufferViews.size()) fail(file, field + ".bufferView", "index out of range");
    const tinygltf::BufferView& v = m.bufferViews[std::size_t(view)];
    const auto end = checks::strided_end(offset, count, stride, element);
    if (!end || *end > v.byteLength) {
        fail(file, field, std::to_string(count) + " elements of " + std::to_string(element) + " bytes, " +
                              std::to_string(stride) + " apart from byte " + std::to_string(offset) +
                              ", reach past the end of bufferViews[" + std::to_string(view) + "] (" +
                              std::to_string(v.byteLength) + " bytes)");
    }
    return m.buffers[std::size_t(v.buffer)].data.data() + v.byteOffset;  // v checked by check_buffer_views
}

std::uint32_t read_index(const unsigned char* p, int component_type) {
    if (component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) return *p;
    if (component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
        std::uint16_t s;
        std::memcpy(&s, p, 2);
        return s;
    }
    std::uint32_t v;
    std::memcpy(&v, p, 4);
    return v;
}

bool is_index_type(int component_type) {
    return component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
           component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
           component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

AccessorData read_accessor(const tinygltf::Model& m, int index, const std::filesystem::path& file,
                           const std::string& field, int want_type, std::initializer_list<int> want_components,
                           std::uint64_t max_count) {
    if (index < 0 || std::size_t(index) >= m.accessors.size()) fail(file, field, "accessor index out of range");
    const tinygltf::Accessor& a = m.accessors[std::size_t(index)];
    const std::string af = indexed("accessors", std::size_t(index));
    if (a.type != want_type) fail(file, field, af + " has the wrong element type");
    bool component_ok = false;
    for (int c : want_components) component_ok |= a.componentType == c;
    if (!component_ok) fail(file, field, af + " has an unsupported component type " + std::to_string(a.componentType));
    if (a.count > max_count) {
        fail(file, af + ".count", std::to_string(a.count) + " is more than the " + std::to_string(max_count) +
                                      " quadshade accepts");
    }
    AccessorData d;
    d.count = a.count;
    d.component_type = a.componentType;
    d.element = std::size_t(tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType))) *
                std::size_t(tinygltf::GetNumComponentsInType(std::uint32_t(a.type)));
    d.bytes.assign(d.count * d.element, 0);  // no buffer view: zeros (sparse data may follow)
    if (a.bufferView >= 0) {
        if (std::size_t(a.bufferView) >= m.bufferViews.size()) fail(file, af + ".bufferView", "index out of range");
        const std::size_t view_stride = m.bufferViews[std::size_t(a.bufferView)].byteStride;
        const std::size_t stride = view_stride ? view_stride : d.element;
        if (stride < d.element) fail(file, af, "byteStride " + std::to_string(stride) + " is less than an element");
        const unsigned char* base = view_range(m, a.bufferView, a.byteOffset, d.count, stride, d.element, file, af);
        for (std::size_t i = 0; i < d.count; ++i) std::memcpy(&d.bytes[i * d.element], base + a.byteOffset + i * stride, d.element);
    }
    if (a.sparse.isSparse) {
        const auto& s = a.sparse;
        const std::string sf = af + ".sparse";
        if (s.count < 1 || std::uint64_t(s.count) > d.count) {
            fail(file, sf + ".count", std::to_string(s.count) + " is not in 1.." + std::to_string(d.count));
        }
        if (!is_index_type(s.indices.componentType)) fail(file, sf + ".indices.componentType", "not an unsigned integer type");
        if (s.indices.byteOffset < 0) fail(file, sf + ".indices.byteOffset", "negative");
        if (s.values.byteOffset < 0) fail(file, sf + ".values.byteOffset", "negative");
        const std::size_t index_size = std::size_t(tinygltf::GetComponentSizeInBytes(std::uint32_t(s.indices.componentType)));
        const unsigned char* indices = view_range(m, s.indices.bufferView, std::uint64_t(s.indices.byteOffset),
                                                  std::uint64_t(s.count), index_size, index_size, file, sf + ".indices");
        const unsigned char* values = view_range(m, s.values.bufferView, std::uint64_t(s.values.byteOffset),
                                                 std::uint64_t(s.count), d.element, d.element, file, sf + ".values");
        indices += s.indices.byteOffset, values += s.values.byteOffset;
        std::int64_t previous = -1;
        for (std::size_t k = 0; k < std::size_t(s.count); ++k) {
            const std::uint32_t i = read_index(indices + k * index_size, s.indices.componentType);
            if (std::int64_t(i) <= previous || i >= d.count) {
                fail(file, sf + ".indices", "index " + std::to_string(i) + " at position " + std::to_string(k) +
                                                " does not increase or is not below count " + std::to_string(d.count));
            }
            previous = i;
            std::memcpy(&d.bytes[i * d.element], values + k * d.element, d.element);
        }
    }
    return d;
}

Mesh read_primitive(const tinygltf::Model& m, std::size_t mi, std::size_t pi, const std::filesystem::path& file,
                    std::uint64_t vertices_left) {
    const tinygltf::Primitive& p = m.meshes[mi].primitives[pi];
    const std::string field = "meshes[" + std::to_string(mi) + "].primitives[" + std::to_string(pi) + "]";
    if (p.mode != -1 && p.mode != TINYGLTF_MODE_TRIANGLES) {
        fail(file, field + ".mode", "only TRIANGLES (4) is supported, found " + std::to_string(p.mode));
    }
    auto pos = p.attributes.find("POSITION");
    if (pos == p.attributes.end()) fail(file, field + ".attributes", "no POSITION");
    const AccessorData pv = read_accessor(m, pos->second, file, field + ".attributes.POSITION", TINYGLTF_TYPE_VEC3,
                                          {TINYGLTF_COMPONENT_TYPE_FLOAT}, vertices_left);
    Mesh mesh;
    mesh.name = m.meshes[mi].name.empty() ? field : m.meshes[mi].name;
    mesh.vertices.resize(pv.count);
    for (std::size_t i = 0; i < pv.count; ++i) {
        float xyz[3];
        std::memcpy(xyz, pv.at(i), sizeof xyz);
        if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2])) {
            fail(file, field + ".attributes.POSITION", "vertex " + std::to_string(i) + " is not finite");
        }
        mesh.vertices[i] = {{xyz[0], xyz[1], xyz[2]}, {0.0f, 0.0f}};
    }
    mesh.has_texcoords = p.attributes.count("TEXCOORD_0") > 0;
    if (auto tc = p.attributes.find("TEXCOORD_0"); tc != p.attributes.end()) {
        const AccessorData tv = read_accessor(m, tc->second, file, field + ".attributes.TEXCOORD_0", TINYGLTF_TYPE_VEC2,
                                              {TINYGLTF_COMPONENT_TYPE_FLOAT}, limits::kVertices);
        if (tv.count != pv.count) fail(file, field + ".attributes.TEXCOORD_0", "count differs from POSITION's");
        for (std::size_t i = 0; i < tv.count; ++i) {
            float st[2];
            std::memcpy(st, tv.at(i), sizeof st);
            if (!std::isfinite(st[0]) || !std::isfinite(st[1])) {
                fail(file, field + ".attributes.TEXCOORD_0", "texcoord " + std::to_string(i) + " is not finite");
            }
            mesh.vertices[i].texcoord = {st[0], st[1]};
        }
    }
    if (p.indices >= 0) {
        const AccessorData iv = read_accessor(m, p.indices, file, field + ".indices", TINYGLTF_TYPE_SCALAR,
                                              {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                               TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                                              3 * limits::kTriangles);
        mesh.indices.resize(iv.count);
        for (std::size_t i = 0; i < iv.count; ++i) {
            const std::uint32_t v = read_index(iv.at(i), iv.component_type);
            if (v >= pv.count) {
                fail(file, field + ".indices", "index " + std::to_string(v) + " at position " + std::to_string(i) +
                                                   " exceeds the " + std::to_string(pv.count) + " vertices");
            }
            mesh.indices[i] = v;
        }
    } else {
        mesh.indices.resize(pv.count);
        for (std::size_t i = 0; i < pv.count; ++i) mesh.indices[i] = std::uint32_t(i);
    }
    if (mesh.indices.size() % 3 != 0) fail(file, field + ".indices", "count is not a multiple of 3");
    return mesh;
}

// ---- nodes and cameras ----------------------------------------------------------------------

// A node's local transform, every number checked: glTF gives them as doubles, and one that does
// not fit in float (a translation of 1e39) would place everything at infinity.
glm::mat4 node_matrix(const tinygltf::Node& n, const std::filesystem::path& file, const std::string& field) {
    auto to_float = [&](double v, const char* what) {
        const float f = float(v);
        if (!std::isfinite(f)) fail(file, field + "." + what, "value " + std::to_string(v) + " is not a finite float");
        return f;
    };
    if (!n.matrix.empty()) {
        if (n.matrix.size() != 16) fail(file, field + ".matrix", "expected 16 numbers");
        glm::mat4 m;
        for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = to_float(n.matrix[std::size_t(i)], "matrix");
        return m;
    }
    glm::mat4 m(1.0f);
    if (!n.translation.empty()) {
        if (n.translation.size() != 3) fail(file, field + ".translation", "expected 3 numbers");
        m = glm::translate(m, glm::vec3(to_float(n.translation[0], "translation"), to_float(n.translation[1], "translation"),
                                        to_float(n.translation[2], "translation")));
    }
    if (!n.rotation.empty()) {
        if (n.rotation.size() != 4) fail(file, field + ".rotation", "expected 4 numbers");
        glm::quat q(to_float(n.rotation[3], "rotation"), to_float(n.rotation[0], "rotation"),
                    to_float(n.rotation[1], "rotation"), to_float(n.rotation[2], "rotation"));
        if (glm::length(q) == 0.0f) fail(file, field + ".rotation", "a zero quaternion is no rotation");
        m = m * glm::mat4_cast(glm::normalize(q));
    }
    if (!n.scale.empty()) {
        if (n.scale.size() != 3) fail(file, field + ".scale", "expected 3 numbers");
        m = glm::scale(m, glm::vec3(to_float(n.scale[0], "scale"), to_float(n.scale[1], "scale"), to_float(n.scale[2], "scale")));
    }
    return m;
}

Camera read_camera(const tinygltf::Model& m, int index, const glm::mat4& world, const std::filesystem::path& file,
                   const std::string& node_field) {
    if (std::size_t(index) >= m.cameras.size()) fail(file, node_field + ".camera", "index out of range");
    if (!checks::places_things(world)) {
        fail(file, node_field, "the camera's transform is not finite or is degenerate (determinant " +
                                   std::to_string(checks::determinant(world)) + "): it sees nothing");
    }
    const tinygltf::Camera& c = m.cameras[std::size_t(index)];
    const std::string cf = indexed("cameras", std::size_t(index));
    Camera cam;
    cam.view = glm::inverse(world);
    if (!checks::is_finite(cam.view)) fail(file, node_field, "the camera's transform cannot be inverted in float");
    auto finite_float = [](double v) { return std::isfinite(float(v)); };
    if (c.type == "perspective") {
        cam.yfov = float(c.perspective.yfov);
        cam.znear = float(c.perspective.znear);
        cam.zfar = c.perspective.zfar > 0.0 ? float(c.perspective.zfar) : 1e6f;
        if (!(cam.yfov > 1e-6f && cam.yfov < 3.14159f)) fail(file, cf + ".perspective.yfov", "must be in (0, pi)");
        if (!finite_float(c.perspective.znear) || !finite_float(c.perspective.zfar) ||
            !(cam.znear > 0.0f && cam.zfar > cam.znear)) {
            fail(file, cf + ".perspective", "needs finite 0 < znear < zfar");
        }
    } else if (c.type == "orthographic") {
        cam.kind = Camera::Kind::Orthographic;
        cam.xmag = float(c.orthographic.xmag), cam.ymag = float(c.orthographic.ymag);
        cam.znear = float(c.orthographic.znear), cam.zfar = float(c.orthographic.zfar);
        for (const float v : {cam.xmag, cam.ymag}) {
            if (!std::isfinite(v) || v == 0.0f || !std::isfinite(1.0f / v)) {
                fail(file, cf + ".orthographic", "xmag and ymag must be finite and non-zero");
            }
        }
        if (!std::isfinite(cam.znear) || !std::isfinite(cam.zfar) || !(cam.zfar > cam.znear) ||
            !std::isfinite(2.0f / (cam.znear - cam.zfar))) {
            fail(file, cf + ".orthographic", "needs finite znear < zfar");
        }
    } else {
        fail(file, cf + ".type", "unknown camera type '" + c.type + "'");
    }
    if (!checks::is_finite(cam.projection(1.0f) * cam.view)) {
        fail(file, cf, "its projection of " + node_field + "'s view is not finite");
    }
    return cam;
}

double number_of(const tinygltf::Value& v) { return v.IsInt() ? double(v.Get<int>()) : v.Get<double>(); }

// tinygltf's image callback: keep the encoded bytes of a data: URI (the only place they are
// kept), decode nothing. Files are read, and bufferViews sliced, when a texture is first used.
bool keep_embedded_image(tinygltf::Image* image, int, std::string*, std::string*, int, int, const unsigned char* bytes,
                         int size, void*) {
    if (image->uri.empty() && image->bufferView < 0) image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

// RFC 4648 base64, for data: URIs.
std::string base64(const std::vector<std::uint8_t>& bytes) {
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
        std::uint32_t v = std::uint32_t(bytes[i]) << 16;
        if (n > 1) v |= std::uint32_t(bytes[i + 1]) << 8;
        if (n > 2) v |= bytes[i + 2];
        for (std::size_t k = 0; k < 4; ++k) out += k <= n ? digits[(v >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

// tinygltf's image writer: write no file, keep each image's URI (or bufferView) as it is.
bool keep_image_uri(const std::string*, const std::string*, const tinygltf::Image*, bool, std::string*, void*) { return false; }

// A material's extras.uniforms: {"uScale": 4.0, "uTint": [1, 0.5, 0.2], ...}, each a number or
// an array of 2 to 16 numbers (matrices column by column).
std::vector<UniformSetting> read_uniforms(const tinygltf::Value& v, const std::filesystem::path& file, const std::string& field) {
    if (!v.IsObject()) fail(file, field, "expected an object of uniform names and values");
    std::vector<UniformSetting> out;
    for (const std::string& name : v.Keys()) {
        const std::string f = field + "." + name;
        if (!is_uniform_name(name)) fail(file, f, "'" + name + "' is not a GLSL uniform name");
        if (name == kResolutionUniform) fail(file, f, "uResolution is the frame's size, set by the renderer (scenes[].extras.size, --size)");
        UniformSetting s{name, {}, file.string() + ": " + f};
        const tinygltf::Value& x = v.Get(name);
        auto number = [&](const tinygltf::Value& n, const std::string& where) {
            if (!n.IsNumber()) fail(file, where, "expected a number");
            const double d = n.GetNumberAsDouble();
            if (!std::isfinite(d)) fail(file, where, "not a finite number");
            s.values.push_back(d);
        };
        if (x.IsArray()) {
            if (x.ArrayLen() < 1 || x.ArrayLen() > 16) fail(file, f, "expected 1 to 16 numbers");
            for (std::size_t i = 0; i < x.ArrayLen(); ++i) number(x.Get(int(i)), f + "[" + std::to_string(i) + "]");
        } else {
            number(x, f);
        }
        out.push_back(std::move(s));
    }
    return out;
}

// The file an image URI names: percent-decoded (RFC 3986, as glTF requires) and resolved by
// resolve_scene_uri (check_uris has already refused what it refuses, naming the field).
std::filesystem::path resolve_image_uri(const std::filesystem::path& scene_file, const std::string& uri,
                                        const ScenePathPolicy& policy, const std::string& field) {
    try {
        return resolve_scene_uri(scene_file, checks::percent_decoded(uri), policy);
    } catch (const SceneError& e) {
        fail(scene_file, field, e.what());
    }
}

// The textures the objects' materials bind to `teximage`, each made once.
class TextureReader {
public:
    TextureReader(const tinygltf::Model& m, const std::filesystem::path& file, const ScenePathPolicy& policy, Scene& scene)
        : m_(m), file_(file), policy_(policy), scene_(scene) {}

    // Material `mi`'s texture: extras.teximage if it names a file (with the baseColorTexture's
    // sampler, if any), else pbrMetallicRoughness.baseColorTexture; -1 for neither.
    int of_material(int mi) {
        const tinygltf::Material& mat = m_.materials[std::size_t(mi)];
        const std::string mf = "materials[" + std::to_string(mi) + "]";
        const tinygltf::TextureInfo& base = mat.pbrMetallicRoughness.baseColorTexture;
        const std::string base_field = mf + ".pbrMetallicRoughness.baseColorTexture";
        if (base.index >= 0 && base.texCoord != 0) {
            fail(file_, base_field + ".texCoord", "only TEXCOORD_0 is supported, found " + std::to_string(base.texCoord));
        }
        if (mat.extras.IsObject() && mat.extras.Has("teximage")) {
            const tinygltf::Value& v = mat.extras.Get("teximage");
            if (!v.IsString()) fail(file_, mf + ".extras.teximage", "expected a file name");
            Texture t;
            t.field = mf + ".extras.teximage";
            t.image = named_file(v.Get<std::string>(), t.field);
            if (base.index >= 0) t.sampler = sampler_of(texture_at(base.index, base_field), base_field);
            for (std::size_t i = 0; i < scene_.textures.size(); ++i) {  // the same file and sampler: one texture
                const Texture& o = scene_.textures[i];
                if (o.image.kind == ImageSource::Kind::File && o.image.file == t.image.file && o.sampler == t.sampler) return int(i);
            }
            return add(std::move(t));
        }
        if (base.index < 0) return -1;
        const auto [it, fresh] = gltf_textures_.try_emplace(base.index, -1);
        if (fresh) it->second = add(read_texture(base.index, base_field));
        return it->second;
    }

    // Material `mi`'s extras.textures (gltf.h): each uniform's texture. One named `teximage`
    // replaces `teximage` (the material's baseColorTexture) as extras.teximage does, which it
    // may not accompany.
    void named_of_material(int mi, Object& o) {
        const tinygltf::Material& mat = m_.materials[std::size_t(mi)];
        if (!mat.extras.IsObject() || !mat.extras.Has("textures")) return;
        const std::string mf = "materials[" + std::to_string(mi) + "].extras";
        const tinygltf::Value& all = mat.extras.Get("textures");
        if (!all.IsObject()) fail(file_, mf + ".textures", "expected an object of sampler names");
        for (const std::string& name : all.Keys()) {
            const std::string field = mf + ".textures." + name;
            if (name.empty() || name.rfind("gl_", 0) == 0 ||
                !std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }) ||
                std::isdigit(static_cast<unsigned char>(name[0]))) {
                fail(file_, mf + ".textures", "'" + name + "' is not a GLSL identifier");
            }
            const int t = binding(all.Get(name), field);
            if (name == "teximage") {
                if (mat.extras.Has("teximage")) fail(file_, field, "teximage is bound twice (extras.teximage too)");
                if (scene_.textures[std::size_t(t)].dims != 2) fail(file_, field, "teximage is a sampler2D: no depth");
                o.texture = t;
            } else {
                o.samplers.push_back({name, t});
            }
        }
    }

private:
    // An image file a material names (extras.teximage, extras.textures): a file name, not a URI,
    // so not percent-decoded; resolved as every file a scene names (the file need not exist: a
    // texture is read only when a shader samples it).
    ImageSource named_file(const std::string& name, const std::string& field) {
        ImageSource image;
        try {
            image.file = resolve_scene_uri(file_, name, policy_);
        } catch (const SceneError& e) {
            fail(file_, field, e.what());
        }
        scene_.inputs.push_back(image.file);
        return image;
    }

    // One binding of extras.textures: a glTF texture index, an image file, or an object of them
    // with a sampler, a depth and wrapR.
    int binding(const tinygltf::Value& v, const std::string& field) {
        if (v.IsInt() || v.IsNumber()) return texture_index(v, field, Sampler{}, false, 2, 1);
        if (v.IsString()) return file_texture(v.Get<std::string>(), field, Sampler{}, 2, 1);
        if (!v.IsObject()) fail(file_, field, "expected a textures[] index, an image file name or an object");
        for (const std::string& key : v.Keys()) {
            if (key != "texture" && key != "image" && key != "sampler" && key != "depth" && key != "wrapR") {
                fail(file_, field + "." + key, "unknown key (texture, image, sampler, depth, wrapR)");
            }
        }
        if (v.Has("texture") == v.Has("image")) fail(file_, field, "needs exactly one of texture (an index) and image (a file)");
        int dims = 2, depth = 1;
        if (v.Has("depth")) {
            const tinygltf::Value& d = v.Get("depth");
            if (!d.IsInt() || d.Get<int>() < 1 || d.Get<int>() > 2048) fail(file_, field + ".depth", "expected a slice count in 1..2048");
            dims = 3, depth = d.Get<int>();
        }
        Sampler sampler;
        const bool own_sampler = v.Has("sampler");
        if (own_sampler) {
            const tinygltf::Value& si = v.Get("sampler");
            if (!si.IsInt()) fail(file_, field + ".sampler", "expected a samplers[] index");
            sampler = sampler_at(si.Get<int>(), field + ".sampler");
        }
        if (v.Has("wrapR")) {
            if (dims != 3) fail(file_, field + ".wrapR", "only a 3D texture (with a depth) has an r axis");
            const tinygltf::Value& w = v.Get("wrapR");
            sampler.wrap_r = wrap_of(w.IsInt() ? w.Get<int>() : -1, field + ".wrapR");
        }
        if (v.Has("image")) {
            if (!v.Get("image").IsString()) fail(file_, field + ".image", "expected a file name");
            return file_texture(v.Get("image").Get<std::string>(), field + ".image", sampler, dims, depth);
        }
        return texture_index(v.Get("texture"), field + ".texture", sampler, own_sampler, dims, depth);
    }

    int texture_index(const tinygltf::Value& v, const std::string& field, const Sampler& sampler, bool own_sampler, int dims,
                      int depth) {
        if (!v.IsInt()) fail(file_, field, "expected a textures[] index");
        Texture t = read_texture(v.Get<int>(), field);
        const Wrap wrap_r = sampler.wrap_r;
        if (own_sampler) t.sampler = sampler;
        t.sampler.wrap_r = wrap_r;
        t.dims = dims, t.depth = depth;
        return add_once(std::move(t));
    }

    int file_texture(const std::string& uri, const std::string& field, const Sampler& sampler, int dims, int depth) {
        Texture t;
        t.field = field;
        t.image = named_file(uri, field);
        t.sampler = sampler;
        t.dims = dims, t.depth = depth;
        return add_once(std::move(t));
    }

    // The same image, sampler and shape: one texture (its first field names it).
    int add_once(Texture t) {
        for (std::size_t i = 0; i < scene_.textures.size(); ++i) {
            Texture o = scene_.textures[i];
            o.field = t.field;
            if (o == t) return int(i);
        }
        return add(std::move(t));
    }

    const tinygltf::Texture& texture_at(int index, const std::string& field) const {
        if (std::size_t(index) >= m_.textures.size()) fail(file_, field + ".index", "texture index out of range");
        return m_.textures[std::size_t(index)];
    }

    Texture read_texture(int index, const std::string& field) const {
        const tinygltf::Texture& gt = texture_at(index, field);
        const std::string tf = "textures[" + std::to_string(index) + "]";
        if (gt.source < 0 || std::size_t(gt.source) >= m_.images.size()) {
            fail(file_, tf + ".source", gt.source < 0 ? "no image (only PNG/JPEG sources are supported)" : "image index out of range");
        }
        const tinygltf::Image& image = m_.images[std::size_t(gt.source)];
        Texture t;
        t.field = field + " (" + tf + ", images[" + std::to_string(gt.source) + "])";
        t.sampler = sampler_of(gt, field);
        t.image.mime_type = image.mimeType;
        if (image.bufferView >= 0) {
            t.image.kind = ImageSource::Kind::BufferView;
            const std::string vf = "images[" + std::to_string(gt.source) + "].bufferView";
            if (std::size_t(image.bufferView) >= m_.bufferViews.size()) fail(file_, vf, "index out of range");
            const tinygltf::BufferView& v = m_.bufferViews[std::size_t(image.bufferView)];
            if (v.buffer < 0 || std::size_t(v.buffer) >= m_.buffers.size()) fail(file_, vf, "buffer view has no buffer");
            const std::vector<unsigned char>& b = m_.buffers[std::size_t(v.buffer)].data;
            if (v.byteOffset > b.size() || v.byteLength > b.size() - v.byteOffset) {
                fail(file_, vf, "reaches past the end of its buffer");
            }
            t.image.bytes.assign(b.begin() + std::ptrdiff_t(v.byteOffset), b.begin() + std::ptrdiff_t(v.byteOffset + v.byteLength));
        } else if (image.uri.empty()) {
            t.image.kind = ImageSource::Kind::DataUri;
            t.image.bytes.assign(image.image.begin(), image.image.end());
            if (t.image.bytes.empty()) fail(file_, "images[" + std::to_string(gt.source) + "].uri", "empty data: URI");
        } else {
            t.image.file = resolve_image_uri(file_, image.uri, policy_, "images[" + std::to_string(gt.source) + "].uri");
        }
        return t;
    }

    // The texture's sampler, glTF's defaults where it gives none, its values checked.
    Sampler sampler_of(const tinygltf::Texture& gt, const std::string& field) const {
        if (gt.sampler < 0) return Sampler{};
        return sampler_at(gt.sampler, field + " sampler");
    }

    Wrap wrap_of(int v, const std::string& field) const {
        if (v != int(Wrap::Repeat) && v != int(Wrap::MirroredRepeat) && v != int(Wrap::ClampToEdge)) {
            fail(file_, field, "unknown wrap mode " + std::to_string(v) + " (10497, 33648 or 33071)");
        }
        return Wrap(v);
    }

    // samplers[index], `field` naming where the index came from.
    Sampler sampler_at(int index, const std::string& field) const {
        Sampler s;
        const std::string sf = "samplers[" + std::to_string(index) + "]";
        if (index < 0 || std::size_t(index) >= m_.samplers.size()) fail(file_, field, sf + " is out of range");
        const tinygltf::Sampler& g = m_.samplers[std::size_t(index)];
        s.wrap_s = wrap_of(g.wrapS, sf + ".wrapS");
        s.wrap_t = wrap_of(g.wrapT, sf + ".wrapT");
        if (g.magFilter != -1) {
            if (g.magFilter != int(Filter::Nearest) && g.magFilter != int(Filter::Linear)) {
                fail(file_, sf + ".magFilter", "unknown filter " + std::to_string(g.magFilter) + " (9728 or 9729)");
            }
            s.mag_filter = Filter(g.magFilter);
        }
        if (g.minFilter != -1) {
            if (g.minFilter != int(Filter::Nearest) && g.minFilter != int(Filter::Linear) &&
                (g.minFilter < int(Filter::NearestMipmapNearest) || g.minFilter > int(Filter::LinearMipmapLinear))) {
                fail(file_, sf + ".minFilter", "unknown filter " + std::to_string(g.minFilter) + " (9728, 9729 or 9984-9987)");
            }
            s.min_filter = Filter(g.minFilter);
        }
        return s;
    }

    int add(Texture t) {
        scene_.textures.push_back(std::move(t));
        return int(scene_.textures.size() - 1);
    }

    const tinygltf::Model& m_;
    const std::filesystem::path& file_;
    const ScenePathPolicy& policy_;
    Scene& scene_;
    std::map<int, int> gltf_textures_;  // glTF texture index -> Scene::textures
};

// For a file without a camera: glTF's front view (looking down -Z, +Y up) at the bounding
// sphere of everything in the scene, with a 45 degree vertical field of view.
Camera framing_camera(const Scene& scene) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const Object& o : scene.objects) {
        for (const Vertex& v : scene.meshes[o.mesh].vertices) {
            const glm::vec3 p = glm::vec3(o.world_from_object * glm::vec4(v.position, 1.0f));
            lo = glm::min(lo, p), hi = glm::max(hi, p);
        }
    }
    const glm::vec3 centre = 0.5f * (lo + hi);
    const float radius = std::max(0.5f * glm::length(hi - lo), 1e-6f);
    Camera cam;
    cam.yfov = glm::radians(45.0f);
    const float distance = radius / std::sin(0.5f * cam.yfov) * 1.05f;
    cam.view = glm::lookAt(centre + glm::vec3(0.0f, 0.0f, distance), centre, glm::vec3(0.0f, 1.0f, 0.0f));
    cam.znear = std::max(distance - 1.5f * radius, distance * 1e-3f);
    cam.zfar = distance + 1.5f * radius;
    return cam;
}

void read_scene_extras(const tinygltf::Value& extras, const std::filesystem::path& path, const std::string& field,
                       Scene& scene) {
    if (!extras.IsObject()) return;
    if (extras.Has("clear_color")) {
        const tinygltf::Value& c = extras.Get("clear_color");
        if (!c.IsArray() || c.ArrayLen() != 4) fail(path, field + ".clear_color", "expected 4 numbers");
        for (int i = 0; i < 4; ++i) {
            if (!c.Get(i).IsNumber() || !std::isfinite(float(number_of(c.Get(i))))) {
                fail(path, field + ".clear_color", "expected 4 finite numbers");
            }
            scene.clear_color[i] = float(number_of(c.Get(i)));
        }
    }
    if (extras.Has("time")) {
        const tinygltf::Value& t = extras.Get("time");
        if (!t.IsNumber() || !std::isfinite(float(number_of(t)))) fail(path, field + ".time", "expected a finite number");
        scene.time = float(number_of(t));
    }
    if (extras.Has("size")) {
        const tinygltf::Value& s = extras.Get("size");
        if (!s.IsArray() || s.ArrayLen() != 2 || !s.Get(0).IsInt() || !s.Get(1).IsInt()) {
            fail(path, field + ".size", "expected [width, height] integers");
        }
        scene.width = s.Get(0).Get<int>(), scene.height = s.Get(1).Get<int>();
        if (scene.width <= 0 || scene.height <= 0 || scene.width > limits::kImageSide || scene.height > limits::kImageSide) {
            fail(path, field + ".size", std::to_string(scene.width) + "x" + std::to_string(scene.height) +
                                            " is outside 1.." + std::to_string(limits::kImageSide));
        }
    }
}

}  // namespace

Scene load_scene(const std::filesystem::path& path, const SceneLoadOptions& options) {
    return parse_scene(read_scene_file(path, limits::kSceneFileBytes, /*follow_symlink=*/true), path, options);
}

Scene parse_scene(std::span<const unsigned char> bytes, const std::filesystem::path& path, const SceneLoadOptions& options) {
    const bool binary = checks::has_glb_magic(bytes);
    if (path.extension() == ".glb" && !binary) fail(path, "header", "a .glb file without the binary glTF magic");
    std::string_view json;
    try {
        json = binary ? checks::glb_json_chunk(bytes) : std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    } catch (const SceneError& e) {
        fail(path, "header", e.what());
    }
    if (checks::json_nesting_depth(json, limits::kJsonDepth) > limits::kJsonDepth) {
        fail(path, "JSON", "objects and arrays nest deeper than " + std::to_string(limits::kJsonDepth) + " levels");
    }
    Scene scene;
    scene.file = path;
    std::error_code ec;
    scene.inputs.push_back(std::filesystem::weakly_canonical(path, ec));
    check_uris(json, path, options.paths, scene.inputs);

    tinygltf::Model m;
    tinygltf::TinyGLTF loader;
    FileAccess access{path, options.paths};
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
        for (std::size_t at; (at = what.find(FileAccess::kBase)) != std::string::npos;) what.replace(at, FileAccess::kBase.size(), folder);
        throw SceneError(path.string() + ": not a valid glTF file: " + what);
    }
    check_buffer_views(m, path);
    // glTF: a loader must refuse a file that requires an extension it does not implement.
    for (std::size_t i = 0; i < m.extensionsRequired.size(); ++i) {
        fail(path, "extensionsRequired[" + std::to_string(i) + "]",
             "'" + m.extensionsRequired[i] + "' is required but not supported (quadshade implements no extension)");
    }

    const int scene_index = m.defaultScene >= 0 ? m.defaultScene : 0;
    if (m.scenes.empty() || std::size_t(scene_index) >= m.scenes.size()) fail(path, "scenes", "no scene to render");
    const tinygltf::Scene& gs = m.scenes[std::size_t(scene_index)];
    read_scene_extras(gs.extras, path, indexed("scenes", std::size_t(scene_index)) + ".extras", scene);

    std::map<std::pair<std::size_t, std::size_t>, std::size_t> mesh_of;  // (mesh, primitive) -> Scene::meshes
    TextureReader textures(m, path, options.paths, scene);
    std::vector<bool> reached(m.nodes.size(), false);
    std::uint64_t vertices = 0, triangles = 0;
    bool have_camera = false;
    std::function<void(int, const glm::mat4&, int)> visit = [&](int ni, const glm::mat4& parent, int depth) {
        if (ni < 0 || std::size_t(ni) >= m.nodes.size()) fail(path, "nodes", "node index " + std::to_string(ni) + " out of range");
        const std::string node_field = indexed("nodes", std::size_t(ni));
        if (reached[std::size_t(ni)]) {
            fail(path, node_field, "is reached twice (a cycle, or a child of two parents): glTF nodes form trees");
        }
        reached[std::size_t(ni)] = true;
        if (depth > limits::kNodeDepth) {
            fail(path, node_field, "lies deeper than " + std::to_string(limits::kNodeDepth) + " levels below the scene's root");
        }
        const tinygltf::Node& n = m.nodes[std::size_t(ni)];
        const glm::mat4 world = parent * node_matrix(n, path, node_field);
        if (!checks::is_finite(world)) fail(path, node_field, "its world transform is not finite (too large for float)");
        if (n.camera >= 0 && !have_camera) {
            scene.camera = read_camera(m, n.camera, world, path, node_field);
            have_camera = true;
        }
        if (n.mesh >= 0) {
            if (std::size_t(n.mesh) >= m.meshes.size()) fail(path, node_field + ".mesh", "index out of range");
            if (!checks::places_things(world)) {
                fail(path, node_field, "its world transform is degenerate (determinant " +
                                           std::to_string(checks::determinant(world)) + "): its mesh would be invisible");
            }
            const tinygltf::Mesh& gm = m.meshes[std::size_t(n.mesh)];
            for (std::size_t pi = 0; pi < gm.primitives.size(); ++pi) {
                const auto key = std::make_pair(std::size_t(n.mesh), pi);
                if (!mesh_of.count(key)) {
                    mesh_of[key] = scene.meshes.size();
                    scene.meshes.push_back(read_primitive(m, std::size_t(n.mesh), pi, path, limits::kVertices - vertices));
                    vertices += scene.meshes.back().vertices.size();
                }
                Object o;
                o.name = n.name.empty() ? node_field : n.name;
                o.mesh = mesh_of[key];
                o.world_from_object = world;
                triangles += scene.meshes[o.mesh].indices.size() / 3;
                if (triangles > limits::kTriangles || scene.objects.size() >= limits::kObjects) {
                    fail(path, node_field, "the scene draws more than " + std::to_string(limits::kTriangles) +
                                               " triangles or " + std::to_string(limits::kObjects) + " objects");
                }
                const int mat = gm.primitives[pi].material;
                if (mat >= 0) {
                    if (std::size_t(mat) >= m.materials.size()) fail(path, "meshes[" + std::to_string(n.mesh) + "].material", "index out of range");
                    const tinygltf::Material& gmat = m.materials[std::size_t(mat)];
                    const std::string mf = "materials[" + std::to_string(mat) + "].extras";
                    o.material = gmat.name.empty() ? "materials[" + std::to_string(mat) + "]" : gmat.name;
                    o.double_sided = gmat.doubleSided;
                    if (gmat.extras.IsObject() && gmat.extras.Has("shader")) {
                        if (!gmat.extras.Get("shader").IsString()) fail(path, mf + ".shader", "expected a shader name");
                        o.shader = gmat.extras.Get("shader").Get<std::string>();
                    }
                    o.texture = textures.of_material(mat);
                    textures.named_of_material(mat, o);
                    if (gmat.extras.IsObject() && gmat.extras.Has("uniforms")) {
                        o.uniforms = read_uniforms(gmat.extras.Get("uniforms"), path, mf + ".uniforms");
                    }
                }
                scene.objects.push_back(o);
            }
        }
        for (int child : n.children) visit(child, world, depth + 1);
    };
    for (int ni : gs.nodes) visit(ni, glm::mat4(1.0f), 0);
    if (scene.objects.empty()) fail(path, "nodes", "no node carries a mesh");
    if (!have_camera) {
        scene.camera = framing_camera(scene);
        if (!checks::is_finite(scene.camera.projection(1.0f) * scene.camera.view)) {
            fail(path, "nodes", "the scene has no camera and its bounds are too large to frame in float");
        }
    }
    return scene;
}

void save_scene(const Scene& scene, const std::filesystem::path& path, std::span<const SavedNode> nodes) {
    tinygltf::Model m;
    m.asset.version = "2.0";
    m.asset.generator = "quadshade scene generator";
    tinygltf::Buffer buffer;
    auto append = [&](const void* data, std::size_t bytes) {
        while (buffer.data.size() % 4) buffer.data.push_back(0);
        const std::size_t offset = buffer.data.size();
        const auto* p = static_cast<const unsigned char*>(data);
        buffer.data.insert(buffer.data.end(), p, p + bytes);
        tinygltf::BufferView v;
        v.buffer = 0, v.byteOffset = offset, v.byteLength = bytes;
        m.bufferViews.push_back(v);
        return int(m.bufferViews.size() - 1);
    };
    auto accessor = [&](int view, int component, int type, std::size_t count, std::vector<double> mn = {},
                        std::vector<double> mx = {}) {
        tinygltf::Accessor a;
        a.bufferView = view, a.componentType = component, a.type = type, a.count = count;
        a.minValues = std::move(mn), a.maxValues = std::move(mx);
        m.accessors.push_back(a);
        return int(m.accessors.size() - 1);
    };
    for (const Mesh& mesh : scene.meshes) {
        std::vector<float> pos, st;
        std::vector<double> mn(3, 1e30), mx(3, -1e30);
        for (const Vertex& v : mesh.vertices) {
            for (int i = 0; i < 3; ++i) {
                pos.push_back(v.position[i]);
                mn[std::size_t(i)] = std::min(mn[std::size_t(i)], double(v.position[i]));
                mx[std::size_t(i)] = std::max(mx[std::size_t(i)], double(v.position[i]));
            }
            st.push_back(v.texcoord.x), st.push_back(v.texcoord.y);
        }
        tinygltf::Primitive p;
        p.mode = TINYGLTF_MODE_TRIANGLES;
        p.attributes["POSITION"] = accessor(append(pos.data(), pos.size() * 4), TINYGLTF_COMPONENT_TYPE_FLOAT,
                                            TINYGLTF_TYPE_VEC3, mesh.vertices.size(), mn, mx);
        if (mesh.has_texcoords) p.attributes["TEXCOORD_0"] = accessor(append(st.data(), st.size() * 4), TINYGLTF_COMPONENT_TYPE_FLOAT,
                                              TINYGLTF_TYPE_VEC2, mesh.vertices.size());
        p.indices = accessor(append(mesh.indices.data(), mesh.indices.size() * 4),
                             TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, mesh.indices.size());
        tinygltf::Mesh gm;
        gm.name = mesh.name;
        gm.primitives.push_back(p);
        m.meshes.push_back(gm);
    }
    const bool binary = path.extension() == ".glb";
    if (!binary) buffer.uri = path.stem().string() + ".bin";

    tinygltf::Scene gs;
    // Textures as glTF writes them: an image (a file beside the scene, a data: URI or a bufferView),
    // a sampler, and the texture pairing them; materials bind theirs as baseColorTexture.
    for (const Texture& t : scene.textures) {
        tinygltf::Image image;
        image.mimeType = t.image.mime_type;
        switch (t.image.kind) {
            case ImageSource::Kind::File:
                image.uri = std::filesystem::relative(t.image.file, path.parent_path()).generic_string();
                image.mimeType.clear();
                break;
            case ImageSource::Kind::DataUri:
                image.uri = "data:" + t.image.mime_type + ";base64," + base64(t.image.bytes);
                image.mimeType.clear();
                break;
            case ImageSource::Kind::BufferView:
                image.bufferView = append(t.image.bytes.data(), t.image.bytes.size());
                break;
        }
        m.images.push_back(image);
        tinygltf::Sampler sampler;
        sampler.magFilter = int(t.sampler.mag_filter), sampler.minFilter = int(t.sampler.min_filter);
        sampler.wrapS = int(t.sampler.wrap_s), sampler.wrapT = int(t.sampler.wrap_t);
        m.samplers.push_back(sampler);
        tinygltf::Texture texture;
        texture.source = texture.sampler = int(m.images.size() - 1);
        m.textures.push_back(texture);
    }
    std::vector<int> mesh_of_object;
    for (const Object& o : scene.objects) {
        tinygltf::Material mat;
        mat.name = o.name;
        mat.doubleSided = o.double_sided;
        tinygltf::Value::Object extras{{"shader", tinygltf::Value(o.shader)}};
        if (!o.uniforms.empty()) {
            tinygltf::Value::Object uniforms;
            for (const UniformSetting& u : o.uniforms) {
                if (u.values.size() == 1) {
                    uniforms[u.name] = tinygltf::Value(u.values[0]);
                } else {
                    tinygltf::Value::Array a;
                    for (double x : u.values) a.emplace_back(x);
                    uniforms[u.name] = tinygltf::Value(std::move(a));
                }
            }
            extras["uniforms"] = tinygltf::Value(std::move(uniforms));
        }
        mat.extras = tinygltf::Value(std::move(extras));
        mat.pbrMetallicRoughness.baseColorTexture.index = o.texture;
        if (!o.samplers.empty()) {
            tinygltf::Value::Object named;
            for (const SamplerBinding& b : o.samplers) {
                const Texture& t = scene.textures[std::size_t(b.texture)];
                if (t.dims == 2) {
                    named[b.uniform] = tinygltf::Value(b.texture);
                } else {
                    named[b.uniform] = tinygltf::Value(tinygltf::Value::Object{{"texture", tinygltf::Value(b.texture)},
                                                                              {"depth", tinygltf::Value(t.depth)},
                                                                              {"wrapR", tinygltf::Value(int(t.sampler.wrap_r))}});
                }
            }
            tinygltf::Value::Object extras = mat.extras.Get<tinygltf::Value::Object>();
            extras["textures"] = tinygltf::Value(named);
            mat.extras = tinygltf::Value(extras);
        }
        m.materials.push_back(mat);
        // A mesh per object, since glTF puts the material on the primitive.
        tinygltf::Mesh gm = m.meshes[o.mesh];
        gm.name = o.name;
        gm.primitives[0].material = int(m.materials.size() - 1);
        m.meshes.push_back(gm);
        mesh_of_object.push_back(int(m.meshes.size() - 1));
        if (!nodes.empty()) continue;
        tinygltf::Node n;
        n.name = o.name;
        n.mesh = mesh_of_object.back();
        n.matrix.assign(glm::value_ptr(o.world_from_object), glm::value_ptr(o.world_from_object) + 16);
        m.nodes.push_back(n);
        gs.nodes.push_back(int(m.nodes.size() - 1));
    }
    std::vector<int> carried(scene.objects.size(), 0);
    const std::size_t first_node = m.nodes.size();  // glTF index of nodes[0]
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const SavedNode& sn = nodes[i];
        const std::string field = path.string() + ": saving node " + std::to_string(i) + " '" + sn.name + "': ";
        if (sn.parent >= int(i) || sn.parent < -1) throw SceneError(field + "its parent must be an earlier node");
        if (sn.object >= int(scene.objects.size()) || sn.object < -1) throw SceneError(field + "no such object");
        tinygltf::Node n;
        n.name = sn.name;
        if (sn.object >= 0) n.mesh = mesh_of_object[std::size_t(sn.object)], ++carried[std::size_t(sn.object)];
        if (sn.matrix) {
            n.matrix.assign(glm::value_ptr(*sn.matrix), glm::value_ptr(*sn.matrix) + 16);
        } else {
            n.translation = {sn.translation.x, sn.translation.y, sn.translation.z};
            n.rotation = {sn.rotation.x, sn.rotation.y, sn.rotation.z, sn.rotation.w};
            n.scale = {sn.scale.x, sn.scale.y, sn.scale.z};
        }
        m.nodes.push_back(n);
        const int index = int(first_node + i);
        if (sn.parent < 0) gs.nodes.push_back(index);
        else m.nodes[first_node + std::size_t(sn.parent)].children.push_back(index);
    }
    if (!nodes.empty() && std::count(carried.begin(), carried.end(), 1) != std::ptrdiff_t(carried.size())) {
        throw SceneError(path.string() + ": saving nodes: every object must sit on exactly one node");
    }
    // Drop the material-less template meshes: objects' meshes follow them.
    const int templates = int(scene.meshes.size());
    m.meshes.erase(m.meshes.begin(), m.meshes.begin() + templates);
    for (tinygltf::Node& n : m.nodes) {
        if (n.mesh >= 0) n.mesh -= templates;
    }

    tinygltf::Camera cam;
    if (scene.camera.kind == Camera::Kind::Perspective) {
        cam.type = "perspective";
        cam.perspective.yfov = scene.camera.yfov;
        cam.perspective.znear = scene.camera.znear;
        cam.perspective.zfar = scene.camera.zfar;
    } else {
        cam.type = "orthographic";
        cam.orthographic.xmag = scene.camera.xmag, cam.orthographic.ymag = scene.camera.ymag;
        cam.orthographic.znear = scene.camera.znear, cam.orthographic.zfar = scene.camera.zfar;
    }
    m.cameras.push_back(cam);
    tinygltf::Node cn;
    cn.name = "camera";
    cn.camera = 0;
    const glm::mat4 world_from_view = glm::inverse(scene.camera.view);
    cn.matrix.assign(glm::value_ptr(world_from_view), glm::value_ptr(world_from_view) + 16);
    m.nodes.push_back(cn);
    gs.nodes.insert(gs.nodes.begin(), int(m.nodes.size() - 1));

    tinygltf::Value::Array clear;
    for (int i = 0; i < 4; ++i) clear.push_back(tinygltf::Value(double(scene.clear_color[i])));
    gs.extras = tinygltf::Value(tinygltf::Value::Object{
        {"clear_color", tinygltf::Value(clear)},
        {"time", tinygltf::Value(double(scene.time))},
        {"size", tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(scene.width), tinygltf::Value(scene.height)})}});
    m.scenes.push_back(gs);
    m.defaultScene = 0;

    m.buffers.push_back(buffer);  // last: textures above may append to it
    tinygltf::TinyGLTF writer;
    writer.SetImageWriter(keep_image_uri, nullptr);
    if (!writer.WriteGltfSceneToFile(&m, path.string(), false, binary, !binary, binary)) {
        throw SceneError(path.string() + ": cannot write glTF");
    }
}

}  // namespace qs
