#include "generators/geometry_scenes.h"

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/gltf.h"
#include "scenes/scene.h"

namespace qs {

namespace {
constexpr double kPi = std::numbers::pi;
}  // namespace

Mesh torus_mesh(float R, float r, int steps_u, int steps_v, float s_repeats, float t_repeats) {
    Mesh m;
    m.name = "torus";
    for (int j = 0; j <= steps_v; ++j) {
        for (int i = 0; i <= steps_u; ++i) {
            const double u = double(i) / steps_u, v = double(j) / steps_v;
            const double a = 2 * kPi * u, b = 2 * kPi * v;
            const double ring = R + r * std::cos(b);
            m.vertices.push_back({{float(ring * std::cos(a)), float(r * std::sin(b)), float(ring * std::sin(a))},
                                  {float(s_repeats * u), float(t_repeats * v)}});
        }
    }
    const auto at = [&](int i, int j) { return std::uint32_t(j * (steps_u + 1) + i); };
    for (int j = 0; j < steps_v; ++j) {
        for (int i = 0; i < steps_u; ++i) {
            m.indices.insert(m.indices.end(), {at(i, j), at(i, j + 1), at(i + 1, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)});
        }
    }
    return m;
}

namespace {

// A cube [-1, 1]^3, four vertices per face with st (0, 0)..(1, 1) on each.
Mesh box_mesh() {
    Mesh m;
    m.name = "box";
    for (int axis = 0; axis < 3; ++axis) {
        for (const float side : {-1.0f, 1.0f}) {
            const std::uint32_t base = std::uint32_t(m.vertices.size());
            for (int k = 0; k < 4; ++k) {
                const float a = (k == 1 || k == 2) ? 1.0f : -1.0f, b = k >= 2 ? 1.0f : -1.0f;
                glm::vec3 p;
                p[axis] = side, p[(axis + 1) % 3] = a * side, p[(axis + 2) % 3] = b;
                m.vertices.push_back({p, {0.5f * a + 0.5f, 0.5f * b + 0.5f}});
            }
            m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        }
    }
    return m;
}

// A size x size plane in xz (y = 0) centred on the origin, cells x cells squares of two
// triangles; st is the position divided by st_unit, shifted to start at 0.
Mesh grid_mesh(float size, int cells, float st_unit) {
    Mesh m;
    m.name = "grid";
    for (int j = 0; j <= cells; ++j) {
        for (int i = 0; i <= cells; ++i) {
            const float x = size * (float(i) / float(cells) - 0.5f), z = size * (float(j) / float(cells) - 0.5f);
            m.vertices.push_back({{x, 0.0f, z}, {(x + 0.5f * size) / st_unit, (z + 0.5f * size) / st_unit}});
        }
    }
    const auto at = [&](int i, int j) { return std::uint32_t(j * (cells + 1) + i); };
    for (int j = 0; j < cells; ++j) {
        for (int i = 0; i < cells; ++i) {
            m.indices.insert(m.indices.end(), {at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    }
    return m;
}

// Slivers in the z = 0 plane, none overlapping another: a disc fanned around its centre into
// `spokes` triangles whose angles alternate between wide and 40 times thinner (windings
// alternate too), and beside it a strip of long triangles 1/150 to 1/30 of their length thin.
Mesh sliver_mesh(int spokes) {
    Mesh m;
    m.name = "slivers";
    auto vertex = [&](float x, float y) {
        m.vertices.push_back({{x, y, 0.0f}, {0.5f * x + 0.5f, 0.5f * y + 0.5f}});
        return std::uint32_t(m.vertices.size() - 1);
    };
    const glm::vec2 centre(-0.35f, 0.05f);
    const std::uint32_t c = vertex(centre.x, centre.y);
    const double wide = 2 * kPi / (spokes / 2) * 40.0 / 41.0, thin = wide / 40.0;
    std::vector<std::uint32_t> ring;
    double angle = 0.0;
    for (int k = 0; k < spokes; ++k) {
        ring.push_back(vertex(centre.x + 0.9f * float(std::cos(angle)), centre.y + 0.9f * float(std::sin(angle))));
        angle += k % 2 ? thin : wide;
    }
    for (int k = 0; k < spokes; ++k) {
        const std::uint32_t a = ring[std::size_t(k)], b = ring[std::size_t((k + 1) % spokes)];
        if (k % 2) m.indices.insert(m.indices.end(), {c, a, b});
        else m.indices.insert(m.indices.end(), {c, b, a});
    }
    for (int k = 0; k < 16; ++k) {
        const float y = -0.9f + 0.11f * float(k), thickness = 0.004f + 0.001f * float(k);
        const std::uint32_t a = vertex(0.65f, y), b = vertex(1.25f, y + thickness), d = vertex(0.65f, y + 0.6f * thickness);
        m.indices.insert(m.indices.end(), {a, b, d});
    }
    return m;
}

Object object(std::string name, std::size_t mesh, const glm::mat4& world_from_object, std::string shader) {
    Object o;
    o.name = std::move(name), o.mesh = mesh, o.world_from_object = world_from_object, o.shader = std::move(shader);
    return o;
}

// A perspective camera at `eye` looking at `target`, turned by `roll_degrees` about its view
// direction (the image rotates the other way).
Camera camera(glm::vec3 eye, glm::vec3 target, float yfov_degrees, float znear, float zfar, float roll_degrees = 0.0f) {
    Camera c;
    const glm::vec3 forward = glm::normalize(target - eye);
    const glm::vec3 up = glm::mat3(glm::rotate(glm::mat4(1.0f), glm::radians(roll_degrees), forward)) * glm::vec3(0, 1, 0);
    c.view = glm::lookAt(eye, target, up);
    c.yfov = glm::radians(yfov_degrees);
    c.znear = znear, c.zfar = zfar;
    return c;
}

Scene base_scene(int width, int height, const Camera& c) {
    Scene s;
    s.camera = c;
    s.clear_color = {0.1f, 0.2f, 0.3f, 0.0f};  // alpha 0: coverage reads from alpha
    s.time = 1.0f;
    s.width = width, s.height = height;
    return s;
}

// A torus seen from above its rim under a rolled camera: every pixel of it is drawn over by
// back faces (its material is double-sided, so that they are drawn), the far inner wall shows
// through the hole and the near part of the ring hides the rest. Odd size.
Scene torus_rolled() {
    Scene s = base_scene(777, 431, camera({0.0f, 1.9f, 2.6f}, {0.0f, -0.15f, 0.0f}, 45.0f, 0.5f, 20.0f, 28.0f));
    s.meshes = {torus_mesh(1.0f, 0.45f, 72, 28, 6.0f, 2.0f)};
    s.objects.push_back(object("torus", 0, glm::mat4(1.0f), "dots"));
    s.objects.back().double_sided = true;
    return s;
}

// Overlapping objects: squares at three depths, a box and a torus both passing through the
// middle square (lines where surfaces cross), drawn far and near in mixed order.
Scene overlap(bool reversed, int width, int height) {
    Scene s = base_scene(width, height, camera({0.8f, 0.9f, 4.2f}, {0.0f, 0.0f, 0.0f}, 40.0f, 1.0f, 10.0f));
    s.meshes = {grid_mesh(2.0f, 1, 2.0f), box_mesh(), torus_mesh(0.5f, 0.2f, 40, 16, 4.0f, 1.0f)};
    const glm::mat4 I(1.0f);
    // The squares stand up: (x, y, z) -> (x, -z, y) takes the grid's xz plane to xy, exactly.
    const glm::mat4 stand_up(glm::vec4(1, 0, 0, 0), glm::vec4(0, 0, 1, 0), glm::vec4(0, -1, 0, 0), glm::vec4(0, 0, 0, 1));
    std::vector<Object> o = {
        object("middle square", 0, glm::rotate(glm::scale(I, glm::vec3(1.2f)), glm::radians(20.0f), {0, 1, 0}) * stand_up, "dots"),
        object("torus", 2, glm::rotate(glm::translate(I, {0.3f, 0.2f, 0.25f}), glm::radians(60.0f), {1, 0, 0}), "dots"),
        object("far square", 0, glm::scale(glm::translate(I, {-0.6f, 0.1f, -1.2f}), glm::vec3(1.5f)) * stand_up, "dots"),
        object("box", 1,
               glm::scale(glm::rotate(glm::translate(I, {-0.5f, -0.4f, 0.1f}), glm::radians(30.0f), {1, 1, 0}), glm::vec3(0.5f)),
               "dots"),
        object("near square", 0,
               glm::rotate(glm::scale(glm::translate(I, {0.6f, -0.5f, 0.9f}), glm::vec3(0.5f)), glm::radians(15.0f), {1, 0, 0}) *
                   stand_up,
               "dots"),
    };
    if (reversed) o.assign(o.rbegin(), o.rend());
    s.objects = o;
    return s;
}

// glTF's node hierarchy: a root placed by a matrix, a child by translation, rotation and
// non-uniform scale, a grandchild by a matrix again (under the parent's non-uniform scale and
// rotation it is sheared), and a second root by TRS alone. The objects' world matrices are left
// for the loader to compose.
void write_hierarchy(const std::filesystem::path& file) {
    Scene s = base_scene(384, 256, camera({1.5f, 2.2f, 5.0f}, {0.4f, 0.2f, -0.6f}, 45.0f, 1.0f, 20.0f));
    s.meshes = {box_mesh(), torus_mesh(0.6f, 0.25f, 40, 16, 4.0f, 1.0f)};
    s.objects = {object("arm box", 0, glm::mat4(1.0f), "dots"), object("hand torus", 1, glm::mat4(1.0f), "dots"),
                 object("base box", 0, glm::mat4(1.0f), "dots"), object("side torus", 1, glm::mat4(1.0f), "dots")};
    const glm::mat4 I(1.0f);
    std::vector<SavedNode> nodes(5);
    nodes[0].name = "base";
    nodes[0].matrix = glm::rotate(glm::translate(I, {0.0f, -0.2f, -1.0f}), glm::radians(20.0f), {0, 1, 0});
    nodes[0].object = 2;
    nodes[1].name = "arm";
    nodes[1].parent = 0;
    nodes[1].translation = {1.2f, 0.3f, 0.0f};
    nodes[1].rotation = glm::angleAxis(glm::radians(30.0f), glm::vec3(0, 0, 1));
    nodes[1].scale = {1.6f, 0.5f, 0.8f};
    nodes[1].object = 0;
    nodes[2].name = "hand";
    nodes[2].parent = 1;
    nodes[2].matrix = glm::scale(glm::rotate(glm::translate(I, {0.8f, 1.5f, 0.0f}), glm::radians(45.0f), {1, 0, 0}),
                                 {0.7f, 1.0f, 1.8f});
    nodes[2].object = 1;
    nodes[3].name = "side";
    nodes[3].translation = {-1.1f, 0.4f, 0.2f};
    nodes[3].rotation = glm::angleAxis(glm::radians(-70.0f), glm::normalize(glm::vec3(1, 0.3f, 0)));
    nodes[3].scale = {1.0f, 2.0f, 0.6f};
    nodes[4].name = "side torus";
    nodes[4].parent = 3;
    nodes[4].object = 3;
    save_scene(s, file, nodes);
}

// The grazing plane: 200 x 200 (8 x 8 cells), seen from 0.3 above, looking 4 degrees down: the
// cells around the eye cross the near plane (0.1) and the screen's sides, the far ones meet
// at the horizon. Odd size.
Scene grazing_plane() {
    const glm::vec3 eye(0.0f, 0.3f, 0.0f);
    const float pitch = glm::radians(-4.0f), yaw = glm::radians(20.0f);
    const glm::vec3 forward(std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch));
    Scene s = base_scene(777, 431, camera(eye, eye + forward, 50.0f, 0.1f, 400.0f));
    s.meshes = {grid_mesh(200.0f, 8, 10.0f)};
    s.objects.push_back(object("plane", 0, glm::mat4(1.0f), "dots"));
    return s;
}

// A fan of slivers and a strip of long thin triangles, tilted away in perspective: nothing
// overlaps, so the depth buffer is left out, and every pixel must still be llvmpipe's. Double
// sided, so that both windings are drawn.
Scene sliver_fan() {
    Scene s = base_scene(256, 192, camera({0.25f, -0.2f, 2.3f}, {0.25f, -0.05f, 0.0f}, 50.0f, 0.5f, 10.0f));
    s.meshes = {sliver_mesh(240)};
    s.objects.push_back(object("slivers", 0, glm::rotate(glm::mat4(1.0f), glm::radians(-55.0f), {1, 0, 0}), "dots"));
    s.objects.back().double_sided = true;
    return s;
}

// Back-face culling as glTF asks for it (materials are single-sided unless doubleSided): a torus
// whose near part crosses the near plane (the clipped pieces are culled by what is seen of them:
// through the cut, its inner walls are culled and the far side shows), a box under a mirroring
// node (its front faces wind clockwise: it must look solid, not hollow), two squares seen from
// behind, single-sided (culled) and double-sided (drawn), and the sliver fan single-sided, whose
// windings alternate: only the thin slivers face the eye. Odd size.
Scene culling() {
    Scene s = base_scene(301, 187, camera({0.0f, 0.0f, 2.4f}, {0.0f, 0.0f, 0.0f}, 60.0f, 0.9f, 10.0f));
    s.meshes = {torus_mesh(0.3f, 0.12f, 48, 20, 6.0f, 2.0f), box_mesh(), grid_mesh(1.0f, 1, 1.0f), sliver_mesh(120)};
    const glm::mat4 I(1.0f);
    // The squares stand up facing -z: (x, y, z) -> (x, z, -y) turns the grid's +y normal away from the eye.
    const glm::mat4 face_away(glm::vec4(1, 0, 0, 0), glm::vec4(0, 0, -1, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0, 0, 0, 1));
    s.objects = {
        object("torus", 0, glm::rotate(glm::translate(I, {0.0f, -0.15f, 1.35f}), glm::radians(-60.0f), {1, 0, 0}), "dots"),
        object("mirrored box", 1,
               glm::scale(glm::rotate(glm::translate(I, {-1.3f, 0.6f, -0.5f}), glm::radians(35.0f), {1, 1, 0}),
                          glm::vec3(-0.3f, 0.3f, 0.3f)),
               "dots"),
        object("single-sided square", 2, glm::translate(I, {1.2f, 0.5f, -0.5f}) * face_away, "dots"),
        object("double-sided square", 2, glm::translate(I, {1.2f, -0.7f, -0.5f}) * face_away, "dots"),
        object("single-sided slivers", 3, glm::scale(glm::translate(I, {-1.3f, -0.8f, -0.5f}), glm::vec3(0.6f)), "dots"),
    };
    s.objects[3].double_sided = true;  // the double-sided square
    return s;
}

}  // namespace

void write_geometry_scenes(const std::filesystem::path& dir) {
    const std::filesystem::path out = dir / "conformance";
    std::filesystem::create_directories(out);
    save_scene(torus_rolled(), out / "torus-rolled.gltf");
    save_scene(overlap(false, 320, 240), out / "overlap.gltf");
    save_scene(overlap(true, 201, 151), out / "overlap-reversed.gltf");
    write_hierarchy(out / "hierarchy.gltf");
    save_scene(grazing_plane(), out / "grazing-plane.gltf");
    save_scene(sliver_fan(), out / "sliver-fan.gltf");
    save_scene(culling(), out / "culling.gltf");
}

}  // namespace qs
