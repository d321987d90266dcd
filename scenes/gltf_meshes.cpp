// A glTF primitive as triangles with its vertices' attributes (POSITION, NORMAL, TEXCOORD_0/1,
// COLOR_0), strips and fans unrolled as GL draws them.
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
#include <tiny_gltf.h>

#include "scenes/gltf_checks.h"
#include "scenes/gltf_read.h"
#include "scenes/limits.h"
#include "scenes/scene_files.h"

namespace qs::gltf_read {

namespace checks = gltf_checks;

namespace {

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

}  // namespace

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

}  // namespace qs::gltf_read
