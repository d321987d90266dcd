#include "render/atlas_bake.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <iterator>
#include <set>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "render/atlas_skirts.h"
#include "render/memory_plan.h"

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

// Every triangle of the scene's meshes at its TEXCOORD_0, checked to lie in the atlas; those with
// no area there are left out (refused if they have some in POSITION).
std::vector<AtlasTriangle> atlas_triangles(const Scene& scene) {
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
    return triangles;
}

// Throws SceneError naming the first two triangles found to overlap; the pairs it compared.
std::size_t sweep_for_overlaps(const Scene& scene, std::vector<AtlasTriangle>& triangles) {
    // A sweep over s (Shamos and Hoey's, for polygons): the triangles the sweep line crosses are
    // kept in the order of their cross-sections, which cannot change between two triangles until
    // they overlap, so the first overlap is between two triangles that are neighbours in that
    // order at some event (one starts, or one between them ends); only neighbours are tested.
    // O(n log n) whatever the mesh (a fan of triangles around one vertex included).
    const std::size_t n = triangles.size();
    struct Extent {
        double x0, x1;
    };
    std::vector<Extent> extent(n);
    std::vector<double> xs;
    xs.reserve(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
        UvTriangle& uv = triangles[i].uv;
        std::sort(uv.begin(), uv.end(), [](Uv a, Uv b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
        extent[i] = {uv[0].x, uv[2].x};  // x0 < x1: the triangle has an area
        xs.push_back(uv[0].x), xs.push_back(uv[2].x);
    }
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    std::vector<std::size_t> by_start(n), by_end(n);
    for (std::size_t i = 0; i < n; ++i) by_start[i] = by_end[i] = i;
    std::sort(by_start.begin(), by_start.end(),
              [&](std::size_t a, std::size_t b) { return extent[a].x0 < extent[b].x0; });
    std::sort(by_end.begin(), by_end.end(), [&](std::size_t a, std::size_t b) { return extent[a].x1 < extent[b].x1; });
    // The sweep line's s: strictly between two events, where every active triangle's
    // cross-section has a length (vertices lie only on events).
    double sweep = 0.0;
    auto middle = [&](std::size_t i) {
        const UvTriangle& t = triangles[i].uv;  // sorted by s; t[0].x < sweep < t[2].x
        auto y_at = [&](Uv p, Uv q) { return p.y + (q.y - p.y) * ((sweep - p.x) / (q.x - p.x)); };
        const double long_edge = y_at(t[0], t[2]), short_edge = sweep < t[1].x ? y_at(t[0], t[1]) : y_at(t[1], t[2]);
        return 0.5 * (long_edge + short_edge);
    };
    auto below = [&](std::size_t a, std::size_t b) {
        const double ma = middle(a), mb = middle(b);
        return ma < mb || (ma == mb && a < b);
    };
    std::set<std::size_t, decltype(below)> active(below);
    std::vector<std::set<std::size_t, decltype(below)>::iterator> where(n);
    constexpr double kSlack = 1e-7;  // texcoord units: well under a texel of the largest atlas
    std::size_t compared = 0;
    auto test = [&](std::size_t a, std::size_t b) {
        ++compared;
        const AtlasTriangle &p = triangles[a], &q = triangles[b];
        if (!overlap_in_uv(p.uv, q.uv, kSlack)) return;
        const Object &op = scene.objects[p.object], &oq = scene.objects[q.object];
        const Uv c = (p.uv[0] + p.uv[1] + p.uv[2]) / 3.0;
        throw SceneError(scene.file.string() + ": mesh '" + scene.meshes[op.mesh].name + "' (object '" + op.name +
                         "') triangle " + std::to_string(p.index) + " and mesh '" + scene.meshes[oq.mesh].name +
                         "' (object '" + oq.name + "') triangle " + std::to_string(q.index) +
                         " overlap in TEXCOORD_0 (near (" + std::to_string(c.x) + ", " + std::to_string(c.y) +
                         ")): an atlas bake needs every texel to belong to one surface point");
    };
    std::size_t next_start = 0, next_end = 0;
    for (std::size_t k = 0; k < xs.size(); ++k) {
        for (; next_end < n && extent[by_end[next_end]].x1 == xs[k]; ++next_end) {
            const auto it = where[by_end[next_end]];
            const auto after = std::next(it);
            if (it != active.begin() && after != active.end()) test(*std::prev(it), *after);
            active.erase(it);
        }
        if (k + 1 == xs.size()) break;
        sweep = xs[k] + 0.5 * (xs[k + 1] - xs[k]);
        for (; next_start < n && extent[by_start[next_start]].x0 == xs[k]; ++next_start) {
            const std::size_t i = by_start[next_start];
            const auto it = active.insert(i).first;
            where[i] = it;
            if (it != active.begin()) test(*std::prev(it), i);
            if (const auto after = std::next(it); after != active.end()) test(i, *after);
        }
    }
    return compared;
}

}  // namespace

std::size_t check_atlas(const Scene& scene) {
    std::vector<AtlasTriangle> triangles = atlas_triangles(scene);
    return sweep_for_overlaps(scene, triangles);
}

std::uint64_t atlas_bake_bytes(const Scene& scene, const AtlasRequest& request) {
    std::uint64_t vertices = 0, triangles = 0;
    for (const Object& o : scene.objects) {
        vertices += scene.meshes[o.mesh].vertices.size();
        triangles += scene.meshes[o.mesh].indices.size() / 3;
    }
    // Skirts: made as atlas_scene makes them, to count them (a small part of the frame's memory).
    std::uint64_t skirt_triangles = 0, skirt_vertices = 0;
    if (request.skirt > 0) {
        for (const Object& o : scene.objects) {
            const Mesh strips = skirt_mesh(scene.meshes[o.mesh], float(request.skirt) / float(request.size));
            skirt_triangles += strips.indices.size() / 3;
            skirt_vertices += strips.vertices.size();
        }
    }
    constexpr std::uint64_t kCheckPerTriangle = 160;  // check_atlas's triangles, events and sweep
    const std::uint64_t texels = std::uint64_t(request.size) * std::uint64_t(request.size);
    // The atlas's scene is a copy of the scene with the skirts' meshes, and the draw calls hold
    // each drawn vertex again as a vertex stage input.
    const std::uint64_t skirt_meshes = skirt_vertices * sizeof(Vertex) + skirt_triangles * 3 * sizeof(std::uint32_t);
    const std::uint64_t draws = (vertices + skirt_vertices) * sizeof(VertexIn);
    return render_working_bytes(texels, vertices + skirt_vertices, triangles + skirt_triangles, true, false) +
           triangles * kCheckPerTriangle + scene_bytes(scene) + skirt_meshes + draws;
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
