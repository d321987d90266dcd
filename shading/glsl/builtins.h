#pragma once
// GLSL built-in functions, written once over any number type (float, double, Pixels, Quads,
// Dual2, Checked), their integers (number/integer.h) and componentwise over vec2/vec3/vec4 of
// them (swizzles included), with GLSL's definitions:
//   fract(x) = x - floor(x)                    mod(x, y) = x - y * floor(x / y)
//   step(e, x) = x < e ? 0 : 1                 clamp(x, a, b) = min(max(x, a), b)
//   mix(x, y, a) = x * (1 - a) + y * a         inversesqrt(x) = 1 / sqrt(x)
//   smoothstep(e0, e1, x): t = clamp((x - e0) / (e1 - e0), 0, 1); t * t * (3 - 2 t)
// Edge cases follow from the definitions and from min/max returning the non-NaN operand:
//   smoothstep(e, e, x) = (x > e) ? 1 : 0 (GLSL: undefined; this is llvmpipe's run-time result,
//   since (x-e)/0 is +inf, -inf or NaN and clamp maps them to 1, 0, 0), mod(x, 0) = NaN,
//   inversesqrt(0) = +inf, normalize(vec(0)) = NaN.
// Where Mesa's GLSL compiler defines a built-in through others, the same operations in the same
// order are used, so that llvmpipe's results are reproduced bit for bit: round is roundEven,
// radians(x) = x * 0.0174532925, degrees(x) = x * 57.29578, reflect, refract and faceforward as
// written below. asin and acos are the accurate functions (Mesa evaluates a polynomial with an
// error of up to 6.7e-5, measured by the vocabulary probes).
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
    qs::atan, qs::asin, qs::acos, qs::roundEven, qs::any, qs::all, qs::exact_product_add;
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
    // common_type named, not instantiated, unless both are fundamental: clang instantiates this
    // for a vector's operands too, while choosing between a built-in's overloads.
    using type = typename std::conditional_t<
        std::is_arithmetic_v<A>,
        std::conditional_t<std::is_arithmetic_v<tail>, std::common_type<A, tail>, std::type_identity<tail>>,
        std::type_identity<A>>::type;
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

// GLSL: round's halves go either way; Mesa rounds them to even.
template <Number F>
F round(const F& x) { return roundEven(x); }

template <Number F>
F radians(const F& deg) { return deg * F(0.0174532925f); }
template <Number F>
F degrees(const F& rad) { return rad * F(57.29578f); }

// The fraction with x's sign; the whole part to `i`.
template <Number F>
F modf(const F& x, F& i) {
    const F t = trunc(x);
    i = t;
    return x - t;
}

// genBType mix(genType x, genType y, genBType a): y where a, x elsewhere.
template <class F>
    requires(Number<F> || IntegerNumber<F>)
F mix(const F& x, const F& y, const Bool<F>& a) { return select(a, y, x); }

// ---- integer built-ins (GLSL 1.30): abs is the integer type's own ---------------------------
template <IntegerNumber I>
I sign(const I& x) {
    return select(x > I(0), I(1), select(x < I(0), I(-1), I(0)));
}
template <IntegerNumber I>
I clamp(const I& x, const std::type_identity_t<I>& lo, const std::type_identity_t<I>& hi) {
    if constexpr (is_checked_v<I>) {  // GLSL: undefined if lo > hi
        return I::builtin(clamp(x.v, lo.v, hi.v), lo > hi, x, lo, hi);
    } else {
        return min(max(x, lo), hi);
    }
}

// ---- bits of floats (GLSL 3.30) ----------------------------------------------------------
template <Number F>
int_t<F> floatBitsToInt(const F& x) { return float_bits<std::int32_t>(x); }
template <Number F>
uint_t<F> floatBitsToUint(const F& x) { return float_bits<std::uint32_t>(x); }
template <IntegerNumber I>
auto intBitsToFloat(const I& i) requires std::is_signed_v<typename I::value_type> { return bits_float(i); }
template <IntegerNumber I>
auto uintBitsToFloat(const I& i) requires std::is_unsigned_v<typename I::value_type> { return bits_float(i); }

template <Number F>
F dot(const F& a, const F& b) { return a * b; }

// ---- componentwise over vectors -----------------------------------------------------------
// A vector argument V may be a swizzle of a vector variable: results are plain vectors
// (vec_t<V>), and the other arguments take V's plain vector type.
#define QS_VEC_UNARY(name)                                                                      \
    template <AnyVector V>                                                                      \
    auto name(const V& v) {                                                                     \
        return vec_t<V>::map(v, [](const typename V::value_type& c) { return name(c); });       \
    }
