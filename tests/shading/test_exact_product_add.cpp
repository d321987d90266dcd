// exact_product_add (number/simd/simd.h) and the noises' mod289 and permute written with it
// (noise/simplex2d.h), snoise3's gradients (noise/simplex3d.h), and the cellular and flow noises'
// permute and mod 7 (noise/flow_noise.h, noise/cellular.h): where the product is exact,
// fusing changes no bit, and the noises' products are exact over the whole range the noise
// comment claims. Each whole number in it is run.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <type_traits>

#include "shading/noise/cellular.h"
#include "shading/noise/simplex2d.h"

// Inside qs::glsl, as shader code is: unqualified built-ins resolve as they do in shaders.
namespace qs::glsl {

namespace {

using L = Pixels<float, 16>;

// The GLSL's mod289 and permute as written, each operation rounded (the build contracts nothing).
float glsl_mod289(float x) { return x - std::floor(x * (1.0f / 289.0f)) * 289.0f; }
float glsl_permute(float x) { return glsl_mod289(((x * 34.0f) + 1.0f) * x); }
// The cellular and flow noises' forms: GLSL mod, which divides.
float glsl_mod(float x, float y) { return x - y * std::floor(x / y); }
float glsl_permute_mod(float x) { return glsl_mod(((x * 34.0f) + 1.0f) * x, 289.0f); }

constexpr float kExactBelow = 16777216.0f - 289.0f;  // 2^24 - 289, noise/simplex2d.h

bool same_bits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }

// Runs check(x, lanes' result, scalar result) for 16 values at a time of `next(i)`, i < count.
template <class Next, class Of, class Check>
void over_lanes(std::int64_t count, Next next, Of of, Check check) {
    for (std::int64_t i = 0; i < count; i += 16) {
        float x[16];
        for (int k = 0; k < 16; ++k) x[k] = next(std::min(i + k, count - 1));
        const L r = of(L::load(x));
        for (int k = 0; k < 16; ++k) check(x[k], r[k], of(x[k]));
    }
}

}  // namespace

TEST_CASE("exact_product_add: a * b + c, the same bits fused or not where a * b is exact", "[noise]") {
    // 3 * 5 is exact, and so is 2^12 * 2^12; the sums round alike both ways.
    CHECK(exact_product_add(3.0f, 5.0f, 0.1f) == 3.0f * 5.0f + 0.1f);
    CHECK(exact_product_add(4096.0f, 4096.0f, 1.0f) == 4096.0f * 4096.0f + 1.0f);
    CHECK(exact_product_add(-0.0f, 289.0f, 0.0f) == 0.0f);
    CHECK(!std::signbit(exact_product_add(-0.0f, 289.0f, 0.0f)));
    CHECK(exact_product_add(3.0, 5.0, 0.1) == 3.0 * 5.0 + 0.1);
    float a[16], b[16], c[16];
    for (int k = 0; k < 16; ++k) a[k] = float(k) - 7.0f, b[k] = 34.0f, c[k] = 0.25f * float(k);
    const L r = exact_product_add(L::load(a), L::load(b), L::load(c));
    for (int k = 0; k < 16; ++k) CHECK(same_bits(r[k], a[k] * b[k] + c[k]));
    // Dual2: d(uv + w) = u dv + v du + dw.
    const Dual2<float> u(2.0f, 1.0f, 0.0f), v(3.0f, 0.0f, 1.0f), w(0.5f, 0.25f, 0.125f);
    const Dual2<float> s = exact_product_add(u, v, w);
    CHECK(s.val == 6.5f);
    CHECK(s.dx == 3.25f);
    CHECK(s.dy == 2.125f);
}

