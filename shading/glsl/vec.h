#pragma once
// GLSL vectors over a number type F: vec2<F>, vec3<F>, vec4<F>.
//
// Componentwise arithmetic, scalar broadcast on either side, and the read swizzles the chapter's
// shaders use, spelled as calls (`v.xy()` for GLSL's `v.xy`). GLSL's write swizzles (`v.xy -= a`)
// have no C++ spelling: the translations rebuild the vector and quote the GLSL beside it.

#include <cstddef>
#include <utility>

#include "shading/number/number.h"

namespace qs::glsl {

template <class F> struct vec2;
template <class F> struct vec3;
template <class F> struct vec4;

// Componentwise operators for a vector type V of N components, F scalar; written once.
#define QS_VEC_OPERATORS(V)                                                                     \
    /* Componentwise application, unrolled at compile time so components stay in registers. */ \
    template <class Op>                                                                         \
    static V map(const V& a, Op op) {                                                           \
        return [&]<int... I>(std::integer_sequence<int, I...>) {                                \
            return V(op(a.template get<I>())...);                                               \
        }(std::make_integer_sequence<int, N>());                                                \
    }                                                                                           \
    template <class Op>                                                                         \
    static V map(const V& a, const V& b, Op op) {                                               \
        return [&]<int... I>(std::integer_sequence<int, I...>) {                                \
            return V(op(a.template get<I>(), b.template get<I>())...);                          \
        }(std::make_integer_sequence<int, N>());                                                \
    }                                                                                           \
    template <class Op>                                                                         \
    static V map(const V& a, const V& b, const V& c, Op op) {                                   \
        return [&]<int... I>(std::integer_sequence<int, I...>) {                                \
            return V(op(a.template get<I>(), b.template get<I>(), c.template get<I>())...);     \
        }(std::make_integer_sequence<int, N>());                                                \
    }                                                                                           \
    friend V operator-(const V& a) { return map(a, [](const F& x) { return -x; }); }             \
    friend V operator+(const V& a, const V& b) { return map(a, b, [](const F& x, const F& y) { return x + y; }); } \
    friend V operator-(const V& a, const V& b) { return map(a, b, [](const F& x, const F& y) { return x - y; }); } \
    friend V operator*(const V& a, const V& b) { return map(a, b, [](const F& x, const F& y) { return x * y; }); } \
    friend V operator/(const V& a, const V& b) { return map(a, b, [](const F& x, const F& y) { return x / y; }); } \
    friend V operator+(const V& a, const F& s) { return a + V(s); }                             \
    friend V operator-(const V& a, const F& s) { return a - V(s); }                             \
    friend V operator*(const V& a, const F& s) { return a * V(s); }                             \
    friend V operator/(const V& a, const F& s) { return a / V(s); }                             \
    friend V operator+(const F& s, const V& a) { return V(s) + a; }                             \
    friend V operator-(const F& s, const V& a) { return V(s) - a; }                             \
    friend V operator*(const F& s, const V& a) { return V(s) * a; }                             \
    friend V operator/(const F& s, const V& a) { return V(s) / a; }                             \
    V& operator+=(const V& b) { return *this = *this + b; }                                     \
    V& operator-=(const V& b) { return *this = *this - b; }                                     \
    V& operator*=(const V& b) { return *this = *this * b; }                                     \
    V& operator/=(const V& b) { return *this = *this / b; }                                     \
    template <class M>                                                                          \
    friend V select(const M& m, const V& a, const V& b) {                                       \
        return map(a, b, [&](const F& x, const F& y) { return select(m, x, y); });              \
    }

// Swizzle generators: each defines a read-only accessor returning a new vector.
#define QS_SWZ2(a, b) vec2<F> a##b() const { return {a, b}; }
#define QS_SWZ3(a, b, c) vec3<F> a##b##c() const { return {a, b, c}; }
#define QS_SWZ4(a, b, c, d) vec4<F> a##b##c##d() const { return {a, b, c, d}; }

template <class F>
struct vec2 {
    using value_type = F;
    static constexpr int N = 2;
    F x, y;
    vec2() = default;
    explicit vec2(const F& s) : x(s), y(s) {}
    vec2(const F& x_, const F& y_) : x(x_), y(y_) {}
    F& operator[](int i) { return i == 0 ? x : y; }
    const F& operator[](int i) const { return i == 0 ? x : y; }
    template <int I>
    const F& get() const {
        if constexpr (I == 0) return x; else return y;
    }
    QS_VEC_OPERATORS(vec2)
    QS_SWZ2(x, x) QS_SWZ2(x, y) QS_SWZ2(y, x) QS_SWZ2(y, y)
    QS_SWZ3(x, x, x) QS_SWZ3(y, y, y)
    QS_SWZ4(x, y, x, y)
};

template <class F>
struct vec3 {
    using value_type = F;
    static constexpr int N = 3;
    F x, y, z;
    vec3() = default;
    explicit vec3(const F& s) : x(s), y(s), z(s) {}
    vec3(const F& x_, const F& y_, const F& z_) : x(x_), y(y_), z(z_) {}
    vec3(const vec2<F>& xy, const F& z_) : x(xy.x), y(xy.y), z(z_) {}
    vec3(const F& x_, const vec2<F>& yz) : x(x_), y(yz.x), z(yz.y) {}
    F& operator[](int i) { return i == 0 ? x : i == 1 ? y : z; }
    const F& operator[](int i) const { return i == 0 ? x : i == 1 ? y : z; }
    template <int I>
    const F& get() const {
        if constexpr (I == 0) return x; else if constexpr (I == 1) return y; else return z;
    }
    QS_VEC_OPERATORS(vec3)
    QS_SWZ2(x, x) QS_SWZ2(x, y) QS_SWZ2(x, z) QS_SWZ2(y, x) QS_SWZ2(y, y) QS_SWZ2(y, z)
    QS_SWZ2(z, x) QS_SWZ2(z, y) QS_SWZ2(z, z)
    QS_SWZ3(x, y, z) QS_SWZ3(y, z, x) QS_SWZ3(z, x, y) QS_SWZ3(x, x, x) QS_SWZ3(y, y, y)
    QS_SWZ3(z, z, z) QS_SWZ3(x, z, y)
};

template <class F>
struct vec4 {
    using value_type = F;
    static constexpr int N = 4;
    F x, y, z, w;
    vec4() = default;
    explicit vec4(const F& s) : x(s), y(s), z(s), w(s) {}
    vec4(const F& x_, const F& y_, const F& z_, const F& w_) : x(x_), y(y_), z(z_), w(w_) {}
    vec4(const vec3<F>& xyz, const F& w_) : x(xyz.x), y(xyz.y), z(xyz.z), w(w_) {}
    vec4(const vec2<F>& xy, const vec2<F>& zw) : x(xy.x), y(xy.y), z(zw.x), w(zw.y) {}
    vec4(const vec2<F>& xy, const F& z_, const F& w_) : x(xy.x), y(xy.y), z(z_), w(w_) {}
    F& operator[](int i) { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
    const F& operator[](int i) const { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
    template <int I>
    const F& get() const {
        if constexpr (I == 0) return x; else if constexpr (I == 1) return y; else if constexpr (I == 2) return z; else return w;
    }
    QS_VEC_OPERATORS(vec4)
    QS_SWZ2(x, y) QS_SWZ2(z, w) QS_SWZ2(x, z) QS_SWZ2(y, w) QS_SWZ2(x, x) QS_SWZ2(y, y)
    QS_SWZ2(y, z) QS_SWZ2(z, z) QS_SWZ2(w, w)
    QS_SWZ3(x, y, z) QS_SWZ3(y, z, w) QS_SWZ3(x, x, x) QS_SWZ3(w, w, w)
    QS_SWZ4(x, y, x, y) QS_SWZ4(x, x, z, z) QS_SWZ4(y, y, w, w) QS_SWZ4(x, z, y, w)
    // GLSL's colour names for the same components
    vec3<F> rgb() const { return xyz(); }
};

#undef QS_SWZ2
#undef QS_SWZ3
#undef QS_SWZ4
#undef QS_VEC_OPERATORS

template <class V>
concept Vector = requires { typename V::value_type; V::N; } && Number<typename V::value_type>;

}  // namespace qs::glsl
