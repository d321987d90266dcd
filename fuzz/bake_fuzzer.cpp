// Fuzz target: the meshes a bake draws into its UV atlas (render/atlas_bake.h's check_atlas: the
// texcoords' range, triangles without area, overlaps found by a sweep). The first byte picks the
// grid the texcoords are snapped to (coarse grids make the shared vertices, collinear edges,
// fans and touching triangles real meshes have); every 6 bytes after it are a triangle's three
// texcoords, a byte each. Besides not crashing, the sweep's verdict must be the one testing every pair gives,
// checked on meshes of up to 40 triangles.
#include <cstdint>
#include <optional>
#include <string>

#include "fuzz/fuzz_check.h"
#include "render/atlas_bake.h"

namespace {

// One mesh of `triangles`, its positions its texcoords (so that a triangle without area in the
// atlas has none on the surface either, which the check allows).
qs::Scene mesh_scene(const std::vector<glm::vec2>& uv) {
    qs::Scene s;
    s.file = "fuzz.gltf";
    qs::Mesh m;
    m.name = "fuzz";
    m.has_texcoords = true;
    for (std::size_t i = 0; i < uv.size(); ++i) {
        qs::Vertex v{};
        v.position = glm::vec3(uv[i], 0.0f);
        v.texcoord = uv[i];
        m.vertices.push_back(v);
        m.indices.push_back(std::uint32_t(i));
    }
    s.meshes.push_back(m);
    qs::Object o;
    o.name = "fuzz";
    o.mesh = 0;
    s.objects.push_back(o);
    return s;
}

// Whether check_atlas refuses the scene for an overlap (nullopt: for something else).
std::optional<bool> overlaps(const qs::Scene& s) {
    try {
        qs::check_atlas(s);
        return false;
    } catch (const qs::SceneError& e) {
        if (std::string(e.what()).find("overlap in TEXCOORD_0") != std::string::npos) return true;
        return std::nullopt;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    static const int kGrids[] = {2, 3, 4, 8, 16, 255};
    const int grid = kGrids[data[0] % 6];
    std::vector<glm::vec2> uv;
    for (std::size_t i = 1; i + 6 <= size && uv.size() < 3 * 4096; i += 6) {
        for (std::size_t k = 0; k < 6; k += 2) {
            uv.emplace_back(float(data[i + k] % (grid + 1)) / float(grid),
                            float(data[i + k + 1] % (grid + 1)) / float(grid));
        }
    }
    if (uv.empty()) return 0;
    const qs::Scene scene = mesh_scene(uv);
    std::size_t compared = 0;
    std::optional<bool> verdict;
    try {
        compared = qs::check_atlas(scene);
        verdict = false;
        FUZZ_CHECK(compared <= uv.size());  // at most 3 tests per triangle
    } catch (const qs::SceneError& e) {
        verdict = overlaps(scene);
    }
    const std::size_t n = uv.size() / 3;
    if (!verdict || n > 40) return 0;
    bool any = false;
    for (std::size_t i = 0; i < n && !any; ++i) {
        for (std::size_t j = i + 1; j < n && !any; ++j) {
            const std::vector<glm::vec2> pair = {uv[3 * i], uv[3 * i + 1], uv[3 * i + 2],
                                                 uv[3 * j], uv[3 * j + 1], uv[3 * j + 2]};
            any = overlaps(mesh_scene(pair)).value_or(false);
        }
    }
    FUZZ_CHECK(*verdict == any);
    return 0;
}