TEST_CASE("mod289 gives the GLSL's bits on every whole number below 2^24 - 289, and floats between",
          "[noise]") {
    const auto whole = std::int64_t(kExactBelow) - 1;  // |x| <= whole
    std::int64_t differ = 0, outside = 0;
    over_lanes(
        2 * whole + 1, [&](std::int64_t i) { return float(i - whole); },
        [](const auto& x) { return noise::mod289(x); },
        [&](float x, float lanes, float scalar) {
            const float g = glsl_mod289(x);
            differ += !same_bits(lanes, g) || !same_bits(scalar, g);
            outside += g < -2.0f || g > 290.0f;  // the range the permute bound rests on
        });
    CHECK(differ == 0);
    CHECK(outside == 0);
    std::mt19937 random(289);
    std::uniform_real_distribution<float> anywhere(-kExactBelow, kExactBelow);
    std::uniform_real_distribution<float> small(-600.0f, 600.0f);
    differ = 0;
    over_lanes(
        1 << 21, [&](std::int64_t i) { return i % 2 ? anywhere(random) : small(random); },
        [](const auto& x) { return noise::mod289(x); },
        [&](float x, float lanes, float scalar) {
            differ += !same_bits(lanes, glsl_mod289(x)) || !same_bits(scalar, glsl_mod289(x));
        });
    CHECK(differ == 0);
}

TEST_CASE("permute gives the GLSL's bits on every whole number the noises permute, and beyond", "[noise]") {
    // The noises permute whole numbers in [-6, 581] (noise/simplex2d.h); x * 34 stays exact far
    // beyond, and the product's mod289 while (34 x + 1) x < 2^24 - 289: |x| <= 702.
    std::int64_t differ = 0;
    over_lanes(
        1405, [](std::int64_t i) { return float(i - 702); }, [](const auto& x) { return noise::permute289(x); },
        [&](float x, float lanes, float scalar) {
            differ += !same_bits(lanes, glsl_permute(x)) || !same_bits(scalar, glsl_permute(x));
        });
    CHECK(differ == 0);
}

TEST_CASE("2D simplex's 2 fract(p / 41) - 1 gives the GLSL's bits on every permutation value and any fraction",
          "[noise]") {
    // Twice a float is exact, whatever its size below 2^127: a permutation's fraction (noise/
    // simplex2d.h) or any other.
    auto glsl = [](float f) { return 2.0f * f - 1.0f; };
    auto fused = [](const auto& f) {
        using T = std::remove_cvref_t<decltype(f)>;
        return exact_product_add(f, T(2.0f), T(-1.0f));
    };
    auto fraction = [](std::int64_t p) {  // fract(p * C.w) of a permutation value p, a margin either side
        const float y = float(p - 50) * 0.024390243902439f;
        return y - std::floor(y);
    };
    std::int64_t differ = 0;
    over_lanes(400, fraction, fused, [&](float f, float lanes, float scalar) {
        differ += !same_bits(lanes, glsl(f)) || !same_bits(scalar, glsl(f));
    });
    std::mt19937 random(41);
    std::uniform_int_distribution<std::uint32_t> bits(0, 0x7EFFFFFFu);  // every finite float below 2^127
    over_lanes(
        1 << 20, [&](std::int64_t i) { return (i % 2 ? 1.0f : -1.0f) * std::bit_cast<float>(bits(random)); }, fused,
        [&](float f, float lanes, float scalar) { differ += !same_bits(lanes, glsl(f)) || !same_bits(scalar, glsl(f)); });
    CHECK(differ == 0);
}

