#pragma once
// What makes a type a shading number type, and the derivative built-ins over all of them.

#include <concepts>
#include <type_traits>

#include "shading/number/checked.h"
#include "shading/number/dual2.h"
#include "shading/number/integer.h"
#include "shading/number/lanes.h"
#include "shading/number/scalar.h"

namespace qs {

template <class F>
struct is_lanes : std::false_type {};
template <class T, int N, class L>
struct is_lanes<Lanes<T, N, L>> : std::true_type {};
template <class F>
struct is_dual2 : std::false_type {};
template <class T>
struct is_dual2<Dual2<T>> : std::true_type {};
template <class F>
struct is_checked : std::false_type {};
template <class L>
struct is_checked<Checked<L>> : std::true_type {};
template <class F>
inline constexpr bool is_checked_v = is_checked<F>::value;

// A Number stands where GLSL has `float`.
template <class F>
concept Number = std::is_floating_point_v<F> || is_lanes<F>::value || is_dual2<F>::value ||
                 (is_checked_v<F> && std::is_floating_point_v<typename F::value_type>);

// How many values one F holds (1 for float, double and Dual2 of them).
template <class F>
constexpr int lanes_of() {
    if constexpr (is_dual2<F>::value) return lanes_of<typename F::value_type>();
    else if constexpr (is_lanes<F>::value || is_checked_v<F> || is_integer_lanes<F>::value) return F::size;
    else return 1;
}

// Lanes that hold whole 2x2 quads (Quads, and Checked Quads), with their DerivativeRule.
template <class F>
concept QuadNumber = requires { F::layout::rule; };

// The mask a comparison of two F yields.
template <Number F>
using mask_t = decltype(F() < F());
// GLSL's bool where F (a Number or an IntegerNumber) stands for float or int: a mask of lanes.
template <class F>
using Bool = decltype(F() < F());

template <class M>
struct is_checked_mask : std::false_type {};
template <class M>
struct is_checked_mask<CheckedMask<M>> : std::true_type {};
// A Boolean stands where GLSL has bool: a mask of lanes (bool for one lane).
template <class M>
concept Boolean = std::is_same_v<M, bool> || is_lane_mask<M>::value || is_checked_mask<M>::value;

// Whether dFdx/dFdy exist on F: quads (lane differences) and Dual2 (carried partials).
template <class F>
struct has_derivatives : std::false_type {};
template <QuadNumber F>
struct has_derivatives<F> : std::true_type {};
template <class T>
struct has_derivatives<Dual2<T>> : std::true_type {};
template <class F>
inline constexpr bool has_derivatives_v = has_derivatives<F>::value;

template <class F>
inline constexpr bool always_false = false;

// ---- GLSL's ++ and -- ----------------------------------------------------------------------
// On every number type, float and integer: ++x adds 1 (1.0 for floats) as x += 1 does and gives x;
// x++ gives the value before. (float and double have their own.)
template <class N>
concept Steppable = (Number<N> || IntegerNumber<N>) && !std::is_arithmetic_v<N>;
template <Steppable N>
N& operator++(N& x) { return x += N(1); }
template <Steppable N>
N& operator--(N& x) { return x -= N(1); }
template <Steppable N>
N operator++(N& x, int) {
    const N before = x;
    x += N(1);
    return before;
}
template <Steppable N>
N operator--(N& x, int) {
    const N before = x;
    x -= N(1);
    return before;
}

// ---- derivative built-ins on quads ---------------------------------------------------------
namespace quad_detail {
// Index functions over the lane number i; `base` is the quad's lane 0. Function objects, not
// functions: their type carries them, so permute() knows the lanes at compile time and makes
// one shuffle of them.
inline constexpr auto base = [](std::size_t i) { return i & ~std::size_t(3); };
inline constexpr auto fine_right = [](std::size_t i) { return i | 1; };
inline constexpr auto fine_left = [](std::size_t i) { return i & ~std::size_t(1); };
inline constexpr auto fine_upper = [](std::size_t i) { return i | 2; };
inline constexpr auto fine_lower = [](std::size_t i) { return i & ~std::size_t(2); };
}  // namespace quad_detail

template <QuadNumber V>
V dFdxFine(const V& v) {
    using namespace quad_detail;
    return v.permute(fine_right) - v.permute(fine_left);
}
template <QuadNumber V>
V dFdyFine(const V& v) {
    using namespace quad_detail;
    return v.permute(fine_upper) - v.permute(fine_lower);
}
// Coarse: one difference for the whole quad. Under the Fine rule (llvmpipe) coarse is fine too.
template <QuadNumber V>
V dFdxCoarse(const V& v) {
    using namespace quad_detail;
    constexpr DerivativeRule R = V::layout::rule;
    if constexpr (R == DerivativeRule::Fine) {
        return dFdxFine(v);
    } else if constexpr (R == DerivativeRule::CoarseLower) {
        return v.permute([](std::size_t i) { return base(i) | 1; }) - v.permute(base);
    } else {
        return v.permute([](std::size_t i) { return base(i) | 3; }) -
               v.permute([](std::size_t i) { return base(i) | 2; });
    }
}
template <QuadNumber V>
V dFdyCoarse(const V& v) {
    using namespace quad_detail;
    if constexpr (V::layout::rule == DerivativeRule::Fine) {
        return dFdyFine(v);
    } else {  // both coarse rules take the left column
        return v.permute([](std::size_t i) { return base(i) | 2; }) - v.permute(base);
    }
}
template <QuadNumber V>
V dFdx(const V& v) { return dFdxCoarse(v); }
template <QuadNumber V>
V dFdy(const V& v) { return dFdyCoarse(v); }

// ---- derivative built-ins on Dual2: the carried partials ----------------------------------
template <class T>
Dual2<T> dFdx(const Dual2<T>& v) { return Dual2<T>(v.dx); }
template <class T>
Dual2<T> dFdy(const Dual2<T>& v) { return Dual2<T>(v.dy); }
template <class T>
Dual2<T> dFdxFine(const Dual2<T>& v) { return dFdx(v); }
template <class T>
Dual2<T> dFdyFine(const Dual2<T>& v) { return dFdy(v); }
template <class T>
Dual2<T> dFdxCoarse(const Dual2<T>& v) { return dFdx(v); }
template <class T>
Dual2<T> dFdyCoarse(const Dual2<T>& v) { return dFdy(v); }

// ---- no neighbours, no derivatives --------------------------------------------------------
#define QS_NO_DERIVATIVE(name)                                                                   \
    template <Number F>                                                                          \
        requires(!has_derivatives_v<F>)                                                          \
    F name(const F&) {                                                                           \
        static_assert(always_false<F>,                                                           \
                      #name " needs neighbouring fragments: instantiate the shader with Quads<> " \
                            "or Dual2<>, not with a per-pixel number type (float, double, Pixels)"); \
        return F();                                                                              \
    }
QS_NO_DERIVATIVE(dFdx)
QS_NO_DERIVATIVE(dFdy)
QS_NO_DERIVATIVE(dFdxFine)
QS_NO_DERIVATIVE(dFdyFine)
QS_NO_DERIVATIVE(dFdxCoarse)
QS_NO_DERIVATIVE(dFdyCoarse)
#undef QS_NO_DERIVATIVE

// GLSL: fwidth(p) = abs(dFdx(p)) + abs(dFdy(p)), exactly (not the gradient's length).
template <Number F>
F fwidth(const F& v) { return abs(dFdx(v)) + abs(dFdy(v)); }
template <Number F>
F fwidthFine(const F& v) { return abs(dFdxFine(v)) + abs(dFdyFine(v)); }
template <Number F>
F fwidthCoarse(const F& v) { return abs(dFdxCoarse(v)) + abs(dFdyCoarse(v)); }

}  // namespace qs
