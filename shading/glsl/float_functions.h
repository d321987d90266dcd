#pragma once
// GLSL 4.00's functions on a float's representation, over every number type:
//   fma(a, b, c): a * b + c rounded once (llvmpipe fuses it on hosts with FMA, as here)
//   frexp(x, out e): x = significand * 2^e, |significand| in [0.5, 1); 0 for 0 (GLSL leaves
//                    infinities and NaN undefined: they keep their value, exponent 0)
//   ldexp(x, e): x * 2^e
// A double instantiation computes in double; Dual2 carries the derivatives (fma's as the
// product's and the sum's, frexp's and ldexp's as the scale's); Checked wraps the float's.

#include <cmath>

#include "shading/glsl/lanewise.h"
#include "shading/number/number.h"

namespace qs::glsl {

template <Number F>
F fma(const F& a, const F& b, const F& c) {
    if constexpr (is_dual2<F>::value) {
        return F(fma(a.val, b.val, c.val), (a.val * b.dx + a.dx * b.val) + c.dx, (a.val * b.dy + a.dy * b.val) + c.dy);
    } else if constexpr (is_checked_v<F>) {
        return F::result(fma(a.v, b.v, c.v), {}, a, b, c);
    } else {
        return lanewise::map(a, b, c, [](auto x, auto y, auto z) { return std::fma(x, y, z); });
    }
}

template <Number F>
F frexp(const F& x, int_t<F>& exponent) {
    if constexpr (is_dual2<F>::value) {
        using T = typename F::value_type;
        const T s = frexp(x.val, exponent);
        const T scale = s / x.val;  // 2^-e, exact (and NaN for 0, where the derivative is 0)
        const auto zero = x.val == T(0.0f);
        return F(s, select(zero, T(0.0f), x.dx * scale), select(zero, T(0.0f), x.dy * scale));
    } else if constexpr (is_checked_v<F>) {
        int_t<decltype(x.v)> e;
        const auto s = frexp(x.v, e);
        exponent = int_t<F>(e, x.cases);
        return F(s, x.cases);
    } else if constexpr (std::is_floating_point_v<F>) {
        int e = 0;
        const F s = std::isfinite(x) ? std::frexp(x, &e) : x;
        exponent = int_t<F>(std::int32_t(e));
        return s;
    } else {
        using T = typename F::value_type;
        alignas(64) T v[F::size];
        alignas(64) std::int32_t e[F::size];
        x.store(v);
        for (int i = 0; i < F::size; ++i) {
            int k = 0;
            if (std::isfinite(v[i])) v[i] = std::frexp(v[i], &k);
            e[i] = k;
        }
        exponent = int_t<F>::load(e);
        return F::load(v);
    }
}

template <Number F>
F ldexp(const F& x, const int_t<F>& exponent) {
    if constexpr (is_dual2<F>::value) {
        using T = typename F::value_type;
        const T scale = ldexp(T(1.0f), exponent);
        return F(ldexp(x.val, exponent), x.dx * scale, x.dy * scale);
    } else if constexpr (is_checked_v<F>) {
        return F(ldexp(x.v, exponent.v), x.cases | exponent.cases);
    } else if constexpr (std::is_floating_point_v<F>) {
        return std::ldexp(x, int(exponent[0]));
    } else {
        return lanewise::map(x, exponent, [](auto v, std::int32_t e) { return std::ldexp(v, e); });
    }
}

}  // namespace qs::glsl
