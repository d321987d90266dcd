#pragma once
// GLSL `int` and `uint` over the lanes of a float number type.
//
// `IntLanes<T, F>` holds one 32-bit integer (T: std::int32_t or std::uint32_t) for each fragment
// of a float number type F: a plain integer for float and double (the per-pixel instantiations),
// SIMD lanes for Pixels and Quads. It compares into F's own mask type, so a GLSL `bool` is one
// type whether it came from floats or integers, and converts to and from F. Shaders name these
// types through int_t<F> / uint_t<F> (below): Dual2 shaders use the integers of their value type,
// Checked shaders Checked integers.
//
// Semantics, GLSL's where it defines them and llvmpipe's (Mesa 22.3, measured by the probes in
// shading/shaders/vocabulary_probes.h) where it does not:
//  - + - * and unary - wrap modulo 2^32, for int and uint alike;
//  - a / b truncates; x / 0 is 0 for int and 0xFFFFFFFF for uint; INT_MIN / -1 wraps to INT_MIN;
//  - a % b is the remainder of the operands' bits taken as unsigned, for int too (Mesa compiles
//    GLSL's `%` to an unsigned remainder; GLSL leaves negative operands undefined); x % 0 is
//    0xFFFFFFFF;
//  - << and >> use the count's low five bits (x << 33 is x << 1), as NIR defines them; >> on int
//    shifts in the sign;
//  - int(x) truncates; out of range or NaN gives INT_MIN (x86's cvttps2dq, what llvmpipe shows);
//    uint(x) is llvmpipe's sequence on AVX2 hosts: int(x) | (int(x - 2^31) & sign mask of int(x)),
//    which is exact on [0, 2^32) and uint(int(x)) for negative x.
// Nothing here traps or is undefined in C++: division goes through double (exact for 32-bit
// operands) with the divisor replaced where it is 0; conversions use x86's, which are defined out
// of range, or check the range.

#include <bit>
#include <concepts>
#include <cstring>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "shading/number/checked.h"
#include "shading/number/dual2.h"
#include "shading/number/lanes.h"
#include "shading/number/scalar.h"
#include "shading/number/simd/simd.h"
#include "shading/number/wide_vector.h"

namespace qs {

namespace integer_detail {

// How many fragments one F holds: its lanes, or 1 for float and double.
template <class F>
struct fragments_of : std::integral_constant<int, 1> {};
template <class S, int N, class L>
struct fragments_of<Lanes<S, N, L>> : std::integral_constant<int, N> {};

// int(x) of N floats or doubles: truncated, INT_MIN out of range (after truncation) and for
// NaN. That is the x86 conversions' answer (cvttps2dq, cvttpd2dq and their wider forms), which
// they give with no masks; elsewhere it is stated lane by lane.
template <class S, int N>
void truncate(const S (&in)[N], std::int32_t (&out)[N]) {
    int k = 0;
    // A register of floats (of doubles, giving half a register of ints) at a time, then halves.
    constexpr int kWidest = int(simd::register_bytes / sizeof(S));
    [&]<int... I>(std::integer_sequence<int, I...>) {
        (
            [&] {
                constexpr int w = kWidest >> I;
                if constexpr (w >= 4 && (std::is_same_v<S, float> || simd::register_bytes >= 32)) {
                    using V = simd::Vector<S, w>;
                    for (; k + w <= N; k += w) simd::store(out + k, simd::convert_truncate(simd::load<V>(in + k)));
                }
            }(),
            ...);
    }(std::make_integer_sequence<int, 3>());
    for (; k < N; ++k) {
        out[k] = (in[k] > S(-2147483649.0) && in[k] < S(2147483648.0)) ? std::int32_t(in[k]) : std::int32_t(INT32_MIN);
    }
}

}  // namespace integer_detail

template <class T, class F>
class IntLanes {
    static_assert(std::is_same_v<T, std::int32_t> || std::is_same_v<T, std::uint32_t>, "GLSL integers are 32-bit");

public:
    using value_type = T;
    using float_type = F;  // the float number type whose fragments these are
    static constexpr int size = integer_detail::fragments_of<F>::value;
    using Vector = simd::Wide<T, size>;  // one lane per fragment (one for float and double)
    using Mask = decltype(F() < F());        // F's own mask: GLSL's bool in this instantiation
    static constexpr bool is_signed = std::is_signed_v<T>;

    Vector v;

