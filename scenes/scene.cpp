#include "scenes/scene.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace qs {

namespace {
struct NamedCompareFunc {
    std::string_view name;
    CompareFunc func;
};
constexpr NamedCompareFunc kCompareFuncs[] = {
    {"NEVER", CompareFunc::Never},     {"LESS", CompareFunc::Less},       {"EQUAL", CompareFunc::Equal},
    {"LEQUAL", CompareFunc::LessEqual}, {"GREATER", CompareFunc::Greater}, {"NOTEQUAL", CompareFunc::NotEqual},
    {"GEQUAL", CompareFunc::GreaterEqual}, {"ALWAYS", CompareFunc::Always},
};
}  // namespace

std::string_view compare_func_name(CompareFunc f) {
    for (const NamedCompareFunc& n : kCompareFuncs) {
        if (n.func == f) return n.name;
    }
    return "?";
}

std::optional<CompareFunc> compare_func_named(std::string_view name) {
    for (const NamedCompareFunc& n : kCompareFuncs) {
        if (n.name == name) return n.func;
    }
    return std::nullopt;
}

glm::dmat4 Camera::projection(double aspect) const {
    if (kind == Kind::Orthographic) {
        // glTF's orthographic projection: x / xmag, y / ymag, z mapped from [-znear, -zfar]; the
        // half height grows where the image is narrower than xmag / ymag.
        // (A negative magnification mirrors that axis.)
        const double half_height = stretch ? std::abs(ymag) : std::max(std::abs(ymag), std::abs(xmag) / aspect);
        glm::dmat4 p(0.0);
        p[0][0] = std::copysign(1.0 / (stretch ? std::abs(xmag) : half_height * aspect), xmag);
        p[1][1] = std::copysign(1.0 / half_height, ymag);
        p[2][2] = 2.0 / (znear - zfar);
        p[3][2] = (zfar + znear) / (znear - zfar);
        p[3][3] = 1.0;
        return p;
    }
    double fov = yfov;
    if (aspect_ratio > 0.0 && aspect < aspect_ratio) {
        fov = 2.0 * std::atan(std::tan(0.5 * yfov) * aspect_ratio / aspect);
    }
    return glm::perspective(fov, aspect, znear, zfar);
}

int Object::texture_for(std::string_view uniform) const {
    if (uniform == "teximage") return texture;
    for (const SamplerBinding& b : samplers) {
        if (b.uniform == uniform) return b.texture;
    }
    return -1;
}

bool Object::mirrors() const { return glm::determinant(glm::dmat3(world_from_object)) < 0.0; }

glm::dmat4 Node::local() const {
    if (has_matrix) return matrix;
    return glm::translate(glm::dmat4(1.0), translation) * glm::mat4_cast(rotation) * glm::scale(glm::dmat4(1.0), scale);
}

namespace {

// The index of the keyframe interval [times[k], times[k + 1]) holding t, and t's fraction of it;
// before the first keyframe (0, 0), after the last (last, 0).
struct Interval {
    std::size_t k = 0;
    double u = 0.0;
    double dt = 0.0;  // times[k + 1] - times[k], 0 at the ends
};
Interval interval_at(const std::vector<double>& times, double t) {
    if (times.size() < 2 || t <= times.front()) return {};
    if (t >= times.back()) return {times.size() - 1, 0.0, 0.0};
    const std::size_t k = std::size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
    const double dt = times[k + 1] - times[k];
    return {k, (t - times[k]) / dt, dt};
}

// glTF's slerp (appendix C): the shorter arc; a plain normalized lerp where the two are nearly
// the same rotation and sin(angle) would lose its digits.
glm::dquat slerp(const glm::dquat& a, glm::dquat b, double u) {
    double d = glm::dot(a, b);
    if (d < 0.0) d = -d, b = -b;
    if (d > 0.9995) return glm::normalize(a * (1.0 - u) + b * u);
    const double angle = std::acos(d), s = std::sin(angle);
    return a * (std::sin(angle * (1.0 - u)) / s) + b * (std::sin(angle * u) / s);
}

// Channel c's value at t: x, y, z (and w for a rotation).
glm::dvec4 sample(const Channel& c, double t) {
    const int n = c.components();
    const bool cubic = c.interpolation == Channel::Interpolation::CubicSpline;
    // Keyframe k's value (the middle of a cubic spline's three), in-tangent and out-tangent.
    auto at = [&](std::size_t k, int which) {
        const std::size_t base = (cubic ? (3 * k + std::size_t(which)) : k) * std::size_t(n);
        glm::dvec4 v(0.0);
        for (int i = 0; i < n; ++i) v[i] = c.values[base + std::size_t(i)];
        return v;
    };
    const Interval iv = interval_at(c.times, t);
    const glm::dvec4 v0 = at(iv.k, 1);
    if (iv.dt == 0.0 || c.interpolation == Channel::Interpolation::Step) return v0;
    const glm::dvec4 v1 = at(iv.k + 1, 1);
    const double u = iv.u;
    glm::dvec4 r;
    if (cubic) {
        // Hermite: (2u^3 - 3u^2 + 1) v0 + dt (u^3 - 2u^2 + u) b0 + (-2u^3 + 3u^2) v1 + dt (u^3 - u^2) a1
        const double u2 = u * u, u3 = u2 * u;
        r = (2.0 * u3 - 3.0 * u2 + 1.0) * v0 + iv.dt * (u3 - 2.0 * u2 + u) * at(iv.k, 2) + (-2.0 * u3 + 3.0 * u2) * v1 +
            iv.dt * (u3 - u2) * at(iv.k + 1, 0);
    } else if (c.path == Channel::Path::Rotation) {
        const glm::dquat q = slerp(glm::dquat(v0.w, v0.x, v0.y, v0.z), glm::dquat(v1.w, v1.x, v1.y, v1.z), u);
        return {q.x, q.y, q.z, q.w};
    } else {
        r = v0 * (1.0 - u) + v1 * u;
    }
    return r;
}

}  // namespace

