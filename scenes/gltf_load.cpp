// load_scene and parse_scene: glTF 2.0 read through tinygltf into the scene model (save_scene, the
// other file that includes tinygltf, is gltf_save.cpp). What tinygltf does not check (file access,
// offsets, strides, sparse data, the node graph, transforms, counts) is checked here before it is
// used, with the help of scenes/gltf_checks.h and scenes/scene_files.h.
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

// ---- attributes ------------------------------------------------------------------------------

// A component type an attribute may have, and whether it is normalized.
struct Component {
    int type;
    bool normalized;
};
constexpr Component kFloat{TINYGLTF_COMPONENT_TYPE_FLOAT, false};
constexpr Component kByteNorm{TINYGLTF_COMPONENT_TYPE_BYTE, true}, kByte{TINYGLTF_COMPONENT_TYPE_BYTE, false};
constexpr Component kUByteNorm{TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, true},
    kUByte{TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, false};
constexpr Component kShortNorm{TINYGLTF_COMPONENT_TYPE_SHORT, true}, kShort{TINYGLTF_COMPONENT_TYPE_SHORT, false};
constexpr Component kUShortNorm{TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, true},
    kUShort{TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, false};

// What glTF 2.0 and KHR_mesh_quantization allow each attribute (and animation and instancing
// data) to be stored as.
const std::initializer_list<Component> kPositionTypes = {kFloat, kByte,      kByteNorm, kUByte,     kUByteNorm,
                                                         kShort, kShortNorm, kUShort,   kUShortNorm};
const std::initializer_list<Component> kNormalTypes = {kFloat, kByteNorm, kShortNorm};
const std::initializer_list<Component> kTexcoordTypes = {kFloat, kByte,      kByteNorm, kUByte,     kUByteNorm,
                                                         kShort, kShortNorm, kUShort,   kUShortNorm};
const std::initializer_list<Component> kColorTypes = {kFloat, kUByteNorm, kUShortNorm};
const std::initializer_list<Component> kRotationTypes = {kFloat, kByteNorm, kUByteNorm, kShortNorm, kUShortNorm};
const std::initializer_list<Component> kFloatOnly = {kFloat};

std::string type_name(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return "SCALAR";
        case TINYGLTF_TYPE_VEC2:
            return "VEC2";
        case TINYGLTF_TYPE_VEC3:
            return "VEC3";
        case TINYGLTF_TYPE_VEC4:
            return "VEC4";
        default:
            return "type " + std::to_string(type);
    }
}

std::string component_name(int component_type, bool normalized) {
    std::string n;
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            n = "BYTE";
            break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            n = "UNSIGNED_BYTE";
            break;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            n = "SHORT";
            break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            n = "UNSIGNED_SHORT";
            break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            n = "UNSIGNED_INT";
            break;
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            n = "FLOAT";
            break;
        default:
            n = std::to_string(component_type);
    }
    return normalized ? n + " normalized" : n;
}

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

