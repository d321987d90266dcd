// Normal maps from a shader's height (render/normal_bake.h): the finite differences against the
// analytic normal, the map's encoding, and `quadshade bake --maps`' combinations and refusals.
// The lit render of the baked maps is checked against OSMesa in tests/reference/test_atlas_bake.cpp.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>

#include <glm/geometric.hpp>

#include "images/image_io.h"
#include "render/atlas_bake.h"
#include "render/normal_bake.h"
#include "scenes/gltf.h"
#include "shading/height_field.h"
#include "tests/test_command.h"
#include "tests/test_paths.h"

namespace qs {

namespace {

using namespace test;

const std::filesystem::path kAtlasCube = kSource / "scenes/assets/bake/atlas-cube.gltf";
const std::filesystem::path kAtlasSphere = kSource / "scenes/assets/bake/atlas-sphere.gltf";

double angle(const glm::dvec3& a, const glm::dvec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

double max_angle(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
    double m = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, angle(a[i], b[i]));
    return m;
}

// An estimate of M2, the largest second derivative of h along a texel's T or B: the analytic
// first derivatives (Dual2, double) differenced over delta, at every texel.
double second_derivative_bound(const HeightField& field, const AtlasTexels& texels) {
    constexpr double delta = 1e-5;
    double m2 = 0.0;
    for (std::size_t begin = 0; begin < texels.texel.size(); begin += kBatchLanes) {
        PointBatch p{}, pt{}, pb{}, t{}, b{};
        for (int l = 0; l < kBatchLanes; ++l) {
            const std::size_t k = std::min(begin + std::size_t(l), texels.texel.size() - 1);
            const glm::dvec3 P = texels.position[k], T = texels.tangent[k], B = texels.bitangent[k];
            const glm::dvec3 PT = P + delta * T, PB = P + delta * B;
            p.x[l] = P.x, p.y[l] = P.y, p.z[l] = P.z;
            pt.x[l] = PT.x, pt.y[l] = PT.y, pt.z[l] = PT.z;
            pb.x[l] = PB.x, pb.y[l] = PB.y, pb.z[l] = PB.z;
            t.x[l] = T.x, t.y[l] = T.y, t.z[l] = T.z;
            b.x[l] = B.x, b.y[l] = B.y, b.z[l] = B.z;
        }
        double h[kBatchLanes], ht[kBatchLanes], hb[kBatchLanes], h2[kBatchLanes], ht2[kBatchLanes], hb2[kBatchLanes];
        field.gradients(Precision::Double, p, t, b, h, ht, hb);
        field.gradients(Precision::Double, pt, t, b, h2, ht2, hb2);
        for (int l = 0; l < kBatchLanes; ++l) m2 = std::max(m2, std::abs(ht2[l] - ht[l]) / delta);
        field.gradients(Precision::Double, pb, t, b, h2, ht2, hb2);
        for (int l = 0; l < kBatchLanes; ++l) m2 = std::max(m2, std::abs(hb2[l] - hb[l]) / delta);
    }
    return m2;
}

// The cube with its first face's chart (its first two triangles) mirrored in s: a left-handed
// tangent frame there.
Scene mirrored_cube() {
    Scene s = load_scene(kAtlasCube);
    Mesh& m = s.meshes[0];
    float lo = 1.0f, hi = 0.0f;
    for (std::size_t t = 0; t < 6; ++t) {
        const float x = m.vertices[m.indices[t]].texcoord.x;
        lo = std::min(lo, x), hi = std::max(hi, x);
    }
    std::vector<bool> done(m.vertices.size(), false);
    for (std::size_t t = 0; t < 6; ++t) {
        const std::uint32_t i = m.indices[t];
        if (done[i]) continue;
        done[i] = true;
        m.vertices[i].texcoord.x = lo + hi - m.vertices[i].texcoord.x;
    }
    return s;
}

}  // namespace

TEST_CASE("normals: finite differences converge to the analytic (Dual2) normal at first order, within Taylor's bound",
          "[bake][normals]") {
    // The bound: with T and B orthonormal and both normals n ~ N - A g (g = h_T T + h_B B, A the
    // amplitude), the forward difference (h(p + eT) - h(p)) / e differs from h_T by at most
    // e/2 M2 (Taylor's remainder; M2 the largest |d2h/dT2|, likewise along B), so the two
    // unnormalised normals differ by |d| <= A sqrt(2) e/2 M2 while both are at least 1 long
    // (N is orthogonal to g): the angle between them is at most asin(|d|). In double the
    // rounding term (about 1e-16 / e) is negligible for e >= 1e-4.
    const HeightField* field = find_height_field("noise_bumps");
    REQUIRE(field);
    for (const Scene& scene : {load_scene(kAtlasSphere), load_scene(kAtlasCube), mirrored_cube()}) {
        const AtlasTexels texels = atlas_texels(scene, 64);
        REQUIRE(texels.texel.size() > 1000);
        NormalBakeRequest r;
        r.size = 64;
        r.precision = Precision::Double;
        const std::vector<glm::dvec3> analytic = surface_normals(*field, texels, r);
        // The relief tilts the normals: the comparison is not of N with N.
        CHECK(max_angle(analytic, texels.normal) > 0.05);
        const double m2 = second_derivative_bound(*field, texels);
        INFO(scene.file.filename().string() << ": M2 " << m2);
        REQUIRE(m2 > 0.0);
        r.method = NormalMethod::FiniteDifferences;
        double previous = 0.0;
        for (const double e : {1e-2, 1e-3, 1e-4}) {
            r.step = e;
            const double worst = max_angle(surface_normals(*field, texels, r), analytic);
            // 1.25: M2 is the largest of the sampled second derivatives, not their supremum.
            const double bound = std::asin(std::min(1.0, 1.25 * field->amplitude() * std::sqrt(2.0) * e / 2.0 * m2));
            INFO("e " << e << ": max angle " << worst << " rad, bound " << bound);
            CHECK(worst <= bound);
            if (previous > 0.0) CHECK(worst < previous / 5.0);  // first order: 10x smaller per decade
            previous = worst;
        }
        // Every normal is a unit vector on the face normal's side, in both frames' handedness.
        for (std::size_t k = 0; k < analytic.size(); ++k) {
            CHECK(std::abs(glm::length(analytic[k]) - 1.0) < 1e-12);
            if (glm::dot(analytic[k], texels.normal[k]) < 0.5) FAIL("texel " << texels.texel[k] << " turned away from its face");
        }
        // Float lanes: the same chain rule, rounded to float.
        r.method = NormalMethod::Analytic;
        r.precision = Precision::Float;
        CHECK(max_angle(surface_normals(*field, texels, r), analytic) < 1e-4);
    }
}

TEST_CASE("normals: the map encodes object-space normals as 0.5 + 0.5 n, alpha 0 in the gutter, skirts dilate into it",
          "[bake][normals]") {
    const HeightField* field = find_height_field("noise_bumps");
    REQUIRE(field);
    const Scene scene = load_scene(kAtlasCube);
    NormalBakeRequest r;
    r.size = 48;
    const AtlasTexels texels = atlas_texels(scene, r.size);
    const std::vector<glm::dvec3> normals = surface_normals(*field, texels, r);
    const Image map = bake_normal_map(scene, *field, r);
    REQUIRE(map.width == 48);
    REQUIRE(map.height == 48);
    std::size_t covered = 0;
    for (std::size_t p = 0; p < 48 * 48; ++p) covered += map.rgba[p * 4 + 3] == 1.0f;
    CHECK(covered == texels.texel.size());
    CHECK(covered < 48 * 48);  // the cube's atlas leaves gutters
    for (std::size_t k = 0; k < texels.texel.size(); ++k) {
        const float* px = &map.rgba[std::size_t(texels.texel[k]) * 4];
        for (int c = 0; c < 3; ++c) CHECK(std::abs(double(px[c]) - (0.5 + 0.5 * normals[k][c])) < 1e-6);
    }
    r.skirt = 2;
    const Image skirted = bake_normal_map(scene, *field, r);
    std::size_t skirted_covered = 0;
    for (std::size_t p = 0; p < 48 * 48; ++p) {
        skirted_covered += skirted.rgba[p * 4 + 3] == 1.0f;
        if (map.rgba[p * 4 + 3] == 1.0f) CHECK(std::equal(&map.rgba[p * 4], &map.rgba[p * 4 + 4], &skirted.rgba[p * 4]));
        if (skirted.rgba[p * 4 + 3] == 1.0f) {
            const glm::dvec3 n = glm::dvec3(skirted.rgba[p * 4], skirted.rgba[p * 4 + 1], skirted.rgba[p * 4 + 2]) * 2.0 - 1.0;
            CHECK(std::abs(glm::length(n) - 1.0) < 1e-6);
        }
    }
    CHECK(skirted_covered > covered);
    CHECK_THROWS_AS(bake_normal_map(scene, *field, NormalBakeRequest{.size = 0}), std::invalid_argument);
    CHECK_THROWS_AS(bake_normal_map(scene, *field, NormalBakeRequest{.size = 8, .skirt = 65}), std::invalid_argument);
    CHECK_THROWS_AS(bake_normal_map(scene, *field, NormalBakeRequest{.size = 8, .method = NormalMethod::FiniteDifferences, .step = 0.0}),
                    std::invalid_argument);
}

TEST_CASE("normals: bake --maps writes the height and normal maps the baked scene binds, or refuses with nothing written",
          "[bake][normals]") {
    const auto dir = temp_dir("bake-normals");
    const std::string qs = (kBin / "quadshade").string();
    const std::string cube = qs + " bake " + kAtlasCube.string() + " --size 32";
    auto files = [&] {
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::directory_iterator(dir)) names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    };
    std::string err;
    const std::string out = " -o " + (dir / "c.gltf").string();
    // Refusals: usage (2), each with a message, and no file written.
    struct Refusal {
        std::string options, message;
    };
    for (const Refusal& r : {Refusal{"--shader noise_bumps --maps normal", "color is required"},
                             Refusal{"--shader noise_bumps --maps color,colour", "'colour' is not a map"},
                             Refusal{"--shader noise_bumps --maps color,normal,normal", "'normal' is named twice"},
                             Refusal{"--shader spots --maps color,normal", "shader 'spots' has no height (shaders with one: noise_bumps"},
                             Refusal{"--shader spots --maps color,height", "--maps height: shader 'spots' has no height"},
                             Refusal{"--shader noise_bumps --normals finite", "add normal to --maps"},
                             Refusal{"--shader noise_bumps --maps color,normal --normal-step 0.001", "needs --normals finite"},
                             Refusal{"--shader noise_bumps --maps color,normal --normals finite --normal-step 0", ""},
                             Refusal{"--shader noise_bumps --maps color,normal --normals finite --normal-step nan", ""},
                             Refusal{"--shader noise_bumps --maps color,normal --normals central", "expected analytic | finite"}}) {
        INFO(r.options);
        CHECK(run(cube + " " + r.options + out, &err, dir / "err.txt") == 2);
        CHECK(err.find(r.message) != std::string::npos);
        CHECK(files() == std::vector<std::string>{"err.txt"});
    }
    // Bad input (1): the mesh named, nothing written.
    Scene no_uv = load_scene(kAtlasCube);
    no_uv.meshes[0].has_texcoords = false;
    save_scene(no_uv, dir / "no-uv.gltf");
    CHECK(run(qs + " bake " + (dir / "no-uv.gltf").string() + " --shader noise_bumps --maps color,height,normal --size 32" + out,
              &err, dir / "err.txt") == 1);
    CHECK(err.find("no-uv.gltf: mesh 'atlas cube'") != std::string::npos);
    CHECK(files() == std::vector<std::string>{"err.txt", "no-uv.bin", "no-uv.gltf"});

