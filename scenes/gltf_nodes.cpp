// glTF nodes' local transforms and cameras, every number checked; the camera a file without one is
// framed by; the scene's extras (clear colour, time, size).
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

double number_of(const tinygltf::Value& v) { return v.IsInt() ? double(v.Get<int>()) : v.Get<double>(); }

}  // namespace

// A node's local transform, every number checked: glTF gives them as doubles, kept as doubles
// (transforms are composed in double), and one that does not fit in float (a translation of
// 1e39) would place everything at infinity once rounded for drawing.
Node read_node(const tinygltf::Node& n, const std::filesystem::path& file, const std::string& field) {
    auto number = [&](double v, const char* what) {
        if (!std::isfinite(float(v))) {
            fail(file, field + "." + what, "value " + std::to_string(v) + " is not a finite float");
        }
        return v;
    };
    Node node;
    node.name = n.name.empty() ? field : n.name;
    if (!n.matrix.empty()) {
        if (n.matrix.size() != 16) fail(file, field + ".matrix", "expected 16 numbers");
        node.has_matrix = true;
        for (int i = 0; i < 16; ++i) glm::value_ptr(node.matrix)[i] = number(n.matrix[std::size_t(i)], "matrix");
        return node;
    }
    if (!n.translation.empty()) {
        if (n.translation.size() != 3) fail(file, field + ".translation", "expected 3 numbers");
        for (int i = 0; i < 3; ++i) node.translation[i] = number(n.translation[std::size_t(i)], "translation");
    }
    if (!n.rotation.empty()) {
        if (n.rotation.size() != 4) fail(file, field + ".rotation", "expected 4 numbers");
        const glm::dquat q(number(n.rotation[3], "rotation"), number(n.rotation[0], "rotation"),
                           number(n.rotation[1], "rotation"), number(n.rotation[2], "rotation"));
        if (glm::length(q) == 0.0) fail(file, field + ".rotation", "a zero quaternion is no rotation");
        node.rotation = glm::normalize(q);
    }
    if (!n.scale.empty()) {
        if (n.scale.size() != 3) fail(file, field + ".scale", "expected 3 numbers");
        for (int i = 0; i < 3; ++i) node.scale[i] = number(n.scale[std::size_t(i)], "scale");
    }
    return node;
}

Camera read_camera(const tinygltf::Model& m, int index, const glm::dmat4& world, const std::filesystem::path& file,
                   const std::string& node_field) {
    if (std::size_t(index) >= m.cameras.size()) fail(file, node_field + ".camera", "index out of range");
    if (!checks::places_things(glm::mat4(world))) {
        fail(file, node_field,
             "the camera's transform is not finite or is degenerate (determinant " +
                 std::to_string(checks::determinant(glm::mat4(world))) + "): it sees nothing");
    }
    const tinygltf::Camera& c = m.cameras[std::size_t(index)];
    const std::string cf = indexed("cameras", std::size_t(index));
    Camera cam;
    cam.view = glm::inverse(world);
    if (!checks::is_finite(glm::mat4(cam.view))) {
        fail(file, node_field, "the camera's transform cannot be inverted in float");
    }
    auto finite_float = [](double v) { return std::isfinite(float(v)); };
    if (c.type == "perspective") {
        cam.yfov = c.perspective.yfov;
        cam.znear = c.perspective.znear;
        cam.zfar = c.perspective.zfar > 0.0 ? c.perspective.zfar : 1e6;
        cam.aspect_ratio = c.perspective.aspectRatio > 0.0 && finite_float(c.perspective.aspectRatio)
                               ? c.perspective.aspectRatio
                               : 0.0;
        if (!(cam.yfov > 1e-6 && cam.yfov < 3.14159)) fail(file, cf + ".perspective.yfov", "must be in (0, pi)");
        if (!finite_float(c.perspective.znear) || !finite_float(c.perspective.zfar) ||
            !(cam.znear > 0.0 && cam.zfar > cam.znear)) {
            fail(file, cf + ".perspective", "needs finite 0 < znear < zfar");
        }
    } else if (c.type == "orthographic") {
        cam.kind = Camera::Kind::Orthographic;
        cam.xmag = c.orthographic.xmag, cam.ymag = c.orthographic.ymag;
        cam.znear = c.orthographic.znear, cam.zfar = c.orthographic.zfar;
        for (const double v : {cam.xmag, cam.ymag}) {
            if (!finite_float(v) || float(v) == 0.0f || !std::isfinite(1.0f / float(v))) {
                fail(file, cf + ".orthographic", "xmag and ymag must be finite and non-zero");
            }
        }
        cam.aspect_ratio = std::abs(cam.xmag / cam.ymag);
        if (!finite_float(cam.znear) || !finite_float(cam.zfar) || !(cam.zfar > cam.znear) ||
            !std::isfinite(2.0f / (float(cam.znear) - float(cam.zfar)))) {
            fail(file, cf + ".orthographic", "needs finite znear < zfar");
        }
    } else {
        fail(file, cf + ".type", "unknown camera type '" + c.type + "'");
    }
    if (!checks::is_finite(glm::mat4(cam.projection(1.0) * cam.view))) {
        fail(file, cf, "its projection of " + node_field + "'s view is not finite");
    }
    return cam;
}

