#pragma once
// The chapter's other patterns on the plane (st in [0,1]^2): Figure 1.2 regular patterns, plain
// and anti-aliased; Figure 1.5 Worley patterns; Listings 1.2 and 1.4 (Listing 1.3 has a family of
// its own, listing_1_3.h). Translated from the .frag files beside this header.

#include "shading/glsl.h"
#include "shading/noise/cellular.h"
#include "shading/noise/flow_noise.h"
#include "shading/program.h"
#include "shading/program_of.h"
#include "shading/shaders/aastep_shaders.h"
#include "shading/shaders/collections.h"
#include "shading/shaders/vertex_stages.h"

namespace qs::shaders {
using namespace qs::glsl;

struct PatternS {
    static constexpr ShaderInfo info{
        .name = "pattern_s",
        .description = "Figure 1.2: s as a grey ramp",
        .glsl_fragment = {"shaders/pattern_s.frag"},
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) { return grey(in.st.x); }
};

struct Lines {
    static constexpr ShaderInfo info{
        .name = "lines",
        .description = "Figure 1.2: fract(10 s)",
        .glsl_fragment = {"shaders/lines.frag"},
        .wide_batches = true,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) { return grey(fract(10.0f * in.st.x)); }
};

struct Ridges {
    static constexpr ShaderInfo info{
        .name = "ridges",
        .description = "Figure 1.2: abs(fract(5 s) * 2 - 1)",
        .glsl_fragment = {"shaders/ridges.frag"},
        .wide_batches = true,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return grey(abs(fract(5.0f * in.st.x) * 2.0f - 1.0f));
    }
};

struct Checker {
    static constexpr ShaderInfo info{
        .name = "checker",
        .description = "Figure 1.2: checkerboard",
        .glsl_fragment = {"shaders/checker.frag"},
        .wide_batches = true,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> st = in.st;
        return grey(mod(floor(10.0f * st.x) + floor(10.0f * st.y), 2.0f));
    }
};

struct Wave {
    static constexpr ShaderInfo info{
        .name = "wave",
        .description = "Figure 1.2: sine wave edge, fixed width",
        .glsl_fragment = {"shaders/wave.frag"},
        .wide_batches = true,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> st = in.st;
        return grey(smoothstep(-0.01f, 0.01f, 0.2f - 0.1f * sin(30.0f * st.x) - st.y));
    }
};

struct WaveAA {
    static constexpr ShaderInfo info{
        .name = "wave_aa",
        .description = "Figure 1.2: sine wave edge with aastep",
        .needs = {.derivatives = true},
        .glsl_fragment = {"shaders/aastep.glsl", "shaders/wave_aa.frag"},
        .wide_batches = true,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> st = in.st;
        return grey(aastep(F(0.0f), 0.2f - 0.1f * sin(30.0f * st.x) - st.y));
    }
};

struct Bricks {
    static constexpr ShaderInfo info{
        .name = "bricks",
        .description = "Figure 1.2: bricks, fixed width",
        .glsl_fragment = {"shaders/bricks.frag"},
        .wide_batches = true,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return grey(smoothstep(0.4f, 0.5f, brick_distance(in.st)));
    }
};

struct Facets {
    static constexpr ShaderInfo info{
        .name = "facets",
        .description = "Figure 1.5: 0.1 + F2 - F1",
        .glsl_fragment = {"noise/cellular.glsl", "shaders/facets.frag"},
        .wide_batches = true,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> Fs = noise::cellular(in.st * 10.0f);
        return grey(0.1f + (Fs.y - Fs.x));
    }
};

struct Blobs {
    static constexpr ShaderInfo info{
        .name = "blobs",
        .description = "Figure 1.5: 1 - F1^2",
        .glsl_fragment = {"noise/cellular.glsl", "shaders/blobs.frag"},
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> Fs = noise::cellular(in.st * 10.0f);
        return grey(1.0f - Fs.x * Fs.x);
    }
};

struct Rings {
    static constexpr ShaderInfo info{
        .name = "rings",
        .description = "Figure 1.5: rings, two aasteps of F1",
        .needs = {.derivatives = true},
        .glsl_fragment = {"noise/cellular.glsl", "shaders/aastep.glsl", "shaders/rings.frag"},
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> Fs = noise::cellular(in.st * 10.0f);
        return grey(1.0f - aastep(F(0.45f), Fs.x) + aastep(F(0.55f), Fs.x));
    }
};

struct Cellular2x2 {
    static constexpr ShaderInfo info{
        .name = "cellular2x2",
        .description = "Listing 1.4 as printed: squared F1, 2x2 search",
        .glsl_fragment = {"shaders/cellular2x2.frag"},
        .wide_batches = true,
    };
    using VertexStage = PlaneSt10;
    template <class V>
    static V permute(const V& x) { return mod((34.0f * x + 1.0f) * x, 289.0f); }
    template <class F>
    static vec2<F> cellular2x2(const vec2<F>& P) {
        const float K = 1.0f / 7.0f;
        const float K2 = 0.5f / 7.0f;
        const float jitter = 0.8f;  // jitter 1.0 makes F1 wrong more often
        vec2<F> Pi = mod(floor(P), 289.0f);
        vec2<F> Pf = fract(P);
        vec4<F> Pfx = Pf.x + vec4<F>(-0.5f, -1.5f, -0.5f, -1.5f);
        vec4<F> Pfy = Pf.y + vec4<F>(-0.5f, -0.5f, -1.5f, -1.5f);
        vec4<F> p = permute(Pi.x + vec4<F>(0.0f, 1.0f, 0.0f, 1.0f));
        p = permute(p + Pi.y + vec4<F>(0.0f, 0.0f, 1.0f, 1.0f));
        vec4<F> ox = mod(p, 7.0f) * K + K2;
        vec4<F> oy = mod(floor(p * K), 7.0f) * K + K2;
        vec4<F> dx = Pfx + jitter * ox;
        vec4<F> dy = Pfy + jitter * oy;
        vec4<F> d = dx * dx + dy * dy;  // distances squared
        // Cheat and pick only F1 for the return value
        vec2<F> dxy = min(d.xy(), d.zw());  // GLSL: d.xy = min(d.xy, d.zw);
        F d1 = min(dxy.x, dxy.y);           // GLSL: d.x = min(d.x, d.y);
        return vec2<F>(d1);                 // F1 duplicated, F2 not computed
    }
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> Fs = cellular2x2(in.st);  // GLSL: vec2 F
        F n = 1.0f - 1.5f * Fs.x;
        return grey(n);
    }
};

struct GradientAA {
    static constexpr ShaderInfo info{
        .name = "gradient_aa",
        .description = "Listing 1.2: noise contour anti-aliased by its analytic gradient and the Jacobian of st",
        .needs = {.derivatives = true},
        .glsl_fragment = {"noise/flow_noise.glsl", "shaders/gradient_aa.frag"},
        .wide_batches = true,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> p = in.st * 10.0f;
        vec2<F> G2_st;
        F n = noise::srdnoise(p, F(0.0f), G2_st);
        mat2<F> Jacobian2(dFdx(p), dFdy(p));
        vec2<F> G2_xy = G2_st * Jacobian2;  // the listing's `Jacobian2 * G2_st` transposed: see the .frag
        F afwidth = 0.7f * length(G2_xy);
        return grey(smoothstep(-afwidth, afwidth, n));
    }
};

QUADSHADE_SHADERS_IN(kGustavson, PatternS, Lines, Ridges, Checker, Wave, WaveAA, Bricks, BricksAA<>, DotsAA<>, Facets, Blobs, Rings,
                     Cellular2x2, GradientAA)

}  // namespace qs::shaders