QS_VEC_UNARY(floor)
QS_VEC_UNARY(ceil)
QS_VEC_UNARY(trunc)
QS_VEC_UNARY(round)
QS_VEC_UNARY(roundEven)
QS_VEC_UNARY(fract)
QS_VEC_UNARY(abs)
QS_VEC_UNARY(sign)
QS_VEC_UNARY(sqrt)
QS_VEC_UNARY(inversesqrt)
QS_VEC_UNARY(radians)
QS_VEC_UNARY(degrees)
QS_VEC_UNARY(sin)
QS_VEC_UNARY(cos)
QS_VEC_UNARY(tan)
QS_VEC_UNARY(asin)
QS_VEC_UNARY(acos)
QS_VEC_UNARY(atan)
QS_VEC_UNARY(exp)
QS_VEC_UNARY(exp2)
QS_VEC_UNARY(log)
QS_VEC_UNARY(log2)
QS_VEC_UNARY(isnan)
QS_VEC_UNARY(isinf)
QS_VEC_UNARY(floatBitsToInt)
QS_VEC_UNARY(floatBitsToUint)
QS_VEC_UNARY(intBitsToFloat)
QS_VEC_UNARY(uintBitsToFloat)
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
    template <AnyVector V>                                                                      \
    vec_t<V> name(const V& a, const std::type_identity_t<vec_t<V>>& b) {                        \
        using F = typename V::value_type;                                                       \
        return vec_t<V>::map(a, b, [](const F& x, const F& y) { return name(x, y); });          \
    }                                                                                           \
    template <AnyVector V>                                                                      \
    vec_t<V> name(const V& a, const std::type_identity_t<typename V::value_type>& b) {          \
        return name(a, vec_t<V>(b));                                                            \
    }
QS_VEC_BINARY(min)
QS_VEC_BINARY(max)
QS_VEC_BINARY(mod)
QS_VEC_BINARY(pow)
QS_VEC_BINARY(atan)
#undef QS_VEC_BINARY

// a * b + c componentwise where every a * b is exact (number/simd/simd.h): not GLSL, a faster
// way to write its a * b + c where that changes no bit.
template <AnyVector V>
vec_t<V> exact_product_add(const V& a, const std::type_identity_t<vec_t<V>>& b, const std::type_identity_t<vec_t<V>>& c) {
    using F = typename V::value_type;
    return vec_t<V>::map(a, b, c, [](const F& x, const F& y, const F& z) { return exact_product_add(x, y, z); });
}

// Componentwise comparisons into a bvec (GLSL's == and != compare whole vectors into one bool).
#define QS_VEC_COMPARE(name, op)                                                                \
    template <AnyVector V>                                                                      \
    auto name(const V& a, const std::type_identity_t<vec_t<V>>& b) {                            \
        using F = typename V::value_type;                                                       \
        return vec_t<V>::map(a, b, [](const F& x, const F& y) { return x op y; });              \
    }
QS_VEC_COMPARE(lessThan, <)
QS_VEC_COMPARE(lessThanEqual, <=)
QS_VEC_COMPARE(greaterThan, >)
QS_VEC_COMPARE(greaterThanEqual, >=)
QS_VEC_COMPARE(equal, ==)
QS_VEC_COMPARE(notEqual, !=)
#undef QS_VEC_COMPARE

// any(bvec), all(bvec): one bool per fragment (not to be confused with any(mask), whether any
// lane of a mask is set, which control flow uses).
template <AnyVector V>
    requires Boolean<typename V::value_type>
typename V::value_type any(const V& v) {
    return vec_t<V>::fold(v, v, [](const auto& p, const auto&) { return p; }, [](const auto& p, const auto& q) { return p || q; });
}
template <AnyVector V>
    requires Boolean<typename V::value_type>
typename V::value_type all(const V& v) {
    return vec_t<V>::fold(v, v, [](const auto& p, const auto&) { return p; }, [](const auto& p, const auto& q) { return p && q; });
}

template <AnyVector V>
vec_t<V> step(const V& edge, const std::type_identity_t<vec_t<V>>& x) {
    using F = typename V::value_type;
    return vec_t<V>::map(edge, x, [](const F& e, const F& v) { return step(e, v); });
}
template <AnyVector V>
vec_t<V> step(const typename V::value_type& edge, const V& x) { return step(vec_t<V>(edge), x); }

