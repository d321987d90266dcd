#include "render/atlas_bake.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "render/atlas_skirts.h"

namespace qs {

namespace {

using Uv = glm::dvec2;
using UvTriangle = std::array<Uv, 3>;

// A drawn triangle in the atlas, and what names it in messages.
struct AtlasTriangle {
    UvTriangle uv;
    std::size_t object;
    std::size_t index;  // within its mesh
};

double cross(Uv a, Uv b) { return a.x * b.y - a.y * b.x; }

// Whether two triangles' interiors overlap (separating axes: for two triangles in the plane the
// six edge normals suffice). Triangles that only touch, along an edge or at a corner, do not:
// `slack` (in texcoord units, scaled by the axis length) absorbs rounding where they touch.
bool overlap_in_uv(const UvTriangle& a, const UvTriangle& b, double slack) {
    for (const UvTriangle* t : {&a, &b}) {
        for (int e = 0; e < 3; ++e) {
            const Uv edge = (*t)[std::size_t((e + 1) % 3)] - (*t)[std::size_t(e)];
            const Uv axis{-edge.y, edge.x};
            const double length = std::hypot(axis.x, axis.y);
            if (length == 0.0) continue;
            double a_min = 1e300, a_max = -1e300, b_min = 1e300, b_max = -1e300;
            for (int i = 0; i < 3; ++i) {
                const double pa = glm::dot(a[std::size_t(i)], axis), pb = glm::dot(b[std::size_t(i)], axis);
                a_min = std::min(a_min, pa), a_max = std::max(a_max, pa);
                b_min = std::min(b_min, pb), b_max = std::max(b_max, pb);
            }
            if (a_max <= b_min + slack * length || b_max <= a_min + slack * length) return false;
        }
    }
    return true;
}

}  // namespace

void check_atlas(const Scene& scene) {
    std::vector<AtlasTriangle> triangles;
    for (std::size_t oi = 0; oi < scene.objects.size(); ++oi) {
        const Object& o = scene.objects[oi];
        const Mesh& mesh = scene.meshes[o.mesh];
        const std::string where = scene.file.string() + ": mesh '" + mesh.name + "' (object '" + o.name + "')";
        if (!mesh.has_texcoords) {
            throw SceneError(where + " has no TEXCOORD_0: an atlas bake draws each triangle at its texcoords "
                                     "(unwrap the mesh into a UV atlas first)");
        }
        for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
            const glm::vec2 st = mesh.vertices[v].texcoord;
            if (!(st.x >= 0.0f && st.x <= 1.0f && st.y >= 0.0f && st.y <= 1.0f)) {
                throw SceneError(where + ": TEXCOORD_0 of vertex " + std::to_string(v) + " is (" + std::to_string(st.x) +
                                 ", " + std::to_string(st.y) + "), outside the atlas [0, 1]^2");
            }
        }
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            AtlasTriangle at{{}, oi, t / 3};
            for (int k = 0; k < 3; ++k) at.uv[std::size_t(k)] = Uv(mesh.vertices[mesh.indices[t + std::size_t(k)]].texcoord);
            if (cross(at.uv[1] - at.uv[0], at.uv[2] - at.uv[0]) != 0.0) {
                triangles.push_back(at);
                continue;
            }
            // No area in the atlas: no texel would hold its surface, unless it has none either.
            const glm::vec3 p0 = mesh.vertices[mesh.indices[t]].position, p1 = mesh.vertices[mesh.indices[t + 1]].position,
                            p2 = mesh.vertices[mesh.indices[t + 2]].position;
            if (glm::dot(glm::cross(p1 - p0, p2 - p0), glm::cross(p1 - p0, p2 - p0)) > 0.0f) {
                throw SceneError(where + ": triangle " + std::to_string(t / 3) +
                                 " has no area in TEXCOORD_0 but has some in POSITION: no texel of the atlas would hold it");
            }
        }
    }
    // Triangles binned by their bounds on a grid, each pair that shares a cell tested once
    // (in the first cell both bounds share).
    constexpr int kCells = 64;
    auto cell = [](double x) { return std::clamp(int(x * kCells), 0, kCells - 1); };
    std::vector<std::vector<std::size_t>> bins(std::size_t(kCells) * kCells);
    struct Bounds { int x0, y0, x1, y1; };
    std::vector<Bounds> bounds;
    bounds.reserve(triangles.size());
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const UvTriangle& uv = triangles[i].uv;
        const Bounds b{cell(std::min({uv[0].x, uv[1].x, uv[2].x})), cell(std::min({uv[0].y, uv[1].y, uv[2].y})),
                       cell(std::max({uv[0].x, uv[1].x, uv[2].x})), cell(std::max({uv[0].y, uv[1].y, uv[2].y}))};
        bounds.push_back(b);
        for (int y = b.y0; y <= b.y1; ++y) {
            for (int x = b.x0; x <= b.x1; ++x) bins[std::size_t(y) * kCells + std::size_t(x)].push_back(i);
        }
    }
    constexpr double kSlack = 1e-7;  // texcoord units: well under a texel of the largest atlas
    for (int y = 0; y < kCells; ++y) {
        for (int x = 0; x < kCells; ++x) {
            const std::vector<std::size_t>& bin = bins[std::size_t(y) * kCells + std::size_t(x)];
            for (std::size_t i = 0; i < bin.size(); ++i) {
                for (std::size_t j = i + 1; j < bin.size(); ++j) {
                    const Bounds &a = bounds[bin[i]], &b = bounds[bin[j]];
                    if (x != std::max(a.x0, b.x0) || y != std::max(a.y0, b.y0)) continue;
                    const AtlasTriangle &p = triangles[bin[i]], &q = triangles[bin[j]];
                    if (!overlap_in_uv(p.uv, q.uv, kSlack)) continue;
                    const Object &op = scene.objects[p.object], &oq = scene.objects[q.object];
                    const Uv c = (p.uv[0] + p.uv[1] + p.uv[2]) / 3.0;
                    throw SceneError(scene.file.string() + ": mesh '" + scene.meshes[op.mesh].name + "' (object '" + op.name +
                                     "') triangle " + std::to_string(p.index) + " and mesh '" + scene.meshes[oq.mesh].name +
                                     "' (object '" + oq.name + "') triangle " + std::to_string(q.index) +
                                     " overlap in TEXCOORD_0 (near (" + std::to_string(c.x) + ", " + std::to_string(c.y) +
                                     ")): an atlas bake needs every texel to belong to one surface point");
                }
            }
        }
    }
}

