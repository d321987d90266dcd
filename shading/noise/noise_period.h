#pragma once
// Large coordinates, kept stable. float32 keeps 24 significant bits, so near |x| = 2^23 (8.4e6)
// no fraction is left: the noise, which needs the position inside its cell, turns into steps
// long before that (tests/shading/test_large_coordinates.cpp measures where). The mod-289
// hashing makes every noise here periodic on its own lattice, 289 cells along each lattice axis;
// reducing a coordinate by whole periods in double, before it is handed to float, leaves the
// noise value unchanged up to float rounding of the now small coordinate. Use these on the CPU
// side (uniforms, offsets, per-vertex positions of one object moved by one offset), never per
// fragment: a wrap between a triangle's vertices would break interpolation.

#include <cmath>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace qs::noise {

inline constexpr double kHashPeriod = 289.0;  // mod289 in permute

namespace period_detail {
inline double wrap(double x) { return x - kHashPeriod * std::floor(x / kHashPeriod); }
}  // namespace period_detail

// Simplex noise: the period lattice is the skewed grid's (289, 0, ...) directions. The wrap
// repeats the shader's own first steps in double, i = floor(v + dot(v, skew)) and
// x0 = v - i + dot(i, unskew) with its float constants, reduces i mod 289 and rebuilds v from
// x0: snoise then finds the same cell offset x0 and the same hash. (Reducing v by the lattice
// vectors instead would drift: the float-rounded constants are not exact inverses, off by 1e-8,
// which at 1e8 moves the cell by a whole unit.)
template <class V>
V wrap_simplex(V v, double skew, double unskew) {
    double sum_v = 0.0;
    for (int k = 0; k < V::length(); ++k) sum_v += v[k];
    V i, wrapped;
    double sum_i = 0.0, sum_w = 0.0;
    for (int k = 0; k < V::length(); ++k) i[k] = std::floor(v[k] + sum_v * skew), sum_i += i[k];
    for (int k = 0; k < V::length(); ++k) wrapped[k] = period_detail::wrap(i[k]), sum_w += wrapped[k];
    V out;
    for (int k = 0; k < V::length(); ++k) {
        const double x0 = v[k] - i[k] + sum_i * unskew;
        out[k] = x0 + wrapped[k] - sum_w * unskew;
    }
    return out;
}

// 2D simplex noise (skew C.y = 0.5 (sqrt(3) - 1), unskew C.x = (3 - sqrt(3)) / 6, as float).
inline glm::dvec2 wrap_simplex2d(glm::dvec2 p) {
    return wrap_simplex(p, double(0.366025403784439f), double(0.211324865405187f));
}
// 3D simplex noise (skew 1/3, unskew 1/6, as float).
inline glm::dvec3 wrap_simplex3d(glm::dvec3 p) { return wrap_simplex(p, double(1.0f / 3.0f), double(1.0f / 6.0f)); }

// Cellular noise hashes floor(P) mod 289 on the unskewed grid: 289 along every axis.
inline glm::dvec2 wrap_cellular(glm::dvec2 p) { return {period_detail::wrap(p.x), period_detail::wrap(p.y)}; }
inline glm::dvec3 wrap_cellular(glm::dvec3 p) {
    return {period_detail::wrap(p.x), period_detail::wrap(p.y), period_detail::wrap(p.z)};
}

}  // namespace qs::noise
