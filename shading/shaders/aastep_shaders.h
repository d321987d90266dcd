#pragma once
// The chapter's shaders that anti-alias an edge, each a template over the width of the edge's
// ramp (aastep.h: the chapter's, 0.7 fwidth, or none), for the error study that compares them.
// Their chapter forms are registered with their figures and tables (figure_1_1.h, table_1_1.h,
// patterns.h), the other forms together (aa_variants.h); this header registers nothing, so that
// all of them include it. Translated from the .frag files beside this header.

#include <span>

#include "shading/glsl.h"
#include "shading/noise/cellular.h"
#include "shading/noise/simplex2d.h"
#include "shading/program.h"
#include "shading/shaders/aastep.h"
#include "shading/shaders/vertex_stages.h"
#include "shading/vertex.h"

namespace qs::shaders {
using namespace qs::glsl;

// The fragment's colour from a grey value.
template <class F>
vec4<F> grey(const F& g) { return vec4<F>(vec3<F>(g), 1.0f); }

// max(|fract(8 s - 0.5 mod(floor(8 t), 2)) - 0.5|, |fract(8 t) - 0.5|): 0.5 on the mortar.
template <class F>
F brick_distance(const vec2<F>& st) {
    return max(abs(fract(8.0f * st.x - 0.5f * mod(floor(8.0f * st.y), 2.0f)) - 0.5f), abs(fract(8.0f * st.y) - 0.5f));
}

// Figure 1.2.
template <AAWidth W = AAWidth::Length>
struct BricksAA {
    static constexpr ShaderInfo info{
        .name = aa_variant_name(W, "bricks_aa", "bricks_aa_fwidth", "bricks_aa_step"),
        .description = "Figure 1.2: bricks with aastep",
        .needs = {.derivatives = W != AAWidth::Step},
        .glsl_fragment = {"shaders/aastep.glsl", "shaders/bricks_aa.frag"},
        .glsl_defines = aa_variant_defines(W),
        .wide_batches = true,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return grey(aastep<W>(F(0.45f), brick_distance(in.st)));
    }
};

template <AAWidth W = AAWidth::Length>
struct DotsAA {
    static constexpr ShaderInfo info{
        .name = aa_variant_name(W, "dots_aa", "dots_aa_fwidth", "dots_aa_step"),
        .description = "Figure 1.2: dots with aastep",
        .needs = {.derivatives = W != AAWidth::Step},
        .glsl_fragment = {"shaders/aastep.glsl", "shaders/dots_aa.frag"},
        .glsl_defines = aa_variant_defines(W),
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return grey(aastep<W>(F(0.31f), length(fract(5.0f * in.st) - 0.5f)));
    }
};

// Table 1.1 / Figure 1.5.
template <AAWidth W = AAWidth::Length>
struct WorleyTiles {
    static constexpr ShaderInfo info{
        .name = aa_variant_name(W, "worley_tiles", "worley_tiles_fwidth", "worley_tiles_step"),
        .description = "Table 1.1 / Figure 1.5: anti-aliased Worley tiles",
        .needs = {.derivatives = W != AAWidth::Step},
        .glsl_fragment = {"noise/cellular.glsl", "shaders/aastep.glsl", "shaders/worley_tiles.frag"},
        .glsl_defines = aa_variant_defines(W),
        .wide_batches = true,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> st = in.st;
        vec4<F> d1d2;
        vec2<F> Fs = noise::cellular_vectors(st * 8.0f, d1d2);  // GLSL: vec2 F
        F thresh = 0.05f * length(d1d2.xy() - d1d2.zw()) / (Fs.x + Fs.y);
        F f = Fs.y - Fs.x + (0.5f - noise::cellular(st * 64.0f).y) * thresh;
        return vec4<F>(vec3<F>(aastep<W>(thresh, f)), 1.0f);
    }
};

// The un-anti-aliased variant: a plain step turns the last-ulp difference of a value lying on its
// threshold into a full flip, which aastep's ramp absorbs (tests/reference/test_reference.cpp).
inline constexpr CheckBound kHalftoneStepCheckBounds[] = {
    {"table-1.1-plane", "", 6, 6, 0,
     "a plain step flips fully where the last ulp of a value on its threshold differs (measured: 1 pixel against "
     "llvmpipe, 3 against softpipe)"}};

// Table 1.1 / Listing 1.5. The blend to plain RGB takes derivatives in every variant, the step
// one included.
template <AAWidth W = AAWidth::Length>
struct Halftone {
    static constexpr ShaderInfo info{
        .name = aa_variant_name(W, "halftone", "halftone_fwidth", "halftone_step"),
        .description = "Table 1.1 / Listing 1.5: CMYK halftone of an image, blended to RGB when minified",
        .needs = {.derivatives = true, .texture = true},
        .glsl_fragment = {"noise/simplex2d.glsl", "shaders/aastep.glsl", "shaders/halftone.frag"},
        .glsl_defines = aa_variant_defines(W),
        .wide_batches = true,
        .check_bounds = W == AAWidth::Step ? std::span<const CheckBound>(kHalftoneStepCheckBounds) : std::span<const CheckBound>(),
    };
    // halftone.vert; its `dims` uniform is the texture's size.
    struct VertexStage {
        static constexpr GlslFiles glsl{"shaders/halftone.vert"};
        template <class T>
        struct Varyings {
            vec2<T> st;
            vec2<T> one;
            auto fields() { return std::tie(st, one); }
        };
        static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<VertexStage>& out) {
            const vec2<float> dims(float(u.teximage->width), float(u.teximage->height));
            out.st = {in.texcoord.x, in.texcoord.y};
            out.one = 1.0f / dims;
            out.gl_Position = transform_point(u.model_view_projection, in.position);
        }
    };
    // Explicit bilinear lookups to circumvent imprecise interpolation.
    template <class F>
    static vec4<F> texture2D_bilinear(const sampler2D& tex, const vec2<F>& st, const vec2<F>& dims, const vec2<F>& one) {
        vec2<F> uv = st * dims;
        vec2<F> uv00 = floor(uv - vec2<F>(0.5f));     // Lower left of lower left texel
        vec2<F> uvlerp = uv - uv00 - vec2<F>(0.5f);   // Texel-local blends [0,1]
        vec2<F> st00 = (uv00 + vec2<F>(0.5f)) * one;
        vec4<F> texel00 = texture2D(tex, st00);
        vec4<F> texel10 = texture2D(tex, st00 + vec2<F>(one.x, 0.0f));
        vec4<F> texel01 = texture2D(tex, st00 + vec2<F>(0.0f, one.y));
        vec4<F> texel11 = texture2D(tex, st00 + one);
        vec4<F> texel0 = mix(texel00, texel01, uvlerp.y);
        vec4<F> texel1 = mix(texel10, texel11, uvlerp.y);
        return mix(texel0, texel1, uvlerp.x);
    }
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        using noise::snoise;
        vec2<F> st = in.st, one = in.one;
        vec2<F> dims(float(u.teximage->width), float(u.teximage->height));
        vec3<F> rgb = texture2D_bilinear(*u.teximage, st, dims, one).rgb();
        F n = 0.1f * snoise(st * 200.0f);
        n += 0.05f * snoise(st * 400.0f);
        n += 0.025f * snoise(st * 800.0f);  // Fractal noise, 3 octaves
        vec4<F> cmyk;
        vec3<F> cmy = 1.0f - rgb;                   // Rough CMY conversion (GLSL: cmyk.xyz = ...)
        cmyk.w = min(cmy.x, min(cmy.y, cmy.z));     // Create K
        cmyk = vec4<F>(cmy - cmyk.w, cmyk.w);       // Subtract K amount from CMY (GLSL: cmyk.xyz -= cmyk.w)

