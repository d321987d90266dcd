#pragma once
// Notes on the book "Noise is Beautiful" (collections.h cites them). Two of their cell hashes, each
// shown on 32 cells across the Table 1.1 plane (the notes say how to hash, not what they drew);
// Perlin noise with gradients from the permutation polynomial in 2D and 3D; simplex noise in 2D (on
// the notes' shear) and 3D (Fibonacci-sphere gradients), their analytic gradients (dnoise), fBm, a
// multifractal, domain warping and the Shadertoy scattering example. The 3D noises are solid
// textures (P = 4 cells per object unit), compared on the sphere scene. Translated from the .frag
// files beside this header and the noise in shading/noise/ (pcg_hash, permute_polynomial,
// simplex2d_skew, simplex3d_fibonacci), line for line.

#include "shading/glsl.h"
#include "shading/program.h"
#include "shading/noise/pcg_hash.h"
#include "shading/noise/permute_polynomial.h"
#include "shading/noise/simplex2d_skew.h"
#include "shading/noise/simplex3d_fibonacci.h"
#include "shading/program_of.h"
#include "shading/shaders/collections.h"
#include "shading/shaders/vertex_stages.h"

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
    static constexpr ShaderInfo info{
        .name = "hash_pcg",
        .description = "the PCG integer hash of 32 cells across (cellnoise_pcg2, GLSL 1.30)",
        .glsl_fragment = {"shaders/hash_pcg.frag"},
        .glsl_version = 130,
        .wide_batches = true,
        .check_bounds = kCellHashCheckBounds,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return vec4<F>(vec3<F>(noise::cellnoise_pcg2(in.st * 32.0f)), 1.0f);
    }
};

