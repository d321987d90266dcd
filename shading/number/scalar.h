#pragma once
// Plain float and double as shading number types: the per-pixel path and the precision oracle.
//
// GLSL semantics that C++ does not give for free are stated here once:
//  - min/max return the non-NaN operand (as llvmpipe does: NIR fmin/fmax with NaN-return-other);
//  - a comparison yields `bool`, the scalar mask type; selection is `select(mask, a, b)`.
// Scalars carry no neighbours, so dFdx/dFdy on them are a compile-time error (number.h: has_derivatives).

#include <cmath>
#include <concepts>
#include <type_traits>

#include "shading/number/sin_cos.h"

namespace qs {

// Two-operand primitives take mixed float/double (a GLSL float literal in a double shader).
template <std::floating_point A, std::floating_point B>
std::common_type_t<A, B> select(bool m, A a, B b) { return m ? a : b; }
template <std::floating_point A, std::floating_point B>
std::common_type_t<A, B> min(A a, B b) { return (std::isnan(b) || a < b) ? a : b; }
template <std::floating_point A, std::floating_point B>
std::common_type_t<A, B> max(A a, B b) { return (std::isnan(b) || a > b) ? a : b; }
template <std::floating_point A, std::floating_point B>
std::common_type_t<A, B> pow(A a, B b) { return std::pow(std::common_type_t<A, B>(a), std::common_type_t<A, B>(b)); }
template <std::floating_point A, std::floating_point B>
std::common_type_t<A, B> atan(A y, B x) { return std::atan2(std::common_type_t<A, B>(y), std::common_type_t<A, B>(x)); }

inline bool select(bool m, bool a, bool b) { return m ? a : b; }

inline bool isnan(float a) { return std::isnan(a); }
inline bool isnan(double a) { return std::isnan(a); }
inline bool isinf(float a) { return std::isinf(a); }
inline bool isinf(double a) { return std::isinf(a); }

// Unary primitives: one name per GLSL built-in, the std:: implementation underneath.
#define QS_SCALAR_UNARY(name, impl)                          \
    inline float name(float a) { return impl(a); }          \
    inline double name(double a) { return impl(a); }
QS_SCALAR_UNARY(floor, std::floor)
QS_SCALAR_UNARY(ceil, std::ceil)
QS_SCALAR_UNARY(trunc, std::trunc)
QS_SCALAR_UNARY(roundEven, std::nearbyint)  // to nearest, halves to even (the default mode)
QS_SCALAR_UNARY(abs, std::fabs)
QS_SCALAR_UNARY(sqrt, std::sqrt)
QS_SCALAR_UNARY(tan, std::tan)
QS_SCALAR_UNARY(asin, std::asin)
QS_SCALAR_UNARY(acos, std::acos)
QS_SCALAR_UNARY(atan, std::atan)
QS_SCALAR_UNARY(exp, std::exp)
QS_SCALAR_UNARY(log, std::log)
QS_SCALAR_UNARY(exp2, std::exp2)
QS_SCALAR_UNARY(log2, std::log2)
#undef QS_SCALAR_UNARY
// sin and cos: float as llvmpipe evaluates them, to the bit (number/sin_cos.h); double, the
// precision oracle, as the C library does.
inline float sin(float a) { return llvmpipe_math::sin(a); }
inline double sin(double a) { return std::sin(a); }
inline float cos(float a) { return llvmpipe_math::cos(a); }
inline double cos(double a) { return std::cos(a); }
// a * b + c where a * b is exact: fused or not, the same bits (number/simd/simd.h).
template <std::floating_point T>
T exact_product_add(T a, T b, T c) {
    return simd::exact_product_add(a, b, c);
}

// Lane access, so that code written over any number type can look at single values.
inline float lane(float a, int) { return a; }
inline double lane(double a, int) { return a; }
inline bool lane(bool m, int) { return m; }
inline bool any(bool m) { return m; }
inline bool all(bool m) { return m; }

}  // namespace qs
