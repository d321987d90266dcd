#pragma once
// GLSL vectors over a component type F: vec2<F>, vec3<F>, vec4<F>. F is a float number type
// (vec), its integers (ivec2<F> = vec2<int_t<F>>, uvec), or its mask (bvec2<F> = vec2<Bool<F>>).
//
// Componentwise arithmetic with scalar broadcast on either side, and every assignment form of it
// GLSL has (+= -= *= /=, ++ and --, a vector or a scalar on the right); for integer vectors also
// % & | ^ ~ << >> and their assignments; == and != compare whole vectors into one bool, as GLSL's do (the componentwise
// comparisons are lessThan, equal, ... in builtins.h); !v of a bvec is GLSL's not(v), and C++'s
// alternative token makes `not(v)` read exactly so.
//
// Swizzles are calls: every GLSL swizzle of xyzw and rgba (v.xy, v.zyx, c.rgb, v.wwxy) is
// `v.xy()`, `v.zyx()`, `c.rgb()`, `v.wwxy()`. On a vector variable a swizzle without repeated
// components also writes, as in GLSL: `v.xy() -= w;`, `c.rgb() = vec3<F>(0.5f);`,
// `p.zx() *= 2.0f;`. Single components are the members x, y, z, w, or r(), g(), b(), a().
// A swizzle object cannot be written once it has a name (`auto s = v.xy(); s = w;` does not
// compile): only the temporary writes back, so a copy never aliases the vector it came from.

#include <cstddef>
#include <type_traits>
#include <utility>

#include "shading/number/number.h"

namespace qs::glsl {

template <class F> struct vec2;
template <class F> struct vec3;
template <class F> struct vec4;

// The vector of N components of type F.
template <class F, int N>
using vec = std::conditional_t<N == 2, vec2<F>, std::conditional_t<N == 3, vec3<F>, vec4<F>>>;

template <class V>
concept AnyVector = requires {
    typename V::value_type;
    V::N;
};
// A vector of floats (a Number): what the float built-ins take. Swizzles are vectors too.
template <class V>
concept Vector = AnyVector<V> && Number<typename V::value_type>;
// The plain vector type of a vector or swizzle.
template <AnyVector V>
using vec_t = vec<typename V::value_type, V::N>;

// A swizzle of a vector variable, written back by GLSL's assignments (see above): the swizzled
// components as a vector like any other, and the components of `Source` they came from.
template <class Source, int... I>
class Swizzle : public vec<typename Source::value_type, int(sizeof...(I))> {
    using F = typename Source::value_type;
    using Base = vec<F, int(sizeof...(I))>;

public:
    explicit Swizzle(Source& s) : Base(s.template get<I>()...), source_(s) {}
    Swizzle(const Swizzle&) = default;

