#pragma once
// The eight benchmark shaders of Table 1.1, each on the full-window plane with st in [0,1]^2,
// translated from the .frag files beside this header.

#include "shading/glsl.h"
#include "shading/noise/cellular.h"
#include "shading/noise/simplex2d.h"
#include "shading/noise/simplex3d.h"
#include "shading/program.h"
#include "shading/program_of.h"
#include "shading/shaders/aastep.h"
#include "shading/shaders/vertex_stages.h"
#include "shading/vertex.h"

namespace qs::shaders {
using namespace qs::glsl;

inline constexpr Needs kPlaneNeeds{.derivatives = false, .texture = false, .time = false};
inline constexpr Needs kPlaneDerivativeNeeds{.derivatives = true, .texture = false, .time = false};

struct ConstantColor {
    static constexpr ShaderInfo info{"constant_color", "Table 1.1: constant colour",
                                     Needs{.coordinates = Coordinates::None, .derivatives = false, .texture = false, .time = false},
                                     {"shaders/plane_st.vert"}, {"shaders/constant_color.frag"}};
    using VertexStage = PlanePosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>&, const Uniforms&) { return vec4<F>(1.0f, 0.5f, 0.0f, 1.0f); }
};

struct SingleTexture {
    static constexpr ShaderInfo info = with_wide_batches(
        ShaderInfo{"single_texture", "Table 1.1: one bilinear texture lookup (clamp, no mipmaps)",
                   Needs{.derivatives = false, .texture = true, .time = false}, {"shaders/plane_st.vert"},
                   {"shaders/single_texture.frag"}});
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        return texture2D(*u.teximage, in.st);
    }
};

struct Dots {
    static constexpr ShaderInfo info{"dots", "Table 1.1 / Figure 1.2: dots, smoothstep(0.3, 0.32, ...)",
                                     kPlaneNeeds, {"shaders/plane_st.vert"}, {"shaders/dots.frag"}};
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> st = in.st;
        F grey = smoothstep(0.3f, 0.32f, length(fract(5.0f * st) - 0.5f));
        return vec4<F>(vec3<F>(grey), 1.0f);
    }
};

struct Perlin {
    static constexpr ShaderInfo info = with_wide_batches(ShaderInfo{
        "perlin", "Table 1.1 / Figure 1.4: 3D simplex noise (benchmark variant 0.51/93)", kPlaneNeeds,
        {"shaders/plane_st.vert"}, {"noise/simplex3d.glsl", "shaders/perlin.frag"},
        noise::Simplex3dBenchmark::glsl_defines});
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> st = in.st;
        F n = noise::snoise3<noise::Simplex3dBenchmark>(vec3<F>(10.0f * st, 60.0f));
        return vec4<F>(vec3<F>(0.5f * n + 0.5f), 1.0f);
    }
};

struct Perlin5 {
    static constexpr ShaderInfo info{"perlin5", "Table 1.1 / Figure 1.4: five octaves of 3D simplex noise", kPlaneNeeds,
                                     {"shaders/plane_st.vert"}, {"noise/simplex3d.glsl", "shaders/perlin5.frag"},
                                     noise::Simplex3dBenchmark::glsl_defines};
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        using V = noise::Simplex3dBenchmark;
        vec2<F> st = in.st;
        F n = noise::snoise3<V>(vec3<F>(5.0f * st, 50.0f));
        n += 0.5f * noise::snoise3<V>(vec3<F>(10.0f * st, 60.0f));
        n += 0.25f * noise::snoise3<V>(vec3<F>(20.0f * st, 70.0f));
        n += 0.125f * noise::snoise3<V>(vec3<F>(40.0f * st, 80.0f));
        n += 0.0625f * noise::snoise3<V>(vec3<F>(80.0f * st, 90.0f));
        return vec4<F>(vec3<F>(0.4f * n + 0.5f), 1.0f);
    }
};

struct Worley {
    static constexpr ShaderInfo info{"worley", "Table 1.1 / Figure 1.5: F1 of 2D cellular noise (3x3 search)",
                                     kPlaneNeeds, {"shaders/plane_st.vert"}, {"noise/cellular.glsl", "shaders/worley.frag"}};
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> Fs = noise::cellular(in.st * 10.0f);  // GLSL: vec2 F
        return vec4<F>(vec3<F>(Fs.x), 1.0f);
    }
};

template <AAWidth W = AAWidth::Length>
struct WorleyTiles {
    static constexpr ShaderInfo info = with_wide_batches(
        ShaderInfo{aa_variant_name(W, "worley_tiles", "worley_tiles_fwidth", "worley_tiles_step"),
                   "Table 1.1 / Figure 1.5: anti-aliased Worley tiles",
                   W == AAWidth::Step ? kPlaneNeeds : kPlaneDerivativeNeeds, {"shaders/plane_st.vert"},
                   {"noise/cellular.glsl", "shaders/aastep.glsl", "shaders/worley_tiles.frag"},
                   aa_variant_defines(W)});
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

// The blend to plain RGB takes derivatives in every variant, the step one included.
template <AAWidth W = AAWidth::Length>
struct Halftone {
    static constexpr ShaderInfo info = with_check_bounds(
        with_wide_batches(ShaderInfo{aa_variant_name(W, "halftone", "halftone_fwidth", "halftone_step"),
                   "Table 1.1 / Listing 1.5: CMYK halftone of an image, blended to RGB when minified",
                   Needs{.derivatives = true, .texture = true, .time = false},
                   {"shaders/halftone.vert"},
                   {"noise/simplex2d.glsl", "shaders/aastep.glsl", "shaders/halftone.frag"},
                   aa_variant_defines(W)}),
        W == AAWidth::Step ? std::span<const CheckBound>(kHalftoneStepCheckBounds) : std::span<const CheckBound>());
    // halftone.vert; its `dims` uniform is the texture's size.
    struct VertexStage {
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

}  // namespace qs::shaders