Floats read_floats(const tinygltf::Model& m, int index, const std::filesystem::path& file, const std::string& field,
                   std::initializer_list<int> want_types, std::initializer_list<Component> want_components,
                   std::uint64_t max_count, const char* element = "element") {
    if (index < 0 || std::size_t(index) >= m.accessors.size()) fail(file, field, "accessor index out of range");
    const tinygltf::Accessor& a = m.accessors[std::size_t(index)];
    const std::string af = indexed("accessors", std::size_t(index));
    if (std::find(want_types.begin(), want_types.end(), a.type) == want_types.end()) {
        std::string types;
        for (int t : want_types) types += (types.empty() ? "" : " or ") + type_name(t);
        fail(file, field, af + " is " + type_name(a.type) + ", expected " + types);
    }
    const bool normalized = a.normalized && a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT;
    bool allowed = false;
    std::string allowed_list;
    for (const Component& c : want_components) {
        allowed |= c.type == a.componentType && c.normalized == normalized;
        allowed_list += (allowed_list.empty() ? "" : ", ") + component_name(c.type, c.normalized);
    }
    if (!allowed) {
        fail(file, field,
             af + " is " + component_name(a.componentType, normalized) + ", which glTF does not allow here (" +
                 allowed_list + ")");
    }
    const AccessorData d = read_accessor(m, index, file, field, a.type, {a.componentType}, max_count);
    Floats f;
    f.count = d.count;
    f.components = tinygltf::GetNumComponentsInType(std::uint32_t(a.type));
    f.values.resize(d.count * std::size_t(f.components));
    const std::size_t size = std::size_t(tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType)));
    for (std::size_t i = 0; i < f.values.size(); ++i) {
        const unsigned char* p = d.bytes.data() + i * size;
        double v = 0.0;
        switch (a.componentType) {
            case TINYGLTF_COMPONENT_TYPE_FLOAT: {
                float x;
                std::memcpy(&x, p, 4);
                if (!std::isfinite(x)) {
                    fail(file, field,
                         std::string(element) + " " + std::to_string(i / std::size_t(f.components)) + " of " + af +
                             " is not finite");
                }
                f.values[i] = x;
                continue;
            }
            case TINYGLTF_COMPONENT_TYPE_BYTE:
                v = double(std::int8_t(*p));
                if (normalized) v = std::max(v / 127.0, -1.0);
                break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                v = double(*p);
                if (normalized) v /= 255.0;
                break;
            case TINYGLTF_COMPONENT_TYPE_SHORT: {
                std::int16_t s;
                std::memcpy(&s, p, 2);
                v = normalized ? std::max(double(s) / 32767.0, -1.0) : double(s);
                break;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                std::uint16_t s;
                std::memcpy(&s, p, 2);
                v = normalized ? double(s) / 65535.0 : double(s);
                break;
            }
            default:
                break;  // not allowed above
        }
        f.values[i] = float(v);
    }
    return f;
}

// The triangles of a primitive's mode from its vertex indices (TRIANGLES as they are; strips and
// fans unrolled as GL draws them, each triangle's last vertex the one that completes it, the
// provoking vertex GL's last-vertex convention picks).
std::vector<std::uint32_t> triangles_of(int mode, const std::vector<std::uint32_t>& v) {
    std::vector<std::uint32_t> t;
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (std::size_t i = 0; i + 2 < v.size(); ++i) {
            // Odd triangles swap their first two vertices: every triangle winds as the first.
            if (i % 2 == 0) {
                t.insert(t.end(), {v[i], v[i + 1], v[i + 2]});
            } else {
                t.insert(t.end(), {v[i + 1], v[i], v[i + 2]});
            }
        }
    } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        for (std::size_t i = 1; i + 1 < v.size(); ++i) t.insert(t.end(), {v[0], v[i], v[i + 1]});
    } else {
        t = v;
        t.resize(v.size() - v.size() % 3);
    }
    return t;
}

