#include "render/atlas_skirts.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace qs {

namespace {

// Texcoords compared by their bits' values: equal texcoords are one vertex.
struct UvLess {
    bool operator()(const glm::vec2& a, const glm::vec2& b) const { return a.x != b.x ? a.x < b.x : a.y < b.y; }
};

}  // namespace

Mesh skirt_mesh(const Mesh& mesh, float width) {
    Mesh skirt;
    skirt.name = mesh.name + " skirts";
    skirt.has_texcoords = mesh.has_texcoords;
    // Welded vertices: one per distinct texcoord; `source` is a mesh vertex that has it.
    std::map<glm::vec2, std::uint32_t, UvLess> weld;
    std::vector<std::uint32_t> welded(mesh.vertices.size()), source;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        auto [it, added] = weld.try_emplace(mesh.vertices[v].texcoord, std::uint32_t(source.size()));
        if (added) source.push_back(std::uint32_t(v));
        welded[v] = it->second;
    }
    // Edges by their welded ends (lower first): how many triangles use each, and for a boundary
    // edge its direction in its triangle and the triangle's third vertex (the inside).
    struct Use {
        int count = 0;
        std::uint32_t from = 0, to = 0, opposite = 0;
    };
    std::map<std::pair<std::uint32_t, std::uint32_t>, Use> edges;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = welded[mesh.indices[t + std::size_t(e)]], b = welded[mesh.indices[t + std::size_t((e + 1) % 3)]],
                                c = welded[mesh.indices[t + std::size_t((e + 2) % 3)]];
            if (a == b) continue;  // a degenerate edge bounds nothing
            Use& u = edges[{std::min(a, b), std::max(a, b)}];
            ++u.count;
            u.from = a, u.to = b, u.opposite = c;
        }
    }
    auto uv = [&](std::uint32_t w) { return mesh.vertices[source[w]].texcoord; };
    // Each boundary edge's outward normal (away from its triangle's inside), summed per vertex.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> boundary;
    std::vector<glm::vec2> normal_sum(source.size(), glm::vec2(0.0f));
    std::vector<std::vector<glm::vec2>> edge_normals(source.size());
    for (const auto& [key, u] : edges) {
        if (u.count != 1) continue;
        const glm::vec2 d = uv(u.to) - uv(u.from);
        glm::vec2 n = glm::normalize(glm::vec2(d.y, -d.x));
        if (glm::dot(n, uv(u.opposite) - uv(u.from)) > 0.0f) n = -n;
        boundary.emplace_back(u.from, u.to);
        for (std::uint32_t w : {u.from, u.to}) normal_sum[w] += n, edge_normals[w].push_back(n);
    }
    // The UV normal, scaled so that the skirt is `width` wide along each of the vertex's edges
    // (a mitre, limited to twice the width at sharp corners).
    std::vector<glm::vec2> offset(source.size(), glm::vec2(0.0f));
    for (std::size_t w = 0; w < source.size(); ++w) {
        const float length = glm::length(normal_sum[w]);
        if (edge_normals[w].empty() || length == 0.0f) continue;
        const glm::vec2 n = normal_sum[w] / length;
        float cos_min = 1.0f;
        for (const glm::vec2& e : edge_normals[w]) cos_min = std::min(cos_min, glm::dot(n, e));
        offset[w] = n * (width / std::max(cos_min, 0.5f));
    }
    for (const auto& [a, b] : boundary) {
        const Vertex& va = mesh.vertices[source[a]];
        const Vertex& vb = mesh.vertices[source[b]];
        const auto base = std::uint32_t(skirt.vertices.size());
        skirt.vertices.insert(skirt.vertices.end(), {va, vb, {vb.position, vb.texcoord + offset[b]}, {va.position, va.texcoord + offset[a]}});
        skirt.indices.insert(skirt.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    return skirt;
}

}  // namespace qs
