// quadshade bake: which meshes an atlas accepts, which way its rows run, and the command's
// outputs and refusals. The atlas's pixels are checked against OSMesa in tests/reference.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>

#include "images/image_io.h"
#include "render/atlas_bake.h"
#include "render/atlas_skirts.h"
#include "scenes/gltf.h"
#include "tests/test_command.h"
#include "tests/test_paths.h"

namespace qs {

namespace {

using namespace test;

const std::filesystem::path kAtlasCube = kSource / "scenes/assets/bake/atlas-cube.gltf";
const std::filesystem::path kAtlasSphere = kSource / "scenes/assets/bake/atlas-sphere.gltf";

std::string error_of(const Scene& s) {
    try {
        check_atlas(s);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("bake: the shipped atlases pass, and missing, out-of-range, collapsed and overlapping texcoords are refused by name", "[bake]") {
    CHECK(error_of(load_scene(kAtlasCube)).empty());
    CHECK(error_of(load_scene(kAtlasSphere)).empty());

    Scene no_uv = load_scene(kAtlasCube);
    no_uv.meshes[0].has_texcoords = false;
    const std::string e1 = error_of(no_uv);
    CHECK(e1.find("atlas-cube.gltf") != std::string::npos);
    CHECK(e1.find("mesh 'atlas cube'") != std::string::npos);
    CHECK(e1.find("no TEXCOORD_0") != std::string::npos);

    Scene outside = load_scene(kAtlasCube);
    outside.meshes[0].vertices[5].texcoord.x = 1.25f;
    CHECK(error_of(outside).find("TEXCOORD_0 of vertex 5 is (1.250000") != std::string::npos);

    // Face 1's chart moved half onto face 0's: their triangles overlap.
    Scene overlap = load_scene(kAtlasCube);
    for (int v = 4; v < 8; ++v) overlap.meshes[0].vertices[std::size_t(v)].texcoord.x -= 0.2f;
    const std::string e2 = error_of(overlap);
    CHECK(e2.find("overlap in TEXCOORD_0") != std::string::npos);
    CHECK(e2.find("triangle") != std::string::npos);

    // A triangle collapsed to a line in the atlas: its surface would get no texel.
    Scene collapsed = load_scene(kAtlasCube);
    collapsed.meshes[0].vertices[2].texcoord = collapsed.meshes[0].vertices[0].texcoord;
    CHECK(error_of(collapsed).find("triangle 0 has no area in TEXCOORD_0") != std::string::npos);

    // One mesh drawn twice bakes every texel twice.
    Scene twice = load_scene(kAtlasSphere);
    twice.objects.push_back(twice.objects[0]);
    CHECK(error_of(twice).find("overlap in TEXCOORD_0") != std::string::npos);

    // Charts that only touch along an edge or at a corner do not overlap.
    Scene touching;
    touching.file = "touching";
    Mesh m{"squares", {}, {}};
    for (int k = 0; k < 2; ++k) {
        const float x = 0.5f * float(k);
        const auto base = std::uint32_t(m.vertices.size());
        m.vertices.insert(m.vertices.end(), {{{x, 0, 0}, {x, 0.0f}}, {{x + 0.5f, 0, 0}, {x + 0.5f, 0.0f}},
                                             {{x + 0.5f, 1, 0}, {x + 0.5f, 0.5f}}, {{x, 1, 0}, {x, 0.5f}}});
        m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    touching.meshes = {m};
    touching.objects.resize(1);
    CHECK(error_of(touching).empty());
}

TEST_CASE("bake: the atlas image's first row is t = 0 (glTF's top of the image)", "[bake]") {
    // One triangle in the corner s, t < 0.5: in the image it lies in the first rows, left.
    Scene s;
    s.file = "corner";
    s.meshes = {Mesh{"corner", {{{0, 0, 0}, {0.0f, 0.0f}}, {{1, 0, 0}, {0.5f, 0.0f}}, {{0, 1, 0}, {0.0f, 0.5f}}}, {0, 1, 2}}};
    Object o;
    o.shader = "constant_color";
    s.objects = {o};
    AtlasRequest req;
    req.size = 16;
    const Image atlas = bake_atlas(s, req);
    REQUIRE(atlas.width == 16);
    REQUIRE(atlas.height == 16);
    auto alpha = [&](int x, int y) { return atlas.rgba[(std::size_t(y) * 16 + std::size_t(x)) * 4 + 3]; };
    CHECK(alpha(0, 0) == 1.0f);
    CHECK(alpha(1, 5) == 1.0f);
    CHECK(alpha(0, 15) == 0.0f);
    CHECK(alpha(15, 0) == 0.0f);
    CHECK_THROWS_AS(bake_atlas(s, AtlasRequest{0, 0, {}}), std::invalid_argument);
}

TEST_CASE("bake: the command writes the baked scene and its texture, or nothing with a message", "[bake]") {
    const auto dir = temp_dir("bake-command");
    const std::string qs = (kBin / "quadshade").string();
    std::string err;
    // A mesh without TEXCOORD_0.
    Scene no_uv = load_scene(kAtlasCube);
    no_uv.meshes[0].has_texcoords = false;
    save_scene(no_uv, dir / "no-uv.gltf");
    CHECK(run(qs + " bake " + (dir / "no-uv.gltf").string() + " --shader spots --size 32 -o " + (dir / "a.gltf").string(),
              &err, dir / "err.txt") == 1);
    CHECK(err.find("no-uv.gltf: mesh 'atlas cube'") != std::string::npos);
    CHECK(err.find("no TEXCOORD_0") != std::string::npos);
    // Overlapping charts.
    Scene overlap = load_scene(kAtlasCube);
    for (int v = 4; v < 8; ++v) overlap.meshes[0].vertices[std::size_t(v)].texcoord.x -= 0.2f;
    save_scene(overlap, dir / "overlap.gltf");
    CHECK(run(qs + " bake " + (dir / "overlap.gltf").string() + " --shader spots --size 32 -o " + (dir / "a.gltf").string(),
              &err, dir / "err.txt") == 1);
    CHECK(err.find("overlap.gltf: mesh 'atlas cube'") != std::string::npos);
    // Usage: an unknown shader or map, a size out of range, an output that is not .gltf.
    const std::string cube = " bake " + kAtlasCube.string();
    CHECK(run(qs + cube + " --shader no_such_shader -o " + (dir / "a.gltf").string()) == 2);
    CHECK(run(qs + cube + " --shader spots --maps colour -o " + (dir / "a.gltf").string()) == 2);
    CHECK(run(qs + cube + " --shader spots --size 0 -o " + (dir / "a.gltf").string()) == 2);
    CHECK(run(qs + cube + " --shader spots -o " + (dir / "a.png").string()) == 2);
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        INFO(name);
        CHECK((name == "no-uv.gltf" || name == "no-uv.bin" || name == "overlap.gltf" || name == "overlap.bin" ||
               name == "err.txt"));
    }

    REQUIRE(run(qs + cube + " --shader spots --size 64 --time 0.5 -o " + (dir / "cube.gltf").string()) == 0);
    const Image color = read_image(dir / "cube-color.png");
    CHECK(color.width == 64);
    CHECK(color.height == 64);
    Scene baked = load_scene(dir / "cube.gltf");
    REQUIRE(baked.objects.size() == 1);
    REQUIRE(baked.textures.size() == 1);
    CHECK(baked.textures[0].image.file.filename() == "cube-color.png");
    CHECK(baked.meshes[0].vertices.size() == load_scene(kAtlasCube).meshes[0].vertices.size());
    CHECK(run(qs + " render " + (dir / "cube.gltf").string() + " --size 32x32 -o " + (dir / "cube.png").string()) == 0);
    std::filesystem::remove_all(dir);
}

TEST_CASE("bake: skirts follow the chart boundaries of vertices welded by texcoord, and fill only the gutter", "[bake]") {
    // The cube: six square charts, four boundary edges each; every skirt vertex keeps a boundary
    // vertex's position, and the outer ones lie `w` beyond their chart's square on both axes at
    // its corners.
    const Scene cube = load_scene(kAtlasCube);
    const Mesh& m = cube.meshes[0];
    const float w = 0.01f;
    const Mesh skirt = skirt_mesh(m, w);
    CHECK(skirt.indices.size() == 24 * 6);
    REQUIRE(skirt.vertices.size() == 24 * 4);
    for (std::size_t q = 0; q < 24; ++q) {
        for (int k = 0; k < 4; ++k) {
            const Vertex& v = skirt.vertices[q * 4 + std::size_t(k)];
            CHECK(std::any_of(m.vertices.begin(), m.vertices.end(), [&](const Vertex& c) { return c.position == v.position; }));
        }
        const Vertex &inner = skirt.vertices[q * 4], &outer = skirt.vertices[q * 4 + 3];
        CHECK(std::abs(std::abs(outer.texcoord.x - inner.texcoord.x) - w) < 1e-6f);
        CHECK(std::abs(std::abs(outer.texcoord.y - inner.texcoord.y) - w) < 1e-6f);
    }
    // A square of two triangles whose diagonal's vertices are duplicated (equal texcoords, other
    // indices): welded, the diagonal is inside the chart, and only the four sides are boundary.
    Mesh square{"square", {{{0, 0, 0}, {0.2f, 0.2f}}, {{1, 0, 0}, {0.8f, 0.2f}}, {{1, 1, 0}, {0.8f, 0.8f}},
                           {{0, 0, 0}, {0.2f, 0.2f}}, {{1, 1, 0}, {0.8f, 0.8f}}, {{0, 1, 0}, {0.2f, 0.8f}}},
                {0, 1, 2, 3, 4, 5}};
    CHECK(skirt_mesh(square, w).indices.size() == 4 * 6);
    // The sphere: its seam's two columns and its poles' notches are boundaries.
    CHECK_FALSE(skirt_mesh(load_scene(kAtlasSphere).meshes[0], w).indices.empty());

    // Baked with skirts, every texel a chart covers keeps its colour; gutter texels near charts
    // are filled.
    AtlasRequest req;
    req.size = 96;
    req.frame.time = 0.5;
    req.frame.shader_override = "spots";
    const Image bare = bake_atlas(cube, req);
    req.skirt = 4;
    const Image skirted = bake_atlas(cube, req);
    std::size_t charts = 0, filled = 0, changed = 0;
    for (std::size_t i = 0; i < bare.rgba.size(); i += 4) {
        if (bare.rgba[i + 3] > 0.0f) {
            ++charts;
            changed += !std::equal(&bare.rgba[i], &bare.rgba[i] + 4, &skirted.rgba[i]);
        } else {
            filled += skirted.rgba[i + 3] > 0.0f;
        }
    }
    CHECK(charts > 0);
    CHECK(changed == 0);
    CHECK(filled > charts / 4);
    CHECK_THROWS_AS(bake_atlas(cube, AtlasRequest{16, kMaxSkirt + 1, {}}), std::invalid_argument);
}

namespace {

// One mesh whose triangles are `uv`, three texcoords each, its positions the texcoords (a triangle
// without area in the atlas then has none on the surface either).
Scene uv_mesh(const std::vector<glm::vec2>& uv) {
    Scene s;
    s.file = "uv-mesh.gltf";
    Mesh m;
    m.name = "uv mesh";
    for (std::size_t i = 0; i < uv.size(); ++i) {
        m.vertices.push_back(Vertex{glm::vec3(uv[i], 0.0f), uv[i]});
        m.indices.push_back(std::uint32_t(i));
    }
    s.meshes.push_back(m);
    Object o;
    o.name = "uv object";
    s.objects.push_back(o);
    return s;
}

// A disc of `n` triangles around one vertex: every triangle touches the centre.
std::vector<glm::vec2> fan(int n) {
    std::vector<glm::vec2> uv;
    auto rim = [n](int k) {
        const double a = 2.0 * 3.141592653589793 * double(k % n) / double(n);
        return glm::vec2(float(0.5 + 0.49 * std::cos(a)), float(0.5 + 0.49 * std::sin(a)));
    };
    for (int k = 0; k < n; ++k) uv.insert(uv.end(), {glm::vec2(0.5f), rim(k), rim(k + 1)});
    return uv;
}

bool overlaps(const std::vector<glm::vec2>& uv) {
    const std::string e = error_of(uv_mesh(uv));
    INFO(e);
    REQUIRE((e.empty() || e.find("overlap in TEXCOORD_0") != std::string::npos));
    return !e.empty();
}

}  // namespace

TEST_CASE(
    "bake: the overlap check tests each triangle against its sweep neighbours only, a 32,000-triangle fan included",
    "[bake]") {
    // Every triangle of the fan shares its centre: the binned check of earlier versions tested
    // every pair (46 s); the sweep tests at most three pairs per triangle.
    std::vector<glm::vec2> disc = fan(32000);
    CHECK(check_atlas(uv_mesh(disc)) <= 3 * 32000);
    // Two rim vertices swapped: one triangle folds over its neighbour.
    std::swap(disc[3 * 100 + 2], disc[3 * 101 + 2]);
    std::swap(disc[3 * 101 + 1], disc[3 * 102 + 1]);
    CHECK(overlaps(disc));
}

TEST_CASE("bake: the sweep finds an overlap exactly when some pair of triangles overlaps", "[bake]") {
    // Meshes of 2 to 9 triangles on coarse grids (shared vertices, collinear and touching edges,
    // slivers, duplicates) and fine ones, from a fixed seed; each verdict against every pair's.
    std::uint64_t state = 88172645463325252ull;
    auto next = [&] {
        state ^= state << 13, state ^= state >> 7, state ^= state << 17;
        return state;
    };
    int found = 0, clear = 0;
    for (int mesh = 0; mesh < 3000; ++mesh) {
        const int grid = std::array<int, 4>{2, 3, 4, 1000}[std::size_t(mesh % 4)];
        const int n = 2 + int(next() % 8);
        // Each triangle within a few grid steps of a corner of its own: many meshes overlap nowhere.
        const int reach = std::max(1, grid / 8);
        auto step = [&] { return int(next() % std::uint64_t(2 * reach + 1)) - reach; };
        auto on_grid = [&](int v) { return float(std::clamp(v, 0, grid)) / float(grid); };
        std::vector<glm::vec2> uv;
        for (int i = 0; i < n; ++i) {
            const int x = int(next() % std::uint64_t(grid + 1)), y = int(next() % std::uint64_t(grid + 1));
            for (int k = 0; k < 3; ++k) uv.emplace_back(on_grid(x + (k ? step() : 0)), on_grid(y + (k ? step() : 0)));
        }
        bool any = false;
        for (int i = 0; i < n && !any; ++i) {
            for (int j = i + 1; j < n && !any; ++j) {
                any = overlaps({uv[std::size_t(3 * i)], uv[std::size_t(3 * i + 1)], uv[std::size_t(3 * i + 2)],
                                uv[std::size_t(3 * j)], uv[std::size_t(3 * j + 1)], uv[std::size_t(3 * j + 2)]});
            }
        }
        INFO("mesh " << mesh);
        CHECK(overlaps(uv) == any);
        (any ? found : clear) += 1;
    }
    CHECK(found > 100);
    CHECK(clear > 100);
}

}  // namespace qs
