#pragma once
// Checked<L>: a lane type L (Pixels or Quads of float, or their integers, number/integer.h) whose
// values also carry, per lane, the GLSL cases with undefined results that they depend on. It is the number type of the
// undefined-case mask (`quadshade render --undefined-mask`). The cases:
//   NaN             an operation returned NaN from operands that were not NaN (0 / 0, inf - inf,
//                   0 * inf, sqrt(-1), a derivative across a helper lane's inf, ...), or a NaN
//                   came in from outside the fragment shader (a varying, a texel);
//   DivisionByZero  x / 0, and so mod(x, 0), which GLSL defines through x / y; integer x / 0
//                   and x % 0;
//   Argument        a built-in outside the domain where GLSL defines it: smoothstep(e0, e1, x)
//                   with e0 >= e1, clamp(x, lo, hi) with lo > hi, sqrt(x < 0), inversesqrt(x <= 0),
//                   log and log2 (x <= 0), pow(x < 0, y) and pow(0, y <= 0), atan(0, 0),
//                   asin and acos (|x| > 1); and integer operations GLSL leaves undefined: int(x)
//                   and uint(x) of a float outside the integer's range, NaN or (uint) negative,
//                   shifts by a count < 0 or >= 32, % with a negative operand;
//   Overflow        an int division whose quotient does not fit: INT_MIN / -1. GLSL 4.60 (4.1.3)
//                   leaves it undefined ("Division resulting in overflow will result in an
//                   undefined value"; 1.30 to 4.50 wrapped it, GLSL ES 3.00 allows INT_MIN or
//                   INT_MAX, and x86's idiv traps on it). +, - and * of int and uint are not
//                   flagged: from 1.30 on GLSL defines them to wrap ("the low-order 32 bits of the
//                   correct result", 4.60's words), as it defines uint's modular arithmetic.
//
// Every operation computes exactly what L computes, so a checked render has the unchecked
// colours bit for bit. The cases flow with the data, not with control: a result carries the
// union of its operands' cases plus those it hits itself, and select(m, a, b) carries m's cases
// and, lane by lane, those of the operand it picks. So a translated GLSL `if`, evaluated on both
// sides and selected, flags only the side GLSL runs; a case whose value is later multiplied by
// zero or clamped away still flags the pixel, whose value did depend on it. dFdx/dFdy move the
// cases with the values: a helper lane's NaN reaches the pixels whose derivatives it enters.

#include <bit>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "shading/number/lanes.h"

namespace qs {

// The cases, as the bits of a pixel's entry in the mask.
enum class Undefined : std::uint8_t { NaN = 1, DivisionByZero = 2, Argument = 4, Overflow = 8 };
inline constexpr int kUndefinedCases = 4;

// Which cases hit which of up to 16 lanes: bit 16 k + i is case k (the k-th bit of Undefined)
// on lane i, so that a union is one OR and untouched values cost nothing to track. Four cases
// fill the 64 bits.
class LaneCases {
public:
    static constexpr int kMaxLanes = 16;

    LaneCases() = default;
    // Case c on the lanes set in `lanes` (bit i: lane i).
    static LaneCases on(std::uint32_t lanes, Undefined c) {
        return LaneCases(std::uint64_t(lanes & 0xFFFFu) << (16 * std::countr_zero(unsigned(c))));
    }

    friend LaneCases operator|(LaneCases a, LaneCases b) { return LaneCases(a.bits_ | b.bits_); }
    LaneCases& operator|=(LaneCases b) {
        bits_ |= b.bits_;
        return *this;
    }
    bool none() const { return bits_ == 0; }

