#include "generators/atlas_scenes.h"

#include <cmath>
#include <numbers>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/gltf.h"
#include "scenes/scene.h"

namespace qs {

namespace {

constexpr double kPi = std::numbers::pi;

// The cube [-1, 1]^3 unwrapped into six square charts, laid out 3 x 2 with a gutter around each
// (the charts are 0.3 of the atlas wide in cells of 1/3 x 1/2). Corners are duplicated per face:
// every edge of the cube is a seam between two charts.
Mesh atlas_cube_mesh() {
    Mesh m;
    m.name = "atlas cube";
    constexpr float kChart = 0.3f;
    int face = 0;
    for (int axis = 0; axis < 3; ++axis) {
        for (const float side : {-1.0f, 1.0f}) {
            const glm::vec2 corner(float(face % 3) / 3.0f + (1.0f / 3.0f - kChart) / 2.0f,
                                   float(face / 3) / 2.0f + (0.5f - kChart) / 2.0f);
            const std::uint32_t base = std::uint32_t(m.vertices.size());
            for (int k = 0; k < 4; ++k) {
                const float a = (k == 1 || k == 2) ? 1.0f : -1.0f, b = k >= 2 ? 1.0f : -1.0f;
                glm::vec3 p;
                p[axis] = side, p[(axis + 1) % 3] = a * side, p[(axis + 2) % 3] = b;
                m.vertices.push_back({p, corner + kChart * glm::vec2(0.5f * a + 0.5f, 0.5f * b + 0.5f)});
            }
            m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
            ++face;
        }
    }
    return m;
}

// A unit UV sphere of `segments` x `rings` quads: u around the y axis, v from the south pole to
// the north, both mapped into [0.02, 0.98] of the atlas. The column at u = 0 is repeated at u = 1
// (a seam), and each pole is one vertex per segment, at its segment's middle u.
Mesh atlas_sphere_mesh(int segments, int rings) {
    Mesh m;
    m.name = "atlas sphere";
    auto uv = [](double u, double v) { return glm::vec2(float(0.02 + 0.96 * u), float(0.02 + 0.96 * v)); };
    for (int j = 0; j <= rings; ++j) {
        for (int i = 0; i <= segments; ++i) {
            const double u = double(i) / segments, v = double(j) / rings;
            const double theta = 2 * kPi * u, phi = kPi * (v - 0.5);
            const bool pole = j == 0 || j == rings;
            const glm::vec3 p(float(std::cos(phi) * std::cos(theta)), float(std::sin(phi)), float(-std::cos(phi) * std::sin(theta)));
            m.vertices.push_back({pole ? glm::vec3(0.0f, j == 0 ? -1.0f : 1.0f, 0.0f) : p,
                                  uv(pole ? (i + 0.5) / segments : u, v)});
        }
    }
    const auto at = [&](int i, int j) { return std::uint32_t(j * (segments + 1) + i); };
    for (int j = 0; j < rings; ++j) {
        for (int i = 0; i < segments; ++i) {
            if (j > 0) m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            if (j < rings - 1) m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
    return m;
}

Scene atlas_scene_of(Mesh mesh, const std::string& shader, glm::vec3 eye) {
    Scene s;
    s.camera.view = glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    s.camera.yfov = glm::radians(40.0f);
    s.camera.znear = 0.5f, s.camera.zfar = 20.0f;
    s.clear_color = {0.1f, 0.2f, 0.3f, 0.0f};
    s.width = 512, s.height = 512;
    s.meshes = {std::move(mesh)};
    Object o;
    o.name = s.meshes[0].name;
    o.shader = shader;
    s.objects = {o};
    return s;
}

}  // namespace

void write_atlas_scenes(const std::filesystem::path& dir) {
    const std::filesystem::path out = dir / "bake";
    std::filesystem::create_directories(out);
    save_scene(atlas_scene_of(atlas_cube_mesh(), "spots", {2.6f, 2.2f, 4.2f}), out / "atlas-cube.gltf");
    save_scene(atlas_scene_of(atlas_sphere_mesh(48, 24), "spots", {0.8f, 1.2f, 3.4f}), out / "atlas-sphere.gltf");
}

}  // namespace qs
