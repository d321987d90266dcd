#include "render/normal_bake.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <tbb/blocked_range.h>

#include "core/parallel.h"
#include "render/atlas_bake.h"

namespace qs {

namespace {

double cross2(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

void check_request(const NormalBakeRequest& r) {
    if (r.size < 1 || r.size > kMaxAtlasSide) {
        throw std::invalid_argument("an atlas's side must be 1 to " + std::to_string(kMaxAtlasSide) + " texels, got " +
                                    std::to_string(r.size));
    }
    if (r.skirt < 0 || r.skirt > kMaxSkirt) {
        throw std::invalid_argument("a skirt must be 0 to " + std::to_string(kMaxSkirt) + " texels wide, got " +
                                    std::to_string(r.skirt));
    }
    if (r.method == NormalMethod::FiniteDifferences && !(std::isfinite(r.step) && r.step > 0.0)) {
        throw std::invalid_argument("a finite-difference step must be finite and positive, got " + std::to_string(r.step));
    }
}

void set(PointBatch& b, int lane, const glm::dvec3& v) { b.x[lane] = v.x, b.y[lane] = v.y, b.z[lane] = v.z; }

}  // namespace

std::uint64_t covered_texels_bound(const Scene& scene, int size) {
    // A convex region of area A and perimeter P holds at most A + P / 2 + 1 points of the unit
    // lattice (in texels): the texel centres a triangle covers.
    const double side = size;
    double covered = 0.0;
    for (const Object& o : scene.objects) {
        const Mesh& mesh = scene.meshes[o.mesh];
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const glm::dvec2 s0(mesh.vertices[mesh.indices[t]].texcoord),
                s1(mesh.vertices[mesh.indices[t + 1]].texcoord), s2(mesh.vertices[mesh.indices[t + 2]].texcoord);
            const double area = 0.5 * std::abs(cross2(s1 - s0, s2 - s0)) * side * side;
            const double perimeter = (glm::length(s1 - s0) + glm::length(s2 - s1) + glm::length(s0 - s2)) * side;
            covered += area + 0.5 * perimeter + 1.0;
        }
    }
    return std::uint64_t(std::min(covered, side * side));
}

AtlasTexels atlas_texels(const Scene& scene, int size) {
    check_atlas(scene);
    AtlasTexels out;
    out.size = size;
    // Reserved once for as many texels as the triangles can cover: no copies while they grow.
    const std::size_t bound = std::size_t(covered_texels_bound(scene, size));
    out.texel.reserve(bound), out.position.reserve(bound), out.normal.reserve(bound);
    out.tangent.reserve(bound), out.bitangent.reserve(bound);
    std::vector<bool> owned(std::size_t(size) * std::size_t(size), false);
    for (const Object& o : scene.objects) {
        const Mesh& mesh = scene.meshes[o.mesh];
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const Vertex &v0 = mesh.vertices[mesh.indices[t]], &v1 = mesh.vertices[mesh.indices[t + 1]],
                         &v2 = mesh.vertices[mesh.indices[t + 2]];
            const glm::dvec3 p0(v0.position), p1(v1.position), p2(v2.position);
            const glm::dvec2 s0(v0.texcoord), s1(v1.texcoord), s2(v2.texcoord);
            const glm::dvec2 ds1 = s1 - s0, ds2 = s2 - s0;
            const double area = cross2(ds1, ds2);
            if (area == 0.0) continue;  // none in POSITION either (check_atlas)
            const glm::dvec3 e1 = p1 - p0, e2 = p2 - p0;
            const glm::dvec3 face = glm::cross(e1, e2);
            if (glm::dot(face, face) == 0.0) continue;  // a triangle without area on the surface: no normal
            const glm::dvec3 N = glm::normalize(face);
            // dp/ds and dp/dt: the texcoord edges' inverse applied to the position edges.
            const glm::dvec3 dp_ds = (e1 * ds2.y - e2 * ds1.y) / area, dp_dt = (e2 * ds1.x - e1 * ds2.x) / area;
            glm::dvec3 T = dp_ds - N * glm::dot(N, dp_ds);
            T = glm::dot(T, T) > 0.0 ? glm::normalize(T) : glm::normalize(glm::cross(dp_dt, N));
            glm::dvec3 B = glm::cross(N, T);
            if (glm::dot(B, dp_dt) < 0.0) B = -B;
            const double smin = std::min({s0.x, s1.x, s2.x}) * size, smax = std::max({s0.x, s1.x, s2.x}) * size;
            const double tmin = std::min({s0.y, s1.y, s2.y}) * size, tmax = std::max({s0.y, s1.y, s2.y}) * size;
            const int i0 = std::max(0, int(std::floor(smin - 0.5))), i1 = std::min(size - 1, int(std::ceil(smax - 0.5)));
            const int j0 = std::max(0, int(std::floor(tmin - 0.5))), j1 = std::min(size - 1, int(std::ceil(tmax - 0.5)));
            for (int j = j0; j <= j1; ++j) {
                for (int i = i0; i <= i1; ++i) {
                    const glm::dvec2 c((i + 0.5) / size, (j + 0.5) / size);
                    // Barycentric weights of the texel centre; on an edge (0) it is inside.
                    const double b1 = cross2(c - s0, ds2) / area, b2 = cross2(ds1, c - s0) / area;
                    const double b0 = 1.0 - b1 - b2;
                    if (b0 < 0.0 || b1 < 0.0 || b2 < 0.0) continue;
                    const std::size_t texel = std::size_t(j) * std::size_t(size) + std::size_t(i);
                    if (owned[texel]) continue;
                    owned[texel] = true;
                    out.texel.push_back(std::uint32_t(texel));
                    out.position.push_back(p0 * b0 + p1 * b1 + p2 * b2);
                    out.normal.push_back(N);
                    out.tangent.push_back(T);
                    out.bitangent.push_back(B);
                }
            }
        }
    }
    return out;
}

