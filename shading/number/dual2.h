#pragma once
// Dual2<T>: a value with its partial derivatives in window x and y, propagated by the chain rule
// (after OSL's Dual2). T is any number type (float, double, Pixels<...>), so one Dual2 shades a
// whole batch of pixels with analytic derivatives and no quads, helper lanes or neighbours.
//
// dFdx/dFdy of a Dual2 return the carried partials. Second derivatives are not carried: the
// result of dFdx is a Dual2 whose own partials are zero, so dFdx(dFdx(v)) is 0, not v_xx.

#include <type_traits>

#include "shading/number/scalar.h"

namespace qs {

template <class T>
struct Dual2 {
    using value_type = T;
    T val{}, dx{}, dy{};

    Dual2() = default;
    Dual2(T v) : val(v), dx(0.0f), dy(0.0f) {}  // NOLINT: a constant has zero derivatives
    template <class S>
        requires(std::is_arithmetic_v<S> && !std::is_same_v<S, T>)
    Dual2(S v) : Dual2(T(v)) {}  // NOLINT
    Dual2(T v, T ddx, T ddy) : val(v), dx(ddx), dy(ddy) {}
    // float(i) and float(b) (integers, number/integer.h, and masks of T): constants.
    template <class I>
        requires std::is_same_v<typename I::float_type, T>
    explicit Dual2(const I& i) : Dual2(T(i)) {}
    template <class M>
        requires(std::is_same_v<M, decltype(T() < T())> && !std::is_arithmetic_v<M>)
    explicit Dual2(const M& m) : Dual2(T(m)) {}

    // d(-u) = -du
    friend Dual2 operator-(const Dual2& a) { return {-a.val, -a.dx, -a.dy}; }
    // d(u+v) = du + dv
    friend Dual2 operator+(const Dual2& a, const Dual2& b) {
        return {a.val + b.val, a.dx + b.dx, a.dy + b.dy};
    }
    friend Dual2 operator-(const Dual2& a, const Dual2& b) {
        return {a.val - b.val, a.dx - b.dx, a.dy - b.dy};
    }
    // d(uv) = u dv + v du
    friend Dual2 operator*(const Dual2& a, const Dual2& b) {
        return {a.val * b.val, a.val * b.dx + a.dx * b.val, a.val * b.dy + a.dy * b.val};
    }
    // d(u/v) = (du - (u/v) dv) / v
    friend Dual2 operator/(const Dual2& a, const Dual2& b) {
        T q = a.val / b.val;
        return {q, (a.dx - q * b.dx) / b.val, (a.dy - q * b.dy) / b.val};
    }
    // a * b + c with a * b exact (number/simd/simd.h); d(uv + w) = u dv + v du + dw, as the
    // product and the sum give it
    friend Dual2 exact_product_add(const Dual2& a, const Dual2& b, const Dual2& c) {
        return {exact_product_add(a.val, b.val, c.val), (a.val * b.dx + a.dx * b.val) + c.dx,
                (a.val * b.dy + a.dy * b.val) + c.dy};
    }
    Dual2& operator+=(const Dual2& b) { return *this = *this + b; }
    Dual2& operator-=(const Dual2& b) { return *this = *this - b; }
    Dual2& operator*=(const Dual2& b) { return *this = *this * b; }
    Dual2& operator/=(const Dual2& b) { return *this = *this / b; }

    // Comparisons look at values only: masks carry no derivatives.
    friend auto operator<(const Dual2& a, const Dual2& b) { return a.val < b.val; }
    friend auto operator<=(const Dual2& a, const Dual2& b) { return a.val <= b.val; }
    friend auto operator>(const Dual2& a, const Dual2& b) { return a.val > b.val; }
    friend auto operator>=(const Dual2& a, const Dual2& b) { return a.val >= b.val; }
    friend auto operator==(const Dual2& a, const Dual2& b) { return a.val == b.val; }
    friend auto operator!=(const Dual2& a, const Dual2& b) { return a.val != b.val; }

