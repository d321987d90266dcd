#pragma once
// GLSL built-in functions, written once over any number type (float, double, Pixels, Quads,
// Dual2) and componentwise over vec2/vec3/vec4 of them, with GLSL's definitions:
//   fract(x) = x - floor(x)                    mod(x, y) = x - y * floor(x / y)
//   step(e, x) = x < e ? 0 : 1                 clamp(x, a, b) = min(max(x, a), b)
//   mix(x, y, a) = x * (1 - a) + y * a         inversesqrt(x) = 1 / sqrt(x)
//   smoothstep(e0, e1, x): t = clamp((x - e0) / (e1 - e0), 0, 1); t * t * (3 - 2 t)
// Edge cases follow from the definitions and from min/max returning the non-NaN operand:
//   smoothstep(e, e, x) = (x > e) ? 1 : 0 (GLSL: undefined; this is llvmpipe's run-time result,
//   since (x-e)/0 is +inf, -inf or NaN and clamp maps them to 1, 0, 0), mod(x, 0) = NaN,
//   inversesqrt(0) = +inf, normalize(vec(0)) = NaN.
// Primitives (floor, abs, sqrt, sin, min, ...) come from the number types themselves. On a
// Checked number (number/checked.h), the built-ins GLSL leaves undefined outside a domain flag
// that case and otherwise compute exactly as on the number type it wraps.

#include <type_traits>

#include "shading/glsl/mat.h"
#include "shading/glsl/vec.h"
#include "shading/number/number.h"