namespace {

// The steps of noise/simplex3d.h's gradients that it fuses, on a permutation value p: j, y_, the
// two s and the two a, as snoise3 computes them (F) and as the GLSL writes them (float).
template <class F>
std::array<F, 6> gradient_steps(const F& p) {
    const float n_ = 1.0f / 7.0f, nsx = n_ * 2.0f - 0.0f, nsy = n_ * 0.5f - 1.0f, nsz = n_ * 1.0f - 0.0f;
    const F j = exact_product_add(floor(p * nsz * nsz), F(-49.0f), p);
    const F x_ = floor(j * nsz);
    const F y_ = floor(exact_product_add(x_, F(-7.0f), j));
    const F x = x_ * nsx + nsy, y = y_ * nsx + nsy;
    const F h = 1.0f - abs(x) - abs(y);
    const F sx = exact_product_add(floor(x), F(2.0f), F(1.0f)), sy = exact_product_add(floor(y), F(2.0f), F(1.0f));
    const F sh = -step(h, F(0.0f));
    return {j, y_, sx, sy, exact_product_add(sx, sh, x), exact_product_add(sy, sh, y)};
}
std::array<float, 6> glsl_gradient_steps(float p) {
    const float n_ = 1.0f / 7.0f, nsx = n_ * 2.0f - 0.0f, nsy = n_ * 0.5f - 1.0f, nsz = n_ * 1.0f - 0.0f;
    const float j = p - 49.0f * std::floor(p * nsz * nsz);
    const float x_ = std::floor(j * nsz);
    const float y_ = std::floor(j - 7.0f * x_);
    const float x = x_ * nsx + nsy, y = y_ * nsx + nsy;
    const float h = 1.0f - std::fabs(x) - std::fabs(y);
    const float sx = std::floor(x) * 2.0f + 1.0f, sy = std::floor(y) * 2.0f + 1.0f;
    const float sh = -(0.0f < h ? 0.0f : 1.0f);
    return {j, y_, sx, sy, x + sx * sh, y + sy * sh};
}

}  // namespace

TEST_CASE("snoise3's gradient steps give the GLSL's bits for every permutation value", "[noise]") {
    // Permutations are whole numbers in [-2, 290] (the mod289 test above); a margin either side.
    std::int64_t differ = 0;
    for (int first = -40; first <= 330; first += 16) {
        float p[16];
        for (int k = 0; k < 16; ++k) p[k] = float(first + k);
        const std::array<L, 6> lanes = gradient_steps(L::load(p));
        for (int k = 0; k < 16; ++k) {
            const std::array<float, 6> scalar = gradient_steps(p[k]), glsl = glsl_gradient_steps(p[k]);
            for (int s = 0; s < 6; ++s) differ += !same_bits(lanes[s][k], glsl[s]) || !same_bits(scalar[s], glsl[s]);
        }
    }
    CHECK(differ == 0);
}

TEST_CASE("the cellular and flow noises' permute and mod 7 give the GLSL's bits on every value they see",
          "[noise]") {
    // mod(x, 289.0) of a whole number below 2^24 lies in [-288, 288] (noise/flow_noise.h): the
    // range the permutations' bound rests on.
    const std::int64_t whole = (std::int64_t(1) << 24) - 1;
    std::int64_t outside = 0;
    over_lanes(
        2 * whole + 1, [&](std::int64_t i) { return float(i - whole); },
        [](const auto& x) { return mod(x, 289.0f); },
        [&](float x, float lanes, float scalar) {
            const float g = glsl_mod(x, 289.0f);
            outside += !same_bits(lanes, g) || !same_bits(scalar, g) || g < -288.0f || g > 288.0f;
        });
    CHECK(outside == 0);
    // Permuted are whole numbers |x| <= 577; the products stay exact up to 702.
    std::int64_t differ = 0;
    outside = 0;
    over_lanes(
        1405, [](std::int64_t i) { return float(i - 702); }, [](const auto& x) { return noise::permute_mod(x); },
        [&](float x, float lanes, float scalar) {
            const float g = glsl_permute_mod(x);
            differ += !same_bits(lanes, g) || !same_bits(scalar, g);
            outside += g < -288.0f || g > 288.0f;
        });
    CHECK(differ == 0);
    CHECK(outside == 0);
    // mod 7 of floor(p * K), p a permutation: whole numbers in [-42, 41]; a margin either side.
    differ = 0;
    over_lanes(
        129, [](std::int64_t i) { return float(i - 64); }, [](const auto& x) { return noise::mod_whole(x, 7.0f); },
        [&](float x, float lanes, float scalar) {
            differ += !same_bits(lanes, glsl_mod(x, 7.0f)) || !same_bits(scalar, glsl_mod(x, 7.0f));
        });
    CHECK(differ == 0);
}

}  // namespace qs::glsl
