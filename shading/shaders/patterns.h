#pragma once
// The chapter's other patterns on the plane (st in [0,1]^2): Figure 1.2 regular patterns, plain
// and anti-aliased; Figure 1.5 Worley patterns; Listings 1.2, 1.3 and 1.4. Translated from the
// .frag files beside this header.

#include "shading/glsl.h"
#include "shading/noise/cellular.h"
#include "shading/noise/flow_noise.h"
#include "shading/noise/simplex2d.h"
#include "shading/program.h"
#include "shading/program_of.h"
#include "shading/shaders/aastep.h"
#include "shading/shaders/table_1_1.h"

namespace qs::shaders {
using namespace qs::glsl;

// Plane pattern: st varying, no time, no texture.
constexpr ShaderInfo plane_pattern(std::string_view name, std::string_view description, bool derivatives,
                                   std::array<std::string_view, 3> fragment, std::string_view defines = {},
                                   std::string_view vertex = "shaders/plane_st.vert") {
    return ShaderInfo{name, description,
                      Needs{.derivatives = derivatives, .texture = false, .time = false},
                      {vertex}, fragment, defines};
}

// The fragment's colour from a grey value.
template <class F>
vec4<F> grey(const F& g) { return vec4<F>(vec3<F>(g), 1.0f); }

struct PatternS {
    static constexpr ShaderInfo info = plane_pattern("pattern_s", "Figure 1.2: s as a grey ramp", false, {"shaders/pattern_s.frag"});
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) { return grey(in.st.x); }
};

struct Lines {
    static constexpr ShaderInfo info = with_wide_batches(plane_pattern("lines", "Figure 1.2: fract(10 s)", false, {"shaders/lines.frag"}));
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) { return grey(fract(10.0f * in.st.x)); }
};

struct Ridges {
    static constexpr ShaderInfo info = with_wide_batches(plane_pattern("ridges", "Figure 1.2: abs(fract(5 s) * 2 - 1)", false, {"shaders/ridges.frag"}));
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return grey(abs(fract(5.0f * in.st.x) * 2.0f - 1.0f));
    }
};

struct Checker {
    static constexpr ShaderInfo info = with_wide_batches(plane_pattern("checker", "Figure 1.2: checkerboard", false, {"shaders/checker.frag"}));
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> st = in.st;
        return grey(mod(floor(10.0f * st.x) + floor(10.0f * st.y), 2.0f));
    }
};

struct Wave {
    static constexpr ShaderInfo info = with_wide_batches(plane_pattern("wave", "Figure 1.2: sine wave edge, fixed width", false, {"shaders/wave.frag"}));
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> st = in.st;
        return grey(smoothstep(-0.01f, 0.01f, 0.2f - 0.1f * sin(30.0f * st.x) - st.y));
    }
};

struct WaveAA {
    static constexpr ShaderInfo info = with_wide_batches(plane_pattern("wave_aa", "Figure 1.2: sine wave edge with aastep", true,
                                                                       {"shaders/aastep.glsl", "shaders/wave_aa.frag"}));
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> st = in.st;
        return grey(aastep(F(0.0f), 0.2f - 0.1f * sin(30.0f * st.x) - st.y));
    }
};

// max(|fract(8 s - 0.5 mod(floor(8 t), 2)) - 0.5|, |fract(8 t) - 0.5|): 0.5 on the mortar.
template <class F>
F brick_distance(const vec2<F>& st) {
    return max(abs(fract(8.0f * st.x - 0.5f * mod(floor(8.0f * st.y), 2.0f)) - 0.5f), abs(fract(8.0f * st.y) - 0.5f));
}

struct Bricks {
    static constexpr ShaderInfo info = with_wide_batches(plane_pattern("bricks", "Figure 1.2: bricks, fixed width", false, {"shaders/bricks.frag"}));
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return grey(smoothstep(0.4f, 0.5f, brick_distance(in.st)));
    }
};

