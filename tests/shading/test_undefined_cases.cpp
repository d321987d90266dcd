// Checked numbers: which GLSL cases with undefined results each lane's value depends on.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "tests/shading/number_types.h"
#include "shading/shaders/aastep.h"

// Inside qs::glsl, as shader code is: unqualified built-ins resolve as they do in shaders.
namespace qs::glsl {

namespace {

using P = Checked<Pixels<float, 16>>;
using Q = Checked<Quads<float, 4>>;

constexpr std::uint8_t kNaN = std::uint8_t(Undefined::NaN);
constexpr std::uint8_t kDivision = std::uint8_t(Undefined::DivisionByZero);
constexpr std::uint8_t kArgument = std::uint8_t(Undefined::Argument);

template <class F>
F lanes(std::initializer_list<float> values) {
    float v[F::size] = {};
    std::size_t i = 0;
    for (float x : values) v[i++] = x;
    return F::load(v);
}

template <class F>
std::uint8_t cases_at(const F& x, int lane) { return x.cases.at(lane); }

}  // namespace

TEST_CASE("defined arithmetic carries no case, and computes what the unchecked lanes compute", "[undefined]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> dist(-100.0f, 100.0f);
    float a[16], b[16];
    for (int i = 0; i < 16; ++i) a[i] = dist(rng), b[i] = dist(rng);
    const P x = P::load(a), y = P::load(b);
    const Pixels<float, 16> ux = Pixels<float, 16>::load(a), uy = Pixels<float, 16>::load(b);
    const P r = smoothstep(-50.0f, 50.0f, x) * mix(x, y, fract(y)) / (abs(y) + 1.0f) + mod(x, 7.0f);
    const Pixels<float, 16> u = smoothstep(-50.0f, 50.0f, ux) * mix(ux, uy, fract(uy)) / (abs(uy) + 1.0f) + mod(ux, 7.0f);
    CHECK(r.cases.none());
    for (int i = 0; i < 16; ++i) {
        const float got = r[i], want = u[i];
        CHECK(std::memcmp(&got, &want, sizeof got) == 0);
    }
}

TEST_CASE("division by zero is flagged on its lanes only, 0 / 0 also produces NaN", "[undefined]") {
    const P r = lanes<P>({1.0f, 0.0f, 2.0f}) / lanes<P>({0.0f, 0.0f, 4.0f, 1.0f});
    CHECK(cases_at(r, 0) == kDivision);        // 1 / 0 = inf: defined in IEEE, not in GLSL
    CHECK(cases_at(r, 1) == (kDivision | kNaN));
    CHECK(cases_at(r, 2) == 0);
    CHECK(cases_at(r, 3) == 0);
    CHECK(cases_at(mod(P(1.0f), P(0.0f)), 0) == (kDivision | kNaN));  // GLSL's mod divides
}

TEST_CASE("NaN is flagged where it is made, and where it comes in, not where it merely passes", "[undefined]") {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    CHECK(cases_at(P(inf) - P(inf), 0) == kNaN);
    CHECK(cases_at(P(0.0f) * P(inf), 0) == kNaN);
    CHECK(cases_at(P(inf) * P(2.0f), 0) == 0);  // inf is not undefined by itself
    const P in = lanes<P>({nan, 1.0f});         // a NaN varying or texel
    CHECK(cases_at(in, 0) == kNaN);
    CHECK(cases_at(in, 1) == 0);
    // A literal NaN (no case) passing through arithmetic makes nothing new.
    CHECK(cases_at(P(nan) + P(1.0f), 0) == 0);
}

TEST_CASE("built-ins outside their GLSL domain are flagged as such, not by how they are computed", "[undefined]") {
    CHECK(cases_at(smoothstep(P(0.5f), P(0.5f), P(0.7f)), 0) == kArgument);  // no division by zero
    CHECK(cases_at(smoothstep(P(1.0f), P(0.0f), P(0.7f)), 0) == kArgument);  // reversed edges
    CHECK(cases_at(smoothstep(P(0.0f), P(1.0f), P(0.7f)), 0) == 0);
    CHECK(cases_at(clamp(P(0.5f), P(1.0f), P(0.0f)), 0) == kArgument);
    CHECK(cases_at(inversesqrt(P(0.0f)), 0) == kArgument);
    CHECK(cases_at(inversesqrt(P(4.0f)), 0) == 0);
    CHECK(cases_at(sqrt(P(-1.0f)), 0) == (kArgument | kNaN));
    CHECK(cases_at(log(P(0.0f)), 0) == kArgument);  // -inf
    CHECK(cases_at(log2(P(-1.0f)), 0) == (kArgument | kNaN));
    CHECK(cases_at(pow(P(-2.0f), P(2.0f)), 0) == kArgument);  // 4 in C, undefined in GLSL
    CHECK(cases_at(pow(P(0.0f), P(-1.0f)), 0) == kArgument);
    CHECK(cases_at(pow(P(0.0f), P(2.0f)), 0) == 0);
    CHECK(cases_at(atan(P(0.0f), P(0.0f)), 0) == kArgument);
    // normalize(vec3(0)) = 0 * inversesqrt(0): outside inversesqrt's domain, and 0 * inf is NaN.
    CHECK(cases_at(normalize(vec3<P>(P(0.0f))).x, 0) == (kArgument | kNaN));
}

TEST_CASE("cases follow the data: select keeps the picked side's, arithmetic keeps all", "[undefined]") {
    const P x = lanes<P>({0.0f, 2.0f, 0.0f, 2.0f});
    // GLSL: if (x > 0) y = 1 / x; else y = 0; -- translated as a select of both sides.
    const P y = select(x > P(0.0f), P(1.0f) / x, P(0.0f));
    CHECK(cases_at(y, 0) == 0);  // the division GLSL would not run on this lane
    CHECK(cases_at(y, 1) == 0);
    // A case multiplied away or clamped still marks the value that depended on it.
    CHECK(cases_at(min(P(1.0f) / x, P(1.0f)) * P(0.0f), 0) == kDivision);
    CHECK(cases_at((P(1.0f) / x) * P(0.0f), 0) == (kDivision | kNaN));  // inf * 0
    CHECK(cases_at(clamp(P(1.0f) / x, 0.0f, 1.0f), 0) == kDivision);
    // The mask's own cases pass on: a branch decided by an undefined value.
    const P z = select(P(1.0f) / x > P(0.5f), P(1.0f), P(0.0f));
    CHECK(cases_at(z, 0) == kDivision);
    CHECK(cases_at(z, 1) == 0);
    // step is a select too, decided by the flagged comparison.
    CHECK(cases_at(step(P(0.5f), P(1.0f) / x), 2) == kDivision);
}

TEST_CASE("derivatives carry a helper lane's cases to the lanes that difference with it", "[undefined]") {
    // Quad 0: lane 1 (lower right) divides by zero; quads 1..3 are clean.
    const Q v = Q(1.0f) / lanes<Q>({1.0f, 0.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f,
                                    1.0f, 1.0f, 1.0f});
    const Q dx = dFdx(v), dy = dFdy(v);
    // Fine rule: dFdx on the lower row is v1 - v0, on the upper row v3 - v2; dFdy in the right
    // column v3 - v1.
    CHECK(cases_at(dx, 0) == kDivision);
    CHECK(cases_at(dx, 1) == kDivision);
    CHECK(cases_at(dx, 2) == 0);
    CHECK(cases_at(dx, 3) == 0);
    CHECK(cases_at(dy, 0) == 0);
    CHECK(cases_at(dy, 3) == kDivision);
    for (int lane = 4; lane < 16; ++lane) CHECK(cases_at(dx, lane) == 0);
    // inf - inf across the quad: a NaN made by the derivative itself.
    const Q w = Q(1.0f) / lanes<Q>({0.0f, 0.0f, 1.0f, 1.0f});
    CHECK(cases_at(dFdx(w), 0) == (kDivision | kNaN));
}

TEST_CASE("aastep with a zero derivative is smoothstep with equal edges: flagged", "[undefined]") {
    // A value constant over each quad: fwidth is 0, aastep's edges coincide.
    const Q constant = Q(0.25f);
    CHECK(cases_at(shaders::aastep(Q(0.5f), constant), 0) == kArgument);
    const Q ramp = lanes<Q>({0.0f, 0.1f, 0.2f, 0.3f});
    CHECK(cases_at(shaders::aastep(Q(0.5f), ramp), 0) == 0);
}

}  // namespace qs::glsl
