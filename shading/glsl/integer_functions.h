#pragma once
// GLSL 4.00's integer functions over the integers of any number type (IntLanes: int_t<F>,
// uint_t<F>), lane by lane as the bit instructions GPUs have:
//   bitfieldExtract(v, offset, bits): `bits` bits from `offset`, sign-extended for int; 0 when
//       bits is 0 (GLSL leaves offset + bits > 32 undefined: here, the bits that exist)
//   bitfieldInsert(base, insert, offset, bits), bitfieldReverse, bitCount
//   findLSB(x), findMSB(x): -1 where there is none (for a negative int, the highest 0 bit)
//   uaddCarry, usubBorrow: the sum or difference, and the carry or borrow (0 or 1)
//   umulExtended, imulExtended: the 64-bit product's high and low halves
// Checked integers compute on their value and keep their operands' cases.

#include <bit>
#include <cstdint>
#include <type_traits>

#include "shading/number/number.h"

namespace qs::glsl {

namespace integer_functions_detail {

inline std::uint32_t low_bits(std::int32_t bits) { return bits >= 32 ? 0xFFFFFFFFu : (1u << (bits & 31)) - 1u; }

// Lane i of the result is f(i), with the lanes of the arguments read into arrays first.
template <class R, class Fn>
R from_lanes(Fn f) {
    alignas(64) typename R::value_type r[R::size];
    for (int i = 0; i < R::size; ++i) r[i] = f(i);
    return R::load(r);
}
template <class I>
struct Lanes32 {
    alignas(64) typename I::value_type v[I::size];
    explicit Lanes32(const I& x) { x.store(v); }
    std::uint32_t bits(int i) const { return std::uint32_t(v[i]); }
    std::int32_t value(int i) const { return std::int32_t(v[i]); }
};

}  // namespace integer_functions_detail

template <class T, class F, class S>
IntLanes<T, F> bitfieldExtract(const IntLanes<T, F>& value, const IntLanes<S, F>& offset, const IntLanes<S, F>& bits) {
    using namespace integer_functions_detail;
    // One declaration each: the value's lanes and the offset's may differ in type.
    const Lanes32 v(value);
    const Lanes32 o(offset), n(bits);
    return from_lanes<IntLanes<T, F>>([&](int i) -> T {
        if (n.value(i) <= 0) return T(0);
        const std::uint32_t field = (v.bits(i) >> (o.bits(i) & 31u)) & low_bits(n.value(i));
        if constexpr (std::is_signed_v<T>) {
            const std::uint32_t sign = n.value(i) >= 32 ? 0u : 1u << (n.value(i) - 1);
            return T(std::int32_t(field ^ sign) - std::int32_t(sign));
        } else {
            return field;
        }
    });
}

template <class T, class F, class S>
IntLanes<T, F> bitfieldInsert(const IntLanes<T, F>& base, const IntLanes<T, F>& insert, const IntLanes<S, F>& offset,
                              const IntLanes<S, F>& bits) {
    using namespace integer_functions_detail;
    const Lanes32 a(base), b(insert);
    const Lanes32 o(offset), n(bits);
    return from_lanes<IntLanes<T, F>>([&](int i) {
        const std::uint32_t shift = o.bits(i) & 31u;
        const std::uint32_t mask = n.value(i) <= 0 ? 0u : low_bits(n.value(i)) << shift;
        return T((a.bits(i) & ~mask) | ((b.bits(i) << shift) & mask));
    });
}

template <class T, class F>
IntLanes<T, F> bitfieldReverse(const IntLanes<T, F>& x) {
    using namespace integer_functions_detail;
    const Lanes32 a(x);
    return from_lanes<IntLanes<T, F>>([&](int i) {
        std::uint32_t u = a.bits(i), r = 0;
        for (int k = 0; k < 32; ++k) r |= ((u >> k) & 1u) << (31 - k);
        return T(r);
    });
}

template <class T, class F>
IntLanes<std::int32_t, F> bitCount(const IntLanes<T, F>& x) {
    using namespace integer_functions_detail;
    const Lanes32 a(x);
    return from_lanes<IntLanes<std::int32_t, F>>([&](int i) { return std::int32_t(std::popcount(a.bits(i))); });
}

template <class T, class F>
IntLanes<std::int32_t, F> findLSB(const IntLanes<T, F>& x) {
    using namespace integer_functions_detail;
    const Lanes32 a(x);
    return from_lanes<IntLanes<std::int32_t, F>>([&](int i) {
        return a.bits(i) == 0 ? std::int32_t(-1) : std::int32_t(std::countr_zero(a.bits(i)));
    });
}

template <class T, class F>
IntLanes<std::int32_t, F> findMSB(const IntLanes<T, F>& x) {
    using namespace integer_functions_detail;
    const Lanes32 a(x);
    return from_lanes<IntLanes<std::int32_t, F>>([&](int i) {
        std::uint32_t u = a.bits(i);
        if (std::is_signed_v<T> && std::int32_t(u) < 0) u = ~u;
        return u == 0 ? std::int32_t(-1) : std::int32_t(31 - std::countl_zero(u));
    });
}

// uaddCarry(x, y, carry), usubBorrow(x, y, borrow)
template <class F>
IntLanes<std::uint32_t, F> uaddCarry(const IntLanes<std::uint32_t, F>& x, const IntLanes<std::uint32_t, F>& y,
                                     IntLanes<std::uint32_t, F>& carry) {
    const IntLanes<std::uint32_t, F> sum = x + y;
    carry = select(sum < x, IntLanes<std::uint32_t, F>(1u), IntLanes<std::uint32_t, F>(0u));
    return sum;
}
template <class F>
IntLanes<std::uint32_t, F> usubBorrow(const IntLanes<std::uint32_t, F>& x, const IntLanes<std::uint32_t, F>& y,
                                      IntLanes<std::uint32_t, F>& borrow) {
    borrow = select(x < y, IntLanes<std::uint32_t, F>(1u), IntLanes<std::uint32_t, F>(0u));
    return x - y;
}

// umulExtended(x, y, msb, lsb) and imulExtended: the high half returned, the low one in `low`.
template <class T, class F>
IntLanes<T, F> mulExtended(const IntLanes<T, F>& x, const IntLanes<T, F>& y, IntLanes<T, F>& low) {
    using namespace integer_functions_detail;
    const Lanes32 a(x), b(y);
    using Wide = std::conditional_t<std::is_signed_v<T>, std::int64_t, std::uint64_t>;
    low = x * y;
    return from_lanes<IntLanes<T, F>>([&](int i) {
        const Wide p = Wide(T(a.v[i])) * Wide(T(b.v[i]));
        return T(std::uint32_t(std::uint64_t(p) >> 32));
    });
}

// The same on Checked integers: the value's, with the operands' cases.
#define QS_CHECKED_INTEGER_FUNCTION(name)                                                              \
    template <class L, class... Rest>                                                                  \
    auto name(const Checked<L>& x, const Rest&... rest) -> decltype(Checked(name(x.v, rest.v...), {})) { \
        return Checked(name(x.v, rest.v...), (x.cases | ... | rest.cases));                            \
    }
QS_CHECKED_INTEGER_FUNCTION(bitfieldExtract)
QS_CHECKED_INTEGER_FUNCTION(bitfieldInsert)
QS_CHECKED_INTEGER_FUNCTION(bitfieldReverse)
QS_CHECKED_INTEGER_FUNCTION(bitCount)
QS_CHECKED_INTEGER_FUNCTION(findLSB)
QS_CHECKED_INTEGER_FUNCTION(findMSB)
#undef QS_CHECKED_INTEGER_FUNCTION
template <class L>
Checked<L> uaddCarry(const Checked<L>& x, const Checked<L>& y, Checked<L>& carry) {
    L c;
    const L s = uaddCarry(x.v, y.v, c);
    carry = Checked<L>(c, x.cases | y.cases);
    return Checked<L>(s, x.cases | y.cases);
}
template <class L>
Checked<L> usubBorrow(const Checked<L>& x, const Checked<L>& y, Checked<L>& borrow) {
    L b;
    const L d = usubBorrow(x.v, y.v, b);
    borrow = Checked<L>(b, x.cases | y.cases);
    return Checked<L>(d, x.cases | y.cases);
}
template <class L>
Checked<L> mulExtended(const Checked<L>& x, const Checked<L>& y, Checked<L>& low) {
    L l;
    const L h = mulExtended(x.v, y.v, l);
    low = Checked<L>(l, x.cases | y.cases);
    return Checked<L>(h, x.cases | y.cases);
}

}  // namespace qs::glsl