struct HashPerm289 {
    static constexpr ShaderInfo info{
        .name = "hash_perm289",
        .description = "the permutation polynomial (34h + 10)h mod 289, chained over 32 cells across",
        .glsl_fragment = {"shaders/hash_perm289.frag"},
        .check_bounds = kCellHashCheckBounds,
    };
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
    static constexpr ShaderInfo info{
        .name = "perlin2d_perm",
        .description = "Perlin noise with gradients from the permutation polynomial, quintic fade, 10 cells across",
        .glsl_fragment = {"noise/permute_polynomial.glsl", "shaders/perlin2d_perm.frag"},
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec2<F> gradient(const vec2<F>& p) {
        using noise::noise_is_beautiful::permute;
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

// The notes' simplex noise jumps where luv.x == luv.y exactly (their step() pair takes the far
// corner twice and leaves one out): at the finer octaves pixel centres of the Table 1.1 plane lie
// exactly on those lines, where softpipe's st, an ulp off llvmpipe's (and quadshade's), misses
// them (measured: fbm 531 pixels over 1/255 at 500x500, multifractal under 600).
inline constexpr CheckBound kOctaveCheckBounds[] = {
    {"table-1.1-plane", "coarse-lower", 900, 700, 0,
     "softpipe's st is an ulp off where the notes' noise jumps (luv.x == luv.y exactly, hit by pixel centres at fine "
     "octaves)"}};

// Solid textures: the object-space position.
inline constexpr Needs kSolidNeeds{.coordinates = Coordinates::Object3D};

struct Perlin3dPerm {
    static constexpr ShaderInfo info{
        .name = "perlin3d_perm",
        .description = "Perlin noise in 3D, the notes' 3D permutation-polynomial gradients, quintic fade; a solid texture",
        .needs = kSolidNeeds,
        .glsl_fragment = {"noise/permute_polynomial.glsl", "shaders/perlin3d_perm.frag"},
    };
    using VertexStage = ObjectPosition;
    template <class F>
    static vec3<F> fade(const vec3<F>& t) { return ((6.0f * t - 15.0f) * t + 10.0f) * t * t * t; }
    template <class F>
    static F noise(const vec3<F>& p) {
        using noise::noise_is_beautiful::gradient;
        vec3<F> f = fract(p);
        vec3<F> pf = floor(p);
        F n000 = dot(f, gradient(pf));
        F n100 = dot(f - vec3<F>(1.f, 0.f, 0.f), gradient(pf + vec3<F>(1.f, 0.f, 0.f)));
        F n010 = dot(f - vec3<F>(0.f, 1.f, 0.f), gradient(pf + vec3<F>(0.f, 1.f, 0.f)));
        F n110 = dot(f - vec3<F>(1.f, 1.f, 0.f), gradient(pf + vec3<F>(1.f, 1.f, 0.f)));
        F n001 = dot(f - vec3<F>(0.f, 0.f, 1.f), gradient(pf + vec3<F>(0.f, 0.f, 1.f)));
        F n101 = dot(f - vec3<F>(1.f, 0.f, 1.f), gradient(pf + vec3<F>(1.f, 0.f, 1.f)));
        F n011 = dot(f - vec3<F>(0.f, 1.f, 1.f), gradient(pf + vec3<F>(0.f, 1.f, 1.f)));
        F n111 = dot(f - vec3<F>(1.f, 1.f, 1.f), gradient(pf + vec3<F>(1.f, 1.f, 1.f)));
        vec3<F> faded = fade(f);
        F n00 = (1.f - faded.x) * n000 + faded.x * n100;
        F n10 = (1.f - faded.x) * n010 + faded.x * n110;
        F n01 = (1.f - faded.x) * n001 + faded.x * n101;
        F n11 = (1.f - faded.x) * n011 + faded.x * n111;
        F n0 = (1.f - faded.y) * n00 + faded.y * n10;
        F n1 = (1.f - faded.y) * n01 + faded.y * n11;
        F n = (1.f - faded.z) * n0 + faded.z * n1;
        return (n + 1.f) / 2.f;
    }
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return vec4<F>(vec3<F>(noise(in.P)), 1.0f);
    }
};

struct Simplex2dSkew {
    static constexpr ShaderInfo info{
        .name = "simplex2d_skew",
        .description = "simplex noise on the notes' xy_to_uv shear, permutation-polynomial gradients, 10 units across",
        .glsl_fragment = {"noise/permute_polynomial.glsl", "noise/simplex2d_skew.glsl", "shaders/simplex2d_skew.frag"},
        .wide_batches = true,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return vec4<F>(vec3<F>(noise::noise_is_beautiful::noise(in.st * 10.0f)), 1.0f);
    }
};

struct Simplex3dFibonacci {
    static constexpr ShaderInfo info{
        .name = "simplex3d_fibonacci",
        .description = "3D simplex noise with gradients on a Fibonacci sphere (the code ours, from the notes' prose); a solid texture",
        .needs = kSolidNeeds,
        .glsl_fragment = {"noise/permute_polynomial.glsl", "noise/simplex3d_fibonacci.glsl", "shaders/simplex3d_fibonacci.frag"},
        .wide_batches = true,
    };
    using VertexStage = ObjectPosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec3<F> grad;
        return vec4<F>(vec3<F>(noise::noise_is_beautiful::noise3(in.P, grad)), 1.0f);
    }
};

struct Simplex2dDnoise {
    static constexpr ShaderInfo info{
        .name = "simplex2d_dnoise",
        .description = "the analytic gradient of its 2D simplex noise (dnoise, ours: the notes' sum was an image) as red and green, the noise as blue",
        .glsl_fragment = {"noise/permute_polynomial.glsl", "noise/simplex2d_skew.glsl", "shaders/simplex2d_dnoise.frag"},
        .wide_batches = true,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> p = in.st * 10.0f;
        return vec4<F>(0.5f + 0.15f * noise::noise_is_beautiful::dnoise(p), noise::noise_is_beautiful::noise(p), 1.0f);
    }
};

struct Simplex3dDnoise {
    static constexpr ShaderInfo info{
        .name = "simplex3d_dnoise",
        .description = "the analytic gradient of its 3D simplex noise as colour; a solid texture",
        .needs = kSolidNeeds,
        .glsl_fragment = {"noise/permute_polynomial.glsl", "noise/simplex3d_fibonacci.glsl", "shaders/simplex3d_dnoise.frag"},
        .wide_batches = true,
    };
    using VertexStage = ObjectPosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec3<F> grad;
        noise::noise_is_beautiful::noise3(in.P, grad);
        return vec4<F>(0.5f + 0.15f * grad, 1.0f);
    }
};

// Octave loops: a float counter to a constant bound, the same in every lane, as in the notes.
struct FbmSimplex2d {
    static constexpr ShaderInfo info{
        .name = "fbm_simplex2d",
        .description = "fBm, 5 octaves of its 2D simplex noise summed with weights 2^-i, divided by 2",
        .glsl_fragment = {"noise/permute_polynomial.glsl", "noise/simplex2d_skew.glsl", "shaders/fbm_simplex2d.frag"},
        .wide_batches = true,
        .check_bounds = kOctaveCheckBounds,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> xy = in.st * 4.0f;
        float k = 5.f;
        F c = 0.f;
        for (float i = 0.f; i < k; i++) {
            c += pow(2.f, -i) * noise::noise_is_beautiful::noise(pow(2.f, i) * xy);
        }
        c /= 2.f;
        return vec4<F>(vec3<F>(c), 1.0f);
    }
};