// For a file without a camera: a three-quarter view of glTF's front (+Z), from 30 degrees to the
// right (+X) and 20 degrees above, +Y up, at the bounding sphere of everything in the scene (where
// it stands before any animation), with a 45 degree field of view and an aspect ratio of 1, so
// that the sphere shows whole at any image size (Camera::projection). Seen straight from the
// front, a box shows one face and a flat part nothing of its depth.
Camera framing_camera(const Scene& scene) {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const Object& o : scene.objects) {
        for (const Vertex& v : scene.meshes[o.mesh].vertices) {
            const glm::dvec3 p = glm::dvec3(o.world_from_object * glm::dvec4(glm::dvec3(v.position), 1.0));
            lo = glm::min(lo, p), hi = glm::max(hi, p);
        }
    }
    const glm::dvec3 centre = 0.5 * (lo + hi);
    const double radius = std::max(0.5 * glm::length(hi - lo), 1e-6);
    Camera cam;
    cam.name = "the default camera";
    cam.yfov = glm::radians(45.0);
    cam.aspect_ratio = 1.0;
    const double distance = radius / std::sin(0.5 * cam.yfov) * 1.05;
    const double azimuth = glm::radians(30.0), elevation = glm::radians(20.0);
    const glm::dvec3 towards_eye(std::sin(azimuth) * std::cos(elevation), std::sin(elevation),
                                 std::cos(azimuth) * std::cos(elevation));
    cam.view = glm::lookAt(centre + distance * towards_eye, centre, glm::dvec3(0.0, 1.0, 0.0));
    cam.znear = std::max(distance - 1.5 * radius, distance * 1e-3);
    cam.zfar = distance + 1.5 * radius;
    return cam;
}

void read_scene_extras(const tinygltf::Value& extras, const std::filesystem::path& path, const std::string& field,
                       Scene& scene) {
    if (!extras.IsObject()) return;
    if (extras.Has("clear_color")) {
        const tinygltf::Value& c = extras.Get("clear_color");
        if (!c.IsArray() || c.ArrayLen() != 4) fail(path, field + ".clear_color", "expected 4 numbers");
        for (int i = 0; i < 4; ++i) {
            if (!c.Get(i).IsNumber() || !std::isfinite(float(number_of(c.Get(i))))) {
                fail(path, field + ".clear_color", "expected 4 finite numbers");
            }
            scene.clear_color[i] = float(number_of(c.Get(i)));
        }
    }
    if (extras.Has("time")) {
        const tinygltf::Value& t = extras.Get("time");
        if (!t.IsNumber() || !std::isfinite(float(number_of(t)))) fail(path, field + ".time", "expected a finite number");
        scene.time = float(number_of(t));
    }
    if (extras.Has("stretch")) {
        if (!extras.Get("stretch").IsBool()) fail(path, field + ".stretch", "expected true or false");
        scene.camera.stretch = extras.Get("stretch").Get<bool>();
    }
    if (extras.Has("size")) {
        const tinygltf::Value& s = extras.Get("size");
        if (!s.IsArray() || s.ArrayLen() != 2 || !s.Get(0).IsInt() || !s.Get(1).IsInt()) {
            fail(path, field + ".size", "expected [width, height] integers");
        }
        scene.width = s.Get(0).Get<int>(), scene.height = s.Get(1).Get<int>();
        if (scene.width <= 0 || scene.height <= 0 || scene.width > limits::kImageSide || scene.height > limits::kImageSide) {
            fail(path, field + ".size", std::to_string(scene.width) + "x" + std::to_string(scene.height) +
                                            " is outside 1.." + std::to_string(limits::kImageSide));
        }
    }
}

}  // namespace qs::gltf_read