template <AnyVector V>
vec_t<V> clamp(const V& x, const std::type_identity_t<vec_t<V>>& lo, const std::type_identity_t<vec_t<V>>& hi) {
    using F = typename V::value_type;
    return vec_t<V>::map(x, lo, hi, [](const F& a, const F& b, const F& c) { return clamp(a, b, c); });
}
template <AnyVector V>
vec_t<V> clamp(const V& x, const std::type_identity_t<typename V::value_type>& lo,
               const std::type_identity_t<typename V::value_type>& hi) {
    return clamp(x, vec_t<V>(lo), vec_t<V>(hi));
}

template <AnyVector V>
vec_t<V> mix(const V& x, const std::type_identity_t<vec_t<V>>& y, const std::type_identity_t<vec_t<V>>& a) {
    using F = typename V::value_type;
    return vec_t<V>::map(x, y, a, [](const F& p, const F& q, const F& t) { return mix(p, q, t); });
}
template <AnyVector V>
vec_t<V> mix(const V& x, const std::type_identity_t<vec_t<V>>& y, const std::type_identity_t<typename V::value_type>& a) {
    return mix(x, y, vec_t<V>(a));
}
// mix(x, y, bvec): y where a, x elsewhere, component by component.
template <AnyVector V>
vec_t<V> mix(const V& x, const std::type_identity_t<vec_t<V>>& y,
             const vec<Bool<typename V::value_type>, V::N>& a) {
    vec_t<V> r = x;
    [&]<int... I>(std::integer_sequence<int, I...>) {
        ((r.template get<I>() = select(a.template get<I>(), y.template get<I>(), r.template get<I>())), ...);
    }(std::make_integer_sequence<int, V::N>());
    return r;
}

template <AnyVector V>
vec_t<V> smoothstep(const V& e0, const std::type_identity_t<vec_t<V>>& e1, const std::type_identity_t<vec_t<V>>& x) {
    using F = typename V::value_type;
    return vec_t<V>::map(e0, e1, x, [](const F& a, const F& b, const F& v) { return smoothstep(a, b, v); });
}
template <AnyVector V>
vec_t<V> smoothstep(const typename V::value_type& e0, const typename V::value_type& e1, const V& x) {
    return smoothstep(vec_t<V>(e0), vec_t<V>(e1), x);
}

template <AnyVector V>
vec_t<V> modf(const V& x, vec_t<V>& i) {
    i = trunc(x);
    return x - i;
}

// ---- geometric ----------------------------------------------------------------------------
// dot sums left to right, as llvmpipe does.
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
typename V::value_type length(const V& v) { return sqrt(dot(vec_t<V>(v), vec_t<V>(v))); }
template <Number F>
F length(const F& x) { return abs(x); }

template <Vector V>
typename V::value_type distance(const V& a, const std::type_identity_t<vec_t<V>>& b) { return length(a - b); }

template <Vector V>
vec_t<V> normalize(const V& v) {
    const vec_t<V> u = v;
    return u * inversesqrt(dot(u, u));
}

// The genType forms take a Number or a vector; T is the plain type, F its component.
template <class V>
struct component {
    using type = typename V::value_type;
};
template <Number F>
struct component<F> {
    using type = F;
};
// faceforward: N if dot(Nref, I) < 0, else -N.
template <class V>
    requires(Number<V> || Vector<V>)
auto faceforward(const V& N, const std::type_identity_t<V>& I, const std::type_identity_t<V>& Nref) {
    using T = std::conditional_t<Number<V>, V, vec_t<V>>;
    const T n = N;
    return select(dot(T(Nref), T(I)) < 0.0f, n, -n);
}
// reflect: I - 2 * (dot(N, I) * N), Mesa's association.
template <class V>
    requires(Number<V> || Vector<V>)
auto reflect(const V& I, const std::type_identity_t<V>& N) {
    using T = std::conditional_t<Number<V>, V, vec_t<V>>;
    const T i = I, n = N;
    return i - 2.0f * (dot(n, i) * n);
}
// refract: k = 1 - eta * (eta * (1 - dot(N, I)^2)); 0 if k < 0, else
// eta * I - (eta * dot(N, I) + sqrt(k)) * N (Mesa's association of the GLSL definition).
template <class V>
    requires(Number<V> || Vector<V>)
auto refract(const V& I, const std::type_identity_t<V>& N, const typename component<V>::type& eta) {
    using T = std::conditional_t<Number<V>, V, vec_t<V>>;
    using F = typename component<V>::type;
    const T i = I, n = N;
    const F d = dot(n, i);
    const F k = F(1.0f) - eta * (eta * (F(1.0f) - d * d));
    return select(k < F(0.0f), T(F(0.0f)), eta * i - (eta * d + sqrt(k)) * n);
}

}  // namespace qs::glsl
