#pragma once
// Orion Lawlor's course notes "Procedural Solid Texturing" (2010; collections.h cites them), whose
// snippets ran in NetRun: each draws grid(texcoords * 10.0) on the Table 1.1 plane, NetRun's
// `texcoords` being the plane's texture coordinates. Translated from the .frag files beside this
// header, line for line; a GLSL if/else that returns is both returns computed and selected.

#include "shading/glsl.h"
#include "shading/program.h"
#include "shading/program_of.h"
#include "shading/shaders/collections.h"
#include "shading/shaders/vertex_stages.h"

namespace qs::shaders {
using namespace qs::glsl;

struct LawlorChecker {
    static constexpr ShaderInfo info{
        .name = "lawlor_checker",
        .description = "a checkerboard, the xor of two comparisons",
        .glsl_fragment = {"shaders/lawlor_checker.frag"},
    };
    using VertexStage = PlaneTexcoords;
    template <class F>
    static vec4<F> grid(const vec2<F>& loc) {
        vec2<F> gridcorner = floor(loc);
        vec2<F> gridfrac = loc - gridcorner;
        return select((gridfrac.x < 0.5f) != (gridfrac.y < 0.5f),  // ^^
                      vec4<F>(1.0f, 0.0f, 0.0f, 1.0f),            // red
                      vec4<F>(0.0f, 0.0f, 0.0f, 1.0f));           // black
    }
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return grid(in.texcoords * 10.0f);
    }
};

struct LawlorDots {
    static constexpr ShaderInfo info{
        .name = "lawlor_dots",
        .description = "a grid of dots, by an if on the distance to the cell's centre",
        .glsl_fragment = {"shaders/lawlor_dots.frag"},
    };
    using VertexStage = PlaneTexcoords;
    template <class F>
    static vec4<F> grid(const vec2<F>& loc) {
        vec2<F> gridcorner = floor(loc);
        vec2<F> gridcenter = gridcorner + vec2<F>(0.5f);
        F radius = length(loc - gridcenter);
        return select(radius < 0.3f, vec4<F>(1.0f, 0.0f, 0.0f, 1.0f),  // red
                      vec4<F>(0.0f, 0.0f, 0.0f, 1.0f));                 // black
    }
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return grid(in.texcoords * 10.0f);
    }
};

// The textured snippets read tex1 (smooth colours) and tex4 (white noise), which NetRun bound:
// scenes/assets/lawlor-plane.gltf binds the repository's (quadshade-make-scenes). Their lookups
// inside a varying `if` are in non-uniform control flow, where GLSL leaves an implicit level of
// detail undefined; these textures have none (no mipmaps, one filter), so nothing depends on it.
inline constexpr Needs kTex1Needs{.samplers = {SamplerUse{"tex1", 2}}};
inline constexpr Needs kTex4Needs{.samplers = {SamplerUse{"tex4", 2}}};
inline constexpr Needs kTex1Tex4Needs{.samplers = {SamplerUse{"tex1", 2}, SamplerUse{"tex4", 2}}};

// main() of every textured snippet but the octaves': grid(texcoords * 10.0). GLSL's grid(loc)
// reads the samplers and texcoords as globals; here they come in as the first two parameters.
template <class Shader>
struct LawlorGrid {
    using VertexStage = PlaneTexcoords;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        return Shader::grid(u, in.texcoords, in.texcoords * 10.0f);
    }
};

struct LawlorDotsTexture : LawlorGrid<LawlorDotsTexture> {
    static constexpr ShaderInfo info{
        .name = "lawlor_dots_texture",
        .description = "the dots coloured by tex1 at the fragment",
        .needs = kTex1Needs,
        .glsl_fragment = {"shaders/lawlor_dots_texture.frag"},
    };
    template <class F>
    static vec4<F> grid(const Uniforms& u, const vec2<F>& texcoords, const vec2<F>& loc) {
        const sampler2D& tex1 = u.sampler2D(0);
        vec2<F> gridcorner = floor(loc);
        vec2<F> gridcenter = gridcorner + vec2<F>(0.5f);
        F radius = length(loc - gridcenter);
        return select(radius < 0.3f, texture2D(tex1, texcoords),  // read texture 3
                      vec4<F>(0.0f, 0.0f, 0.0f, 1.0f));          // black
    }
};