        // CMYK halftone screens, in angles 15/-15/0/45 degrees
        vec2<F> Cuv = 50.0f * mat2<F>(0.966f, -0.259f, 0.259f, 0.966f) * st;
        Cuv = fract(Cuv) - 0.5f;
        F c = aastep<W>(F(0.0f), sqrt(cmyk.x) - 2.0f * length(Cuv) + n);
        vec2<F> Muv = 50.0f * mat2<F>(0.966f, 0.259f, -0.259f, 0.966f) * st;
        Muv = fract(Muv) - 0.5f;
        F m = aastep<W>(F(0.0f), sqrt(cmyk.y) - 2.0f * length(Muv) + n);
        vec2<F> Yuv = 50.0f * st;  // 0 deg
        Yuv = fract(Yuv) - 0.5f;
        F y = aastep<W>(F(0.0f), sqrt(cmyk.z) - 2.0f * length(Yuv) + n);
        vec2<F> Kuv = 50.0f * mat2<F>(0.707f, -0.707f, 0.707f, 0.707f) * st;
        Kuv = fract(Kuv) - 0.5f;
        F k = aastep<W>(F(0.0f), sqrt(cmyk.w) - 2.0f * length(Kuv) + n);

        vec3<F> rgbscreen = 1.0f - vec3<F>(c, m, y);
        rgbscreen = mix(rgbscreen, vec3<F>(0.0f), 0.7f * k + 0.5f * n);
        vec2<F> fw = fwidth(st);
        F blend = smoothstep(0.7f, 1.4f, 200.0f * max(fw.x, fw.y));  // GLSL: fw.s, fw.t
        return vec4<F>(mix(rgbscreen, rgb, blend), 1.0f);
    }
};

// Figure 1.1 sphere 3. The book's form blends over fwidth; the error study adds the gradient's
// length (AAWidth::Length) and no anti-aliasing (AAWidth::Step), selected in GLSL by SPOTS_LENGTH /
// SPOTS_STEP.
template <AAWidth W = AAWidth::Fwidth>
struct Spots {
    static constexpr ShaderInfo info{
        .name = W == AAWidth::Fwidth ? "spots" : W == AAWidth::Length ? "spots_length" : "spots_step",
        .description = "Figure 1.1 sphere 3: rings around 3D Worley points (cellular2x2x2), fwidth anti-aliasing",
        .needs = {.coordinates = Coordinates::Object3D, .derivatives = W != AAWidth::Step, .time = true},
        .glsl_fragment = {"noise/cellular.glsl", "shaders/spots.frag"},
        .glsl_defines = W == AAWidth::Fwidth ? "" : W == AAWidth::Length ? "#define SPOTS_LENGTH\n" : "#define SPOTS_STEP\n",
        .time_period = 289.0,  // P.z moves with time; cellular hashes floor(P) mod 289
        .wide_batches = true,
    };
    using VertexStage = Sphere<4, -1>;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> Fs = noise::cellular2x2x2(in.P);  // GLSL: vec2 F
        if constexpr (W == AAWidth::Step) {
            F n1 = step(0.4f, Fs.x);
            F n2 = step(0.5f, Fs.x);
            return vec4<F>(n1, n2, n2, 1.0f);
        } else {
            F s = W == AAWidth::Length ? length(vec2<F>(dFdx(Fs.x), dFdy(Fs.x))) : fwidth(Fs.x);
            F n1 = smoothstep(0.4f - s, 0.4f + s, Fs.x);
            F n2 = smoothstep(0.5f - s, 0.5f + s, Fs.x);
            return vec4<F>(n1, n2, n2, 1.0f);
        }
    }
};

}  // namespace qs::shaders
