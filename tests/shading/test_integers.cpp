// GLSL int and uint on every number type, lane by lane against a scalar oracle written here in
// plain 64-bit C++ (not sharing code with number/integer.h): arithmetic that wraps, division
// and remainder with llvmpipe's answers where GLSL has none, shifts, comparisons into the float
// mask, conversions both ways, bits of floats and per-lane table lookups.
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "tests/shading/number_types.h"

namespace qs::glsl {
using test::from_values;
using test::lanes_of;
using test::scalar_t;

namespace {

// ---- the oracle ---------------------------------------------------------------------------
std::uint32_t wrap(std::int64_t x) { return std::uint32_t(std::uint64_t(x) & 0xFFFFFFFFull); }
std::int32_t as_int(std::uint32_t u) { return u >= 0x80000000u ? std::int32_t(std::int64_t(u) - 0x100000000ll) : std::int32_t(u); }

// int / int: 0 for a zero divisor, INT_MIN / -1 wraps.
std::int32_t oracle_div(std::int32_t a, std::int32_t b) {
    if (b == 0) return 0;
    return as_int(wrap(std::int64_t(a) / std::int64_t(b)));  // C++ truncates, as GLSL
}
std::uint32_t oracle_udiv(std::uint32_t a, std::uint32_t b) { return b == 0 ? 0xFFFFFFFFu : a / b; }
// % of the bits as unsigned (Mesa), 0xFFFFFFFF for a zero divisor.
std::uint32_t oracle_urem(std::uint32_t a, std::uint32_t b) { return b == 0 ? 0xFFFFFFFFu : a % b; }
std::int32_t oracle_rem(std::int32_t a, std::int32_t b) { return as_int(oracle_urem(std::uint32_t(a), std::uint32_t(b))); }
std::uint32_t oracle_shl(std::uint32_t a, std::uint32_t n) { return wrap(std::int64_t(std::uint64_t(a) << (n & 31))); }
std::uint32_t oracle_ushr(std::uint32_t a, std::uint32_t n) { return a >> (n & 31); }
std::int32_t oracle_ishr(std::int32_t a, std::uint32_t n) {
    const std::int64_t x = a;
    return std::int32_t(x >> (n & 31));  // arithmetic on a non-negative count
}
// int(x): truncation, INT_MIN out of range and for NaN.
std::int32_t oracle_int(double x) {
    if (!(x > -2147483649.0 && x < 2147483648.0)) return std::numeric_limits<std::int32_t>::min();
    return std::int32_t(std::trunc(x));
}
// uint(x): int(x) | (int(x - 2^31) & sign of int(x)).
std::uint32_t oracle_uint(double x) {
    const std::uint32_t i = std::uint32_t(oracle_int(x)), high = std::uint32_t(oracle_int(x - 2147483648.0));
    return i | ((i & 0x80000000u) ? high : 0u);
}

const std::vector<std::int64_t> kInts = {0, 1, -1, 2, -2, 3, -3, 7, -7, 8, -8, 31, 32, 33, -33, 255, 256, 0xFFFF, 65536,
                                         12345678, -98765432, 2147483647, -2147483648ll, -2147483647, 1000003, -46341};

template <class I>
I ints(const std::vector<std::int64_t>& v, std::size_t base) {
    using T = typename I::value_type;
    T tmp[I::size];
    for (int k = 0; k < I::size; ++k) tmp[k] = T(wrap(v[(base + std::size_t(k)) % v.size()]));
    return I::load(tmp);
}

template <class I>
std::int64_t at(const I& x, int k) { return std::int64_t(lane(x, k)); }

template <class M>
bool mask_at(const M& m, int k) {
    if constexpr (is_checked_mask<M>::value) {
        return lane(m.m, k);
    } else {
        return lane(m, k);
    }
}

// Every pair (a, b) of kInts, lane by lane: op on the lanes against the oracle.
template <class I, class Op, class Oracle>
void check_pairs(Op op, Oracle oracle, const char* what) {
    using T = typename I::value_type;
    const std::size_t n = kInts.size();
    for (std::size_t shift = 0; shift < n; ++shift) {
        std::vector<std::int64_t> second(n);
        for (std::size_t i = 0; i < n; ++i) second[i] = kInts[(i + shift) % n];
        for (std::size_t base = 0; base < n; base += std::size_t(I::size)) {
            const I a = ints<I>(kInts, base), b = ints<I>(second, base);
            const auto r = op(a, b);
            for (int k = 0; k < I::size; ++k) {
                const T x = T(wrap(kInts[(base + std::size_t(k)) % n])), y = T(wrap(second[(base + std::size_t(k)) % n]));
                INFO(what << "(" << std::int64_t(x) << ", " << std::int64_t(y) << ") lane " << k);
                CHECK(std::int64_t(lane(r, k)) == std::int64_t(oracle(x, y)));
            }
        }
    }
}

}  // namespace

#define NUMBER_TYPES float, double, (Pixels<float, 16>), (Quads<float, 4>), (Pixels<double, 8>), Dual2<float>, \
                     (Dual2<Pixels<float, 16>>), (Checked<Pixels<float, 16>>), (Checked<Quads<float, 4>>)

TEMPLATE_TEST_CASE("int arithmetic wraps and divides as llvmpipe, lane by lane", "[integers]", NUMBER_TYPES) {
    using I = int_t<TestType>;
    using S = std::int32_t;
    check_pairs<I>(std::plus<>(), [](S a, S b) { return as_int(wrap(std::int64_t(a) + b)); }, "+");
    check_pairs<I>(std::minus<>(), [](S a, S b) { return as_int(wrap(std::int64_t(a) - b)); }, "-");
    check_pairs<I>(std::multiplies<>(), [](S a, S b) { return as_int(wrap(std::int64_t(a) * b)); }, "*");
    check_pairs<I>([](const I& a, const I& b) { return a / b; }, oracle_div, "/");
    check_pairs<I>([](const I& a, const I& b) { return a % b; }, oracle_rem, "%");
    check_pairs<I>([](const I& a, const I&) { return -a; }, [](S a, S) { return as_int(wrap(-std::int64_t(a))); }, "negate");
    check_pairs<I>([](const I& a, const I&) { return abs(a); }, [](S a, S) { return as_int(wrap(a < 0 ? -std::int64_t(a) : a)); }, "abs");
    check_pairs<I>([](const I& a, const I& b) { return min(a, b); }, [](S a, S b) { return std::min(a, b); }, "min");
    check_pairs<I>([](const I& a, const I& b) { return max(a, b); }, [](S a, S b) { return std::max(a, b); }, "max");
    check_pairs<I>([](const I& a, const I&) { return sign(a); }, [](S a, S) { return S((a > 0) - (a < 0)); }, "sign");
    check_pairs<I>([](const I& a, const I& b) { return clamp(a, min(b, I(7)), I(7)); },
                   [](S a, S b) { return std::min(std::max(a, std::min(b, 7)), 7); }, "clamp");
}

TEMPLATE_TEST_CASE("uint arithmetic wraps and divides as llvmpipe, lane by lane", "[integers]", NUMBER_TYPES) {
    using U = uint_t<TestType>;
    using S = std::uint32_t;
    check_pairs<U>(std::plus<>(), [](S a, S b) { return wrap(std::int64_t(a) + b); }, "+");
    check_pairs<U>(std::minus<>(), [](S a, S b) { return wrap(std::int64_t(a) - b); }, "-");
    check_pairs<U>(std::multiplies<>(), [](S a, S b) { return wrap(std::int64_t(std::uint64_t(a) * b)); }, "*");
    check_pairs<U>([](const U& a, const U& b) { return a / b; }, oracle_udiv, "/");
    check_pairs<U>([](const U& a, const U& b) { return a % b; }, oracle_urem, "%");
    check_pairs<U>([](const U& a, const U& b) { return min(a, b); }, [](S a, S b) { return std::min(a, b); }, "min");
    check_pairs<U>([](const U& a, const U& b) { return max(a, b); }, [](S a, S b) { return std::max(a, b); }, "max");
}

TEMPLATE_TEST_CASE("bit operations and shifts (count's low five bits) on int and uint", "[integers]", NUMBER_TYPES) {
    using I = int_t<TestType>;
    using U = uint_t<TestType>;
    check_pairs<I>(std::bit_and<>(), [](std::int32_t a, std::int32_t b) { return a & b; }, "&");
    check_pairs<I>(std::bit_or<>(), [](std::int32_t a, std::int32_t b) { return a | b; }, "|");
    check_pairs<I>(std::bit_xor<>(), [](std::int32_t a, std::int32_t b) { return a ^ b; }, "^");
    check_pairs<U>([](const U& a, const U&) { return ~a; }, [](std::uint32_t a, std::uint32_t) { return ~a; }, "~");
    check_pairs<I>([](const I& a, const I& b) { return a << b; },
                   [](std::int32_t a, std::int32_t b) { return as_int(oracle_shl(std::uint32_t(a), std::uint32_t(b))); }, "<<");
    check_pairs<I>([](const I& a, const I& b) { return a >> b; },
                   [](std::int32_t a, std::int32_t b) { return oracle_ishr(a, std::uint32_t(b)); }, ">>");
    check_pairs<U>([](const U& a, const U& b) { return a << b; }, oracle_shl, "<<");
    check_pairs<U>([](const U& a, const U& b) { return a >> b; }, oracle_ushr, ">>");
    // A count of the other signedness, and counts the same for every lane.
    check_pairs<U>([](const U& a, const U& b) { return a >> I(b); }, oracle_ushr, "uint >> int");
    check_pairs<I>([](const I& a, const I&) { return a >> 33; }, [](std::int32_t a, std::int32_t) { return oracle_ishr(a, 33); }, ">> 33");
    check_pairs<U>([](const U& a, const U&) { return a << 4u; }, [](std::uint32_t a, std::uint32_t) { return oracle_shl(a, 4); }, "<< 4u");
}

TEMPLATE_TEST_CASE("integer comparisons are the float type's masks, and select on them", "[integers]", NUMBER_TYPES) {
    using F = TestType;
    using I = int_t<F>;
    using U = uint_t<F>;
    static_assert(std::is_same_v<decltype(I() < I()), Bool<F>>);
    static_assert(std::is_same_v<decltype(U() < U()), Bool<F>>);
    const std::size_t n = kInts.size();
    for (std::size_t base = 0; base < n; base += std::size_t(I::size)) {
        std::vector<std::int64_t> other(kInts.rbegin(), kInts.rend());
        const I a = ints<I>(kInts, base), b = ints<I>(other, base);
        const U ua(a), ub(b);
        const Bool<F> lt = a < b, ult = ua < ub, eq = a == b, ne = a != b, ge = a >= b;
        const I picked = select(lt, a, b);
        const F fpicked = select(ult, F(1.0f), F(2.0f));
        for (int k = 0; k < I::size; ++k) {
            const std::int32_t x = as_int(wrap(kInts[(base + std::size_t(k)) % n])), y = as_int(wrap(other[(base + std::size_t(k)) % n]));
            CHECK(mask_at(lt, k) == (x < y));
            CHECK(mask_at(ult, k) == (std::uint32_t(x) < std::uint32_t(y)));
            CHECK(mask_at(eq, k) == (x == y));
            CHECK(mask_at(ne, k) == (x != y));
            CHECK(mask_at(ge, k) == (x >= y));
            CHECK(at(picked, k) == std::min(x, y));
            CHECK(double(lane(fpicked, k)) == (std::uint32_t(x) < std::uint32_t(y) ? 1.0 : 2.0));
        }
    }
}

TEMPLATE_TEST_CASE("int(x) and uint(x) truncate, with llvmpipe's answers out of range, float(i) rounds", "[integers]", NUMBER_TYPES) {
    using F = TestType;
    using I = int_t<F>;
    using U = uint_t<F>;
    using S = scalar_t<F>;
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    std::vector<double> xs = {0.0, -0.0, 0.5, -0.5, 0.99, -0.99, 1.5, -1.5, 2.5, -2.5, 7.75, -7.75, 16777217.0, 2147483520.0,
                              -2147483648.0, 2147483648.0, 3e9, -3e9, 4294967040.0, 4294967296.0, 5e9, 1e10, -1e10,
                              nan, inf, -inf, 123456.789, -98765.4321};
    while (xs.size() % std::size_t(lanes_of<F>())) xs.push_back(1.0);
    for (std::size_t base = 0; base < xs.size(); base += std::size_t(lanes_of<F>())) {
        const F x = from_values<F>(&xs[base]);
        const I i(x);
        const U u(x);
        for (int k = 0; k < lanes_of<F>(); ++k) {
            const double v = double(S(xs[base + std::size_t(k)]));
            INFO("x = " << v << " lane " << k);
            CHECK(at(i, k) == oracle_int(v));
            CHECK(std::uint32_t(at(u, k)) == oracle_uint(v));
        }
    }
    // float(i) and float(u): exact to 2^24, rounded to nearest above.
    for (std::size_t base = 0; base < kInts.size(); base += std::size_t(I::size)) {
        const I i = ints<I>(kInts, base);
        const U u(i);
        const F fi(i), fu(u);
        for (int k = 0; k < I::size; ++k) {
            const std::int32_t x = as_int(wrap(kInts[(base + std::size_t(k)) % kInts.size()]));
            CHECK(double(lane(fi, k)) == double(S(x)));
            CHECK(double(lane(fu, k)) == double(S(std::uint32_t(x))));
        }
    }
}

TEMPLATE_TEST_CASE("bits of floats: floatBitsToInt, floatBitsToUint and back", "[integers]", NUMBER_TYPES) {
    using F = TestType;
    std::vector<double> xs = {0.0, -0.0, 1.0, -1.0, 0.1, 3.4e38, -1e-30, std::numeric_limits<double>::infinity(), 0.5, 123.25};
    while (xs.size() % std::size_t(lanes_of<F>())) xs.push_back(2.0);
    for (std::size_t base = 0; base < xs.size(); base += std::size_t(lanes_of<F>())) {
        const F x = from_values<F>(&xs[base]);
        const auto i = floatBitsToInt(x);
        const auto u = floatBitsToUint(x);
        const F back = intBitsToFloat(i), uback = uintBitsToFloat(u ^ uint_t<F>(0x80000000u));
        for (int k = 0; k < lanes_of<F>(); ++k) {
            const float f = float(xs[base + std::size_t(k)]);
            CHECK(at(i, k) == std::bit_cast<std::int32_t>(f));
            CHECK(std::uint32_t(at(u, k)) == std::bit_cast<std::uint32_t>(f));
            CHECK(std::bit_cast<std::uint32_t>(float(lane(back, k))) == std::bit_cast<std::uint32_t>(f));
            CHECK(double(lane(uback, k)) == double(-f));
        }
    }
}

TEMPLATE_TEST_CASE("a constant table read per lane (a permutation), 0 outside it", "[integers]", NUMBER_TYPES) {
    using F = TestType;
    using I = int_t<F>;
    static constexpr table<int, 7> perm{{5, 3, 6, 0, 2, 4, 1}};
    static constexpr table<float, 3> weights{{0.25f, -1.5f, 8.0f}};
    static constexpr table<unsigned, 2> masks{{0xFFFF0000u, 0x0000FFFFu}};
    const std::vector<std::int64_t> indices = {0, 1, 2, 3, 4, 5, 6, 7, -1, 1000, 6, 5, 4, 3, 2, 1, 0, -2147483648ll, 2147483647};
    for (std::size_t base = 0; base < indices.size(); base += std::size_t(I::size)) {
        const I i = ints<I>(indices, base);
        const I p = perm[i];
        const F w = weights[i];
        const uint_t<F> m = masks[uint_t<F>(i)];
        for (int k = 0; k < I::size; ++k) {
            const std::int64_t x = as_int(wrap(indices[(base + std::size_t(k)) % indices.size()]));
            INFO("index " << x);
            CHECK(at(p, k) == (x >= 0 && x < 7 ? perm[std::size_t(x)] : 0));
            CHECK(double(lane(w, k)) == (x >= 0 && x < 3 ? double(weights[std::size_t(x)]) : 0.0));
            CHECK(std::uint32_t(at(m, k)) == (x >= 0 && x < 2 ? masks[std::size_t(x)] : 0u));
        }
    }
}

TEST_CASE("integer vectors: componentwise operators, conversions and swizzles", "[integers]") {
    using F = Pixels<float, 16>;
    const ivec3<F> a(int_t<F>(7), int_t<F>(-8), int_t<F>(255));
    const ivec3<F> b = (a * 3 + 1) % 5 ^ (a << 2) & ivec3<F>(int_t<F>(0xFF));
    const uvec3<F> u(b);
    const vec3<F> f(u.zxy());
    const ivec3<F> back(f);
    for (int k = 0; k < 16; k += 5) {
        // C++ and GLSL alike: % before ^, & before ^; % on the bits as unsigned.
        CHECK(lane(b.x, k) == (oracle_rem(7 * 3 + 1, 5) ^ ((7 << 2) & 0xFF)));
        CHECK(lane(b.y, k) == (oracle_rem(-8 * 3 + 1, 5) ^ (as_int(oracle_shl(std::uint32_t(-8), 2)) & 0xFF)));
        CHECK(lane(f.y, k) == float(lane(b.x, k)));
        CHECK(lane(back.z, k) == lane(b.y, k));
    }
}

TEST_CASE("Checked integers flag GLSL's undefined integer cases, lane by lane", "[integers][undefined]") {
    using P = Checked<Pixels<float, 16>>;
    using I = int_t<P>;
    using U = uint_t<P>;
    constexpr std::uint8_t kDivision = std::uint8_t(Undefined::DivisionByZero), kArgument = std::uint8_t(Undefined::Argument);
    auto lanes = [](std::initializer_list<std::int32_t> v) {
        std::int32_t x[16] = {};
        std::size_t k = 0;
        for (std::int32_t e : v) x[k++] = e;
        return I::load(x);
    };
    const I a = lanes({7, 7, -7, 7, 1, 1, 1, 1}), b = lanes({0, 2, 3, -3, 31, 32, -1, 0});
    const I q = a / b, r = a % b;
    CHECK(q.cases.at(0) == kDivision);
    CHECK(q.cases.at(1) == 0);
    CHECK(r.cases.at(0) == kDivision);
    CHECK(r.cases.at(2) == kArgument);  // % of a negative operand
    CHECK(r.cases.at(3) == kArgument);
    CHECK(r.cases.at(1) == 0);
    const I s = a << b;
    CHECK(s.cases.at(4) == 0);          // << 31
    CHECK(s.cases.at(5) == kArgument);  // << 32
    CHECK(s.cases.at(6) == kArgument);  // << -1
    const U us = U(a) >> U(b);
    CHECK(us.cases.at(5) == kArgument);
    CHECK(us.cases.at(4) == 0);
    // Conversions of floats outside the integer's range, NaN, and negative floats to uint.
    float xs[16] = {1.5f, -1.5f, 3e9f, -3e9f, std::numeric_limits<float>::quiet_NaN(), 5e9f, -0.5f, 2147483520.0f};
    const P x = P::load(xs);
    const I i(x);
    const U u(x);
    const std::uint8_t kNaN = std::uint8_t(Undefined::NaN);
    CHECK(i.cases.at(0) == 0);
    CHECK(i.cases.at(1) == 0);
    CHECK(i.cases.at(2) == kArgument);
    CHECK(i.cases.at(3) == kArgument);
    CHECK(i.cases.at(4) == (kArgument | kNaN));  // the NaN came in as a varying, and int(NaN) is undefined
    CHECK(i.cases.at(7) == 0);
    CHECK(u.cases.at(0) == 0);
    CHECK(u.cases.at(1) == kArgument);
    CHECK(u.cases.at(2) == 0);  // 3e9 fits a uint
    CHECK(u.cases.at(5) == kArgument);
    CHECK(u.cases.at(6) == kArgument);  // GLSL: negative floats have no uint
    // The cases flow on through integer arithmetic and back to floats.
    const P back = P((i + 1) * 2);
    CHECK(back.cases.at(2) == kArgument);
    CHECK(back.cases.at(0) == 0);
    // A table read outside the table.
    static constexpr table<int, 4> t{{1, 2, 3, 4}};
    const I looked = t[lanes({0, 3, 4, -1})];
    CHECK(looked.cases.at(1) == 0);
    CHECK(looked.cases.at(2) == kArgument);
    CHECK(looked.cases.at(3) == kArgument);
    CHECK(lane(looked, 2) == 0);
}

TEST_CASE("Checked integers flag int division's overflow, and no wrap GLSL defines", "[integers][undefined]") {
    using P = Checked<Pixels<float, 16>>;
    using I = int_t<P>;
    using U = uint_t<P>;
    constexpr std::uint8_t kOverflow = std::uint8_t(Undefined::Overflow);
    auto lanes = [](std::initializer_list<std::int32_t> v) {
        std::int32_t x[16] = {};
        std::size_t k = 0;
        for (std::int32_t e : v) x[k++] = e;
        return I::load(x);
    };
    const I a = lanes({INT32_MIN, INT32_MIN, INT32_MAX, -7, INT32_MIN}), b = lanes({-1, 1, -1, -1, 2});
    const I q = a / b;
    CHECK(q.cases.at(0) == kOverflow);  // INT_MIN / -1: GLSL 4.60 leaves it undefined
    CHECK(lane(q, 0) == INT32_MIN);     // llvmpipe's answer, computed as the unchecked lanes compute it
    for (int i = 1; i < 5; ++i) CHECK(q.cases.at(i) == 0);
    // +, - and * wrap as GLSL defines them, for int and uint alike; uint has no such division.
    const I sum = a + a, difference = a - lanes({1}), product = a * a;
    const U u = U(a), wrapped = u * u + U(0xFFFFFFFFu), quotient = u / U(0xFFFFFFFFu);
    for (int i = 0; i < 16; ++i) {
        CHECK(sum.cases.at(i) == 0);
        CHECK(difference.cases.at(i) == 0);
        CHECK(product.cases.at(i) == 0);
        CHECK(wrapped.cases.at(i) == 0);
        CHECK((quotient.cases.at(i) & kOverflow) == 0);
    }
    CHECK(lane(sum, 0) == 0);
    CHECK(lane(difference, 0) == INT32_MAX);
}

}  // namespace qs::glsl