struct MultifractalSimplex2d {
    static constexpr ShaderInfo info{
        .name = "multifractal_simplex2d",
        .description = "a multifractal, each octave weighted by 2^-i and the previous octave's noise (a reconstruction: the notes' formula was an image)",
        .glsl_fragment = {"noise/permute_polynomial.glsl", "noise/simplex2d_skew.glsl", "shaders/multifractal_simplex2d.frag"},
        .wide_batches = true,
        .check_bounds = kOctaveCheckBounds,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> xy = in.st * 4.0f;
        float k = 5.f;
        F c = 0.f;
        F previous = 1.f;
        for (float i = 0.f; i < k; i++) {
            F n = noise::noise_is_beautiful::noise(pow(2.f, i) * xy);
            c += pow(2.f, -i) * previous * n;
            previous = n;
        }
        c /= 2.f;
        return vec4<F>(vec3<F>(c), 1.0f);
    }
};

struct WarpDnoise {
    static constexpr ShaderInfo info{
        .name = "warp_dnoise",
        .description = "domain warping, each octave displaced by the summed dnoise gradients of the previous ones",
        .glsl_fragment = {"noise/permute_polynomial.glsl", "noise/simplex2d_skew.glsl", "shaders/warp_dnoise.frag"},
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> xy = in.st * 4.0f;
        float k = 3.f;
        F c = 0.f;
        vec2<F> disp = vec2<F>(0.f);
        for (float i = 0.f; i < k; i++) {
            // We displace what we're sampling from the noise function here
            vec2<F> trans_xy = pow(2.f, i) * (xy + disp);
            c += pow(2.f, -i) * noise::noise_is_beautiful::noise(trans_xy);
            // Update our displacement based on the sampled gradient
            disp += noise::noise_is_beautiful::dnoise(trans_xy);
        }
        c /= 2.f;
        return vec4<F>(vec3<F>(c), 1.0f);
    }
};

// Shadertoy's inputs: iTime is `time`, iResolution.xy the uResolution uniform (the frame's size in
// pixels, set by both renderers), fragCoord gl_FragCoord.xy (scattering3d.frag's #defines).
struct Scattering3d {
    static constexpr UniformDecl kUniforms[] = {
        // Always the frame's size in both renderers; this is only for a draw without a scene.
        {"uResolution", UniformType::Vec2, {64.0f, 64.0f}},
    };
    enum : int { uResolution };
    static constexpr ShaderInfo info{
        .name = "scattering3d",
        .description = "the scattering example (Shadertoy's mainImage): the nearest of 3x3x3 jittered points in (window x 15, time)",
        .needs = {.coordinates = Coordinates::None, .time = true, .frag_coord = true},
        .glsl_fragment = {"noise/permute_polynomial.glsl", "shaders/scattering3d.frag"},
        .uniforms = kUniforms,
        .time_period = 289.0,  // time is the lattice's z, hashed mod 289
        .wide_batches = true,
    };
    using VertexStage = PlanePosition;
    template <class F>
    static vec4<F> mainImage(const vec2<F>& fragCoord, const Uniforms& u) {
        vec3<F> iResolution(uniform<vec2<F>>(u, uResolution), 1.0f);
        F iTime = u.time;
        vec2<F> uv = fragCoord / iResolution.xy();
        vec3<F> xyz = vec3<F>(uv * 15.f, iTime);
        // Config
        float jitter = 0.5f;
        // Determine the cell we are in
        vec3<F> cur_cell = floor(xyz);
        F c = 0.f;
        F d1 = 100.f;
        // Iterate through the neighbors of the cell
        for (int i = -1; i <= 1; i++) {
            for (int j = -1; j <= 1; j++) {
                for (int k = -1; k <= 1; k++) {
                    vec3<F> cell = cur_cell + vec3<F>(float(i), float(j), float(k));
                    // Compute the pseudorandom point from that cell
                    vec3<F> jitter_vec = noise::noise_is_beautiful::gradient(cell) * jitter;
                    vec3<F> point = cell + vec3<F>(0.5f) + jitter_vec;
                    // Compute distance to this point
                    F d = length(point - xyz);
                    // Update d1, d2. D1 is distance to closest, D2
                    // is 2nd closest
                    d1 = select(d < d1, d, d1);
                }
            }
        }
        c = 1.f - 2.f * d1 * d1;
        // Output to screen
        vec3<F> color = mix(vec3<F>(0.1f), vec3<F>(0.8f, 0.1f, 0.2f), c);
        return vec4<F>(color, 1.f);
    }
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        return mainImage(in.gl_FragCoord.xy(), u);
    }
};

QUADSHADE_SHADERS_IN(kNoiseIsBeautiful, HashPcg, HashPerm289, Perlin2dPerm, Perlin3dPerm, Simplex2dSkew, Simplex3dFibonacci, Simplex2dDnoise,
                     Simplex3dDnoise, FbmSimplex2d, MultifractalSimplex2d, WarpDnoise, Scattering3d)

}  // namespace qs::shaders
