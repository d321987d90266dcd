// The GLSL vocabulary beyond arithmetic, on every number type, lane by lane against oracles
// written here in plain scalar C++ (GLM where it computes what GLSL defines): the rounding, angle
// and inverse trigonometric built-ins, reflect, refract and faceforward, bools and bvecs, loops
// that leave per lane (break, continue, return, nested), discard, matrices of every shape and
// write swizzles. Mesa's own answers for the same operations are the probes in
// tests/reference/test_reference.cpp.
#include <catch2/catch.hpp>

#include <cfenv>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_access.hpp>

#include "shading/program_of.h"
#include "tests/shading/number_types.h"

namespace qs::glsl {
using test::from_values;
using test::lanes_of;
using test::same;
using test::scalar_t;
using test::value_at;

namespace {

// Inputs spread over the lanes: halves for the rounding ties, [-1, 1] for asin and acos.
const std::vector<double> kInputs = {-3.5, -2.5, -1.5, -1.0, -0.75, -0.5, -0.25, -0.0, 0.0, 0.25, 0.5, 0.75, 1.0,
                                     1.5,  2.5,  3.5,  4.5,  -4.5,  0.3,  -0.7,  7.25, 100.5, -1e-3, 0.999, -0.999};

template <class F>
std::vector<double> padded(std::vector<double> v) {
    while (v.size() % std::size_t(lanes_of<F>())) v.push_back(0.125);
    return v;
}

// op on the lanes of F against oracle on each lane's scalar, within `relative` (0: exactly).
template <class F, class Op, class Oracle>
void check_lanes(const std::vector<double>& inputs, Op op, Oracle oracle, double relative, const char* what) {
    using S = scalar_t<F>;
    const std::vector<double> in = padded<F>(inputs);
    for (std::size_t base = 0; base < in.size(); base += std::size_t(lanes_of<F>())) {
        const F r = op(from_values<F>(&in[base]));
        for (int k = 0; k < lanes_of<F>(); ++k) {
            const double want = double(oracle(S(in[base + std::size_t(k)])));
            const double got = value_at(r, k);
            INFO(what << "(" << in[base + std::size_t(k)] << ") lane " << k << ": " << got << " want " << want);
            if (relative == 0.0 || !std::isfinite(want)) {
                CHECK(same(got, want));
            } else {
                CHECK(std::abs(got - want) <= relative * std::max(1.0, std::abs(want)));
            }
        }
    }
}

// Lane k of a number type holding base + k * step.
template <class F>
F ramp(double base, double step) {
    std::vector<double> v(std::size_t(lanes_of<F>()));
    for (std::size_t k = 0; k < v.size(); ++k) v[k] = base + double(k) * step;
    return from_values<F>(v.data());
}

}  // namespace

#define NUMBER_TYPES float, double, (Pixels<float, 16>), (Quads<float, 4>), (Pixels<double, 8>), Dual2<float>, \
                     (Dual2<Pixels<float, 16>>), (Checked<Pixels<float, 16>>), (Checked<Quads<float, 4>>)

// Within a float's rounding of the exact value (for double instantiations: of the float constant
// GLSL's float arithmetic uses), and a few ulps for the inverse trigonometric functions.
constexpr double kOneRounding = 1.2e-7, kTrigonometric = 4e-7;

TEMPLATE_TEST_CASE("rounding, angle and inverse trigonometric built-ins equal their definitions lane by lane", "[builtins]",
                   NUMBER_TYPES) {
    using F = TestType;
    REQUIRE(std::fegetround() == FE_TONEAREST);
    check_lanes<F>(kInputs, [](F x) { return trunc(x); }, [](auto x) { return std::trunc(x); }, 0.0, "trunc");
    // round: GLSL lets halves go either way; Mesa (and quadshade) round them to even.
    check_lanes<F>(kInputs, [](F x) { return roundEven(x); }, [](auto x) { return std::nearbyint(x); }, 0.0, "roundEven");
    check_lanes<F>(kInputs, [](F x) { return round(x); }, [](auto x) { return std::nearbyint(x); }, 0.0, "round");
    check_lanes<F>(kInputs, [](F x) { return radians(x); }, [](auto x) { return double(x) * std::numbers::pi / 180.0; },
                   kOneRounding, "radians");
    check_lanes<F>(kInputs, [](F x) { return degrees(x); }, [](auto x) { return double(x) * 180.0 / std::numbers::pi; },
                   kOneRounding, "degrees");
    std::vector<double> unit;
    for (double x : kInputs) if (std::abs(x) <= 1.0) unit.push_back(x);
    check_lanes<F>(unit, [](F x) { return asin(x); }, [](auto x) { return std::asin(double(x)); }, kTrigonometric, "asin");
    check_lanes<F>(unit, [](F x) { return acos(x); }, [](auto x) { return std::acos(double(x)); }, kTrigonometric, "acos");
    check_lanes<F>(kInputs, [](F x) { return atan(x); }, [](auto x) { return std::atan(double(x)); }, kTrigonometric, "atan");
    check_lanes<F>(kInputs, [](F x) { return tan(x * 0.5f); }, [](auto x) { return std::tan(double(x * decltype(x)(0.5))); },
                   kTrigonometric, "tan");
    check_lanes<F>(kInputs, [](F x) { return atan(x, F(-0.5f)); }, [](auto x) { return std::atan2(double(x), -0.5); },
                   kTrigonometric, "atan2");
    // modf: the fraction and the whole part, both with x's sign.
    check_lanes<F>(kInputs, [](F x) { F i; return modf(x, i); }, [](auto x) { return x - std::trunc(x); }, 0.0, "modf fraction");
    check_lanes<F>(kInputs, [](F x) { F i; modf(x, i); return i; }, [](auto x) { return std::trunc(x); }, 0.0, "modf whole");
}

TEMPLATE_TEST_CASE("reflect, refract and faceforward equal GLM's, total internal reflection included", "[builtins]", NUMBER_TYPES) {
    using F = TestType;
    using S = scalar_t<F>;
    using G = glm::vec<3, S>;
    // Per lane: an incident direction sweeping from grazing to head-on, a fixed normal.
    const vec3<F> I = vec3<F>(ramp<F>(-0.9, 0.11), F(-1.0f), ramp<F>(0.3, -0.05));
    const vec3<F> N = normalize(vec3<F>(0.25f, 1.0f, -0.125f));
    const F eta = ramp<F>(0.6, 0.09);  // past 1: total internal reflection at grazing lanes
    const vec3<F> r = reflect(I, N), t = refract(normalize(I), N, eta), f = faceforward(N, I, vec3<F>(ramp<F>(-1.0, 0.2), F(0.5f), F(0.0f)));
    int reflected_totally = 0;
    for (int k = 0; k < lanes_of<F>(); ++k) {
        const G gi(S(lane(I.x, k)), S(lane(I.y, k)), S(lane(I.z, k))), gn(S(lane(N.x, k)), S(lane(N.y, k)), S(lane(N.z, k)));
        const G nref(S(-1.0 + 0.2 * k), S(0.5), S(0.0));
        const G want_r = glm::reflect(gi, gn), want_t = glm::refract(glm::normalize(gi), gn, S(lane(eta, k)));
        const G want_f = glm::faceforward(gn, gi, nref);
        reflected_totally += want_t == G(S(0));
        for (int c = 0; c < 3; ++c) {
            INFO("lane " << k << " component " << c);
            CHECK(std::abs(value_at(r[c], k) - double(want_r[c])) <= 4e-7 * std::max(1.0, std::abs(double(want_r[c]))));
            CHECK(std::abs(value_at(t[c], k) - double(want_t[c])) <= 4e-6);
            CHECK(value_at(f[c], k) == double(want_f[c]));  // a sign chosen: exact
        }
    }
    if (lanes_of<F>() >= 16) CHECK(reflected_totally > 0);
}

TEMPLATE_TEST_CASE("bools and bvecs: && || ! ^^ == != any all not and mix by a bvec, lane by lane", "[booleans]", NUMBER_TYPES) {
    using F = TestType;
    using B = Bool<F>;
    const F x = ramp<F>(-3.0, 0.5), y = ramp<F>(2.0, -0.25);
    const B a = x < 0.0f, b = y > 1.0f, c = mod(x, F(1.5f)) == 0.0f;
    const B and_ = a && b, or_ = a || c, not_ = !a, xor_ = a != b, eq = b == c;
    const bvec3<F> v(a, b, c), w = lessThan(vec3<F>(x, y, x + y), vec3<F>(F(0.0f), F(1.0f), F(0.5f)));
    const B any_v = any(v), all_v = all(v), all_w = all(not(w)), same_vw = v == w, differ_vw = v != w;
    const bvec3<F> ne = notEqual(vec3<F>(x), vec3<F>(y, x, -x)), ge = greaterThanEqual(vec3<F>(x), vec3<F>(y, x, -x));
    const vec3<F> m = mix(vec3<F>(1.0f, 2.0f, 3.0f), vec3<F>(-1.0f, -2.0f, -3.0f), w);
    const F as_float = F(and_) + 2.0f * F(xor_);  // float(b): 1.0 or 0.0
    for (int k = 0; k < lanes_of<F>(); ++k) {
        const double sx = value_at(x, k), sy = value_at(y, k);
        const bool A = sx < 0.0, Bb = sy > 1.0, C = std::fmod(sx, 1.5) == 0.0;
        const bool W[3] = {sx < 0.0, sy < 1.0, value_at(x + y, k) < 0.5};
        INFO("lane " << k << " x " << sx << " y " << sy);
        CHECK(lane(and_, k) == (A && Bb));
        CHECK(lane(or_, k) == (A || C));
        CHECK(lane(not_, k) == !A);
        CHECK(lane(xor_, k) == (A != Bb));
        CHECK(lane(eq, k) == (Bb == C));
        CHECK(lane(any_v, k) == (A || Bb || C));
        CHECK(lane(all_v, k) == (A && Bb && C));
        CHECK(lane(all_w, k) == (!W[0] && !W[1] && !W[2]));
        CHECK(lane(same_vw, k) == (A == W[0] && Bb == W[1] && C == W[2]));
        CHECK(lane(differ_vw, k) == !(A == W[0] && Bb == W[1] && C == W[2]));
        CHECK(lane(ne.x, k) == (sx != sy));
        CHECK(lane(ne.y, k) == false);
        CHECK(lane(ne.z, k) == (sx != -sx));
        CHECK(lane(ge.x, k) == (sx >= sy));
        CHECK(lane(ge.z, k) == (sx >= -sx));
        for (int i = 0; i < 3; ++i) CHECK(value_at(m[i], k) == (W[i] ? -(i + 1.0) : i + 1.0));
        CHECK(value_at(as_float, k) == double(A && Bb) + 2.0 * double(A != Bb));
    }
}

// ---- loops ----------------------------------------------------------------------------------
namespace {

// GLSL:
//   float first_step(float start, float step) {
//       float v = start;
//       for (int i = 0; i < 20; i++) { v += step; if (fract(v * 0.375) > 0.8) return v; }
//       return -1.0;
//   }
template <class F>
F first_step(F start, F step) {
    Return<F> ret;
    F v = start;
    Loop loop(v);
    for (int i = 0; loop(i < 20); i++) {
        v += step;
        loop.return_if(ret, fract(v * 0.375f) > 0.8f, v);
    }
    return ret.value_or(-1.0f);
}
template <class S>
S first_step_oracle(S start, S step) {
    S v = start;
    for (int i = 0; i < 20; i++) {
        v += step;
        if (v * S(0.375) - std::floor(v * S(0.375)) > S(0.8)) return v;
    }
    return S(-1);
}

// GLSL:
//   float steps = 0.0, sum = 0.0, v = seed;
//   while (v != 1.0) {                                 // Collatz, capped at 60 steps
//       if (steps >= 60.0) break;
//       v = mod(v, 2.0) == 0.0 ? v * 0.5 : 3.0 * v + 1.0;
//       steps += 1.0;
//       if (mod(v, 3.0) == 0.0) continue;
//       for (int j = 0; j < 4; j++) { sum += v; if (sum > 500.0) break; }   // nested, breaks alone
//   }
template <class F>
vec2<F> collatz(F seed) {
    F steps = 0.0f, sum = 0.0f, v = seed;
    Loop loop(steps, sum, v);
    while (loop(v != 1.0f)) {
        loop.break_if(steps >= 60.0f);
        v = select(mod(v, 2.0f) == 0.0f, v * 0.5f, 3.0f * v + 1.0f);
        steps += 1.0f;
        loop.continue_if(mod(v, 3.0f) == 0.0f);
        Loop inner(loop, sum);
        for (int j = 0; inner(j < 4); j++) {
            sum += v;
            inner.break_if(sum > 500.0f);
        }
    }
    return vec2<F>(steps, sum);
}
template <class S>
std::pair<S, S> collatz_oracle(S seed) {
    S steps = 0, sum = 0, v = seed;
    while (v != S(1)) {
        if (steps >= S(60)) break;
        v = std::fmod(v, S(2)) == S(0) ? v * S(0.5) : S(3) * v + S(1);
        steps += S(1);
        if (std::fmod(v, S(3)) == S(0)) continue;
        for (int j = 0; j < 4; j++) {
            sum += v;
            if (sum > S(500)) break;
        }
    }
    return {steps, sum};
}

}  // namespace

TEMPLATE_TEST_CASE("loops leave per lane: break, continue, return, while and a nested loop equal the scalar loop", "[loops]",
                   NUMBER_TYPES) {
    using F = TestType;
    using S = scalar_t<F>;
    for (double base : {1.0, 17.0, 40.0, 97.0}) {
        const F seed = ramp<F>(base, 1.0);
        const vec2<F> c = collatz(seed);
        const F start = ramp<F>(-2.0 + base * 0.01, 0.37), f = first_step(start, F(0.125f));
        for (int k = 0; k < lanes_of<F>(); ++k) {
            const auto [steps, sum] = collatz_oracle(S(value_at(seed, k)));
            INFO("seed " << value_at(seed, k) << " lane " << k);
            CHECK(value_at(c.x, k) == double(steps));
            CHECK(value_at(c.y, k) == double(sum));
            CHECK(value_at(f, k) == double(first_step_oracle(S(value_at(start, k)), S(0.125))));
        }
    }
}

TEMPLATE_TEST_CASE("a loop inside a varying if runs only for the lanes inside, a lane that discards runs on", "[loops][discard]",
                   NUMBER_TYPES) {
    using F = TestType;
    using S = scalar_t<F>;
    const F x = ramp<F>(-4.0, 0.75);
    // if (x > 0.0) { for (int i = 0; i < 10; i++) { acc += x; if (acc > 6.0) discard; } }
    FragmentOut<F> out;
    F acc = 0.0f, runs = 0.0f;
    {
        Loop loop(inside(x > 0.0f), acc, runs);
        for (int i = 0; loop(i < 10); i++) {
            acc += x;
            runs += 1.0f;
            loop.discard_if(out, acc > 6.0f);
        }
    }
    out.discard_if(x < -3.0f);  // and a discard outside any loop
    for (int k = 0; k < lanes_of<F>(); ++k) {
        const S sx = S(value_at(x, k));
        S want_acc = 0;
        bool discarded = sx < S(-3);
        if (sx > S(0)) {
            for (int i = 0; i < 10; i++) {
                want_acc += sx;
                discarded = discarded || want_acc > S(6);  // discard: the lane runs on as a helper
            }
        }
        INFO("x " << sx << " lane " << k);
        CHECK(value_at(acc, k) == double(want_acc));
        CHECK(value_at(runs, k) == (sx > S(0) ? 10.0 : 0.0));
        CHECK(lane(out.discarded, k) == discarded);
    }
}

namespace {

// Loops nested until the thread's room for saved values runs out (GLSL cannot recurse; this
// only checks the limit). `depth` counts the loops that got their room.
void nest_loops(vec4<Pixels<double, 16>>& v, int& depth) {
    Loop loop(v);
    ++depth;
    if (depth < 1000) nest_loops(v, depth);
}

}  // namespace

TEST_CASE("a loop's saved values are released when it ends, also when an exception leaves it, loops beyond the room are refused",
          "[loops]") {
    const std::size_t before = loop_detail::saved_values.top();
    const vec2<Pixels<float, 16>> c = collatz(ramp<Pixels<float, 16>>(1.0, 1.0));
    CHECK(value_at(c.x, 0) == 0.0);  // seed 1: the loop ends at once
    CHECK(loop_detail::saved_values.top() == before);

    vec4<Pixels<double, 16>> v(1.0f);
    int depth = 0;
    CHECK_THROWS_AS(nest_loops(v, depth), std::length_error);
    CHECK(depth == int((loop_detail::SavedValues::kBytes - before) / sizeof(vec4<Pixels<double, 16>>)));
    CHECK(loop_detail::saved_values.top() == before);
}

// ---- matrices ---------------------------------------------------------------------------------
namespace {

// A C x R matrix whose component (c, r) in lane k is a small varying number; its scalar copy.
template <class F, int C, int R>
mat<F, C, R> varying_matrix(double seed) {
    mat<F, C, R> m;
    m.for_each([&](int c, int r, F& x) { x = ramp<F>(std::fmod(seed * (c + 1) + 0.37 * r, 3.0) - 1.25, 0.0625 * (1 + c - r)); });
    return m;
}
template <int C, int R, class F>
glm::mat<C, R, scalar_t<F>> at_lane(const mat<F, C, R>& m, int k) {
    glm::mat<C, R, scalar_t<F>> g;
    for (int c = 0; c < C; ++c)
        for (int r = 0; r < R; ++r) g[c][r] = scalar_t<F>(value_at(m[c][r], k));
    return g;
}
template <class F, int N>
glm::vec<N, scalar_t<F>> vec_at_lane(const vec<F, N>& v, int k) {
    glm::vec<N, scalar_t<F>> g;
    for (int i = 0; i < N; ++i) g[i] = scalar_t<F>(value_at(v[i], k));
    return g;
}

// The oracle for products, in the order mat.h states Mesa evaluates them: m * v sums the
// columns scaled by v's components left to right; v * m is dot(v, m[c]) for each column.
template <int C, int R, class S>
glm::vec<R, S> times(const glm::mat<C, R, S>& m, const glm::vec<C, S>& v) {
    glm::vec<R, S> r = m[0] * v[0];
    for (int c = 1; c < C; ++c) r = r + m[c] * v[c];
    return r;
}
template <int C, int R, class S>
glm::vec<C, S> times(const glm::vec<R, S>& v, const glm::mat<C, R, S>& m) {
    glm::vec<C, S> r;
    for (int c = 0; c < C; ++c) {
        S d = v[0] * m[c][0];
        for (int i = 1; i < R; ++i) d = d + v[i] * m[c][i];
        r[c] = d;
    }
    return r;
}

template <int C, int R, class F>
void check_equal(const mat<F, C, R>& got, const glm::mat<C, R, scalar_t<F>>& want, int k, double relative) {
    for (int c = 0; c < C; ++c) {
        for (int r = 0; r < R; ++r) {
            INFO("(" << c << ", " << r << ") of " << C << "x" << R << " lane " << k);
            const double w = double(want[c][r]);
            CHECK(std::abs(value_at(got[c][r], k) - w) <= relative * std::max(1.0, std::abs(w)));
        }
    }
}

// Every product shape of a C x R matrix with vectors and with a K x C matrix, exactly as the
// oracle; transpose, outerProduct and matrixCompMult.
template <class F, int C, int R, int K>
void check_products(double seed) {
    const mat<F, C, R> m = varying_matrix<F, C, R>(seed);
    const mat<F, K, C> n = varying_matrix<F, K, C>(seed + 0.5);
    const mat<F, C, R> o = varying_matrix<F, C, R>(seed + 1.25);
    const vec<F, C> v = n[0];
    const vec<F, R> u = m[C - 1] * 0.5f + 0.25f;
    const vec<F, R> mv = m * v;
    const vec<F, C> um = u * m;
    const mat<F, K, R> mn = m * n;
    const mat<F, R, C> mt = transpose(m);
    const mat<F, C, R> outer = outerProduct(u, v), comp = matrixCompMult(m, o);
    const mat<F, C, R> scaled = m * 2.5f - o;
    for (int k = 0; k < lanes_of<F>(); ++k) {
        const auto gm = at_lane(m, k);
        const auto gn = at_lane(n, k);
        const auto gv = vec_at_lane<F, C>(v, k);
        const auto gu = vec_at_lane<F, R>(u, k);
        const auto want_mv = times(gm, gv);
        const auto want_um = times(gu, gm);
        for (int r = 0; r < R; ++r) CHECK(value_at(mv[r], k) == double(want_mv[r]));
        for (int c = 0; c < C; ++c) CHECK(value_at(um[c], k) == double(want_um[c]));
        glm::mat<K, R, scalar_t<F>> want_mn;
        for (int c = 0; c < K; ++c) want_mn[c] = times(gm, gn[c]);
        check_equal<K, R>(mn, want_mn, k, 0.0);
        check_equal<R, C>(mt, glm::transpose(gm), k, 0.0);
        check_equal<C, R>(outer, glm::outerProduct(gu, gv), k, 0.0);
        check_equal<C, R>(comp, glm::matrixCompMult(gm, at_lane(o, k)), k, 0.0);
        check_equal<C, R>(scaled, gm * scalar_t<F>(2.5) - at_lane(o, k), k, 0.0);
    }
}

// determinant and inverse: Mesa's cofactor expansions (mat.h) against GLM's, within rounding.
template <class F, int N>
void check_inverse(double seed) {
    const mat<F, N, N> m = varying_matrix<F, N, N>(seed) + mat<F, N, N>(F(2.0f));  // well conditioned
    const F d = determinant(m);
    const mat<F, N, N> inv = inverse(m);
    const mat<F, N, N> identity = m * inv;
    for (int k = 0; k < lanes_of<F>(); ++k) {
        const auto g = at_lane(m, k);
        const double want = double(glm::determinant(g));
        INFO("determinant of a " << N << "x" << N << " lane " << k);
        CHECK(std::abs(value_at(d, k) - want) <= 2e-6 * std::max(1.0, std::abs(want)));
        check_equal<N, N>(inv, glm::inverse(g), k, 2e-5);
        check_equal<N, N>(identity, glm::mat<N, N, scalar_t<F>>(1), k, 2e-5);
    }
}

}  // namespace

TEMPLATE_TEST_CASE("matrices of every shape: constructors, products, transpose, outerProduct, matrixCompMult as the oracle",
                   "[matrices]", NUMBER_TYPES) {
    using F = TestType;
    check_products<F, 2, 2, 2>(0.3);
    check_products<F, 3, 3, 3>(0.7);
    check_products<F, 4, 4, 4>(1.1);
    check_products<F, 2, 3, 4>(0.2);
    check_products<F, 3, 2, 4>(0.9);
    check_products<F, 2, 4, 3>(1.7);
    check_products<F, 4, 2, 2>(0.4);
    check_products<F, 3, 4, 2>(1.3);
    check_products<F, 4, 3, 3>(2.1);
    // GLSL's constructors: components column by column, a diagonal, another matrix's upper left.
    const F a = ramp<F>(1.0, 0.5);
    const mat3<F> m(a, F(2.0f), F(3.0f), F(4.0f), F(5.0f), F(6.0f), F(7.0f), F(8.0f), F(9.0f));
    const mat4<F> widened(m);
    const mat2x3<F> cut(m);
    const mat3<F> diagonal(a);
    for (int k = 0; k < lanes_of<F>(); ++k) {
        CHECK(value_at(m[0][0], k) == 1.0 + 0.5 * k);
        CHECK(value_at(m[1][0], k) == 4.0);  // column 1, row 0
        CHECK(value_at(m[0][2], k) == 3.0);
        CHECK(value_at(widened[3][3], k) == 1.0);
        CHECK(value_at(widened[3][0], k) == 0.0);
        CHECK(value_at(widened[2][1], k) == 8.0);
        CHECK(value_at(cut[1][2], k) == 6.0);
        CHECK(value_at(diagonal[1][1], k) == 1.0 + 0.5 * k);
        CHECK(value_at(diagonal[0][1], k) == 0.0);
    }
}

TEMPLATE_TEST_CASE("determinant and inverse of mat2, mat3 and mat4 agree with GLM", "[matrices]", NUMBER_TYPES) {
    using F = TestType;
    check_inverse<F, 2>(0.3);
    check_inverse<F, 3>(0.6);
    check_inverse<F, 4>(0.9);
}

TEMPLATE_TEST_CASE("write swizzles assign the named components only, in their order", "[swizzles]", NUMBER_TYPES) {
    using F = TestType;
    const F s = ramp<F>(0.5, 0.25);
    vec4<F> v(s, 2.0f * s, 3.0f, -1.0f);
    v.xy() -= vec2<F>(s, 1.0f);  // (0, 2s - 1, 3, -1)
    v.wz() = v.xy() * 0.5f;      // w = 0, z = s - 0.5
    v.yxw() *= vec3<F>(2.0f, -1.0f, 4.0f);
    v.b() += 1.0f;
    vec3<F> c(0.0f);
    c.zx() = vec2<F>(s, -s);  // (-s, 0, s)
    for (int k = 0; k < lanes_of<F>(); ++k) {
        const double x = value_at(s, k);
        INFO("lane " << k << " s " << x);
        CHECK(value_at(v.x, k) == -0.0);
        CHECK(value_at(v.y, k) == 2.0 * (2.0 * x - 1.0));
        CHECK(value_at(v.z, k) == (x - 0.5) + 1.0);
        CHECK(value_at(v.w, k) == 0.0);
        CHECK(value_at(c.x, k) == -x);
        CHECK(value_at(c.y, k) == 0.0);
        CHECK(value_at(c.z, k) == x);
    }
}

}  // namespace qs::glsl