namespace qs::glsl {

using qs::abs, qs::ceil, qs::cos, qs::exp, qs::exp2, qs::floor, qs::isinf, qs::isnan, qs::log,
    qs::log2, qs::max, qs::min, qs::pow, qs::select, qs::sin, qs::sqrt, qs::tan, qs::trunc,
    qs::atan;
using qs::dFdx, qs::dFdy, qs::dFdxFine, qs::dFdyFine, qs::dFdxCoarse, qs::dFdyCoarse, qs::fwidth,
    qs::fwidthFine, qs::fwidthCoarse;

// The number type an expression of mixed operands has: the first non-fundamental operand's,
// so that `step(0.5f, x)` with x a Pixels<float, 16> is a Pixels<float, 16>.
template <class... Ts>
struct promote;
template <class T>
struct promote<T> { using type = T; };
template <class A, class B, class... Rest>
struct promote<A, B, Rest...> {
    using tail = typename promote<B, Rest...>::type;
    using type = std::conditional_t<std::is_arithmetic_v<A>,
                                    std::conditional_t<std::is_arithmetic_v<tail>, std::common_type_t<A, tail>, tail>,
                                    A>;
};
template <class... Ts>
using promote_t = typename promote<Ts...>::type;

template <class... Ts>
concept Numbers = (Number<Ts> && ...);

// ---- scalar built-ins ---------------------------------------------------------------------
template <Number F>
F fract(const F& x) { return x - floor(x); }

template <class X, class Y>
    requires Numbers<X, Y>
promote_t<X, Y> mod(const X& x, const Y& y) {
    using F = promote_t<X, Y>;
    return F(x) - F(y) * floor(F(x) / F(y));
}

template <Number F>
F sign(const F& x) {
    return select(x > F(0.0f), F(1.0f), select(x < F(0.0f), F(-1.0f), F(0.0f)));
}

template <class X, class A, class B>
    requires Numbers<X, A, B>
promote_t<X, A, B> clamp(const X& x, const A& lo, const B& hi) {
    using F = promote_t<X, A, B>;
    if constexpr (is_checked_v<F>) {  // GLSL: undefined if lo > hi
        const F v(x), a(lo), b(hi);
        return F::builtin(clamp(v.v, a.v, b.v), a > b, v, a, b);
    } else {
        return min(max(F(x), F(lo)), F(hi));
    }
}

template <class X, class Y, class A>
    requires Numbers<X, Y, A>
promote_t<X, Y, A> mix(const X& x, const Y& y, const A& a) {
    using F = promote_t<X, Y, A>;
    return F(x) * (F(1.0f) - F(a)) + F(y) * F(a);
}

template <class E, class X>
    requires Numbers<E, X>
promote_t<E, X> step(const E& edge, const X& x) {
    using F = promote_t<E, X>;
    return select(F(x) < F(edge), F(0.0f), F(1.0f));
}

template <class E0, class E1, class X>
    requires Numbers<E0, E1, X>
promote_t<E0, E1, X> smoothstep(const E0& e0, const E1& e1, const X& x) {
    using F = promote_t<E0, E1, X>;
    if constexpr (is_checked_v<F>) {
        // GLSL: undefined if e0 >= e1; flagged as that, not as the division by zero it implies.
        const F a(e0), b(e1), v(x);
        return F::builtin(smoothstep(a.v, b.v, v.v), a >= b, a, b, v);
    } else {
        F t = clamp((F(x) - F(e0)) / (F(e1) - F(e0)), 0.0f, 1.0f);
        return t * t * (F(3.0f) - F(2.0f) * t);
    }
}

template <Number F>
F inversesqrt(const F& x) {
    if constexpr (is_checked_v<F>) {  // GLSL: undefined if x <= 0
        return F::builtin(inversesqrt(x.v), x <= F(0.0f), x);
    } else {
        return F(1.0f) / sqrt(x);
    }
}

template <Number F>
F radians(const F& deg) { return deg * F(0.017453292519943295f); }

// ---- componentwise over vectors -----------------------------------------------------------
#define QS_VEC_UNARY(name)                                                                      \
    template <Vector V>                                                                         \
    V name(const V& v) {                                                                        \
        return V::map(v, [](const typename V::value_type& c) { return name(c); });              \
    }
QS_VEC_UNARY(floor)
QS_VEC_UNARY(ceil)
QS_VEC_UNARY(trunc)
QS_VEC_UNARY(fract)
QS_VEC_UNARY(abs)
QS_VEC_UNARY(sign)
QS_VEC_UNARY(sqrt)
QS_VEC_UNARY(inversesqrt)
QS_VEC_UNARY(sin)
QS_VEC_UNARY(cos)
QS_VEC_UNARY(exp)
QS_VEC_UNARY(exp2)
QS_VEC_UNARY(log)
QS_VEC_UNARY(log2)
QS_VEC_UNARY(dFdx)
QS_VEC_UNARY(dFdy)
QS_VEC_UNARY(dFdxFine)
QS_VEC_UNARY(dFdyFine)
QS_VEC_UNARY(dFdxCoarse)
QS_VEC_UNARY(dFdyCoarse)
QS_VEC_UNARY(fwidth)
#undef QS_VEC_UNARY

// genType f(genType, genType) and genType f(genType, float)
#define QS_VEC_BINARY(name)                                                                     \
    template <Vector V>                                                                         \
    V name(const V& a, const V& b) {                                                            \
        using F = typename V::value_type;                                                       \
        return V::map(a, b, [](const F& x, const F& y) { return name(x, y); });                 \
    }                                                                                           \
    template <Vector V>                                                                         \
    V name(const V& a, const typename V::value_type& b) { return name(a, V(b)); }
QS_VEC_BINARY(min)
QS_VEC_BINARY(max)
QS_VEC_BINARY(mod)
QS_VEC_BINARY(pow)
#undef QS_VEC_BINARY

template <Vector V>
V step(const V& edge, const V& x) {
    using F = typename V::value_type;
    return V::map(edge, x, [](const F& e, const F& v) { return step(e, v); });
}
template <Vector V>
V step(const typename V::value_type& edge, const V& x) { return step(V(edge), x); }

template <Vector V>
V clamp(const V& x, const V& lo, const V& hi) {
    using F = typename V::value_type;
    return V::map(x, lo, hi, [](const F& a, const F& b, const F& c) { return clamp(a, b, c); });
}
template <Vector V>
V clamp(const V& x, const typename V::value_type& lo, const typename V::value_type& hi) {
    return clamp(x, V(lo), V(hi));
}

template <Vector V>
V mix(const V& x, const V& y, const V& a) {
    using F = typename V::value_type;
    return V::map(x, y, a, [](const F& p, const F& q, const F& t) { return mix(p, q, t); });
}
template <Vector V>
V mix(const V& x, const V& y, const typename V::value_type& a) { return mix(x, y, V(a)); }

template <Vector V>
V smoothstep(const V& e0, const V& e1, const V& x) {
    using F = typename V::value_type;
    return V::map(e0, e1, x, [](const F& a, const F& b, const F& v) { return smoothstep(a, b, v); });
}
template <Vector V>
V smoothstep(const typename V::value_type& e0, const typename V::value_type& e1, const V& x) {
    return smoothstep(V(e0), V(e1), x);
}

// ---- geometric ----------------------------------------------------------------------------
template <class F>
F dot(const vec2<F>& a, const vec2<F>& b) { return a.x * b.x + a.y * b.y; }
template <class F>
F dot(const vec3<F>& a, const vec3<F>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <class F>
F dot(const vec4<F>& a, const vec4<F>& b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }

template <class F>
vec3<F> cross(const vec3<F>& a, const vec3<F>& b) {
    return {a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y};
}

template <Vector V>
typename V::value_type length(const V& v) { return sqrt(dot(v, v)); }
template <Number F>
F length(const F& x) { return abs(x); }

template <Vector V>
typename V::value_type distance(const V& a, const V& b) { return length(a - b); }

template <Vector V>
V normalize(const V& v) { return v * inversesqrt(dot(v, v)); }

}  // namespace qs::glsl