    void operator=(const Base& w) && { write(w); }
    void operator=(const Swizzle& w) && { write(w); }
    void operator+=(const Base& w) && { write(*this + w); }
    void operator-=(const Base& w) && { write(*this - w); }
    void operator*=(const Base& w) && { write(*this * w); }
    void operator/=(const Base& w) && { write(*this / w); }
    void operator*=(const F& s) && { write(*this * s); }
    void operator/=(const F& s) && { write(*this / s); }
    void operator+=(const F& s) && { write(*this + s); }
    void operator-=(const F& s) && { write(*this - s); }
    void operator%=(const Base& w) && requires IntegerNumber<F> { write(*this % w); }
    void operator&=(const Base& w) && requires IntegerNumber<F> { write(*this & w); }
    void operator|=(const Base& w) && requires IntegerNumber<F> { write(*this | w); }
    void operator^=(const Base& w) && requires IntegerNumber<F> { write(*this ^ w); }
    void operator<<=(const Base& w) && requires IntegerNumber<F> { write(*this << w); }
    void operator>>=(const Base& w) && requires IntegerNumber<F> { write(*this >> w); }
    void operator%=(const F& s) && requires IntegerNumber<F> { write(*this % s); }
    void operator&=(const F& s) && requires IntegerNumber<F> { write(*this & s); }
    void operator|=(const F& s) && requires IntegerNumber<F> { write(*this | s); }
    void operator^=(const F& s) && requires IntegerNumber<F> { write(*this ^ s); }
    void operator<<=(const F& s) && requires IntegerNumber<F> { write(*this << s); }
    void operator>>=(const F& s) && requires IntegerNumber<F> { write(*this >> s); }
    // v.xy++ and ++v.xy: the components written back; the value before, or after.
    Base operator++(int) && requires(!Boolean<F>) { const Base before = *this; write(before + F(1)); return before; }
    Base operator--(int) && requires(!Boolean<F>) { const Base before = *this; write(before - F(1)); return before; }
    Base operator++() && requires(!Boolean<F>) { const Base after = *this + F(1); write(after); return after; }
    Base operator--() && requires(!Boolean<F>) { const Base after = *this - F(1); write(after); return after; }

private:
    void write(const Base& w) {
        [&]<int... K>(std::integer_sequence<int, K...>) {
            ((source_.template get<I>() = w.template get<K>()), ...);
        }(std::make_integer_sequence<int, int(sizeof...(I))>());
    }
    Source& source_;
};

namespace vec_detail {
template <int... I>
constexpr bool distinct() {
    const int i[] = {I...};
    for (std::size_t a = 0; a < sizeof...(I); ++a) {
        for (std::size_t b = a + 1; b < sizeof...(I); ++b) {
            if (i[a] == i[b]) return false;
        }
    }
    return true;
}
}  // namespace vec_detail

// What every vector type V of N components of F has; written once.
#define QS_VEC_COMMON(V)                                                                        \
    /* Componentwise application, unrolled at compile time so components stay in registers. */ \
    template <class Op>                                                                         \
    static auto map(const V& a, Op op) {                                                        \
        return [&]<int... I>(std::integer_sequence<int, I...>) {                                \
            return vec<decltype(op(a.x)), N>(op(a.template get<I>())...);                       \
        }(std::make_integer_sequence<int, N>());                                                \
    }                                                                                           \
    template <class Op>                                                                         \
    static auto map(const V& a, const V& b, Op op) {                                            \
        return [&]<int... I>(std::integer_sequence<int, I...>) {                                \
            return vec<decltype(op(a.x, b.x)), N>(op(a.template get<I>(), b.template get<I>())...); \
        }(std::make_integer_sequence<int, N>());                                                \
    }                                                                                           \
    template <class Op>                                                                         \
    static auto map(const V& a, const V& b, const V& c, Op op) {                                \
        return [&]<int... I>(std::integer_sequence<int, I...>) {                                \
            return vec<decltype(op(a.x, b.x, c.x)), N>(                                         \
                op(a.template get<I>(), b.template get<I>(), c.template get<I>())...);          \
        }(std::make_integer_sequence<int, N>());                                                \
    }                                                                                           \
    /* All components of a and b, folded with op (GLSL's == and != of whole vectors). */        \
    template <class Op, class Fold>                                                             \
    static auto fold(const V& a, const V& b, Op op, Fold f) {                                   \
        return [&]<int... I>(std::integer_sequence<int, I...>) {                                \
            auto r = op(a.x, b.x);                                                              \
            ((r = f(r, op(a.template get<I + 1>(), b.template get<I + 1>()))), ...);            \
            return r;                                                                           \
        }(std::make_integer_sequence<int, N - 1>());                                            \
    }                                                                                           \
    template <int... I>                                                                         \
    vec<F, int(sizeof...(I))> swizzle() const& {                                                \
        return vec<F, int(sizeof...(I))>(get<I>()...);                                          \
    }                                                                                           \
    template <int... I>                                                                         \
    auto swizzle() & {                                                                          \
        if constexpr (vec_detail::distinct<I...>()) {                                           \
            return Swizzle<V, I...>(*this);                                                     \
        } else {                                                                                \
            return std::as_const(*this).template swizzle<I...>();                               \
        }                                                                                       \
    }                                                                                           \
    /* GLSL's conversions between vector types: vec2(ivec2), ivec2(vec2), uvec2(ivec2), ... */  \
    template <class G>                                                                          \
        requires(!std::is_same_v<G, F> && std::is_constructible_v<F, const G&>)                 \
    explicit V(const V<G>& o)                                                                   \
        : V([&]<int... I>(std::integer_sequence<int, I...>) {                                   \
              return V(F(o.template get<I>())...);                                              \
          }(std::make_integer_sequence<int, N>())) {}                                           \
    F r() const& { return x; }                                                                  \
    F& r() & { return x; }                                                                      \
    F g() const& { return y; }                                                                  \
    F& g() & { return y; }                                                                      \
    friend V operator-(const V& a) { return map(a, [](const F& p) { return -p; }); }             \
    friend V operator+(const V& a, const V& b) { return map(a, b, [](const F& p, const F& q) { return p + q; }); } \
    friend V operator-(const V& a, const V& b) { return map(a, b, [](const F& p, const F& q) { return p - q; }); } \
    friend V operator*(const V& a, const V& b) { return map(a, b, [](const F& p, const F& q) { return p * q; }); } \
    friend V operator/(const V& a, const V& b) { return map(a, b, [](const F& p, const F& q) { return p / q; }); } \
    friend V operator+(const V& a, const F& s) { return a + V(s); }                             \
    friend V operator-(const V& a, const F& s) { return a - V(s); }                             \
    friend V operator*(const V& a, const F& s) { return a * V(s); }                             \
    friend V operator/(const V& a, const F& s) { return a / V(s); }                             \
    friend V operator+(const F& s, const V& a) { return V(s) + a; }                             \
    friend V operator-(const F& s, const V& a) { return V(s) - a; }                             \
    friend V operator*(const F& s, const V& a) { return V(s) * a; }                             \
    friend V operator/(const F& s, const V& a) { return V(s) / a; }                             \
    V& operator+=(const V& b) & { return *this = *this + b; }                                   \
    V& operator-=(const V& b) & { return *this = *this - b; }                                   \
    V& operator*=(const V& b) & { return *this = *this * b; }                                   \
    V& operator/=(const V& b) & { return *this = *this / b; }                                   \
    V& operator*=(const F& s) & { return *this = *this * s; }                                   \
    V& operator/=(const F& s) & { return *this = *this / s; }                                   \
    V& operator+=(const F& s) & { return *this = *this + s; }                                   \
    V& operator-=(const F& s) & { return *this = *this - s; }                                   \
    /* ++v, v++, --v, v--: every component, as GLSL's */                                         \
    V& operator++() & requires(!Boolean<F>) { return *this += F(1); }                           \
    V& operator--() & requires(!Boolean<F>) { return *this -= F(1); }                           \
    V operator++(int) & requires(!Boolean<F>) { const V before = *this; *this += F(1); return before; } \
    V operator--(int) & requires(!Boolean<F>) { const V before = *this; *this -= F(1); return before; } \
    /* Integer vectors: % & | ^ ~ << >>, componentwise, a scalar on either side. */             \
    friend V operator%(const V& a, const V& b) requires IntegerNumber<F> { return map(a, b, [](const F& p, const F& q) { return p % q; }); } \
    friend V operator&(const V& a, const V& b) requires IntegerNumber<F> { return map(a, b, [](const F& p, const F& q) { return p & q; }); } \
    friend V operator|(const V& a, const V& b) requires IntegerNumber<F> { return map(a, b, [](const F& p, const F& q) { return p | q; }); } \
    friend V operator^(const V& a, const V& b) requires IntegerNumber<F> { return map(a, b, [](const F& p, const F& q) { return p ^ q; }); } \
    friend V operator<<(const V& a, const V& b) requires IntegerNumber<F> { return map(a, b, [](const F& p, const F& q) { return p << q; }); } \
    friend V operator>>(const V& a, const V& b) requires IntegerNumber<F> { return map(a, b, [](const F& p, const F& q) { return p >> q; }); } \
    friend V operator~(const V& a) requires IntegerNumber<F> { return map(a, [](const F& p) { return ~p; }); } \
    friend V operator%(const V& a, const F& s) requires IntegerNumber<F> { return a % V(s); }   \
    friend V operator&(const V& a, const F& s) requires IntegerNumber<F> { return a & V(s); }   \
    friend V operator|(const V& a, const F& s) requires IntegerNumber<F> { return a | V(s); }   \
    friend V operator^(const V& a, const F& s) requires IntegerNumber<F> { return a ^ V(s); }   \
    friend V operator<<(const V& a, const F& s) requires IntegerNumber<F> { return a << V(s); } \
    friend V operator>>(const V& a, const F& s) requires IntegerNumber<F> { return a >> V(s); } \
    V& operator%=(const V& b) & requires IntegerNumber<F> { return *this = *this % b; }         \
    V& operator&=(const V& b) & requires IntegerNumber<F> { return *this = *this & b; }         \
    V& operator|=(const V& b) & requires IntegerNumber<F> { return *this = *this | b; }         \
    V& operator^=(const V& b) & requires IntegerNumber<F> { return *this = *this ^ b; }         \
    V& operator<<=(const V& b) & requires IntegerNumber<F> { return *this = *this << b; }       \
    V& operator>>=(const V& b) & requires IntegerNumber<F> { return *this = *this >> b; }       \
    V& operator%=(const F& s) & requires IntegerNumber<F> { return *this = *this % s; }         \
    V& operator&=(const F& s) & requires IntegerNumber<F> { return *this = *this & s; }         \
    V& operator|=(const F& s) & requires IntegerNumber<F> { return *this = *this | s; }         \
    V& operator^=(const F& s) & requires IntegerNumber<F> { return *this = *this ^ s; }         \
    V& operator<<=(const F& s) & requires IntegerNumber<F> { return *this = *this << s; }       \
    V& operator>>=(const F& s) & requires IntegerNumber<F> { return *this = *this >> s; }       \
    /* GLSL's == and != of whole vectors: one bool. */                                          \
    friend auto operator==(const V& a, const V& b) {                                            \
        return fold(a, b, [](const F& p, const F& q) { return p == q; }, [](const auto& p, const auto& q) { return p && q; }); \
    }                                                                                           \
    friend auto operator!=(const V& a, const V& b) {                                            \
        return fold(a, b, [](const F& p, const F& q) { return p != q; }, [](const auto& p, const auto& q) { return p || q; }); \
    }                                                                                           \
    /* not(bvec) */                                                                             \
    friend V operator!(const V& a) requires Boolean<F> { return map(a, [](const F& p) { return !p; }); } \
    template <class M>                                                                          \
    friend V select(const M& m, const V& a, const V& b) {                                       \
        return map(a, b, [&](const F& p, const F& q) { return select(m, p, q); });              \
    }

// Swizzle names. QS_EACH_<set>_<depth>(M, args...) is M(args..., c) for each component name c
// of the set; one macro per depth, as a macro cannot expand inside itself.
#define QS_EACH_xy_1(M, ...) M(__VA_ARGS__, x) M(__VA_ARGS__, y)
#define QS_EACH_xy_2(M, ...) M(__VA_ARGS__, x) M(__VA_ARGS__, y)
#define QS_EACH_xy_3(M, ...) M(__VA_ARGS__, x) M(__VA_ARGS__, y)
#define QS_EACH_xy_4(M, ...) M(__VA_ARGS__, x) M(__VA_ARGS__, y)
#define QS_EACH_rg_1(M, ...) M(__VA_ARGS__, r) M(__VA_ARGS__, g)
#define QS_EACH_rg_2(M, ...) M(__VA_ARGS__, r) M(__VA_ARGS__, g)
#define QS_EACH_rg_3(M, ...) M(__VA_ARGS__, r) M(__VA_ARGS__, g)
#define QS_EACH_rg_4(M, ...) M(__VA_ARGS__, r) M(__VA_ARGS__, g)
#define QS_EACH_xyz_1(M, ...) M(__VA_ARGS__, x) M(__VA_ARGS__, y) M(__VA_ARGS__, z)
#define QS_EACH_xyz_2(M, ...) M(__VA_ARGS__, x) M(__VA_ARGS__, y) M(__VA_ARGS__, z)
#define QS_EACH_xyz_3(M, ...) M(__VA_ARGS__, x) M(__VA_ARGS__, y) M(__VA_ARGS__, z)
#define QS_EACH_xyz_4(M, ...) M(__VA_ARGS__, x) M(__VA_ARGS__, y) M(__VA_ARGS__, z)
#define QS_EACH_rgb_1(M, ...) M(__VA_ARGS__, r) M(__VA_ARGS__, g) M(__VA_ARGS__, b)
#define QS_EACH_rgb_2(M, ...) M(__VA_ARGS__, r) M(__VA_ARGS__, g) M(__VA_ARGS__, b)
#define QS_EACH_rgb_3(M, ...) M(__VA_ARGS__, r) M(__VA_ARGS__, g) M(__VA_ARGS__, b)
#define QS_EACH_rgb_4(M, ...) M(__VA_ARGS__, r) M(__VA_ARGS__, g) M(__VA_ARGS__, b)
#define QS_EACH_xyzw_1(M, ...) M(__VA_ARGS__, x) M(__VA_ARGS__, y) M(__VA_ARGS__, z) M(__VA_ARGS__, w)
#define QS_EACH_xyzw_2(M, ...) M(__VA_ARGS__, x) M(__VA_ARGS__, y) M(__VA_ARGS__, z) M(__VA_ARGS__, w)
#define QS_EACH_xyzw_3(M, ...) M(__VA_ARGS__, x) M(__VA_ARGS__, y) M(__VA_ARGS__, z) M(__VA_ARGS__, w)
#define QS_EACH_xyzw_4(M, ...) M(__VA_ARGS__, x) M(__VA_ARGS__, y) M(__VA_ARGS__, z) M(__VA_ARGS__, w)
#define QS_EACH_rgba_1(M, ...) M(__VA_ARGS__, r) M(__VA_ARGS__, g) M(__VA_ARGS__, b) M(__VA_ARGS__, a)
#define QS_EACH_rgba_2(M, ...) M(__VA_ARGS__, r) M(__VA_ARGS__, g) M(__VA_ARGS__, b) M(__VA_ARGS__, a)
#define QS_EACH_rgba_3(M, ...) M(__VA_ARGS__, r) M(__VA_ARGS__, g) M(__VA_ARGS__, b) M(__VA_ARGS__, a)
#define QS_EACH_rgba_4(M, ...) M(__VA_ARGS__, r) M(__VA_ARGS__, g) M(__VA_ARGS__, b) M(__VA_ARGS__, a)
// Component indices of the names.
#define QS_COMPONENT_x 0
#define QS_COMPONENT_y 1
#define QS_COMPONENT_z 2
#define QS_COMPONENT_w 3
#define QS_COMPONENT_r 0
#define QS_COMPONENT_g 1
#define QS_COMPONENT_b 2
#define QS_COMPONENT_a 3
// One swizzle: read on any vector, written through a Swizzle on a variable.
#define QS_SWIZZLE(name, ...)                                           \
    auto name() const& { return swizzle<__VA_ARGS__>(); }               \
    auto name() & { return swizzle<__VA_ARGS__>(); }
#define QS_SWIZZLE_2(set) QS_EACH_##set##_1(QS_SWIZZLE_2A, set)
#define QS_SWIZZLE_2A(set, a) QS_EACH_##set##_2(QS_SWIZZLE_2B, a)
#define QS_SWIZZLE_2B(a, b) QS_SWIZZLE(a##b, QS_COMPONENT_##a, QS_COMPONENT_##b)
#define QS_SWIZZLE_3(set) QS_EACH_##set##_1(QS_SWIZZLE_3A, set)
#define QS_SWIZZLE_3A(set, a) QS_EACH_##set##_2(QS_SWIZZLE_3B, set, a)
#define QS_SWIZZLE_3B(set, a, b) QS_EACH_##set##_3(QS_SWIZZLE_3C, a, b)
#define QS_SWIZZLE_3C(a, b, c) QS_SWIZZLE(a##b##c, QS_COMPONENT_##a, QS_COMPONENT_##b, QS_COMPONENT_##c)
#define QS_SWIZZLE_4(set) QS_EACH_##set##_1(QS_SWIZZLE_4A, set)
#define QS_SWIZZLE_4A(set, a) QS_EACH_##set##_2(QS_SWIZZLE_4B, set, a)
#define QS_SWIZZLE_4B(set, a, b) QS_EACH_##set##_3(QS_SWIZZLE_4C, set, a, b)
#define QS_SWIZZLE_4C(set, a, b, c) QS_EACH_##set##_4(QS_SWIZZLE_4D, a, b, c)
#define QS_SWIZZLE_4D(a, b, c, d) \
    QS_SWIZZLE(a##b##c##d, QS_COMPONENT_##a, QS_COMPONENT_##b, QS_COMPONENT_##c, QS_COMPONENT_##d)
// Every swizzle of 2, 3 and 4 components over a set of component names.
#define QS_SWIZZLES(set) QS_SWIZZLE_2(set) QS_SWIZZLE_3(set) QS_SWIZZLE_4(set)

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
    template <int I>
    F& get() {
        if constexpr (I == 0) return x; else return y;
    }
    QS_VEC_COMMON(vec2)
    QS_SWIZZLES(xy)
    QS_SWIZZLES(rg)
};

template <class F>
struct vec3 {
    using value_type = F;
    static constexpr int N = 3;
    F x, y, z;
    vec3() = default;
    explicit vec3(const F& s) : x(s), y(s), z(s) {}
    vec3(const F& x_, const F& y_, const F& z_) : x(x_), y(y_), z(z_) {}
    vec3(const vec2<F>& xy_, const F& z_) : x(xy_.x), y(xy_.y), z(z_) {}
    vec3(const F& x_, const vec2<F>& yz_) : x(x_), y(yz_.x), z(yz_.y) {}
    F& operator[](int i) { return i == 0 ? x : i == 1 ? y : z; }
    const F& operator[](int i) const { return i == 0 ? x : i == 1 ? y : z; }
    template <int I>
    const F& get() const {
        if constexpr (I == 0) return x; else if constexpr (I == 1) return y; else return z;
    }
    template <int I>
    F& get() {
        if constexpr (I == 0) return x; else if constexpr (I == 1) return y; else return z;
    }
    QS_VEC_COMMON(vec3)
    F b() const& { return z; }
    F& b() & { return z; }
    QS_SWIZZLES(xyz)
    QS_SWIZZLES(rgb)
};

template <class F>
struct vec4 {
    using value_type = F;
    static constexpr int N = 4;
    F x, y, z, w;
    vec4() = default;
    explicit vec4(const F& s) : x(s), y(s), z(s), w(s) {}
    vec4(const F& x_, const F& y_, const F& z_, const F& w_) : x(x_), y(y_), z(z_), w(w_) {}
    vec4(const vec3<F>& xyz_, const F& w_) : x(xyz_.x), y(xyz_.y), z(xyz_.z), w(w_) {}
    vec4(const F& x_, const vec3<F>& yzw_) : x(x_), y(yzw_.x), z(yzw_.y), w(yzw_.z) {}
    vec4(const vec2<F>& xy_, const vec2<F>& zw_) : x(xy_.x), y(xy_.y), z(zw_.x), w(zw_.y) {}
    vec4(const vec2<F>& xy_, const F& z_, const F& w_) : x(xy_.x), y(xy_.y), z(z_), w(w_) {}
    vec4(const F& x_, const vec2<F>& yz_, const F& w_) : x(x_), y(yz_.x), z(yz_.y), w(w_) {}
    vec4(const F& x_, const F& y_, const vec2<F>& zw_) : x(x_), y(y_), z(zw_.x), w(zw_.y) {}
    F& operator[](int i) { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
    const F& operator[](int i) const { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
    template <int I>
    const F& get() const {
        if constexpr (I == 0) return x; else if constexpr (I == 1) return y; else if constexpr (I == 2) return z; else return w;
    }
    template <int I>
    F& get() {
        if constexpr (I == 0) return x; else if constexpr (I == 1) return y; else if constexpr (I == 2) return z; else return w;
    }
    QS_VEC_COMMON(vec4)
    F b() const& { return z; }
    F& b() & { return z; }
    F a() const& { return w; }
    F& a() & { return w; }
    QS_SWIZZLES(xyzw)
    QS_SWIZZLES(rgba)
};

#undef QS_VEC_COMMON
#undef QS_SWIZZLES
#undef QS_SWIZZLE
#undef QS_SWIZZLE_2
#undef QS_SWIZZLE_2A
#undef QS_SWIZZLE_2B
#undef QS_SWIZZLE_3
#undef QS_SWIZZLE_3A
#undef QS_SWIZZLE_3B
#undef QS_SWIZZLE_3C
#undef QS_SWIZZLE_4
#undef QS_SWIZZLE_4A
#undef QS_SWIZZLE_4B
#undef QS_SWIZZLE_4C
#undef QS_SWIZZLE_4D
#undef QS_EACH_xy_1
#undef QS_EACH_xy_2
#undef QS_EACH_xy_3
#undef QS_EACH_xy_4
#undef QS_EACH_rg_1
#undef QS_EACH_rg_2
#undef QS_EACH_rg_3
#undef QS_EACH_rg_4
#undef QS_EACH_xyz_1
#undef QS_EACH_xyz_2
#undef QS_EACH_xyz_3
#undef QS_EACH_xyz_4
#undef QS_EACH_rgb_1
#undef QS_EACH_rgb_2
#undef QS_EACH_rgb_3
#undef QS_EACH_rgb_4
#undef QS_EACH_xyzw_1
#undef QS_EACH_xyzw_2
#undef QS_EACH_xyzw_3
#undef QS_EACH_xyzw_4
#undef QS_EACH_rgba_1
#undef QS_EACH_rgba_2
#undef QS_EACH_rgba_3
#undef QS_EACH_rgba_4
#undef QS_COMPONENT_x
#undef QS_COMPONENT_y
#undef QS_COMPONENT_z
#undef QS_COMPONENT_w
#undef QS_COMPONENT_r
#undef QS_COMPONENT_g
#undef QS_COMPONENT_b
#undef QS_COMPONENT_a

// GLSL's integer and boolean vectors of the fragments F stands for.
template <class F> using ivec2 = vec2<int_t<F>>;
template <class F> using ivec3 = vec3<int_t<F>>;
template <class F> using ivec4 = vec4<int_t<F>>;
template <class F> using uvec2 = vec2<uint_t<F>>;
template <class F> using uvec3 = vec3<uint_t<F>>;
template <class F> using uvec4 = vec4<uint_t<F>>;
template <class F> using bvec2 = vec2<Bool<F>>;
template <class F> using bvec3 = vec3<Bool<F>>;
template <class F> using bvec4 = vec4<Bool<F>>;

}  // namespace qs::glsl
