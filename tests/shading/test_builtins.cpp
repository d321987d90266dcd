// Every GLSL built-in, on every number type, against GLM's scalar implementation lane by lane.
#include <catch2/catch.hpp>

#include <bit>
#include <cstdint>
#include <iterator>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "tests/shading/number_types.h"

// Inside qs::glsl, as shader code is: unqualified built-ins resolve as they do in shaders.
namespace qs::glsl {
using test::from_values;
using test::lanes_of;
using test::same;
using test::scalar_t;
using test::value_at;

namespace {

// Negative values for mod/fract, exact step and smoothstep edges, zeros, halves, large values.
const std::vector<double> kInputs = {-3.75, -2.5, -1.0, -0.5, -0.25, 0.0,  0.25,  0.5,   0.75, 1.0,
                                     1.5,   2.5,  3.0,  7.25, -7.0,  100.125, 0.3, 0.32, -0.0, 289.0,
                                     1e-3, 578.5, -289.0, 0.31};
const std::vector<double> kSecond = {2.0, -2.0, 0.5, 1.0, 289.0, 7.0, 0.25, -0.75};

// Transcendentals: std::experimental::simd evaluates sin/cos/exp/log with its own polynomials,
// which may differ from libm in the last bits (GLSL allows far more: 2^-11 absolute for sin).
constexpr double kTranscendentalRelative = 4e-7;

template <class F, class Op, class Oracle>
void check_unary(Op op, Oracle oracle, double relative_tolerance = 0.0) {
    using S = scalar_t<F>;
    constexpr int n = lanes_of<F>();
    std::vector<double> in = kInputs;
    while (in.size() % n) in.push_back(1.0);
    for (std::size_t base = 0; base < in.size(); base += n) {
        const F r = op(from_values<F>(&in[base]));
        for (int i = 0; i < n; ++i) {
            const double want = double(oracle(S(in[base + std::size_t(i)])));
            const double got = value_at(r, i);
            INFO("input " << in[base + std::size_t(i)] << " lane " << i);
            if (relative_tolerance == 0.0 || !std::isfinite(want)) {
                CHECK(same(got, want));
            } else {
                CHECK(std::abs(got - want) <= relative_tolerance * std::max(1.0, std::abs(want)));
            }
        }
    }
}

template <class F, class Op, class Oracle>
void check_binary(Op op, Oracle oracle) {
    using S = scalar_t<F>;
    constexpr int n = lanes_of<F>();
    for (double second : kSecond) {
        std::vector<double> in = kInputs;
        while (in.size() % n) in.push_back(1.0);
        std::vector<double> y(in.size(), second);
        for (std::size_t base = 0; base < in.size(); base += n) {
            const F r = op(from_values<F>(&in[base]), from_values<F>(&y[base]));
            for (int i = 0; i < n; ++i) {
                const double want = double(oracle(S(in[base + std::size_t(i)]), S(second)));
                INFO("inputs " << in[base + std::size_t(i)] << ", " << second);
                CHECK(same(value_at(r, i), want));
            }
        }
    }
}

}  // namespace

#define NUMBER_TYPES float, double, (Pixels<float, 16>), (Quads<float, 4>), (Pixels<double, 8>), Dual2<float>, \
                     (Dual2<Pixels<float, 16>>), (Checked<Pixels<float, 16>>), (Checked<Quads<float, 4>>)

TEMPLATE_TEST_CASE("unary built-ins equal GLM lane by lane", "[builtins]", NUMBER_TYPES) {
    using F = TestType;
    check_unary<F>([](F x) { return floor(x); }, [](auto x) { return glm::floor(x); });
    check_unary<F>([](F x) { return ceil(x); }, [](auto x) { return glm::ceil(x); });
    check_unary<F>([](F x) { return fract(x); }, [](auto x) { return glm::fract(x); });
    check_unary<F>([](F x) { return abs(x); }, [](auto x) { return glm::abs(x); });
    check_unary<F>([](F x) { return sign(x); }, [](auto x) { return glm::sign(x); });
    check_unary<F>([](F x) { return sqrt(x); }, [](auto x) { return glm::sqrt(x); });
    check_unary<F>([](F x) { return inversesqrt(x); }, [](auto x) { return glm::inversesqrt(x); });
}

TEMPLATE_TEST_CASE("transcendental built-ins match GLM within a few ulps", "[builtins]", NUMBER_TYPES) {
    using F = TestType;
    const double tol = kTranscendentalRelative;
    check_unary<F>([](F x) { return sin(x); }, [](auto x) { return glm::sin(x); }, tol);
    check_unary<F>([](F x) { return cos(x); }, [](auto x) { return glm::cos(x); }, tol);
    check_unary<F>([](F x) { return exp(x * 0.125f); }, [](auto x) { return glm::exp(x * decltype(x)(0.125)); }, tol);
    check_unary<F>([](F x) { return exp2(x * 0.125f); }, [](auto x) { return glm::exp2(x * decltype(x)(0.125)); }, tol);
    check_unary<F>([](F x) { return log2(abs(x) + 1.0f); }, [](auto x) { return glm::log2(glm::abs(x) + decltype(x)(1)); }, tol);
    check_unary<F>([](F x) { return pow(abs(x), F(1.5f)); }, [](auto x) { return glm::pow(glm::abs(x), decltype(x)(1.5)); }, tol);
}

TEMPLATE_TEST_CASE("binary built-ins equal GLM lane by lane, negative operands included", "[builtins]", NUMBER_TYPES) {
    using F = TestType;
    check_binary<F>([](F x, F y) { return mod(x, y); }, [](auto x, auto y) { return glm::mod(x, y); });
    check_binary<F>([](F x, F y) { return min(x, y); }, [](auto x, auto y) { return glm::min(x, y); });
    check_binary<F>([](F x, F y) { return max(x, y); }, [](auto x, auto y) { return glm::max(x, y); });
    check_binary<F>([](F e, F x) { return step(e, x); }, [](auto e, auto x) { return glm::step(e, x); });
    check_binary<F>([](F x, F y) { return step(x, y); }, [](auto x, auto y) { return glm::step(x, y); });
}

TEMPLATE_TEST_CASE("clamp, mix and smoothstep equal GLM, exactly at the edges too", "[builtins]", NUMBER_TYPES) {
    using F = TestType;
    check_unary<F>([](F x) { return clamp(x, F(-0.5f), F(1.0f)); }, [](auto x) { return glm::clamp(x, decltype(x)(-0.5), decltype(x)(1)); });
    check_unary<F>([](F x) { return mix(F(2.0f), F(-3.0f), x); }, [](auto x) { return glm::mix(decltype(x)(2), decltype(x)(-3), x); });
    check_unary<F>([](F x) { return smoothstep(F(0.3f), F(0.32f), x); },
                   [](auto x) { return glm::smoothstep(decltype(x)(0.3f), decltype(x)(0.32f), x); });
    check_unary<F>([](F x) { return smoothstep(F(-1.0f), F(1.0f), x); },
                   [](auto x) { return glm::smoothstep(decltype(x)(-1), decltype(x)(1), x); });
}

TEMPLATE_TEST_CASE("geometric built-ins on vec3 equal GLM", "[builtins]", NUMBER_TYPES) {
    using F = TestType;
    using S = scalar_t<F>;
    const double a[3] = {0.25, -1.5, 3.0}, b[3] = {2.0, 0.75, -0.125};
    auto v = [](const double* p) {
        return vec3<F>(from_values<F>(std::vector<double>(16, p[0]).data()), from_values<F>(std::vector<double>(16, p[1]).data()),
                       from_values<F>(std::vector<double>(16, p[2]).data()));
    };
    const glm::vec<3, S> ga{S(a[0]), S(a[1]), S(a[2])}, gb{S(b[0]), S(b[1]), S(b[2])};
    CHECK(value_at(dot(v(a), v(b)), 0) == double(glm::dot(ga, gb)));
    CHECK(value_at(length(v(a)), 0) == double(glm::length(ga)));
    CHECK(value_at(distance(v(a), v(b)), 0) == double(glm::distance(ga, gb)));
    const vec3<F> c = cross(v(a), v(b));
    const auto gc = glm::cross(ga, gb);
    const vec3<F> n = normalize(v(a));
    const auto gn = glm::normalize(ga);
    for (int i = 0; i < 3; ++i) {
        CHECK(value_at(c[i], 0) == double(gc[i]));
        CHECK(value_at(n[i], 0) == double(gn[i]));
    }
}

TEST_CASE("mat2 and mat2x3 multiply as GLSL (column-major) and as GLM", "[builtins]") {
    const mat2<float> m(0.966f, -0.259f, 0.259f, 0.966f);
    const glm::mat2 gm(0.966f, -0.259f, 0.259f, 0.966f);
    const vec2<float> v(0.3f, -1.25f);
    const glm::vec2 gv(0.3f, -1.25f);
    CHECK((m * v).x == (gm * gv).x);
    CHECK((m * v).y == (gm * gv).y);
    CHECK((v * m).x == (gv * gm).x);
    CHECK((v * m).y == (gv * gm).y);
    CHECK((50.0f * m * v).x == (50.0f * gm * gv).x);
    const mat2x3<float> j(vec3<float>(1.0f, 2.0f, 3.0f), vec3<float>(-1.0f, 0.5f, 4.0f));
    const glm::mat2x3 gj(glm::vec3(1.0f, 2.0f, 3.0f), glm::vec3(-1.0f, 0.5f, 4.0f));
    const vec3<float> g3(0.5f, -2.0f, 1.0f);
    const glm::vec3 gg3(0.5f, -2.0f, 1.0f);
    CHECK((g3 * j).x == (gg3 * gj).x);
    CHECK((g3 * j).y == (gg3 * gj).y);
    CHECK((j * v).z == (gj * gv).z);
}

TEMPLATE_TEST_CASE("NaN and infinity follow llvmpipe: min and max return the non-NaN operand", "[builtins][nan]", float,
                   double, (Pixels<float, 16>), (Quads<float, 4>), Dual2<float>, (Checked<Quads<float, 4>>)) {
    using F = TestType;
    const F nan = std::numeric_limits<float>::quiet_NaN();
    const F inf = std::numeric_limits<float>::infinity();
    CHECK(value_at(min(nan, F(1.0f)), 0) == 1.0);
    CHECK(value_at(min(F(1.0f), nan), 0) == 1.0);
    CHECK(value_at(max(nan, F(-2.0f)), 0) == -2.0);
    CHECK(value_at(clamp(nan, 0.0f, 1.0f), 0) == 0.0);  // as a NaN through fsat in llvmpipe
    CHECK(std::isnan(value_at(sqrt(F(-1.0f)), 0)));
    CHECK(value_at(inversesqrt(F(0.0f)), 0) == std::numeric_limits<double>::infinity());
    CHECK(std::isnan(value_at(mod(F(1.5f), F(0.0f)), 0)));
    CHECK(std::isnan(value_at(normalize(vec3<F>(F(0.0f))).x, 0)));
    CHECK(std::isnan(value_at(F(1.0f) + nan, 0)));  // arithmetic propagates NaN
    CHECK(value_at(step(F(0.0f), inf), 0) == 1.0);
    CHECK(value_at(fract(F(-0.25f)), 0) == 0.75);
}

// Lanes' min and max are minps/maxps with a NaN b's lanes taking a (number/lanes.h): the same
// bits as the rule they stand for, select(isnan(b) || a < b, a, b), for every pair of special
// and ordinary values, signed zeros included (equal, they give b as the rule does), on each
// register width the lanes come in.
TEMPLATE_TEST_CASE("min and max give the bits of select(isnan(b) || a < b, a, b) on every lane",
                   "[builtins][nan]", (Pixels<float, 4>), (Pixels<float, 8>), (Pixels<float, 16>), (Pixels<float, 32>),
                   (Pixels<double, 8>), (Pixels<double, 16>)) {
    using F = TestType;
    using T = typename F::value_type;
    const T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN();
    const T values[] = {T(0), -T(0), T(1), T(-1), T(0.5), inf, -inf, nan, -nan, std::numeric_limits<T>::denorm_min(),
                        std::numeric_limits<T>::max(), T(-3.25)};
    constexpr int kValues = int(std::size(values));
    const auto bits = [](T x) {
        if constexpr (sizeof(T) == 4) return std::uint64_t(std::bit_cast<std::uint32_t>(x));
        else return std::bit_cast<std::uint64_t>(x);
    };
    // Every (a, b) pair, F::size of them at a time.
    for (int first = 0; first < kValues * kValues; first += F::size) {
        T a[F::size], b[F::size];
        for (int i = 0; i < F::size; ++i) {
            const int pair = (first + i) % (kValues * kValues);
            a[i] = values[pair / kValues];
            b[i] = values[pair % kValues];
        }
        const F lo = min(F::load(a), F::load(b)), hi = max(F::load(a), F::load(b));
        for (int i = 0; i < F::size; ++i) {
            const bool b_nan = std::isnan(b[i]);
            const T want_lo = b_nan || a[i] < b[i] ? a[i] : b[i], want_hi = b_nan || a[i] > b[i] ? a[i] : b[i];
            INFO("a = " << a[i] << ", b = " << b[i]);
            CHECK(bits(lo[i]) == bits(want_lo));
            CHECK(bits(hi[i]) == bits(want_hi));
        }
    }
}

TEMPLATE_TEST_CASE("smoothstep with equal edges is x > edge, as llvmpipe runs it", "[builtins][nan]", float, double,
                   (Pixels<float, 16>), (Quads<float, 4>), Dual2<float>, (Checked<Quads<float, 4>>)) {
    using F = TestType;
    CHECK(value_at(smoothstep(F(0.5f), F(0.5f), F(0.25f)), 0) == 0.0);
    CHECK(value_at(smoothstep(F(0.5f), F(0.5f), F(0.5f)), 0) == 0.0);  // 0/0 is NaN, clamped to 0
    CHECK(value_at(smoothstep(F(0.5f), F(0.5f), F(0.75f)), 0) == 1.0);
    // GLM, following the C++ comparison, returns NaN on the edge itself.
    CHECK(std::isnan(glm::smoothstep(0.5f, 0.5f, 0.5f)));
}

}  // namespace qs::glsl
