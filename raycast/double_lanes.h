#pragma once
// glm's double-precision vector and matrix arithmetic on the sixteen lanes of a batch, in glm's
// order of operations: each lane rounds exactly as the scalar glm expression it stands for (the
// build does not contract a * b + c, and a vector operation rounds every lane as its scalar
// one). The ray caster's rays and plane intersections are computed this way; done lane by lane
// in scalar double they were half of its time.

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/lanes16.h"

namespace qs::lanes16 {

using Doubles = simd::Vector<double, kBatchLanes>;

inline Doubles to_double(const Floats& v) { return __builtin_convertvector(v, Doubles); }
inline Doubles to_double(const Ints& v) { return __builtin_convertvector(v, Doubles); }
inline Floats to_float(const Doubles& v) { return __builtin_convertvector(v, Floats); }

struct Doubles3 {
    Doubles x, y, z;

    glm::dvec3 at(int lane) const { return {x[lane], y[lane], z[lane]}; }
};

// The lanes rounded to float, component c into to[c].
inline void store(float (&to)[3][kBatchLanes], const Doubles3& v) {
    store(to[0], to_float(v.x)), store(to[1], to_float(v.y)), store(to[2], to_float(v.z));
}

struct Doubles4 {
    Doubles x, y, z, w;
};

inline Doubles3 operator+(const Doubles3& a, const Doubles3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Doubles3 operator-(const Doubles3& a, const Doubles3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Doubles3 operator*(const Doubles& s, const Doubles3& v) { return {s * v.x, s * v.y, s * v.z}; }

// glm::dot: the products summed from x to z.
inline Doubles dot(const Doubles3& a, const Doubles3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// m * vec4(x, y, z, w) as glm computes it, row by row: (m0 x + m1 y) + (m2 z + m3 w). z and w
// are lanes or one value for all; a product of one value is formed once, as each lane would.
template <class Z, class W>
Doubles4 transform(const glm::dmat4& m, const Doubles& x, const Doubles& y, const Z& z, const W& w) {
    auto row = [&](int r) { return (m[0][r] * x + m[1][r] * y) + (m[2][r] * z + m[3][r] * w); };
    return {row(0), row(1), row(2), row(3)};
}
inline Doubles4 transform(const glm::dmat4& m, const Doubles3& p, double w) { return transform(m, p.x, p.y, p.z, w); }

}  // namespace qs::lanes16