Scene atlas_scene(const Scene& scene, int size, int skirt) {
    Scene s = scene;
    s.clear_color = glm::vec4(0.0f);
    s.width = s.height = size;
    if (skirt > 0) {
        for (const Object& o : scene.objects) {
            Mesh strips = skirt_mesh(scene.meshes[o.mesh], float(skirt) / float(size));
            if (strips.indices.empty()) continue;
            s.meshes.push_back(std::move(strips));
            Object skirts = o;
            skirts.name = o.name + " skirts";
            skirts.mesh = s.meshes.size() - 1;
            s.objects.push_back(skirts);
        }
    }
    return s;
}

Framebuffer render_atlas_frame(const Scene& scene, const AtlasRequest& request) {
    if (request.size < 1 || request.size > kMaxAtlasSide) {
        throw std::invalid_argument("an atlas's side must be 1 to " + std::to_string(kMaxAtlasSide) + " texels, got " +
                                    std::to_string(request.size));
    }
    check_atlas(scene);
    if (request.skirt < 0 || request.skirt > kMaxSkirt) {
        throw std::invalid_argument("a skirt must be 0 to " + std::to_string(kMaxSkirt) + " texels wide, got " +
                                    std::to_string(request.skirt));
    }
    Scene s = atlas_scene(scene, request.size, request.skirt);
    FrameRequest frame = request.frame;
    frame.width = frame.height = request.size;
    frame.atlas = true;
    return render_frame(s, frame);
}

Scene baked_scene(const Scene& scene, const std::filesystem::path& texture) { return baked_scene(scene, texture, {}, {}); }

Scene baked_scene(const Scene& scene, const std::filesystem::path& texture, const std::filesystem::path& normal_map,
                  const std::filesystem::path& height_map) {
    Scene s = scene;
    auto atlas = [](const std::filesystem::path& file) {
        Texture t;
        t.image.file = file;
        t.image.mime_type = "image/png";
        t.sampler = Sampler{Filter::Linear, Filter::LinearMipmapLinear, Wrap::ClampToEdge, Wrap::ClampToEdge, Wrap::ClampToEdge};
        t.field = "the baked atlas " + file.filename().string();
        return t;
    };
    s.textures = {atlas(texture)};
    std::vector<SamplerBinding> samplers;
    if (!normal_map.empty()) {
        s.textures.push_back(atlas(normal_map));
        samplers.push_back({"normalmap", int(s.textures.size()) - 1});
    }
    if (!height_map.empty()) {
        s.textures.push_back(atlas(height_map));
        samplers.push_back({"heightmap", int(s.textures.size()) - 1});
    }
    for (Object& o : s.objects) {
        o.shader = normal_map.empty() ? "single_texture" : "baked_lit";
        o.texture = 0;
        o.samplers = samplers;
        o.uniforms.clear();
    }
    return s;
}

Image flip_rows(const Framebuffer& frame) {
    Image image{frame.width, frame.height, std::vector<float>(frame.rgba.size())};
    const std::size_t row = std::size_t(frame.width) * 4;
    for (int y = 0; y < frame.height; ++y) {
        std::memcpy(image.rgba.data() + std::size_t(y) * row, frame.rgba.data() + std::size_t(frame.height - 1 - y) * row,
                    row * sizeof(float));
    }
    return image;
}

Image bake_atlas(const Scene& scene, const AtlasRequest& request) { return flip_rows(render_atlas_frame(scene, request)); }

}  // namespace qs
