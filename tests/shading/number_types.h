#pragma once
// Test helpers: build any shading number type from plain lane values and read lanes back, so one
// test body runs over float, double, SIMD lanes, quads and Dual2 alike.

#include <array>
#include <cmath>

#include "shading/glsl.h"

namespace qs::test {

using qs::lanes_of;

// The scalar type a number type computes in (float or double).
template <class F>
struct scalar_of { using type = F; };
template <class T, int N, class L>
struct scalar_of<Lanes<T, N, L>> { using type = T; };
template <class T>
struct scalar_of<Dual2<T>> { using type = typename scalar_of<T>::type; };
template <class L>
struct scalar_of<Checked<L>> { using type = typename scalar_of<L>::type; };
template <class F>
using scalar_t = typename scalar_of<F>::type;

template <class F>
F from_values(const double* v) {
    if constexpr (is_dual2<F>::value) {
        return F(from_values<typename F::value_type>(v));
    } else if constexpr (is_lanes<F>::value || is_checked_v<F>) {
        typename F::value_type tmp[F::size];
        for (int i = 0; i < F::size; ++i) tmp[i] = typename F::value_type(v[i]);
        return F::load(tmp);
    } else {
        return F(v[0]);
    }
}

template <class F>
double value_at(const F& x, int i) { return double(lane(x, i)); }

// Equal as GLSL results: bit-equal values, or both NaN.
inline bool same(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

}  // namespace qs::test
