#pragma once
// What translations written by `quadshade translate` (frontend/cpp_writer.h) use beyond the
// vocabulary the hand translations use: the scene's matrices and texture size as GLSL values, and
// conversions of whole vectors (a hand translation converts component by component).

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "shading/glsl/mat.h"
#include "shading/glsl/texture.h"
#include "shading/glsl/texture_cube.h"
#include "shading/glsl/texture_queries.h"
#include "shading/glsl/texture_shadow.h"

namespace qs::glsl {

// A host matrix as a GLSL matrix, column by column.
template <class F>
mat4<F> transform(const glm::mat4& m) {
    mat4<F> r;
    for (int c = 0; c < 4; ++c) {
        for (int k = 0; k < 4; ++k) r[c][k] = F(m[c][k]);
    }
    return r;
}

template <class F>
mat3<F> transform(const glm::mat3& m) {
    mat3<F> r;
    for (int c = 0; c < 3; ++c) {
        for (int k = 0; k < 3; ++k) r[c][k] = F(m[c][k]);
    }
    return r;
}

// `uniform vec2 dims`: the size of `teximage` in texels (0 without one).
template <class F>
vec2<F> texture_size(const sampler2D* t) {
    return t ? vec2<F>(F(float(t->width)), F(float(t->height))) : vec2<F>(F(0.0f));
}

// GLSL's vecN(v), ivecN(v), uvecN(v) of a vector of another number type.
template <class To, class From>
To convert(const From& v) {
    using T = typename To::value_type;
    To r;
    for (int i = 0; i < To::N; ++i) {
        r[i] = T(v[i]);
    }
    return r;
}

}  // namespace qs::glsl