struct LawlorDotsCenterColor : LawlorGrid<LawlorDotsCenterColor> {
    static constexpr ShaderInfo info{
        .name = "lawlor_dots_center_color",
        .description = "each dot one colour, tex1 at its centre",
        .needs = kTex1Needs,
        .glsl_fragment = {"shaders/lawlor_dots_center_color.frag"},
    };
    template <class F>
    static vec4<F> grid(const Uniforms& u, const vec2<F>&, const vec2<F>& loc) {
        const sampler2D& tex1 = u.sampler2D(0);
        vec2<F> gridcorner = floor(loc);
        vec2<F> gridcenter = gridcorner + vec2<F>(0.5f);
        F radius = length(loc - gridcenter);
        return select(radius < 0.3f, texture2D(tex1, gridcenter * 0.1f),  // read texture 3
                      vec4<F>(0.0f, 0.0f, 0.0f, 1.0f));                  // black
    }
};

struct LawlorDotsMoved : LawlorGrid<LawlorDotsMoved> {
    static constexpr ShaderInfo info{
        .name = "lawlor_dots_moved",
        .description = "dots moved by a shift read from tex1",
        .needs = kTex1Needs,
        .glsl_fragment = {"shaders/lawlor_dots_moved.frag"},
    };
    template <class F>
    static vec4<F> grid(const Uniforms& u, const vec2<F>&, const vec2<F>& loc) {
        const sampler2D& tex1 = u.sampler2D(0);
        vec2<F> gridcorner = floor(loc);
        vec2<F> gridshift = 0.4f * texture2D(tex1, gridcorner * 0.1234f).xy();
        vec2<F> gridcenter = gridcorner + vec2<F>(0.3f) + gridshift;
        F radius = length(loc - gridcenter);
        return select(radius < 0.3f, texture2D(tex1, gridcenter * 0.1f),  // read texture 3
                      vec4<F>(0.0f, 0.0f, 0.0f, 1.0f));                  // black
    }
};

struct LawlorDotsSearch : LawlorGrid<LawlorDotsSearch> {
    static constexpr ShaderInfo info{
        .name = "lawlor_dots_search",
        .description = "dots shifted by tex4, searched over the 3x3 neighbouring cells, colours added",
        .needs = kTex1Tex4Needs,
        .glsl_fragment = {"shaders/lawlor_dots_search.frag"},
    };
    template <class F>
    static vec4<F> grid(const Uniforms& u, const vec2<F>&, const vec2<F>& loc) {
        const sampler2D &tex1 = u.sampler2D(0), &tex4 = u.sampler2D(1);
        vec4<F> ret = vec4<F>(0.0f);
        vec2<F> gridcorner = floor(loc);
        for (float dy = -1.0f; dy <= 1.0f; dy++)
            for (float dx = -1.0f; dx <= 1.0f; dx++) {
                vec2<F> thiscorner = gridcorner + vec2<F>(dx, dy);
                vec2<F> gridshift = 2.4f * texture2D(tex4, thiscorner * 3.456f).xy();
                vec2<F> center = thiscorner + vec2<F>(-0.7f) + gridshift;
                F radius = length(loc - center);
                ret = select(radius < 0.3f, ret + texture2D(tex1, center * 0.1f), ret);
            }
        return ret;
    }
};