    IntLanes() = default;
    IntLanes(T x) : v(Vector::splat(x)) {}  // NOLINT: broadcast, as GLSL promotes a literal
    template <std::integral S>
        requires(!std::is_same_v<S, T> && !std::is_same_v<S, bool>)
    IntLanes(S x) : IntLanes(T(x)) {}  // NOLINT: an integer literal of either signedness
    explicit IntLanes(const Vector& x) : v(x) {}

    // GLSL int(x), uint(x) of a float: truncation, out-of-range results as stated above.
    explicit IntLanes(const F& x) : v(from_float(x)) {}
    explicit IntLanes(const Dual2<F>& x) : IntLanes(x.val) {}
    template <std::floating_point S>
        requires(!std::is_same_v<S, F>)
    explicit IntLanes(S x) : IntLanes(F(x)) {}
    // int(u), uint(i): the same bits.
    template <class U>
        requires(!std::is_same_v<U, T>)
    explicit IntLanes(const IntLanes<U, F>& o) : v(simd::bit_cast<T>(o.v)) {}
    // int(b): 1 or 0.
    explicit IntLanes(const Mask& m) : IntLanes(select(m, IntLanes(1), IntLanes(0))) {}

    // float(i), double(i) where F is float or double.
    explicit operator float() const requires std::is_floating_point_v<F> { return float(v[0]); }
    explicit operator double() const requires std::is_floating_point_v<F> { return double(v[0]); }

    static IntLanes load(const T* p) { return IntLanes(Vector::load(p)); }
    void store(T* p) const { v.store(p); }
    T operator[](int i) const { return v[i]; }

    // ---- arithmetic, wrapping: computed on the unsigned bits ----
    friend IntLanes operator-(const IntLanes& a) { return wrap(bits(0u) - bits(a)); }
    friend IntLanes operator~(const IntLanes& a) { return IntLanes(~a.v); }
    friend IntLanes operator+(const IntLanes& a, const IntLanes& b) { return wrap(bits(a) + bits(b)); }
    friend IntLanes operator-(const IntLanes& a, const IntLanes& b) { return wrap(bits(a) - bits(b)); }
    friend IntLanes operator*(const IntLanes& a, const IntLanes& b) { return wrap(bits(a) * bits(b)); }
    friend IntLanes operator/(const IntLanes& a, const IntLanes& b) {
        const auto zero = simd::equal(b.v, Vector{});
        // x / 0 = 0 for int, 0xFFFFFFFF for uint; INT_MIN / -1 = INT_MIN, the quotient 2^31 wrapped.
        const IntLanes q = quotient(a, simd::select(zero, Vector::splat(T(1)), b.v));
        return IntLanes(simd::select(zero, Vector::splat(is_signed ? T(0) : T(0xFFFFFFFFu)), q.v));
    }
    friend IntLanes operator%(const IntLanes& a, const IntLanes& b) {
        using U = IntLanes<std::uint32_t, F>;
        const U ua(a), ub(b);
        const U r = ua - (ua / ub) * ub;  // x % 0: x - 0xFFFFFFFF * 0 = x, fixed below
        return IntLanes(simd::select(simd::equal(b.v, Vector{}), Vector::splat(T(0xFFFFFFFFu)), IntLanes(r).v));
    }
    friend IntLanes operator&(const IntLanes& a, const IntLanes& b) { return IntLanes(a.v & b.v); }
    friend IntLanes operator|(const IntLanes& a, const IntLanes& b) { return IntLanes(a.v | b.v); }
    friend IntLanes operator^(const IntLanes& a, const IntLanes& b) { return IntLanes(a.v ^ b.v); }
    // Shifts by the count's low five bits; the count may be int or uint, lanes or one number.
    template <class C>
    friend IntLanes operator<<(const IntLanes& a, const IntLanes<C, F>& n) {
        return wrap(bits(a) << count(n));
    }
    template <class C>
    friend IntLanes operator>>(const IntLanes& a, const IntLanes<C, F>& n) {
        return IntLanes(a.v >> simd::bit_cast<T>(count(n)));
    }
    friend IntLanes operator<<(const IntLanes& a, int n) { return wrap(bits(a) << (n & 31)); }
    friend IntLanes operator>>(const IntLanes& a, int n) { return IntLanes(a.v >> (n & 31)); }