std::vector<glm::dvec3> surface_normals(const HeightField& field, const AtlasTexels& texels, const NormalBakeRequest& request) {
    check_request(request);
    const std::size_t n = texels.texel.size();
    std::vector<glm::dvec3> normals(n);
    const double A = field.amplitude(), e = request.step;
    const std::size_t batches = (n + kBatchLanes - 1) / kBatchLanes;
    auto shade = [&](std::size_t first_batch, std::size_t end_batch) {
        for (std::size_t batch = first_batch; batch < end_batch; ++batch) {
            const std::size_t begin = batch * kBatchLanes, count = std::min<std::size_t>(kBatchLanes, n - begin);
            // Short batches repeat their last texel.
            auto at = [&](const std::vector<glm::dvec3>& v, int lane) { return v[begin + std::min<std::size_t>(std::size_t(lane), count - 1)]; };
            if (request.method == NormalMethod::Analytic) {
                PointBatch p, t, b;
                for (int l = 0; l < kBatchLanes; ++l) {
                    set(p, l, at(texels.position, l)), set(t, l, at(texels.tangent, l)), set(b, l, at(texels.bitangent, l));
                }
                double h[kBatchLanes], h_t[kBatchLanes], h_b[kBatchLanes];
                field.gradients(request.precision, p, t, b, h, h_t, h_b);
                for (std::size_t l = 0; l < count; ++l) {
                    const glm::dvec3 N = texels.normal[begin + l], T = texels.tangent[begin + l], B = texels.bitangent[begin + l];
                    normals[begin + l] = glm::normalize(N - A * (h_t[l] * T + h_b[l] * B));
                }
            } else {
                // The three points in the precision of the evaluation: p + e T rounded to float
                // in a float bake, as a GPU would hold it.
                PointBatch p0, p1, p2;
                for (int l = 0; l < kBatchLanes; ++l) {
                    const glm::dvec3 p = at(texels.position, l);
                    set(p0, l, p), set(p1, l, p + e * at(texels.tangent, l)), set(p2, l, p + e * at(texels.bitangent, l));
                }
                double h0[kBatchLanes], h1[kBatchLanes], h2[kBatchLanes];
                field.heights(request.precision, p0, h0);
                field.heights(request.precision, p1, h1);
                field.heights(request.precision, p2, h2);
                for (std::size_t l = 0; l < count; ++l) {
                    const glm::dvec3 N = texels.normal[begin + l], T = texels.tangent[begin + l], B = texels.bitangent[begin + l];
                    const glm::dvec3 p = texels.position[begin + l];
                    const glm::dvec3 q0 = p + A * h0[l] * N, q1 = p + e * T + A * h1[l] * N, q2 = p + e * B + A * h2[l] * N;
                    glm::dvec3 c = glm::cross(q1 - q0, q2 - q0);
                    if (glm::dot(c, N) < 0.0) c = -c;  // a left-handed frame (mirrored chart)
                    normals[begin + l] = glm::normalize(c);
                }
            }
        }
    };
    const ThreadLimit limit(request.threads);
    parallel_chunks<std::size_t>(0, batches, 64,
                                 [&](const tbb::blocked_range<std::size_t>& r) { shade(r.begin(), r.end()); });
    return normals;
}