    // color,height: unlit, the height map bound for other tools; it is noise_bumps_height's atlas.
    REQUIRE(run(cube + " --shader noise_bumps --maps color,height --skirt 2" + out) == 0);
    CHECK(files() == std::vector<std::string>{"c-color.png", "c-height.png", "c.bin", "c.gltf", "err.txt", "no-uv.bin", "no-uv.gltf"});
    Scene baked = load_scene(dir / "c.gltf");
    CHECK(baked.objects.at(0).shader == "single_texture");
    CHECK(baked.objects.at(0).texture_for("heightmap") >= 0);
    CHECK(baked.objects.at(0).texture_for("normalmap") < 0);
    AtlasRequest h;
    h.size = 32, h.skirt = 2;
    h.frame.shader_override = "noise_bumps_height";
    const Image height = bake_atlas(load_scene(kAtlasCube), h), written = read_image(dir / "c-height.png");
    REQUIRE(written.rgba.size() == height.rgba.size());
    for (std::size_t i = 0; i < height.rgba.size(); ++i) {
        if (std::abs(written.rgba[i] - height.rgba[i]) > 0.5f / 255.0f + 1e-6f) FAIL("height map differs at " << i / 4);
    }
    std::filesystem::remove(dir / "c.gltf");

    // color,height,normal (finite): drawn lit by baked_lit, the normal map bound as `normalmap`.
    REQUIRE(run(cube + " --shader noise_bumps --maps normal,color,height --normals finite --normal-step 1e-3 --normal-precision double" + out) == 0);
    baked = load_scene(dir / "c.gltf");
    CHECK(baked.objects.at(0).shader == "baked_lit");
    const int n = baked.objects.at(0).texture_for("normalmap");
    REQUIRE(n >= 0);
    CHECK(baked.textures[std::size_t(n)].image.file.filename() == "c-normal.png");
    CHECK(baked.objects.at(0).texture_for("heightmap") >= 0);
    CHECK(run(qs + " render " + (dir / "c.gltf").string() + " --size 32x32 -o " + (dir / "c.png").string()) == 0);
    // The same with the analytic normals: at e = 1e-3 in double the two maps agree to a step of 8 bits.
    const Image finite = read_image(dir / "c-normal.png");
    std::filesystem::remove(dir / "c.gltf");
    REQUIRE(run(cube + " --shader noise_bumps --maps color,normal" + out) == 0);
    const Image analytic = read_image(dir / "c-normal.png");
    REQUIRE(finite.rgba.size() == analytic.rgba.size());
    for (std::size_t i = 0; i < finite.rgba.size(); ++i) {
        if (std::abs(finite.rgba[i] - analytic.rgba[i]) > 1.5f / 255.0f) FAIL("normal maps differ at " << i / 4);
    }
    std::filesystem::remove_all(dir);
}

}  // namespace qs