// The Voronoi snippets' search: F1 and F2 of the (2 reach + 1)^2 neighbouring cells' points.
template <class F>
struct NearestTwo {
    F dist, second;
};
template <int Reach, class F>
NearestTwo<F> lawlor_voronoi(const sampler2D& tex4, const vec2<F>& loc) {
    F dist = 10.0f;    // distance to closest grid cell
    F second = 10.0f;  // distance to the next-nearest grid cell
    vec2<F> gridcorner = floor(loc);
    for (float dy = -Reach; dy <= Reach; dy++)
        for (float dx = -Reach; dx <= Reach; dx++) {
            vec2<F> thiscorner = gridcorner + vec2<F>(dx, dy);
            vec2<F> gridshift = texture2D(tex4, thiscorner * 3.456f).xy();
            vec2<F> center = thiscorner + gridshift;
            F radius = length(loc - center);
            if constexpr (Reach == 1) {
                dist = min(radius, dist);
            } else {
                const auto best = radius < dist;  // new best; else if radius < second, new second-best
                second = select(best, dist, select(radius < second, radius, second));
                dist = select(best, radius, dist);
            }
        }
    return {dist, second};
}

struct LawlorVoronoiF1 : LawlorGrid<LawlorVoronoiF1> {
    static constexpr ShaderInfo info{
        .name = "lawlor_voronoi_f1",
        .description = "Voronoi F1 over the 3x3 neighbouring cells' points, shifted by tex4",
        .needs = kTex4Needs,
        .glsl_fragment = {"shaders/lawlor_voronoi_f1.frag"},
    };
    template <class F>
    static vec4<F> grid(const Uniforms& u, const vec2<F>&, const vec2<F>& loc) {
        return vec4<F>(lawlor_voronoi<1>(u.sampler2D(0), loc).dist);
    }
};

struct LawlorVoronoiF2 : LawlorGrid<LawlorVoronoiF2> {
    static constexpr ShaderInfo info{
        .name = "lawlor_voronoi_f2",
        .description = "Voronoi F2 over the 5x5 neighbouring cells' points",
        .needs = kTex4Needs,
        .glsl_fragment = {"shaders/lawlor_voronoi_f2.frag"},
    };
    template <class F>
    static vec4<F> grid(const Uniforms& u, const vec2<F>&, const vec2<F>& loc) {
        return vec4<F>(lawlor_voronoi<2>(u.sampler2D(0), loc).second * 0.7f);
    }
};

struct LawlorStainedGlass : LawlorGrid<LawlorStainedGlass> {
    static constexpr ShaderInfo info{
        .name = "lawlor_stained_glass",
        .description = "stained glass, Voronoi F2 - F1 over the 5x5 neighbouring cells",
        .needs = kTex4Needs,
        .glsl_fragment = {"shaders/lawlor_stained_glass.frag"},
    };
    template <class F>
    static vec4<F> grid(const Uniforms& u, const vec2<F>&, const vec2<F>& loc) {
        const NearestTwo<F> d = lawlor_voronoi<2>(u.sampler2D(0), loc);
        return 2.0f * vec4<F>(d.second - d.dist);
    }
};

struct LawlorTextureHigh : LawlorGrid<LawlorTextureHigh> {
    static constexpr ShaderInfo info{
        .name = "lawlor_texture_high",
        .description = "the repeating noise texture, ten times across",
        .needs = kTex4Needs,
        .glsl_fragment = {"shaders/lawlor_texture_high.frag"},
        .wide_batches = true,
    };
    template <class F>
    static vec4<F> grid(const Uniforms& u, const vec2<F>&, const vec2<F>& loc) {
        return texture2D(u.sampler2D(0), loc);
    }
};

struct LawlorTextureLow : LawlorGrid<LawlorTextureLow> {
    static constexpr ShaderInfo info{
        .name = "lawlor_texture_low",
        .description = "the repeating noise texture stretched, five times across",
        .needs = kTex4Needs,
        .glsl_fragment = {"shaders/lawlor_texture_low.frag"},
        .wide_batches = true,
    };
    template <class F>
    static vec4<F> grid(const Uniforms& u, const vec2<F>&, const vec2<F>& loc) {
        return texture2D(u.sampler2D(0), loc * 0.5f);
    }
};