    IntLanes& operator+=(const IntLanes& b) & { return *this = *this + b; }
    IntLanes& operator-=(const IntLanes& b) & { return *this = *this - b; }
    IntLanes& operator*=(const IntLanes& b) & { return *this = *this * b; }
    IntLanes& operator/=(const IntLanes& b) & { return *this = *this / b; }
    IntLanes& operator%=(const IntLanes& b) & { return *this = *this % b; }
    IntLanes& operator&=(const IntLanes& b) & { return *this = *this & b; }
    IntLanes& operator|=(const IntLanes& b) & { return *this = *this | b; }
    IntLanes& operator^=(const IntLanes& b) & { return *this = *this ^ b; }
    IntLanes& operator<<=(int n) & { return *this = *this << n; }
    IntLanes& operator>>=(int n) & { return *this = *this >> n; }

    friend Mask operator<(const IntLanes& a, const IntLanes& b) { return mask(simd::less(a.v, b.v)); }
    friend Mask operator<=(const IntLanes& a, const IntLanes& b) { return mask(simd::less_equal(a.v, b.v)); }
    friend Mask operator>(const IntLanes& a, const IntLanes& b) { return mask(simd::less(b.v, a.v)); }
    friend Mask operator>=(const IntLanes& a, const IntLanes& b) { return mask(simd::less_equal(b.v, a.v)); }
    friend Mask operator==(const IntLanes& a, const IntLanes& b) { return mask(simd::equal(a.v, b.v)); }
    friend Mask operator!=(const IntLanes& a, const IntLanes& b) { return mask(simd::not_equal(a.v, b.v)); }

    friend IntLanes select(const Mask& m, const IntLanes& a, const IntLanes& b) {
        return IntLanes(simd::select(lane_bits_of(m), a.v, b.v));
    }
    // GLSL's integer min, max, abs (abs(INT_MIN) wraps to INT_MIN, as it does on GPUs).
    friend IntLanes min(const IntLanes& a, const IntLanes& b) { return IntLanes(simd::select(simd::less(a.v, b.v), a.v, b.v)); }
    friend IntLanes max(const IntLanes& a, const IntLanes& b) { return IntLanes(simd::select(simd::less(b.v, a.v), a.v, b.v)); }
    friend IntLanes abs(const IntLanes& a) requires is_signed { return select(a < IntLanes(0), -a, a); }

    friend T lane(const IntLanes& a, int i) { return a.v[i]; }

    // The lanes' bits as uint (for wrapping arithmetic), and back.
    using Bits = simd::Wide<std::uint32_t, size>;
    static Bits bits(const IntLanes& a) { return simd::bit_cast<std::uint32_t>(a.v); }
    static Bits bits(std::uint32_t x) { return Bits::splat(x); }
    static IntLanes wrap(const Bits& b) { return IntLanes(simd::bit_cast<T>(b)); }

private:
    using Comparison = simd::Wide<std::int32_t, size>;  // what comparing two Vectors yields

    static Mask mask(const Comparison& c) {
        if constexpr (std::is_same_v<Mask, bool>) return c[0] != 0;
        else if constexpr (std::is_same_v<typename Mask::Vector, Comparison>) return Mask(c);
        else return Mask(simd::convert<typename Mask::Bits>(c));  // double lanes: widened
    }
    static Comparison lane_bits_of(const Mask& m) {
        if constexpr (std::is_same_v<Mask, bool>) return Comparison::splat(m ? -1 : 0);
        else if constexpr (std::is_same_v<typename Mask::Vector, Comparison>) return m.bits;
        else return simd::convert<std::int32_t>(m.bits);
    }
    template <class C>
    static Bits count(const IntLanes<C, F>& n) {
        return IntLanes<C, F>::bits(n) & Bits::splat(31u);
    }

    // a / b for b != 0, truncated: in double, exact for 32-bit operands (a quotient's distance to
    // the next integer is at least 1/|b| > 2^-32, far above double's rounding error), then
    // brought into range, which only INT_MIN / -1 leaves.
    static IntLanes quotient(const IntLanes& a, const Vector& b) {
        const auto q = simd::round<simd::Rounding::Trunc>(simd::convert<double>(a.v) / simd::convert<double>(b));
        const auto w = simd::convert<std::int64_t>(q);  // |q| <= 2^32: in range
        return wrap(simd::convert<std::uint32_t>(w));  // the low 32 bits
    }

