#pragma once
// The "Noise is Beautiful" notes' permutation polynomial with a parameter, and its 3D gradient: translated from
// permute_polynomial.glsl beside this file, line for line.

#include "shading/glsl.h"

namespace qs::noise::noise_is_beautiful {
using namespace qs::glsl;

// Generate gradient vecors using a permutation polynomial
// We can vary B to get different permutation outputs.
template <class F>
F permute(const F& x, float b) {
    F h = mod(x, 289.0f);
    return mod((34.0f * h + b) * h, 289.0f);
}

// The scattering example's gradient ("Scatterings", "Example: Sample Code"): a lattice point's three hashes, centred and
// normalised: NaN at lattice (142, 2, 248) mod 289, where all three hashes are 144 (no scene
// here reaches it).
template <class F>
vec3<F> gradient(const vec3<F>& p) {
    float B1 = 11.f;
    float B2 = 134.f;
    float B3 = 53.f;
    F x = permute(permute(permute(p.x, B1) + p.y, B1) + p.z, B1) / 288.f;
    F y = permute(permute(permute(p.x, B2) + p.y, B2) + p.z, B2) / 288.f;
    F z = permute(permute(permute(p.x, B3) + p.y, B3) + p.z, B3) / 288.f;
    // Our permutation function gives us a value in [0,1].
    // Convert this to a gradient vector that can go in any direction.
    return normalize(vec3<F>(x, y, z) - vec3<F>(0.5f, 0.5f, 0.5f));
}

}  // namespace qs::noise::noise_is_beautiful
