// The analytic gradients of the noises (dnoise of the "Noise is Beautiful" simplex noise in 2D and 3D, the
// gradient of the chapter's 3D simplex noise that Listing 1.2 and the bump map use)
// against the same noise differentiated by Dual2 (the chain rule through every operation, the
// same branches: equal up to rounding) and against central differences (independent of both
// derivations: equal up to the differences' truncation).
#include <catch2/catch.hpp>

#include <cmath>

#include "shading/noise/simplex2d_skew.h"
#include "shading/noise/simplex3d_fibonacci.h"
#include "shading/noise/simplex3d_grad.h"

// Inside qs::glsl, as shader code is: unqualified built-ins resolve as they do in shaders.
namespace qs::glsl {

namespace {

using qs::noise::noise_is_beautiful::dnoise;
using qs::noise::noise_is_beautiful::noise;
using qs::noise::noise_is_beautiful::noise3;

// Sample points: a Weyl sequence over [-20, 20)^3, deterministic and off every lattice.
std::vector<glm::dvec3> points() {
    std::vector<glm::dvec3> all;
    for (int i = 1; i <= 300; ++i) {
        all.push_back({std::fmod(i * 0.7548776662466927, 1.0) * 40.0 - 20.0, std::fmod(i * 0.5698402909980532, 1.0) * 40.0 - 20.0,
                       std::fmod(i * 0.3247179572447460, 1.0) * 40.0 - 20.0});
    }
    return all;
}
// Points on simplex boundaries: lattice corners, the 2D shear's diagonal (luv.x == luv.y, where
// the notes' step() pair counts the far corner twice and leaves one out), 3D faces. There the
// noises jump or kink (the 3D kernels' radius^2 0.6 reaches past a simplex's faces; the 2D defect
// above), so central differences straddle two branches: only Dual2, which follows the same
// branch as the analytic gradient, is compared there.
const glm::dvec3 kBoundaryPoints[] = {{0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}, {0.25, 0.5, 0.75}, {2.5, 2.5, 2.5}, {-3.5, 2.25, -7.125}};

// Central differences with step h have truncation error h^2/6 |f'''| plus rounding of about
// 1e-16/h: with h = 1e-5 in double, the largest difference measured over the 300 points is
// 1.6e-9 for the notes' noises (gradients up to 2.7) and 4.8e-9 for the chapter's (up to 7.3);
// the tolerance is 20 times that.
constexpr double kH = 1e-5;
constexpr double kCentralTolerance = 1e-7;
// Dual2 and the analytic gradient evaluate the same products in another order: a few ulps of
// double.
constexpr double kDualTolerance = 1e-12;

// Checks an analytic gradient `g` at p against Dual2 of the value (`dual(p, axis)`: the noise of
// p with unit partials along x and y, or along z when axis is 2) and, when `central`, against
// central differences of `value`.
template <int N, class Value, class Dual>
void check_gradient(const glm::dvec3& p, const double (&g)[N], const Value& value, const Dual& dual, bool central,
                    double& largest_central) {
    INFO("at (" << p.x << ", " << p.y << ", " << p.z << ")");
    const Dual2<double> xy = dual(p, 0);
    CHECK(xy.val == value(p));
    CHECK(g[0] == Approx(xy.dx).margin(kDualTolerance));
    CHECK(g[1] == Approx(xy.dy).margin(kDualTolerance));
    if (N == 3) CHECK(g[N - 1] == Approx(dual(p, 2).dx).margin(kDualTolerance));
    if (!central) return;
    for (int a = 0; a < N; ++a) {
        glm::dvec3 h(0.0);
        h[a] = kH;
        const double c = (value(p + h) - value(p - h)) / (2 * kH);
        largest_central = std::max(largest_central, std::abs(g[a] - c));
        CHECK(g[a] == Approx(c).margin(kCentralTolerance));
    }
}

// Dual2 numbers for p, unit partials on x and y (axis 0) or on z (axis 2).
vec3<Dual2<double>> dual_point(const glm::dvec3& p, int axis) {
    return axis == 0 ? vec3<Dual2<double>>(Dual2<double>(p.x, 1.0, 0.0), Dual2<double>(p.y, 0.0, 1.0), Dual2<double>(p.z))
                     : vec3<Dual2<double>>(Dual2<double>(p.x), Dual2<double>(p.y), Dual2<double>(p.z, 1.0, 0.0));
}

}  // namespace

TEST_CASE("Noise is Beautiful: the 2D dnoise is the gradient of its simplex noise", "[noise][gradient]") {
    auto value = [](const glm::dvec3& p) { return noise(vec2<double>(p.x, p.y)); };
    auto dual = [](const glm::dvec3& p, int) { return noise(dual_point(p, 0).xy()); };
    double largest = 0.0, largest_central = 0.0;
    auto check = [&](const glm::dvec3& p, bool central) {
        const vec2<double> d = dnoise(vec2<double>(p.x, p.y));
        largest = std::max({largest, std::abs(d.x), std::abs(d.y)});
        const double g[2] = {d.x, d.y};
        check_gradient(p, g, value, dual, central, largest_central);
        // The float translation the shaders run: within float rounding of the double one.
        const vec2<float> df = dnoise(vec2<float>(float(p.x), float(p.y)));
        CHECK(df.x == Approx(d.x).margin(2e-5));
        CHECK(df.y == Approx(d.y).margin(2e-5));
    };
    for (const glm::dvec3& p : points()) check(p, true);
    for (const glm::dvec3& p : kBoundaryPoints) check(p, false);
    CHECK(largest > 0.5);  // the points see the noise's slopes, not only its flat spots
}

TEST_CASE("Noise is Beautiful: the 3D noise returns its own gradient", "[noise][gradient]") {
    vec3<double> unused;
    vec3<Dual2<double>> unused_dual;
    auto value = [&](const glm::dvec3& p) { return noise3(vec3<double>(p.x, p.y, p.z), unused); };
    auto dual = [&](const glm::dvec3& p, int axis) { return noise3(dual_point(p, axis), unused_dual); };
    double largest = 0.0, largest_central = 0.0;
    auto check = [&](const glm::dvec3& p, bool central) {
        vec3<double> d;
        noise3(vec3<double>(p.x, p.y, p.z), d);
        largest = std::max({largest, std::abs(d.x), std::abs(d.y), std::abs(d.z)});
        const double g[3] = {d.x, d.y, d.z};
        check_gradient(p, g, value, dual, central, largest_central);
    };
    for (const glm::dvec3& p : points()) check(p, true);
    for (const glm::dvec3& p : kBoundaryPoints) check(p, false);
    CHECK(largest > 0.5);
}

TEST_CASE("the chapter's 3D simplex noise with its gradient: snoise3's value, and its gradient", "[noise][gradient]") {
    using noise::Simplex3dDemo;
    auto value = [](const glm::dvec3& p) { return noise::snoise3<Simplex3dDemo>(vec3<double>(p.x, p.y, p.z)); };
    auto dual = [](const glm::dvec3& p, int axis) { return noise::snoise3<Simplex3dDemo>(dual_point(p, axis)); };
    double largest = 0.0, largest_central = 0.0;
    auto check = [&](const glm::dvec3& p, bool central) {
        // The value is snoise3's, bit for bit, in the float the shaders run.
        const vec3<float> pf(float(p.x), float(p.y), float(p.z));
        vec3<float> gf;
        CHECK(noise::snoise3_grad<Simplex3dDemo>(pf, gf) == noise::snoise3<Simplex3dDemo>(pf));
        vec3<double> d;
        CHECK(noise::snoise3_grad<Simplex3dDemo>(vec3<double>(p.x, p.y, p.z), d) == value(p));
        largest = std::max({largest, std::abs(d.x), std::abs(d.y), std::abs(d.z)});
        const double g[3] = {d.x, d.y, d.z};
        check_gradient(p, g, value, dual, central, largest_central);
    };
    for (const glm::dvec3& p : points()) check(p, true);
    for (const glm::dvec3& p : kBoundaryPoints) check(p, false);
    CHECK(largest > 0.5);
}

}  // namespace qs::glsl