    // int(x), uint(x) of F's lanes.
    static Vector from_float(const F& x) {
        if constexpr (std::is_floating_point_v<F>) {
            return Vector::splat(convert_one(x));
        } else {
            using S = typename F::value_type;
            using I = simd::Wide<std::int32_t, size>;
            auto to_int = [](const F& f) {
                alignas(64) S in[size];
                alignas(64) std::int32_t out[size];
                f.store(in);
                integer_detail::truncate(in, out);
                I r;
                std::memcpy(&r, out, sizeof r);
                return r;
            };
            const I i = to_int(x);
            if constexpr (is_signed) {
                return i;
            } else {
                const I high = to_int(x - F(S(2147483648.0)));
                return simd::bit_cast<T>(i | (high & (i >> 31)));
            }
        }
    }
    static T convert_one(F x) {
        auto to_int = [](F f) -> std::int32_t {
            return (f > F(-2147483649.0) && f < F(2147483648.0)) ? std::int32_t(f) : std::int32_t(INT32_MIN);
        };
        const std::int32_t i = to_int(x);
        if constexpr (is_signed) {
            return i;
        } else {
            const std::int32_t high = to_int(x - F(2147483648.0));
            return std::uint32_t(i) | (std::uint32_t(high) & std::uint32_t(i >> 31));
        }
    }
};

// ---- the integers of a number type --------------------------------------------------------
template <class T, class F>
struct integer_of {
    using type = IntLanes<T, F>;  // float, double, Pixels, Quads
};
template <class T, class G>
struct integer_of<T, Dual2<G>> : integer_of<T, G> {};  // integers carry no derivatives
template <class T, class L>
struct integer_of<T, Checked<L>> {
    using type = Checked<typename integer_of<T, L>::type>;
};
template <class T, class U, class F>
struct integer_of<T, IntLanes<U, F>> : integer_of<T, F> {};

// GLSL int and uint where F stands for float.
template <class F>
using int_t = typename integer_of<std::int32_t, F>::type;
template <class F>
using uint_t = typename integer_of<std::uint32_t, F>::type;

template <class I>
struct is_integer_lanes : std::false_type {};
template <class T, class F>
struct is_integer_lanes<IntLanes<T, F>> : std::true_type {};
template <class L>
struct is_integer_lanes<Checked<L>> : is_integer_lanes<L> {};
// An IntegerNumber stands where GLSL has int or uint.
template <class I>
concept IntegerNumber = is_integer_lanes<I>::value;

// ---- bits of floats (GLSL floatBitsToInt, intBitsToFloat and their uint forms) -------------
// Through memory, which the compiler turns into register moves. In a double instantiation the
// bits are those of the value rounded to float: GLSL's float is 32-bit.
template <class T, class F>
IntLanes<T, F> float_bits(const F& x) {
    using I = IntLanes<T, F>;
    if constexpr (std::is_floating_point_v<F>) {
        return I(std::bit_cast<T>(float(x)));
    } else {
        float f[I::size];
        if constexpr (std::is_same_v<typename F::value_type, float>) {
            x.store(f);
        } else {
            for (int i = 0; i < I::size; ++i) f[i] = float(x[i]);
        }
        T bits[I::size];
        std::memcpy(bits, f, sizeof bits);
        return I::load(bits);
    }
}
template <class T, class G>
IntLanes<T, G> float_bits(const Dual2<G>& x) { return float_bits<T>(x.val); }
template <class T, class L>
Checked<typename integer_of<T, L>::type> float_bits(const Checked<L>& x) { return {float_bits<T>(x.v), x.cases}; }

template <class T, class F>
F bits_float(const IntLanes<T, F>& i) {
    if constexpr (std::is_floating_point_v<F>) {
        return F(std::bit_cast<float>(T(i.v[0])));
    } else {
        using S = typename F::value_type;
        T bits[IntLanes<T, F>::size];
        i.store(bits);
        float f[IntLanes<T, F>::size];
        std::memcpy(f, bits, sizeof f);
        if constexpr (std::is_same_v<S, float>) {
            return F::load(f);
        } else {
            S wide[IntLanes<T, F>::size];
            for (int k = 0; k < IntLanes<T, F>::size; ++k) wide[k] = S(f[k]);
            return F::load(wide);
        }
    }
}
// GLSL: the float of a NaN's bits is unspecified; flagged as a NaN made here.
template <class L>
auto bits_float(const Checked<L>& i) -> Checked<typename L::float_type> {
    const typename L::float_type f = bits_float(i.v);
    return {f, i.cases | LaneCases::on(lane_bits(isnan(f)), Undefined::NaN)};
}

}  // namespace qs