template <AAWidth W = AAWidth::Length>
struct BricksAA {
    static constexpr ShaderInfo info = with_wide_batches(plane_pattern(aa_variant_name(W, "bricks_aa", "bricks_aa_fwidth", "bricks_aa_step"),
                                                                       "Figure 1.2: bricks with aastep", W != AAWidth::Step,
                                                                       {"shaders/aastep.glsl", "shaders/bricks_aa.frag"}, aa_variant_defines(W)));
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return grey(aastep<W>(F(0.45f), brick_distance(in.st)));
    }
};

template <AAWidth W = AAWidth::Length>
struct DotsAA {
    static constexpr ShaderInfo info = plane_pattern(aa_variant_name(W, "dots_aa", "dots_aa_fwidth", "dots_aa_step"),
                                                     "Figure 1.2: dots with aastep", W != AAWidth::Step,
                                                     {"shaders/aastep.glsl", "shaders/dots_aa.frag"}, aa_variant_defines(W));
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return grey(aastep<W>(F(0.31f), length(fract(5.0f * in.st) - 0.5f)));
    }
};

struct Facets {
    static constexpr ShaderInfo info = with_wide_batches(
        plane_pattern("facets", "Figure 1.5: 0.1 + F2 - F1", false, {"noise/cellular.glsl", "shaders/facets.frag"}));
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> Fs = noise::cellular(in.st * 10.0f);
        return grey(0.1f + (Fs.y - Fs.x));
    }
};

struct Blobs {
    static constexpr ShaderInfo info =
        plane_pattern("blobs", "Figure 1.5: 1 - F1^2", false, {"noise/cellular.glsl", "shaders/blobs.frag"});
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> Fs = noise::cellular(in.st * 10.0f);
        return grey(1.0f - Fs.x * Fs.x);
    }
};

struct Rings {
    static constexpr ShaderInfo info = plane_pattern("rings", "Figure 1.5: rings, two aasteps of F1", true,
                                                     {"noise/cellular.glsl", "shaders/aastep.glsl", "shaders/rings.frag"});
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> Fs = noise::cellular(in.st * 10.0f);
        return grey(1.0f - aastep(F(0.45f), Fs.x) + aastep(F(0.55f), Fs.x));
    }
};

// The typo makes the noise jump across simplex edges (tests/shading); Mesa's reassociated dot
// products put one pixel of the grazing plane on the jump's other side (measured: 1 pixel, 83/255).
inline constexpr CheckBound kSeedTypoCheckBounds[] = {
    {"grazing-plane", "fine", 3, 3, 0,
     "the typo's jumps along simplex edges, where Mesa's reassociated dot products move a pixel across (measured 1)"}};

template <noise::Simplex2dCorner corner>
struct Simplex2d {
    static constexpr bool typo = corner == noise::Simplex2dCorner::SeedTypo;
    static constexpr ShaderInfo info = with_check_bounds(
        with_wide_batches(plane_pattern(
            typo ? "simplex2d_seed_typo" : "simplex2d",
            typo ? "Listing 1.3 with the seed's C.xxxx typo (breaks along simplex edges)" : "Listing 1.3: 2D simplex noise",
            false, {"noise/simplex2d.glsl", "shaders/simplex2d.frag"}, typo ? "#define SIMPLEX2D_SEED_TYPO\n" : "",
            "shaders/plane_st10.vert")),
        typo ? std::span<const CheckBound>(kSeedTypoCheckBounds) : std::span<const CheckBound>());
    using VertexStage = PlaneSt10;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return grey(0.5f + 0.5f * noise::snoise<F, corner>(in.st));
    }
};

struct Cellular2x2 {
    static constexpr ShaderInfo info = with_wide_batches(plane_pattern(
        "cellular2x2", "Listing 1.4 as printed: squared F1, 2x2 search", false, {"shaders/cellular2x2.frag"}, {},
        "shaders/plane_st10.vert"));
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
    static constexpr ShaderInfo info = with_wide_batches(plane_pattern(
        "gradient_aa", "Listing 1.2: noise contour anti-aliased by its analytic gradient and the Jacobian of st", true,
        {"noise/flow_noise.glsl", "shaders/gradient_aa.frag"}));
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

}  // namespace qs::shaders
