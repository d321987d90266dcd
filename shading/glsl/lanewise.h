#pragma once
// Lane by lane: a function of one float, double or 32-bit integer applied to every lane of a
// number type, for the few GLSL built-ins with no vector instruction (frexp, fma, the integer
// bit functions). Dual2 and Checked numbers are handled by the built-ins themselves.

#include <cstdint>
#include <type_traits>

#include "shading/number/number.h"

namespace qs::glsl::lanewise {

// Lane i of the result is f(lane i of x, ...): for F a float or double, or Lanes or IntLanes.
template <class X, class Fn>
X map(const X& x, Fn f) {
    if constexpr (std::is_arithmetic_v<X>) {
        return f(x);
    } else {
        using T = typename X::value_type;
        alignas(64) T a[X::size];
        x.store(a);
        for (int i = 0; i < X::size; ++i) a[i] = f(a[i]);
        return X::load(a);
    }
}
template <class X, class Y, class Fn>
X map(const X& x, const Y& y, Fn f) {
    if constexpr (std::is_arithmetic_v<X>) {
        return f(x, y);
    } else {
        using T = typename X::value_type;
        using U = typename Y::value_type;
        alignas(64) T a[X::size];
        alignas(64) U b[X::size];
        x.store(a);
        y.store(b);
        for (int i = 0; i < X::size; ++i) a[i] = f(a[i], b[i]);
        return X::load(a);
    }
}
template <class X, class Y, class Z, class Fn>
X map(const X& x, const Y& y, const Z& z, Fn f) {
    if constexpr (std::is_arithmetic_v<X>) {
        return f(x, y, z);
    } else {
        using T = typename X::value_type;
        using U = typename Y::value_type;
        using V = typename Z::value_type;
        alignas(64) T a[X::size];
        alignas(64) U b[X::size];
        alignas(64) V c[X::size];
        x.store(a);
        y.store(b);
        z.store(c);
        for (int i = 0; i < X::size; ++i) a[i] = f(a[i], b[i], c[i]);
        return X::load(a);
    }
}

}  // namespace qs::glsl::lanewise