bool is_triangles(int mode) {
    return mode == -1 || mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
           mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

// Primitive `pi` of mesh `mi` as triangles with its attributes. `texcoord1_set`: the TEXCOORD_n
// Vertex::texcoord1 holds (1, or the material's base colour set when that is 2 or more).
Mesh read_primitive(const tinygltf::Model& m, std::size_t mi, std::size_t pi, const std::filesystem::path& file,
                    std::uint64_t vertices_left, int texcoord1_set) {
    const tinygltf::Primitive& p = m.meshes[mi].primitives[pi];
    const std::string field = "meshes[" + std::to_string(mi) + "].primitives[" + std::to_string(pi) + "]";
    if (!is_triangles(p.mode)) fail(file, field + ".mode", "not a triangle mode: " + std::to_string(p.mode));
    auto pos = p.attributes.find("POSITION");
    if (pos == p.attributes.end()) fail(file, field + ".attributes", "no POSITION");
    const Floats pv = read_floats(m, pos->second, file, field + ".attributes.POSITION", {TINYGLTF_TYPE_VEC3},
                                  kPositionTypes, vertices_left, "vertex");
    Mesh mesh;
    mesh.name = m.meshes[mi].name.empty() ? field : m.meshes[mi].name;
    mesh.source = field;
    mesh.vertices.resize(pv.count);
    for (std::size_t i = 0; i < pv.count; ++i) {
        const glm::vec3 xyz(pv.at(i));
        mesh.vertices[i].position = xyz;
        mesh.vertices[i].texcoord = {0.0f, 0.0f};
        if (i == 0) mesh.lower = mesh.upper = xyz;
        mesh.lower = glm::min(mesh.lower, xyz), mesh.upper = glm::max(mesh.upper, xyz);
    }
    // An attribute of the same count as POSITION, read into each vertex by `put`.
    auto attribute = [&](const std::string& name, std::initializer_list<int> types,
                         std::initializer_list<Component> kinds, auto put) {
        const auto it = p.attributes.find(name);
        if (it == p.attributes.end()) return false;
        const std::string af = field + ".attributes." + name;
        const Floats a = read_floats(m, it->second, file, af, types, kinds, limits::kVertices, "vertex");
        if (a.count != pv.count) fail(file, af, "count differs from POSITION's");
        for (std::size_t i = 0; i < a.count; ++i) put(mesh.vertices[i], a.at(i), a.components);
        return true;
    };
    mesh.has_texcoords = attribute("TEXCOORD_0", {TINYGLTF_TYPE_VEC2}, kTexcoordTypes, [](Vertex& v, glm::vec4 a, int) {
        v.texcoord = {a.x, a.y};
    });
    mesh.has_texcoord1 = attribute("TEXCOORD_" + std::to_string(texcoord1_set), {TINYGLTF_TYPE_VEC2}, kTexcoordTypes,
                                   [](Vertex& v, glm::vec4 a, int) {
                                       v.texcoord1 = {a.x, a.y};
                                   });
    mesh.has_normals = attribute("NORMAL", {TINYGLTF_TYPE_VEC3}, kNormalTypes,
                                 [](Vertex& v, glm::vec4 a, int) { v.normal = glm::vec3(a); });
    attribute("COLOR_0", {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, kColorTypes,
              [](Vertex& v, glm::vec4 a, int n) { v.color = n == 3 ? glm::vec4(glm::vec3(a), 1.0f) : a; });
    std::vector<std::uint32_t> order;
    if (p.indices >= 0) {
        const AccessorData iv = read_accessor(m, p.indices, file, field + ".indices", TINYGLTF_TYPE_SCALAR,
                                              {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                               TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                                              3 * limits::kTriangles);
        order.resize(iv.count);
        for (std::size_t i = 0; i < iv.count; ++i) {
            const std::uint32_t v = read_index(iv.at(i), iv.component_type);
            if (v >= pv.count) {
                fail(file, field + ".indices", "index " + std::to_string(v) + " at position " + std::to_string(i) +
                                                   " exceeds the " + std::to_string(pv.count) + " vertices");
            }
            order[i] = v;
        }
    } else {
        order.resize(pv.count);
        for (std::size_t i = 0; i < pv.count; ++i) order[i] = std::uint32_t(i);
    }
    const int mode = p.mode == -1 ? TINYGLTF_MODE_TRIANGLES : p.mode;
    if (mode == TINYGLTF_MODE_TRIANGLES && order.size() % 3 != 0) {
        fail(file, field + (p.indices >= 0 ? ".indices" : ".attributes.POSITION"), "count is not a multiple of 3");
    }
    if (order.size() > 3 * limits::kTriangles) {
        fail(file, field, "more than " + std::to_string(limits::kTriangles) + " triangles");
    }
    mesh.indices = triangles_of(mode, order);
    return mesh;
}

// ---- nodes and cameras ----------------------------------------------------------------------

// A node's local transform, every number checked: glTF gives them as doubles, kept as doubles
// (transforms are composed in double), and one that does not fit in float (a translation of
// 1e39) would place everything at infinity once rounded for drawing.
Node read_node(const tinygltf::Node& n, const std::filesystem::path& file, const std::string& field) {
    auto number = [&](double v, const char* what) {
        if (!std::isfinite(float(v))) {
            fail(file, field + "." + what, "value " + std::to_string(v) + " is not a finite float");
        }
        return v;
    };
    Node node;
    node.name = n.name.empty() ? field : n.name;
    if (!n.matrix.empty()) {
        if (n.matrix.size() != 16) fail(file, field + ".matrix", "expected 16 numbers");
        node.has_matrix = true;
        for (int i = 0; i < 16; ++i) glm::value_ptr(node.matrix)[i] = number(n.matrix[std::size_t(i)], "matrix");
        return node;
    }
    if (!n.translation.empty()) {
        if (n.translation.size() != 3) fail(file, field + ".translation", "expected 3 numbers");
        for (int i = 0; i < 3; ++i) node.translation[i] = number(n.translation[std::size_t(i)], "translation");
    }
    if (!n.rotation.empty()) {
        if (n.rotation.size() != 4) fail(file, field + ".rotation", "expected 4 numbers");
        const glm::dquat q(number(n.rotation[3], "rotation"), number(n.rotation[0], "rotation"),
                           number(n.rotation[1], "rotation"), number(n.rotation[2], "rotation"));
        if (glm::length(q) == 0.0) fail(file, field + ".rotation", "a zero quaternion is no rotation");
        node.rotation = glm::normalize(q);
    }
    if (!n.scale.empty()) {
        if (n.scale.size() != 3) fail(file, field + ".scale", "expected 3 numbers");
        for (int i = 0; i < 3; ++i) node.scale[i] = number(n.scale[std::size_t(i)], "scale");
    }
    return node;
}

Camera read_camera(const tinygltf::Model& m, int index, const glm::dmat4& world, const std::filesystem::path& file,
                   const std::string& node_field) {
    if (std::size_t(index) >= m.cameras.size()) fail(file, node_field + ".camera", "index out of range");
    if (!checks::places_things(glm::mat4(world))) {
        fail(file, node_field,
             "the camera's transform is not finite or is degenerate (determinant " +
                 std::to_string(checks::determinant(glm::mat4(world))) + "): it sees nothing");
    }
    const tinygltf::Camera& c = m.cameras[std::size_t(index)];
    const std::string cf = indexed("cameras", std::size_t(index));
    Camera cam;
    cam.view = glm::inverse(world);
    if (!checks::is_finite(glm::mat4(cam.view))) {
        fail(file, node_field, "the camera's transform cannot be inverted in float");
    }
    auto finite_float = [](double v) { return std::isfinite(float(v)); };
    if (c.type == "perspective") {
        cam.yfov = c.perspective.yfov;
        cam.znear = c.perspective.znear;
        cam.zfar = c.perspective.zfar > 0.0 ? c.perspective.zfar : 1e6;
        cam.aspect_ratio = c.perspective.aspectRatio > 0.0 && finite_float(c.perspective.aspectRatio)
                               ? c.perspective.aspectRatio
                               : 0.0;
        if (!(cam.yfov > 1e-6 && cam.yfov < 3.14159)) fail(file, cf + ".perspective.yfov", "must be in (0, pi)");
        if (!finite_float(c.perspective.znear) || !finite_float(c.perspective.zfar) ||
            !(cam.znear > 0.0 && cam.zfar > cam.znear)) {
            fail(file, cf + ".perspective", "needs finite 0 < znear < zfar");
        }
    } else if (c.type == "orthographic") {
        cam.kind = Camera::Kind::Orthographic;
        cam.xmag = c.orthographic.xmag, cam.ymag = c.orthographic.ymag;
        cam.znear = c.orthographic.znear, cam.zfar = c.orthographic.zfar;
        for (const double v : {cam.xmag, cam.ymag}) {
            if (!finite_float(v) || float(v) == 0.0f || !std::isfinite(1.0f / float(v))) {
                fail(file, cf + ".orthographic", "xmag and ymag must be finite and non-zero");
            }
        }
        cam.aspect_ratio = std::abs(cam.xmag / cam.ymag);
        if (!finite_float(cam.znear) || !finite_float(cam.zfar) || !(cam.zfar > cam.znear) ||
            !std::isfinite(2.0f / (float(cam.znear) - float(cam.zfar)))) {
            fail(file, cf + ".orthographic", "needs finite znear < zfar");
        }
    } else {
        fail(file, cf + ".type", "unknown camera type '" + c.type + "'");
    }
    if (!checks::is_finite(glm::mat4(cam.projection(1.0) * cam.view))) {
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
                if (scene_.textures[std::size_t(t)].dims != 2) fail(file_, field, "teximage is a sampler2D: no depth, no faces");
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
            if (key != "texture" && key != "image" && key != "faces" && key != "sampler" && key != "depth" &&
                key != "wrapR" && key != "compare") {
                fail(file_, field + "." + key, "unknown key (texture, image, faces, sampler, depth, wrapR, compare)");
            }
        }
        if (int(v.Has("texture")) + int(v.Has("image")) + int(v.Has("faces")) != 1) {
            fail(file_, field, "needs exactly one of texture (an index), image (a file) and faces (a cube map's six files)");
        }
        if (v.Has("faces") && v.Has("depth")) fail(file_, field + ".depth", "a cube map (faces) has no depth");
        int dims = v.Has("faces") ? kCubeMap : 2, depth = 1;
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
        std::optional<CompareFunc> compare;
        if (v.Has("compare")) {
            const tinygltf::Value& c = v.Get("compare");
            if (c.IsString()) compare = compare_func_named(c.Get<std::string>());
            if (!compare) {
                fail(file_, field + ".compare",
                     "expected a compare function: NEVER, LESS, EQUAL, LEQUAL, GREATER, NOTEQUAL, GEQUAL or ALWAYS");
            }
            if (dims == 3) fail(file_, field + ".compare", "a depth comparison texture is 2D or a cube map (no depth)");
        }
        if (v.Has("image") && !v.Get("image").IsString()) fail(file_, field + ".image", "expected a file name");
        return v.Has("faces")   ? cube_texture(v.Get("faces"), field + ".faces", sampler, compare)
               : v.Has("image") ? file_texture(v.Get("image").Get<std::string>(), field + ".image", sampler, dims, depth,
                                               compare)
                                : texture_index(v.Get("texture"), field + ".texture", sampler, own_sampler, dims, depth,
                                                compare);
    }

    int texture_index(const tinygltf::Value& v, const std::string& field, const Sampler& sampler, bool own_sampler, int dims,
                      int depth, std::optional<CompareFunc> compare = std::nullopt) {
        if (!v.IsInt()) fail(file_, field, "expected a textures[] index");
        Texture t = read_texture(v.Get<int>(), field);
        const Wrap wrap_r = sampler.wrap_r;
        if (own_sampler) t.sampler = sampler;
        t.sampler.wrap_r = wrap_r;
        t.dims = dims, t.depth = depth, t.compare = compare;
        return add_once(std::move(t));
    }

    int file_texture(const std::string& uri, const std::string& field, const Sampler& sampler, int dims, int depth,
                     std::optional<CompareFunc> compare = std::nullopt) {
        Texture t;
        t.field = field;
        t.image = named_file(uri, field);
        t.sampler = sampler;
        t.dims = dims, t.depth = depth, t.compare = compare;
        return add_once(std::move(t));
    }

    // A cube map from six image files in GL's face order (+X, -X, +Y, -Y, +Z, -Z); their sizes
    // are checked when the images are read.
    int cube_texture(const tinygltf::Value& v, const std::string& field, const Sampler& sampler,
                     std::optional<CompareFunc> compare) {
        if (!v.IsArray() || v.ArrayLen() != 6) {
            fail(file_, field, "expected an array of six image files, the faces +X, -X, +Y, -Y, +Z, -Z");
        }
        Texture t;
        t.field = field;
        for (int i = 0; i < 6; ++i) {
            const std::string face_field = field + "[" + std::to_string(i) + "]";
            if (!v.Get(i).IsString()) fail(file_, face_field, "expected an image file name");
            t.faces.push_back(named_file(v.Get(i).Get<std::string>(), face_field));
        }
        t.sampler = sampler;
        t.dims = kCubeMap, t.compare = compare;
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

// For a file without a camera: a three-quarter view of glTF's front (+Z), from 30 degrees to the
// right (+X) and 20 degrees above, +Y up, at the bounding sphere of everything in the scene (where
// it stands before any animation), with a 45 degree field of view and an aspect ratio of 1, so
// that the sphere shows whole at any image size (Camera::projection). Seen straight from the
// front, a box shows one face and a flat part nothing of its depth.
Camera framing_camera(const Scene& scene) {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const Object& o : scene.objects) {
        for (const Vertex& v : scene.meshes[o.mesh].vertices) {
            const glm::dvec3 p = glm::dvec3(o.world_from_object * glm::dvec4(glm::dvec3(v.position), 1.0));
            lo = glm::min(lo, p), hi = glm::max(hi, p);
        }
    }
    const glm::dvec3 centre = 0.5 * (lo + hi);
    const double radius = std::max(0.5 * glm::length(hi - lo), 1e-6);
    Camera cam;
    cam.name = "the default camera";
    cam.yfov = glm::radians(45.0);
    cam.aspect_ratio = 1.0;
    const double distance = radius / std::sin(0.5 * cam.yfov) * 1.05;
    const double azimuth = glm::radians(30.0), elevation = glm::radians(20.0);
    const glm::dvec3 towards_eye(std::sin(azimuth) * std::cos(elevation), std::sin(elevation),
                                 std::cos(azimuth) * std::cos(elevation));
    cam.view = glm::lookAt(centre + distance * towards_eye, centre, glm::dvec3(0.0, 1.0, 0.0));
    cam.znear = std::max(distance - 1.5 * radius, distance * 1e-3);
    cam.zfar = distance + 1.5 * radius;
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
    if (extras.Has("stretch")) {
        if (!extras.Get("stretch").IsBool()) fail(path, field + ".stretch", "expected true or false");
        scene.camera.stretch = extras.Get("stretch").Get<bool>();
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

double number_in(const tinygltf::Value& v, const std::filesystem::path& file, const std::string& field) {
    if (!v.IsNumber()) fail(file, field, "expected a number");
    const double d = v.GetNumberAsDouble();
    if (!std::isfinite(float(d))) fail(file, field, "not a finite float");
    return d;
}

// KHR_texture_transform on a textureInfo: glTF's translation * rotation * scale, and the texCoord
// it may override.
void read_texture_transform(const tinygltf::Value& t, const std::filesystem::path& file, const std::string& field,
                            Material& look) {
    if (!t.IsObject()) fail(file, field, "expected an object");
    glm::dvec2 offset(0.0), scale(1.0);
    double rotation = 0.0;
    auto pair = [&](const char* key, glm::dvec2& out) {
        if (!t.Has(key)) return;
        const tinygltf::Value& a = t.Get(key);
        if (!a.IsArray() || a.ArrayLen() != 2) fail(file, field + "." + key, "expected 2 numbers");
        for (int i = 0; i < 2; ++i) out[i] = number_in(a.Get(i), file, field + "." + key);
    };
    pair("offset", offset);
    pair("scale", scale);
    if (t.Has("rotation")) rotation = number_in(t.Get("rotation"), file, field + ".rotation");
    if (t.Has("texCoord")) {
        const tinygltf::Value& c = t.Get("texCoord");
        if (!c.IsInt() || c.Get<int>() < 0) fail(file, field + ".texCoord", "expected a TEXCOORD_n set, n >= 0");
        look.texcoord = c.Get<int>();
    }
    // Column by column. The rotation turns the image clockwise as the extension describes it
    // (u' = c u + s v, v' = -s u + c v), as viewers and Khronos's TextureTransformTest take it: the
    // GLSL listing in the extension's text writes its transpose.
    const glm::dmat3 translation(1.0, 0.0, 0.0, 0.0, 1.0, 0.0, offset.x, offset.y, 1.0);
    const double c = std::cos(rotation), s = std::sin(rotation);
    const glm::dmat3 rotate(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0);
    const glm::dmat3 scaling(scale.x, 0.0, 0.0, 0.0, scale.y, 0.0, 0.0, 0.0, 1.0);
    look.texture_transform = translation * rotate * scaling;
}

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
