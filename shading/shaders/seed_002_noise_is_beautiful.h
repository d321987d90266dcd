#pragma once
// Seed 002: the "Noise is Beautiful" notes. Two of its cell hashes, each shown on 32 cells across
// the Table 1.1 plane (the seed says how to hash, not what it drew), and Perlin noise with
// gradients from the permutation polynomial. Translated from the .frag
// files beside this header, line for line; pcg_hash and cellnoise_pcg2 are seed_patterns.h's.

#include "shading/glsl.h"
#include "shading/program.h"
#include "shading/program_of.h"
#include "shading/shaders/seed_patterns.h"
#include "shading/shaders/table_1_1.h"

namespace qs::shaders {
using namespace qs::glsl;

// softpipe's st is an ulp off llvmpipe's (and quadshade's) at some pixels; a hash of 32 cells
// across flips to the neighbouring cell's value there, fully (the tests' bound, measured on the
// Table 1.1 plane: 1495 pixels of 250000 for either hash).
inline constexpr CheckBound kCellHashCheckBounds[] = {
    {"table-1.1-plane", "coarse-lower", 1800, 1800, 0,
     "softpipe's st is an ulp off at cell borders, where a hash of floor(st * 32) picks the neighbouring cell "
     "(measured: 1495 pixels)"}};

struct HashPcg {
    static constexpr ShaderInfo info = with_check_bounds(
        with_glsl_version(ShaderInfo{"hash_pcg", "seed 002: the PCG integer hash of 32 cells across (cellnoise_pcg2, GLSL 1.30)",
                                     kPlaneNeeds, {"shaders/plane_st.vert"}, {"shaders/hash_pcg.frag"}},
                          130),
        kCellHashCheckBounds);
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return vec4<F>(vec3<F>(cellnoise_pcg2(in.st * 32.0f)), 1.0f);
    }
};

struct HashPerm289 {
    static constexpr ShaderInfo info = with_check_bounds(
        ShaderInfo{"hash_perm289", "seed 002: the permutation polynomial (34h + 10)h mod 289, chained over 32 cells across",
                   kPlaneNeeds, {"shaders/plane_st.vert"}, {"shaders/hash_perm289.frag"}},
        kCellHashCheckBounds);
    using VertexStage = PlaneSt;
    template <class F>
    static F permute(const F& x) {
        F h = mod(x, 289.0f);
        return mod((34.0f * h + 10.0f) * h, 289.0f);
    }
    // As always, we can generalize this to higher dimensions by chaining
    template <class F>
    static F cellnoise_perm(const vec2<F>& p) {
        // The division by 288.0 normalizes to [0,1].
        return permute(permute(p.x) + p.y) / 288.0f;
    }
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return vec4<F>(vec3<F>(cellnoise_perm(floor(in.st * 32.0f))), 1.0f);
    }
};

struct Perlin2dPerm {
    static constexpr ShaderInfo info{"perlin2d_perm", "seed 002: Perlin noise with gradients from the permutation polynomial, quintic fade, 10 cells across",
                                     kPlaneNeeds, {"shaders/plane_st.vert"}, {"shaders/perlin2d_perm.frag"}};
    using VertexStage = PlaneSt;
    // Generate gradient vecors using a permutation polynomial
    // We can vary B to get different permutation outputs.
    template <class F>
    static F permute(const F& x, float b) {
        F h = mod(x, 289.0f);
        return mod((34.0f * h + b) * h, 289.0f);
    }
    template <class F>
    static vec2<F> gradient(const vec2<F>& p) {
        // Adjustable pseudo-random generator parameter
        float B1 = 7.f;
        float B2 = 23.f;
        F x = permute(permute(p.x, B1) + p.y, B1) / 288.f;
        F y = permute(permute(p.x, B2) + p.y, B2) / 288.f;
        // Our permutation function gives us a value in [0,1].
        // Convert this to a gradient vector that can go in any direction.
        return normalize(vec2<F>(x, y) - vec2<F>(0.5f, 0.5f));
    }
    // Perlin Noise
    template <class F>
    static vec2<F> fade(const vec2<F>& t) { return ((6.0f * t - 15.0f) * t + 10.0f) * t * t * t; }
    template <class F>
    static F noise(const vec2<F>& p) {
        F s = fract(p.x);
        F t = fract(p.y);
        vec2<F> v00 = vec2<F>(s, t);
        vec2<F> v01 = vec2<F>(s, t - 1.0f);
        vec2<F> v10 = vec2<F>(s - 1.0f, t);
        vec2<F> v11 = vec2<F>(s - 1.0f, t - 1.0f);
        vec2<F> pf = floor(p);
        vec2<F> g00 = gradient(pf);
        vec2<F> g01 = gradient(pf + vec2<F>(0.0f, 1.0f));
        vec2<F> g10 = gradient(pf + vec2<F>(1.0f, 0.0f));
        vec2<F> g11 = gradient(pf + vec2<F>(1.0f, 1.0f));
        F n00 = dot(v00, g00);
        F n01 = dot(v01, g01);
        F n10 = dot(v10, g10);
        F n11 = dot(v11, g11);
        vec2<F> faded = fade(vec2<F>(s, t));
        F n0 = (1.0f - faded.x) * n00 + faded.x * n10;
        F n1 = (1.0f - faded.x) * n01 + faded.x * n11;
        F n = (1.0f - faded.y) * n0 + faded.y * n1;
        return (n + 1.0f) / 2.0f;
    }
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return vec4<F>(vec3<F>(noise(in.st * 10.0f)), 1.0f);
    }
};

}  // namespace qs::shaders
