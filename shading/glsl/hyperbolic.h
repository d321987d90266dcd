#pragma once
// GLSL 1.30's hyperbolic functions, written through exp, log and sqrt as Mesa's GLSL compiler
// defines them, so that they hold for every number type (Dual2 carries their derivatives
// through exp and log):
//   sinh(x) = (e^x - e^-x) / 2         asinh(x) = sign(x) log(|x| + sqrt(x^2 + 1))
//   cosh(x) = (e^x + e^-x) / 2         acosh(x) = log(x + sqrt(x^2 - 1))
//   tanh(x) = (e^x - e^-x) / (e^x + e^-x), x clamped to [-10, 10] first, where tanh is +-1 in
//             float anyway and e^x would overflow to inf / inf
//   atanh(x) = log((1 + x) / (1 - x)) / 2

#include "shading/glsl/builtins.h"

namespace qs::glsl {

template <Number F>
F sinh(const F& x) { return F(0.5f) * (exp(x) - exp(-x)); }
template <Number F>
F cosh(const F& x) { return F(0.5f) * (exp(x) + exp(-x)); }
template <Number F>
F tanh(const F& x) {
    const F t = clamp(x, F(-10.0f), F(10.0f));
    return (exp(t) - exp(-t)) / (exp(t) + exp(-t));
}
template <Number F>
F asinh(const F& x) { return sign(x) * log(abs(x) + sqrt(x * x + F(1.0f))); }
template <Number F>
F acosh(const F& x) { return log(x + sqrt(x * x - F(1.0f))); }
template <Number F>
F atanh(const F& x) { return F(0.5f) * log((F(1.0f) + x) / (F(1.0f) - x)); }

}  // namespace qs::glsl