    // The cases of the lanes set in `lanes` only.
    LaneCases only(std::uint32_t lanes) const {
        return LaneCases(bits_ & (std::uint64_t(lanes & 0xFFFFu) * 0x0001'0001'0001'0001ull));
    }
    // Lane i takes the cases of lane index(i), as Lanes::permute moves values.
    template <class Index>
    LaneCases permute(Index index, int lanes) const {
        if (none()) return *this;
        std::uint64_t moved = 0;
        for (int k = 0; k < kUndefinedCases; ++k) {
            for (int i = 0; i < lanes; ++i) moved |= (bits_ >> (16 * k + int(index(std::size_t(i)))) & 1u) << (16 * k + i);
        }
        return LaneCases(moved);
    }
    // Lane i's cases as Undefined bits.
    std::uint8_t at(int lane) const {
        std::uint8_t r = 0;
        for (int k = 0; k < kUndefinedCases; ++k) r |= std::uint8_t((bits_ >> (16 * k + lane) & 1u) << k);
        return r;
    }

private:
    explicit LaneCases(std::uint64_t bits) : bits_(bits) {}
    std::uint64_t bits_ = 0;
};

// ---- the loops' rule, checked -----------------------------------------------------------------
// A glsl::Loop holds the variables its body assigns (glsl/control.h): the body runs on for the
// lanes that have left the loop, and only the variables the loop holds keep those lanes' values.
// Another variable declared before the loop and assigned in its body goes on changing for them,
// and the image comes out wrong wherever neighbouring fragments leave at different iterations,
// with nothing to say so. The checked instantiation checks every write against the loops running:
// each checked value (Checked, CheckedMask) knows how many loops were running where it was made,
// and a write to one made outside a running loop must fall inside a variable that loop holds.
// A loop runs from its head's first test to its end (the head that ends it, or end()); the
// loops' own bookkeeping (saving and restoring the lanes' values) is not checked.
class LoopWrites {
public:
    struct Held {
        const void* begin;
        const void* end;
    };

    // A loop holding `held` is made (its head not yet tested); returns its place.
    std::size_t enter(std::vector<Held> held) {
        loops_.push_back({std::move(held), nullptr, 0, false});
        return loops_.size() - 1;
    }
    // Its head is tested at file:line: from here on the loop runs.
    void head(std::size_t loop, const char* file, unsigned line) {
        Loop& l = loops_[loop];
        if (!l.running && !l.file) {
            l.file = file, l.line = line, l.running = true;
            ++running_;
        }
    }
    // The loop has ended (its body runs no more); then it is gone.
    void end(std::size_t loop) {
        if (loops_[loop].running) --running_;
        loops_[loop].running = false;
    }
    void leave(std::size_t loop) {
        end(loop);
        loops_.resize(loop);
    }
    // How many loops are running: what a value made here records.
    int running() const { return running_; }

    // A write of `bytes` bytes at `at` to a value made where `made` loops were running. Throws
    // std::logic_error naming the innermost running loop that does not hold it.
    void check(const void* at, std::size_t bytes, int made, const char* what) const {
        if (suspended_ || made >= running_) return;
        const auto* a = static_cast<const std::byte*>(at);
        int seen = 0;
        for (const Loop& l : loops_) {
            if (!l.running || seen++ < made) continue;
            bool held = false;
            for (const Held& h : l.held) held = held || (a >= h.begin && a + bytes <= static_cast<const std::byte*>(h.end));
            if (!held) {
                throw std::logic_error(std::string("a Loop's body writes ") + what + " declared before the loop (" + l.file + ":" +
                                       std::to_string(l.line) +
                                       ") that the loop does not hold: give it to the Loop (Loop loop(x, y, ...)) or declare "
                                       "it inside the body");
            }
        }
    }

    // While one is alive, writes are the loops' own.
    class Suspend {
    public:
        explicit Suspend(LoopWrites& w) : w_(w) { ++w_.suspended_; }
        ~Suspend() { --w_.suspended_; }
        Suspend(const Suspend&) = delete;
        Suspend& operator=(const Suspend&) = delete;

    private:
        LoopWrites& w_;
    };

private:
    struct Loop {
        std::vector<Held> held;
        const char* file;
        unsigned line;
        bool running;
    };
    std::vector<Loop> loops_;  // innermost last
    int running_ = 0;
    int suspended_ = 0;
};
inline thread_local LoopWrites loop_writes;

// A mask's lanes as bits (bit i: lane i).
template <class M>
std::uint32_t lane_bits(const M& m) {
    if (!any(m)) return 0;
    std::uint32_t bits = 0;
    for (int i = 0; i < int(m.size()); ++i) bits |= std::uint32_t(bool(m[i])) << i;
    return bits;
}

// A comparison's mask with the cases of the values compared. M is the unchecked mask, the same
// for float and integer lanes of the same fragments.
template <class M>
struct CheckedMask {
    M m;
    LaneCases cases;

    CheckedMask() = default;
    CheckedMask(const M& mask, LaneCases c) : m(mask), cases(c) {}
    CheckedMask(bool b) : m(b) {}  // NOLINT: GLSL's true and false
    CheckedMask(const CheckedMask& o) : m(o.m), cases(o.cases) {}  // made here, not where o was
    CheckedMask& operator=(const CheckedMask& o) {
        loop_writes.check(this, sizeof *this, made_, "a bool");
        m = o.m, cases = o.cases;
        return *this;
    }

    friend CheckedMask operator&&(const CheckedMask& a, const CheckedMask& b) { return {a.m && b.m, a.cases | b.cases}; }
    friend CheckedMask operator||(const CheckedMask& a, const CheckedMask& b) { return {a.m || b.m, a.cases | b.cases}; }
    friend CheckedMask operator!(const CheckedMask& a) { return {!a.m, a.cases}; }
    // GLSL's == and != of bools; a ^^ b is a != b.
    friend CheckedMask operator==(const CheckedMask& a, const CheckedMask& b) { return {a.m == b.m, a.cases | b.cases}; }
    friend CheckedMask operator!=(const CheckedMask& a, const CheckedMask& b) { return {a.m != b.m, a.cases | b.cases}; }
    friend CheckedMask select(const CheckedMask& s, const CheckedMask& a, const CheckedMask& b) {
        return (s && a) || (!s && b);
    }
    friend bool any(const CheckedMask& a) { return any(a.m); }
    friend bool all(const CheckedMask& a) { return all(a.m); }
    friend bool lane(const CheckedMask& a, int i) { return a.m[i]; }

private:
    int made_ = loop_writes.running();  // loops running where it was made (LoopWrites)
};

namespace checked_detail {
template <class L>
struct layout_of {
    using type = void;  // integer lanes: no derivatives
};
template <class L>
    requires requires { typename L::layout; }
struct layout_of<L> {
    using type = typename L::layout;
};
}  // namespace checked_detail

template <class L>
class Checked {
public:
    using value_type = typename L::value_type;
    using layout = typename checked_detail::layout_of<L>::type;
    using Mask = CheckedMask<typename L::Mask>;
    static constexpr bool is_integer = std::is_integral_v<value_type>;
    static constexpr int size = L::size;
    static_assert(size <= LaneCases::kMaxLanes, "LaneCases holds 16 lanes");

    L v;
    LaneCases cases;

    Checked() = default;
    Checked(const Checked& o) : v(o.v), cases(o.cases) {}  // made here, not where o was (LoopWrites)
    Checked& operator=(const Checked& o) {
        loop_writes.check(this, sizeof *this, made_, !is_integer ? "a float" : std::is_signed_v<value_type> ? "an int" : "a uint");
        v = o.v, cases = o.cases;
        return *this;
    }
    Checked(value_type x) : v(x) {}  // NOLINT: broadcast, as GLSL promotes a literal
    template <class S>
        requires(std::is_arithmetic_v<S> && !std::is_same_v<S, value_type>)
    Checked(S x) : v(x) {}  // NOLINT
    Checked(const L& value, LaneCases c) : v(value), cases(c) {}
    // GLSL's conversions between float and integer lanes (int(x), uint(x), float(i), int(u)):
    // the value as L converts it, with the cases carried, and a float GLSL cannot convert (out
    // of the integer's range after truncation, NaN, negative for uint) flagged as Argument.
    template <class L2>
        requires(!std::is_same_v<L2, L> && std::is_constructible_v<L, const L2&>)
    explicit Checked(const Checked<L2>& o) : v(o.v), cases(o.cases | unconvertible(o.v)) {}
    // float(b), int(b): 1 or 0.
    explicit Checked(const Mask& m) : v(m.m), cases(m.cases) {}

    // Values from outside the shader (varyings, texels): a NaN among them is flagged on entry.
    static Checked load(const value_type* p) {
        const L x = L::load(p);
        if constexpr (is_integer) {
            return {x, LaneCases()};
        } else {
            return {x, LaneCases::on(lane_bits(isnan(x)), Undefined::NaN)};
        }
    }
    void store(value_type* p) const { v.store(p); }
    value_type operator[](int i) const { return v[i]; }

    template <class Index>
    Checked permute(Index index) const {
        return {v.permute(index), cases.permute(index, size)};
    }

    // The result r of an operation on `operands`: their cases, the cases `hit`, and NaN on the
    // lanes where r is NaN and no operand was.
    template <class... Operands>
    static Checked result(const L& r, LaneCases hit, const Operands&... operands) {
        LaneCases c = (hit | ... | operands.cases);
        if constexpr (!is_integer) {
            const auto nan = isnan(r);
            if (any(nan)) c |= LaneCases::on(lane_bits((nan && ... && !isnan(operands.v))), Undefined::NaN);
        }
        return {r, c};
    }
    // A built-in GLSL leaves undefined where `outside` holds, r computed as L computes it.
    template <class... Operands>
    static Checked builtin(const L& r, const Mask& outside, const Operands&... operands) {
        return result(r, outside.cases | LaneCases::on(lane_bits(outside.m), Undefined::Argument), operands...);
    }

    friend Checked operator-(const Checked& a) { return {-a.v, a.cases}; }
    friend Checked operator+(const Checked& a, const Checked& b) { return result(a.v + b.v, {}, a, b); }
    friend Checked operator-(const Checked& a, const Checked& b) { return result(a.v - b.v, {}, a, b); }
    friend Checked operator*(const Checked& a, const Checked& b) { return result(a.v * b.v, {}, a, b); }
    friend Checked exact_product_add(const Checked& a, const Checked& b, const Checked& c) {
        return result(exact_product_add(a.v, b.v, c.v), {}, a, b, c);
    }
    friend Checked operator/(const Checked& a, const Checked& b) {
        LaneCases hit = LaneCases::on(lane_bits(b.v == L(0)), Undefined::DivisionByZero);
        if constexpr (is_integer && std::is_signed_v<value_type>) {
            hit |= LaneCases::on(lane_bits(a.v == L(std::int32_t(INT32_MIN)) && b.v == L(-1)), Undefined::Overflow);
        }
        return result(a.v / b.v, hit, a, b);
    }
    // Integer lanes only. GLSL: x % 0 undefined (as x / 0), % undefined for negative operands,
    // shifts undefined by counts < 0 or >= 32.
    friend Checked operator%(const Checked& a, const Checked& b)
        requires is_integer
    {
        LaneCases hit = LaneCases::on(lane_bits(b.v == L(0)), Undefined::DivisionByZero);
        if constexpr (std::is_signed_v<value_type>) hit |= LaneCases::on(lane_bits(a.v < L(0) || b.v < L(0)), Undefined::Argument);
        return result(a.v % b.v, hit, a, b);
    }
    friend Checked operator&(const Checked& a, const Checked& b) requires is_integer { return result(a.v & b.v, {}, a, b); }
    friend Checked operator|(const Checked& a, const Checked& b) requires is_integer { return result(a.v | b.v, {}, a, b); }
    friend Checked operator^(const Checked& a, const Checked& b) requires is_integer { return result(a.v ^ b.v, {}, a, b); }
    friend Checked operator~(const Checked& a) requires is_integer { return {~a.v, a.cases}; }
    template <class L2>
    friend Checked operator<<(const Checked& a, const Checked<L2>& n) requires is_integer {
        return result(a.v << n.v, bad_count(n.v), a, n);
    }
    template <class L2>
    friend Checked operator>>(const Checked& a, const Checked<L2>& n) requires is_integer {
        return result(a.v >> n.v, bad_count(n.v), a, n);
    }
    friend Checked operator<<(const Checked& a, int n) requires is_integer { return a << Checked(n); }
    friend Checked operator>>(const Checked& a, int n) requires is_integer { return a >> Checked(n); }
    Checked& operator%=(const Checked& b) requires is_integer { return *this = *this % b; }
    Checked& operator&=(const Checked& b) requires is_integer { return *this = *this & b; }
    Checked& operator|=(const Checked& b) requires is_integer { return *this = *this | b; }
    Checked& operator^=(const Checked& b) requires is_integer { return *this = *this ^ b; }
    Checked& operator<<=(int n) requires is_integer { return *this = *this << n; }
    Checked& operator>>=(int n) requires is_integer { return *this = *this >> n; }
    Checked& operator+=(const Checked& b) { return *this = *this + b; }
    Checked& operator-=(const Checked& b) { return *this = *this - b; }
    Checked& operator*=(const Checked& b) { return *this = *this * b; }
    Checked& operator/=(const Checked& b) { return *this = *this / b; }

    friend Mask operator<(const Checked& a, const Checked& b) { return {a.v < b.v, a.cases | b.cases}; }
    friend Mask operator<=(const Checked& a, const Checked& b) { return {a.v <= b.v, a.cases | b.cases}; }
    friend Mask operator>(const Checked& a, const Checked& b) { return {a.v > b.v, a.cases | b.cases}; }
    friend Mask operator>=(const Checked& a, const Checked& b) { return {a.v >= b.v, a.cases | b.cases}; }
    friend Mask operator==(const Checked& a, const Checked& b) { return {a.v == b.v, a.cases | b.cases}; }
    friend Mask operator!=(const Checked& a, const Checked& b) { return {a.v != b.v, a.cases | b.cases}; }

    friend Checked select(const Mask& m, const Checked& a, const Checked& b) {
        LaneCases c = m.cases;
        if (!a.cases.none() || !b.cases.none()) {
            const std::uint32_t picked = lane_bits(m.m);
            c |= a.cases.only(picked) | b.cases.only(~picked);
        }
        return {select(m.m, a.v, b.v), c};
    }
    friend Mask isnan(const Checked& a) { return {isnan(a.v), a.cases}; }
    friend Mask isinf(const Checked& a) { return {isinf(a.v), a.cases}; }
    friend Checked min(const Checked& a, const Checked& b) { return result(min(a.v, b.v), {}, a, b); }
    friend Checked max(const Checked& a, const Checked& b) { return result(max(a.v, b.v), {}, a, b); }

    friend Checked floor(const Checked& a) { return result(floor(a.v), {}, a); }
    friend Checked ceil(const Checked& a) { return result(ceil(a.v), {}, a); }
    friend Checked trunc(const Checked& a) { return result(trunc(a.v), {}, a); }
    friend Checked roundEven(const Checked& a) { return result(roundEven(a.v), {}, a); }
    friend Checked abs(const Checked& a) { return result(abs(a.v), {}, a); }
    friend Checked sin(const Checked& a) { return result(sin(a.v), {}, a); }
    friend Checked cos(const Checked& a) { return result(cos(a.v), {}, a); }
    friend Checked tan(const Checked& a) { return result(tan(a.v), {}, a); }
    friend Checked atan(const Checked& a) { return result(atan(a.v), {}, a); }
    friend Checked exp(const Checked& a) { return result(exp(a.v), {}, a); }
    friend Checked exp2(const Checked& a) { return result(exp2(a.v), {}, a); }
    // GLSL: undefined if x < 0 (sqrt), x <= 0 (log, log2), x < 0 or x = 0 and y <= 0 (pow),
    // x = y = 0 (atan(y, x)).
    friend Checked sqrt(const Checked& a) { return builtin(sqrt(a.v), a < Checked(0.0f), a); }
    // GLSL: asin and acos undefined for |x| > 1.
    friend Checked asin(const Checked& a) { return builtin(asin(a.v), abs(a) > Checked(1.0f), a); }
    friend Checked acos(const Checked& a) { return builtin(acos(a.v), abs(a) > Checked(1.0f), a); }
    friend Checked log(const Checked& a) { return builtin(log(a.v), a <= Checked(0.0f), a); }
    friend Checked log2(const Checked& a) { return builtin(log2(a.v), a <= Checked(0.0f), a); }
    friend Checked pow(const Checked& a, const Checked& b) {
        return builtin(pow(a.v, b.v), a < Checked(0.0f) || (a == Checked(0.0f) && b <= Checked(0.0f)), a, b);
    }
    friend Checked atan(const Checked& y, const Checked& x) {
        return builtin(atan(y.v, x.v), y == Checked(0.0f) && x == Checked(0.0f), y, x);
    }

    friend value_type lane(const Checked& a, int i) { return a.v[i]; }

private:
    int made_ = loop_writes.running();  // loops running where it was made (LoopWrites)

    // The lanes of a shift count GLSL leaves undefined.
    template <class N>
    static LaneCases bad_count(const N& n) {
        const auto bad = std::is_signed_v<typename N::value_type> ? (n < N(0) || n > N(31)) : n > N(31);
        return LaneCases::on(lane_bits(bad), Undefined::Argument);
    }
    // The lanes of x that int(x) or uint(x) (L's type) leaves undefined; none for other conversions.
    template <class L2>
    static LaneCases unconvertible(const L2& x) {
        if constexpr (is_integer && std::is_floating_point_v<typename L2::value_type>) {
            using S = typename L2::value_type;
            const auto defined = std::is_signed_v<value_type> ? (x > L2(S(-2147483649.0)) && x < L2(S(2147483648.0)))
                                                              : (x >= L2(S(0.0)) && x < L2(S(4294967296.0)));
            return LaneCases::on(lane_bits(!defined), Undefined::Argument);
        } else {
            return {};
        }
    }
};

}  // namespace qs
