#pragma once
// What translations written by `quadshade translate` (frontend/cpp_writer.h) use beyond the
// vocabulary the hand translations use: the scene's matrices and texture size as GLSL values, and
// conversions of whole vectors (a hand translation converts component by component), and
// GLSL's c - a * b rounded once where the writer proves a * b exact (frontend/exact_products.h),
// and a loop nest's part run for all its iterations at once (iteration_lanes.h).

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "shading/glsl/builtins.h"
#include "shading/glsl/iteration_lanes.h"
#include "shading/glsl/mat.h"
#include "shading/glsl/texture.h"
#include "shading/glsl/texture_cube.h"
#include "shading/glsl/texture_queries.h"
#include "shading/glsl/texture_shadow.h"
#include "shading/number/dual2.h"

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

// GLSL's a * b - c and c - a * b where a * b is exact (and the operand negated, c or b, is not
// NaN, whose sign a negation would turn): exact_product_add with that operand negated, the same
// bits as the product and the difference give. With derivatives, the partials as the product and
// the difference give them: through exact_product_add, -(u dv + v du) would be u (-dv) + v du or
// the like, whose zero or NaN can take the other sign.
template <class F>
    requires(!AnyVector<F>)
F exact_product_sub(const F& a, const F& b, const F& c) {
    return exact_product_add(a, b, -c);
}

template <class F>
    requires(!AnyVector<F>)
F exact_sub_product(const F& c, const F& a, const F& b) {
    return exact_product_add(a, -b, c);
}

template <class T>
Dual2<T> exact_product_sub(const Dual2<T>& a, const Dual2<T>& b, const Dual2<T>& c) {
    return {exact_product_add(a.val, b.val, -c.val), (a.val * b.dx + a.dx * b.val) - c.dx,
            (a.val * b.dy + a.dy * b.val) - c.dy};
}

template <class T>
Dual2<T> exact_sub_product(const Dual2<T>& c, const Dual2<T>& a, const Dual2<T>& b) {
    return {exact_product_add(a.val, -b.val, c.val), c.dx - (a.val * b.dx + a.dx * b.val),
            c.dy - (a.val * b.dy + a.dy * b.val)};
}

template <AnyVector V>
vec_t<V> exact_product_sub(const V& a, const std::type_identity_t<vec_t<V>>& b,
                           const std::type_identity_t<vec_t<V>>& c) {
    using F = typename V::value_type;
    return vec_t<V>::map(a, b, c, [](const F& x, const F& y, const F& z) { return exact_product_sub(x, y, z); });
}

template <AnyVector V>
vec_t<V> exact_sub_product(const V& c, const std::type_identity_t<vec_t<V>>& a,
                           const std::type_identity_t<vec_t<V>>& b) {
    using F = typename V::value_type;
    return vec_t<V>::map(c, a, b, [](const F& x, const F& y, const F& z) { return exact_sub_product(x, y, z); });
}

}  // namespace qs::glsl