std::uint64_t normal_bake_bytes(const Scene& scene, const NormalBakeRequest& request) {
    // Per covered texel: index, position, normal, tangent, bitangent and the normal made (124
    // bytes, in vectors reserved once); per texel of the map: the image and a skirt pass's copy.
    constexpr std::uint64_t kPerCovered = 128, kPerTexel = 2 * 4 * sizeof(float) + 1;
    const std::uint64_t texels = std::uint64_t(request.size) * std::uint64_t(request.size);
    return covered_texels_bound(scene, request.size) * kPerCovered + texels * kPerTexel;
}

Image bake_normal_map(const Scene& scene, const HeightField& field, const NormalBakeRequest& request) {
    check_request(request);
    const AtlasTexels texels = atlas_texels(scene, request.size);
    const std::vector<glm::dvec3> normals = surface_normals(field, texels, request);
    const int size = request.size;
    Image image{size, size, std::vector<float>(std::size_t(size) * std::size_t(size) * 4, 0.0f)};
    for (std::size_t k = 0; k < normals.size(); ++k) {
        float* px = &image.rgba[std::size_t(texels.texel[k]) * 4];
        for (int c = 0; c < 3; ++c) px[c] = float(0.5 + 0.5 * normals[k][c]);
        px[3] = 1.0f;
    }
    // Skirts: each pass gives every gutter texel with a covered 8-neighbour the normalised mean of
    // those neighbours' normals.
    for (int pass = 0; pass < request.skirt; ++pass) {
        Image next = image;
        for (int j = 0; j < size; ++j) {
            for (int i = 0; i < size; ++i) {
                float* px = &next.rgba[(std::size_t(j) * std::size_t(size) + std::size_t(i)) * 4];
                if (px[3] != 0.0f) continue;
                glm::dvec3 sum(0.0);
                int found = 0;
                for (int dj = -1; dj <= 1; ++dj) {
                    for (int di = -1; di <= 1; ++di) {
                        const int x = i + di, y = j + dj;
                        if (x < 0 || y < 0 || x >= size || y >= size) continue;
                        const float* q = &image.rgba[(std::size_t(y) * std::size_t(size) + std::size_t(x)) * 4];
                        if (q[3] == 0.0f) continue;
                        sum += glm::dvec3(q[0], q[1], q[2]) * 2.0 - 1.0;
                        ++found;
                    }
                }
                if (!found || glm::dot(sum, sum) == 0.0) continue;
                const glm::dvec3 n = glm::normalize(sum);
                for (int c = 0; c < 3; ++c) px[c] = float(0.5 + 0.5 * n[c]);
                px[3] = 1.0f;
            }
        }
        image = std::move(next);
    }
    return image;
}

}  // namespace qs