    template <class M>
    friend Dual2 select(const M& m, const Dual2& a, const Dual2& b) {
        return {select(m, a.val, b.val), select(m, a.dx, b.dx), select(m, a.dy, b.dy)};
    }
    friend auto isnan(const Dual2& a) { return isnan(a.val); }
    friend auto isinf(const Dual2& a) { return isinf(a.val); }
    // min/max pick a whole operand, derivatives included (one-sided at a tie).
    friend Dual2 min(const Dual2& a, const Dual2& b) {
        return select(isnan(b.val) || a.val < b.val, a, b);
    }
    friend Dual2 max(const Dual2& a, const Dual2& b) {
        return select(isnan(b.val) || a.val > b.val, a, b);
    }

    // Apply f with derivative f' at the same point: d f(u) = f'(u) du.
    static Dual2 chain(T f, T fprime, const Dual2& u) { return {f, fprime * u.dx, fprime * u.dy}; }

    // floor, ceil, trunc are piecewise constant: they lose derivatives.
    friend Dual2 floor(const Dual2& a) { return Dual2(floor(a.val)); }
    friend Dual2 ceil(const Dual2& a) { return Dual2(ceil(a.val)); }
    friend Dual2 trunc(const Dual2& a) { return Dual2(trunc(a.val)); }
    friend Dual2 roundEven(const Dual2& a) { return Dual2(roundEven(a.val)); }
    // d|u| = sign(u) du (zero derivative at u = 0, the subgradient's midpoint)
    friend Dual2 abs(const Dual2& a) {
        T s = select(a.val > T(0.0f), T(1.0f), select(a.val < T(0.0f), T(-1.0f), T(0.0f)));
        return chain(abs(a.val), s, a);
    }
    // d sqrt(u) = du / (2 sqrt(u))
    friend Dual2 sqrt(const Dual2& a) {
        T r = sqrt(a.val);
        return chain(r, T(0.5f) / r, a);
    }
    // d sin(u) = cos(u) du, d cos(u) = -sin(u) du
    friend Dual2 sin(const Dual2& a) { return chain(sin(a.val), cos(a.val), a); }
    friend Dual2 cos(const Dual2& a) { return chain(cos(a.val), -sin(a.val), a); }
    // d tan(u) = (1 + tan^2 u) du
    friend Dual2 tan(const Dual2& a) {
        T t = tan(a.val);
        return chain(t, T(1.0f) + t * t, a);
    }
    // d asin(u) = du / sqrt(1 - u^2), d acos(u) = -du / sqrt(1 - u^2)
    friend Dual2 asin(const Dual2& a) { return chain(asin(a.val), T(1.0f) / sqrt(T(1.0f) - a.val * a.val), a); }
    friend Dual2 acos(const Dual2& a) { return chain(acos(a.val), T(-1.0f) / sqrt(T(1.0f) - a.val * a.val), a); }
    // d atan(u) = du / (1 + u^2)
    friend Dual2 atan(const Dual2& a) { return chain(atan(a.val), T(1.0f) / (T(1.0f) + a.val * a.val), a); }
    // d atan(y, x) = (x dy - y dx) / (x^2 + y^2)
    friend Dual2 atan(const Dual2& y, const Dual2& x) {
        const T q = x.val * x.val + y.val * y.val;
        return {atan(y.val, x.val), (x.val * y.dx - y.val * x.dx) / q, (x.val * y.dy - y.val * x.dy) / q};
    }
    // d exp(u) = exp(u) du, d exp2(u) = ln2 exp2(u) du
    friend Dual2 exp(const Dual2& a) {
        T e = exp(a.val);
        return chain(e, e, a);
    }
    friend Dual2 exp2(const Dual2& a) {
        T e = exp2(a.val);
        return chain(e, T(0.69314718055994531f) * e, a);
    }
    // d log(u) = du / u, d log2(u) = du / (u ln2)
    friend Dual2 log(const Dual2& a) { return chain(log(a.val), T(1.0f) / a.val, a); }
    friend Dual2 log2(const Dual2& a) {
        return chain(log2(a.val), T(1.0f) / (a.val * T(0.69314718055994531f)), a);
    }
    // d u^v = v u^(v-1) du + u^v ln(u) dv
    friend Dual2 pow(const Dual2& a, const Dual2& b) {
        T p = pow(a.val, b.val);
        T du = b.val * pow(a.val, b.val - T(1.0f));
        T dv = p * log(a.val);
        return {p, du * a.dx + dv * b.dx, du * a.dy + dv * b.dy};
    }

    friend auto lane(const Dual2& a, int i) { return lane(a.val, i); }
};

}  // namespace qs
