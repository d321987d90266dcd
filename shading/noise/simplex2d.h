#pragma once
// 2D simplex noise, Listing 1.3, translated from simplex2d.glsl beside this file.

#include "shading/glsl.h"

namespace qs::noise {
using namespace qs::glsl;

// GLSL: x - floor(x * (1.0 / 289.0)) * 289.0 and mod289(((x*34.0)+1.0)*x). Each multiply and
// the addition after it are one exact_product_add: where the product is exact, rounding once or
// twice gives the same bits, and fused they take one step and a multiply pipe instead of two
// steps, one on the adders the noise keeps busiest (5x Perlin 3% faster, Perlin 4%).
// - floor(x / 289) * 289 is exact while |x| < 2^24 - 289: the product's magnitude stays below
//   2^24 (2^53 in double), where floats are whole numbers.
// - x * 34 is exact for whole x below 2^24 / 34. These noises permute whole numbers below 582:
//   mod289 of a whole number below 2^24 lies in [-2, 290] (its floor may be one off next to a
//   multiple of 289), and each permute adds at most 291 to one; (34 * 581 + 1) * 581 < 2^24 - 289.
// So the noises give llvmpipe's bits while their lattice point i (the coordinates skewed, up to
// 2.3 times them in 4D) stays below 2^24 - 289 in magnitude: for coordinates below about 7
// million, near where a float's spacing reaches 1 and no fraction is left to make noise of
// (tests/shading/test_exact_product_add.cpp checks every whole number in range, and floats
// between them).
template <class V>
V mod289(const V& x) { return exact_product_add(floor(x * (1.0f / 289.0f)), V(-289.0f), x); }
template <class V>
V permute289(const V& x) { return mod289(exact_product_add(x, V(34.0f), V(1.0f)) * x); }  // GLSL: permute

// Corner offset of Listing 1.3. The chapter prints C.xxxx; every published copy has C.xxzz.
enum class Simplex2dCorner { Correct, ListingTypo };

template <class F, Simplex2dCorner corner = Simplex2dCorner::Correct>
F snoise(const vec2<F>& v) {
    const vec4<F> C(0.211324865405187f,    // (3.0-sqrt(3.0))/6.0
                    0.366025403784439f,    // 0.5*(sqrt(3.0)-1.0)
                    -0.577350269189626f,   // -1.0 + 2.0 * C.x
                    0.024390243902439f);   // 1.0 / 41.0
    // First corner
    vec2<F> i = floor(v + dot(v, C.yy()));
    vec2<F> x0 = v - i + dot(i, C.xx());
    // Other corners
    vec2<F> i1 = select(x0.x > x0.y, vec2<F>(1.0f, 0.0f), vec2<F>(0.0f, 1.0f));
    vec4<F> x12 = x0.xyxy() + (corner == Simplex2dCorner::Correct ? C.xxzz() : vec4<F>(C.x));
    x12 = vec4<F>(x12.xy() - i1, x12.zw());  // GLSL: x12.xy -= i1;
    // Permutations
    i = mod289(i);  // Avoid truncation effects in permutation
    vec3<F> p = permute289(permute289(i.y + vec3<F>(0.0f, i1.y, 1.0f)) + i.x + vec3<F>(0.0f, i1.x, 1.0f));
    vec3<F> m = max(0.5f - vec3<F>(dot(x0, x0), dot(x12.xy(), x12.xy()), dot(x12.zw(), x12.zw())), 0.0f);
    m = m * m;
    m = m * m;
    // Gradients
    // 2 f is exact (a power of two's multiple, f in [0, 1)), so fused it is the GLSL's bits.
    vec3<F> x = exact_product_add(fract(p * vec3<F>(C.w)), vec3<F>(2.0f), vec3<F>(-1.0f));  // GLSL: 2.0 * fract(p * C.www) - 1.0
    vec3<F> h = abs(x) - 0.5f;
    vec3<F> a0 = x - floor(x + 0.5f);
    // Normalise gradients implicitly by scaling m
    m *= 1.79284291400159f - 0.85373472095314f * (a0 * a0 + h * h);
    // Compute final noise value at P
    vec3<F> g;
    g.x = a0.x * x0.x + h.x * x0.y;
    vec2<F> gyz = vec2<F>(a0.y, a0.z) * x12.xz() + vec2<F>(h.y, h.z) * x12.yw();  // GLSL: g.yz = ...
    g.y = gyz.x;
    g.z = gyz.y;
    return 130.0f * dot(m, g);
}

}  // namespace qs::noise
