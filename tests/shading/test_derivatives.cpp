// dFdx/dFdy/fwidth under each quad rule, and Dual2's carried derivatives.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "shading/noise/flow_noise.h"
#include "shading/noise/simplex2d.h"
#include "tests/shading/number_types.h"
#include "shading/shaders/aastep.h"

// Inside qs::glsl, as shader code is: unqualified built-ins resolve as they do in shaders.
namespace qs::glsl {

namespace {

// v = x^2 + 100 y^2 + 10 x y: nonlinear, so every rule gives different differences; all values
// are small integers, exact in float.
double v_at(double x, double y) { return x * x + 100 * y * y + 10 * x * y; }

// Four quads at these lower-left corners (window coordinates, y up).
const int kQuadX[4] = {0, 2, 10, -4}, kQuadY[4] = {0, 0, 6, 8};

template <DerivativeRule R>
Quads<float, 4, R> v_over_quads() {
    float values[16];
    for (int q = 0; q < 4; ++q) {
        for (int l = 0; l < 4; ++l) values[4 * q + l] = float(v_at(kQuadX[q] + (l & 1), kQuadY[q] + (l >> 1)));
    }
    return Quads<float, 4, R>::load(values);
}

// The expected difference for lane l of quad q: x1/y1 of the pixels subtracted, x0/y0 the base.
double diff(int q, int xa, int ya, int xb, int yb) {
    return v_at(kQuadX[q] + xa, kQuadY[q] + ya) - v_at(kQuadX[q] + xb, kQuadY[q] + yb);
}

}  // namespace

TEST_CASE("fine rule: each row its own dFdx, each column its own dFdy (llvmpipe)", "[derivatives]") {
    const auto v = v_over_quads<DerivativeRule::Fine>();
    const auto dx = dFdx(v), dy = dFdy(v);
    for (int q = 0; q < 4; ++q) {
        for (int l = 0; l < 4; ++l) {
            const int row = l >> 1, col = l & 1;
            CHECK(dx[4 * q + l] == diff(q, 1, row, 0, row));
            CHECK(dy[4 * q + l] == diff(q, col, 1, col, 0));
        }
    }
    // llvmpipe treats the explicit coarse variants as fine too.
    for (int i = 0; i < 16; ++i) CHECK(dFdxCoarse(v)[i] == dx[i]);
}

TEST_CASE("coarse-lower rule: the lower row and left column for the whole quad (softpipe)", "[derivatives]") {
    const auto v = v_over_quads<DerivativeRule::CoarseLower>();
    const auto dx = dFdx(v), dy = dFdy(v);
    const auto fine_dx = dFdxFine(v);
    for (int q = 0; q < 4; ++q) {
        for (int l = 0; l < 4; ++l) {
            CHECK(dx[4 * q + l] == diff(q, 1, 0, 0, 0));
            CHECK(dy[4 * q + l] == diff(q, 0, 1, 0, 0));
            CHECK(fine_dx[4 * q + l] == diff(q, 1, l >> 1, 0, l >> 1));  // dFdxFine stays fine
        }
    }
}

TEST_CASE("coarse-upper rule: the upper row and left column for the whole quad", "[derivatives]") {
    const auto v = v_over_quads<DerivativeRule::CoarseUpper>();
    const auto dx = dFdx(v), dy = dFdy(v);
    for (int q = 0; q < 4; ++q) {
        for (int l = 0; l < 4; ++l) {
            CHECK(dx[4 * q + l] == diff(q, 1, 1, 0, 1));
            CHECK(dy[4 * q + l] == diff(q, 0, 1, 0, 0));
        }
    }
}

TEST_CASE("fwidth is exactly |dFdx| + |dFdy| under every rule", "[derivatives]") {
    auto check = [](auto v) {
        const auto w = fwidth(v), dx = dFdx(v), dy = dFdy(v);
        for (int i = 0; i < 16; ++i) CHECK(w[i] == std::abs(dx[i]) + std::abs(dy[i]));
    };
    check(v_over_quads<DerivativeRule::Fine>());
    check(v_over_quads<DerivativeRule::CoarseLower>());
    check(v_over_quads<DerivativeRule::CoarseUpper>());
}

TEST_CASE("Dual2 derivatives of a nonlinear shader match central differences", "[derivatives][dual2]") {
    // Flow noise of a perspective-like mapping of window (x, y), evaluated in double.
    auto f = [](auto x, auto y) {
        using F = decltype(x);
        vec2<F> p(x * 0.37 + y * y * 0.01, y * 0.21 - x * y * 0.005);
        vec2<F> g;
        return noise::srdnoise(p, F(0.3), g) + 0.5 * noise::snoise(p * 2.0);
    };
    constexpr double h = 1e-5;
    // Central differences have O(h^2) error; the analytic result is exact up to rounding.
    constexpr double kTolerance = 1e-6;
    for (double x : {1.5, 7.25, 13.0, 40.5}) {
        for (double y : {2.5, 9.75, 21.0}) {
            const Dual2<double> r = f(Dual2<double>(x, 1.0, 0.0), Dual2<double>(y, 0.0, 1.0));
            const double cx = (f(x + h, y) - f(x - h, y)) / (2 * h);
            const double cy = (f(x, y + h) - f(x, y - h)) / (2 * h);
            INFO("at " << x << ", " << y);
            CHECK(r.val == Approx(f(x, y)).margin(1e-12));
            CHECK(r.dx == Approx(cx).margin(kTolerance));
            CHECK(r.dy == Approx(cy).margin(kTolerance));
        }
    }
}

TEST_CASE("Dual2 over SIMD lanes equals Dual2 over float, lane by lane", "[derivatives][dual2]") {
    using L = Pixels<float, 16>;
    float xs[16], ys[16];
    for (int i = 0; i < 16; ++i) xs[i] = 0.7f * float(i) - 3.0f, ys[i] = 0.3f * float(i * i) * 0.1f + 0.5f;
    const Dual2<L> x(L::load(xs), L(1.0f), L(0.0f)), y(L::load(ys), L(0.0f), L(1.0f));
    const Dual2<L> r = noise::snoise(vec2<Dual2<L>>(x, y) * 3.0f);
    for (int i = 0; i < 16; ++i) {
        const Dual2<float> s = noise::snoise(vec2<Dual2<float>>(Dual2<float>(xs[i], 1.0f, 0.0f),
                                                                Dual2<float>(ys[i], 0.0f, 1.0f)) * 3.0f);
        CHECK(r.val[i] == s.val);
        CHECK(r.dx[i] == s.dx);
        CHECK(r.dy[i] == s.dy);
    }
}

TEST_CASE("dFdx of a Dual2 is its carried partial, and second derivatives are not carried", "[derivatives][dual2]") {
    const Dual2<float> x(3.0f, 1.0f, 0.0f);
    const Dual2<float> v = x * x;  // d/dx x^2 = 2x = 6
    CHECK(dFdx(v).val == 6.0f);
    CHECK(dFdy(v).val == 0.0f);
    CHECK(fwidth(v).val == 6.0f);
    CHECK(dFdx(dFdx(v)).val == 0.0f);
}

TEST_CASE("aastep never makes NaN from a finite value: zero, huge and infinite derivatives", "[derivatives][stability]") {
    // Quad 0 constant (zero derivatives: equal smoothstep edges), quad 1 with differences of
    // 1e38 (finite), quad 2 with 3e38 - (-3e38) = inf, quad 3 with a NaN neighbour as a helper
    // lane might carry at infinity.
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float values[16] = {0.5f, 0.5f, 0.5f, 0.5f,  0.0f, 1e38f, 0.0f, 1e38f,
                              -3e38f, 3e38f, 0.2f, 0.4f,  0.3f, nan, 0.3f, 0.35f};
    const auto v = Quads<float, 4, DerivativeRule::Fine>::load(values);
    const auto a = shaders::aastep(Quads<float, 4, DerivativeRule::Fine>(0.31f), v);
    for (int i = 0; i < 16; ++i) {
        INFO("lane " << i << " value " << values[i] << " -> " << a[i]);
        if (std::isnan(values[i])) continue;  // NaN in, NaN out: GLSL defines nothing better
        CHECK_FALSE(std::isnan(a[i]));
        CHECK(a[i] >= 0.0f);
        CHECK(a[i] <= 1.0f);
    }
    // Equal edges (constant value over the quad): llvmpipe's value > threshold.
    CHECK(a[0] == 1.0f);
}

}  // namespace qs::glsl