struct LawlorTextureTwoOctaves : LawlorGrid<LawlorTextureTwoOctaves> {
    static constexpr ShaderInfo info{
        .name = "lawlor_texture_two_octaves",
        .description = "the high and the low octave of the noise texture, averaged",
        .needs = kTex4Needs,
        .glsl_fragment = {"shaders/lawlor_texture_two_octaves.frag"},
        .wide_batches = true,
    };
    template <class F>
    static vec4<F> grid(const Uniforms& u, const vec2<F>&, const vec2<F>& loc) {
        const sampler2D& tex4 = u.sampler2D(0);
        vec4<F> high = texture2D(tex4, loc);
        vec4<F> low = texture2D(tex4, loc * 0.5f);
        return 0.5f * (high + low);
    }
};

struct LawlorTextureOctaves {
    static constexpr ShaderInfo info{
        .name = "lawlor_texture_octaves",
        .description = "six octaves of the noise texture, frequency 8 down to 0.25",
        .needs = kTex4Needs,
        .glsl_fragment = {"shaders/lawlor_texture_octaves.frag"},
    };
    using VertexStage = PlaneTexcoords;
    template <class F>
    static vec4<F> grid(const sampler2D& tex4, const vec2<F>& loc) {
        vec4<F> ret = vec4<F>(0.0f);
        for (float freq = 8.0f; freq >= 0.25f; freq *= 0.5f) ret += texture2D(tex4, loc * freq);
        return (1.0f / 6.0f) * ret;
    }
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        return grid(u.sampler2D(0), in.texcoords);
    }
};

// The Mandelbrot set at the plane's texture coordinates. Mesa's optimizer (NIR) reassociates
// x = (x*x - y*y) + cx into (x*x + cx) - y*y, which GLSL allows without `precise`; the
// translation adds in Mesa's order, so the two round alike: measured on llvmpipe's own texcoords
// (Mesa 22.3.6, 500x500), the notes' order differs from llvmpipe's result on 155583 of 250000
// pixels, most by ulps and 574 over 1/255 near the set's boundary, where an ulp changes the
// escape time; Mesa's order on none.
struct LawlorMandelbrot {
    static constexpr ShaderInfo info{
        .name = "lawlor_mandelbrot",
        .description = "the Mandelbrot set at the texture coordinates, up to 100 iterations with break",
        .glsl_fragment = {"shaders/lawlor_mandelbrot.frag"},
        .glsl_version = 120,
        .wide_batches = true,
    };
    using VertexStage = PlaneTexcoords;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        F cx = in.texcoords.x, cy = in.texcoords.y;  // location onscreen
        F x = cx, y = cy;                             // point to iterate
        F r = 0.0f;                                   // radius of point (squared)

        Loop loop(x, y, r);
        for (int i = 0; loop(i < 100); i++) {  //<- repeat!
            F newx = x * x + cx - y * y;  // x*x - y*y, biased by cx below: in Mesa's order
            y = 2.0f * x * y;             // <- complex multiplication

            x = newx;
            y = y + cy;  // bias by onscreen location

            r = x * x + y * y;  // check radius
            loop.break_if(r > 4.0f);
        }
        return vec4<F>(x, r * 0.1f, y, 1.0f);  // the notes' alpha 0 made 1 (see the .frag)
    }
};

QUADSHADE_SHADERS_IN(kLawlor, LawlorChecker, LawlorDots, LawlorDotsTexture, LawlorDotsCenterColor, LawlorDotsMoved, LawlorDotsSearch,
                     LawlorVoronoiF1, LawlorVoronoiF2, LawlorStainedGlass, LawlorTextureHigh, LawlorTextureLow,
                     LawlorTextureTwoOctaves, LawlorTextureOctaves, LawlorMandelbrot)

}  // namespace qs::shaders