Pose Scene::rest() const {
    Pose p;
    p.world_from_object.reserve(objects.size());
    for (const Object& o : objects) p.world_from_object.push_back(o.world_from_object);
    p.view = camera.view;
    return p;
}

Pose Scene::pose(double time) const {
    if (channels.empty()) return rest();
    std::vector<Node> posed = nodes;
    for (const Channel& c : channels) {
        const glm::dvec4 v = sample(c, time);
        Node& n = posed[std::size_t(c.node)];
        switch (c.path) {
            case Channel::Path::Translation:
                n.translation = glm::dvec3(v);
                break;
            case Channel::Path::Scale:
                n.scale = glm::dvec3(v);
                break;
            case Channel::Path::Rotation: {
                const glm::dquat q(v.w, v.x, v.y, v.z);
                const double length = glm::length(q);
                n.rotation = length > 0.0 ? q / length : glm::dquat(1.0, 0.0, 0.0, 0.0);
                break;
            }
        }
    }
    // Parents come before their children (Node::parent).
    std::vector<glm::dmat4> world(posed.size());
    for (std::size_t i = 0; i < posed.size(); ++i) {
        const glm::dmat4 local = posed[i].local();
        world[i] = posed[i].parent < 0 ? local : world[std::size_t(posed[i].parent)] * local;
    }
    Pose p;
    p.world_from_object.reserve(objects.size());
    for (const Object& o : objects) {
        p.world_from_object.push_back(o.node < 0 ? o.world_from_object : world[std::size_t(o.node)] * o.instance);
    }
    p.view = camera_node < 0 ? camera.view : glm::inverse(world[std::size_t(camera_node)]);
    return p;
}

glm::dmat4 Scene::view_from_object(const Pose& pose, std::size_t i) const {
    return pose.view * pose.world_from_object[i];
}

glm::mat4 Scene::clip_from_object(const Pose& pose, std::size_t i, double aspect) const {
    return glm::mat4(camera.projection(aspect) * view_from_object(pose, i));
}

std::vector<std::size_t> Scene::draw_order(const Pose& pose) const {
    std::vector<std::size_t> order, blended;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        (objects[i].look.alpha_mode == AlphaMode::Blend ? blended : order).push_back(i);
    }
    if (blended.empty()) return order;
    std::vector<double> depth(objects.size(), 0.0);
    for (std::size_t i : blended) {
        const Mesh& m = meshes[objects[i].mesh];
        const glm::dvec3 centre = 0.5 * (glm::dvec3(m.lower) + glm::dvec3(m.upper));
        depth[i] = (view_from_object(pose, i) * glm::dvec4(centre, 1.0)).z;  // the camera looks down -z
    }
    std::stable_sort(blended.begin(), blended.end(), [&](std::size_t a, std::size_t b) { return depth[a] < depth[b]; });
    order.insert(order.end(), blended.begin(), blended.end());
    return order;
}

bool mirrors(const Pose& pose, std::size_t i) { return glm::determinant(glm::dmat3(pose.world_from_object[i])) < 0.0; }

}  // namespace qs
