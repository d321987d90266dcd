#pragma once
// GLSL matrices used by the chapter: mat2 (Listing 1.5's screen rotations, Listing 1.2's
// Jacobian) and mat2x3 (Listing 1.2, 2 columns of vec3). Column-major as in GLSL: the
// constructor takes columns, `m * v` combines columns, `v * m` dots v with each column.

#include "shading/glsl/vec.h"

namespace qs::glsl {

template <class F>
struct mat2 {
    vec2<F> c0, c1;  // columns
    mat2(const vec2<F>& col0, const vec2<F>& col1) : c0(col0), c1(col1) {}
    // GLSL mat2(a, b, c, d): first column (a, b), second (c, d)
    mat2(const F& a, const F& b, const F& c, const F& d) : c0(a, b), c1(c, d) {}
    friend vec2<F> operator*(const mat2& m, const vec2<F>& v) { return m.c0 * v.x + m.c1 * v.y; }
    friend vec2<F> operator*(const vec2<F>& v, const mat2& m) {
        return {v.x * m.c0.x + v.y * m.c0.y, v.x * m.c1.x + v.y * m.c1.y};
    }
    friend mat2 operator*(const F& s, const mat2& m) { return {s * m.c0, s * m.c1}; }
    friend mat2 operator*(const mat2& m, const F& s) { return {m.c0 * s, m.c1 * s}; }
};

template <class F>
struct mat2x3 {
    vec3<F> c0, c1;  // two columns of three rows
    mat2x3(const vec3<F>& col0, const vec3<F>& col1) : c0(col0), c1(col1) {}
    // mat2x3 * vec2 -> vec3
    friend vec3<F> operator*(const mat2x3& m, const vec2<F>& v) { return m.c0 * v.x + m.c1 * v.y; }
    // vec3 * mat2x3 -> vec2: (dot(v, c0), dot(v, c1))
    friend vec2<F> operator*(const vec3<F>& v, const mat2x3& m) {
        return {v.x * m.c0.x + v.y * m.c0.y + v.z * m.c0.z, v.x * m.c1.x + v.y * m.c1.y + v.z * m.c1.z};
    }
};

}  // namespace qs::glsl
