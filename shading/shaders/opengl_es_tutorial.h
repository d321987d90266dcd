#pragma once
// Ricardo Rendon Cepeda's OpenGL ES Pixel Shaders Tutorial (2014; collections.h cites it), its
// procedural textures ("Procedural Textures: Square Grid" and "Smooth Noise", RWTNoise.fsh), drawn
// over the whole window from gl_FragCoord and uResolution. The square viewport (gl_FragCoord over
// the window's width) discards what lies above it in a window taller than wide. Translated from the
// .frag files beside this header and es_random_noise.glsl, line for line.
//
// randomNoise is fract(sin(x) * 43758.5453), which makes the last bits of sin the noise: it is
// llvmpipe's because quadshade's sin on float is llvmpipe's polynomial to the bit
// (shading/number/sin_cos.h). softpipe calls the C library's sinf, half an ulp of 1 off on many
// arguments, which the factor makes a different grey.

#include "shading/glsl.h"
#include "shading/program.h"
#include "shading/program_of.h"
#include "shading/shaders/collections.h"
#include "shading/shaders/vertex_stages.h"

namespace qs::shaders {
using namespace qs::glsl;

// What every shader of the family reads and declares: gl_FragCoord and uResolution.
struct EsTutorial {
    static constexpr UniformDecl kUniforms[] = {
        // Always the frame's size in both renderers; this is only for a draw without a scene.
        {"uResolution", UniformType::Vec2, {64.0f, 96.0f}},
    };
    enum : int { uResolution };
    static constexpr Needs kNeeds{.coordinates = Coordinates::None, .frag_coord = true};
    using VertexStage = PlanePosition;

    template <class F>
    static F randomNoise(const vec2<F>& p) {
        return fract(sin(dot(p, vec2<F>(12.9898f, 78.233f))) * 43758.5453f);
    }
    // The square viewport: position in [0, 1] across the window's width; the rest discarded.
    template <class F>
    static vec2<F> square_position(const FragmentIn<F, VertexStage>& in, const Uniforms& u, FragmentOut<F>& out) {
        vec2<F> position = in.gl_FragCoord.xy() / uniform<vec2<F>>(u, uResolution).xx();
        out.discard_if((position.x > 1.0f) || (position.y > 1.0f));
        return position;
    }
};

struct EsTiles2 : EsTutorial {
    static constexpr ShaderInfo info{
        .name = "es_tiles2",
        .description = "the square viewport in 2x2 random tiles",
        .needs = kNeeds,
        .glsl_fragment = {"shaders/es_random_noise.glsl", "shaders/es_tiles2.frag"},
        .uniforms = kUniforms,
        .wide_batches = true,
    };
    template <class F>
    static FragmentOut<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        FragmentOut<F> out;
        vec2<F> position = square_position(in, u, out);
        float tiles = 2.0f;
        position = floor(position * tiles);
        F n = randomNoise(position);
        out.gl_FragColor = vec4<F>(vec3<F>(n), 1.0f);
        return out;
    }
};

// The square viewport in per-pixel noise, and the noise's input moved by -1 and by +1.
template <int Shift>
struct EsRandomSquareShifted : EsTutorial {
    static constexpr ShaderInfo info{
        .name = Shift == 0 ? "es_random_square" : Shift < 0 ? "es_random_square_minus1" : "es_random_square_plus1",
        .description = Shift == 0  ? "the square viewport in per-pixel random noise, above it discarded"
                       : Shift < 0 ? "es_random_square with the noise's input moved by -1"
                                   : "es_random_square with the noise's input moved by +1",
        .needs = kNeeds,
        .glsl_fragment = {"shaders/es_random_noise.glsl", Shift == 0  ? "shaders/es_random_square.frag"
                                                          : Shift < 0 ? "shaders/es_random_square_minus1.frag"
                                                                      : "shaders/es_random_square_plus1.frag"},
        .uniforms = kUniforms,
        .wide_batches = true,
    };
    template <class F>
    static FragmentOut<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        FragmentOut<F> out;
        vec2<F> position = square_position(in, u, out);
        F n = Shift == 0 ? randomNoise(position) : randomNoise(position + float(Shift));  // position-1. or position+1.
        out.gl_FragColor = vec4<F>(vec3<F>(n), 1.0f);
        return out;
    }
};
using EsRandomSquare = EsRandomSquareShifted<0>;
using EsRandomSquareMinus1 = EsRandomSquareShifted<-1>;
using EsRandomSquarePlus1 = EsRandomSquareShifted<1>;

struct EsTiles128 : EsTutorial {
    static constexpr ShaderInfo info{
        .name = "es_tiles128",
        .description = "the square viewport in 128x128 random tiles",
        .needs = kNeeds,
        .glsl_fragment = {"shaders/es_random_noise.glsl", "shaders/es_tiles128.frag"},
        .uniforms = kUniforms,
        .wide_batches = true,
    };
    template <class F>
    static FragmentOut<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        FragmentOut<F> out;
        vec2<F> position = square_position(in, u, out);
        float tiles = 128.0f;
        position = floor(position * tiles);
        F n = randomNoise(position);
        out.gl_FragColor = vec4<F>(vec3<F>(n), 1.0f);
        return out;
    }
};

struct EsSmooth9Tiles128 : EsTutorial {
    static constexpr ShaderInfo info{
        .name = "es_smooth9_tiles128",
        .description = "128 tiles, each the average of its 3x3 neighbourhood's noise (whole window)",
        .needs = kNeeds,
        .glsl_fragment = {"shaders/es_random_noise.glsl", "shaders/es_smooth9_tiles128.frag"},
        .uniforms = kUniforms,
    };
    template <class F>
    static F smoothNoise(const vec2<F>& p) {
        vec2<F> nn(p.x, p.y + 1.0f);
        vec2<F> ne(p.x + 1.0f, p.y + 1.0f);
        vec2<F> ee(p.x + 1.0f, p.y);
        vec2<F> se(p.x + 1.0f, p.y - 1.0f);
        vec2<F> ss(p.x, p.y - 1.0f);
        vec2<F> sw(p.x - 1.0f, p.y - 1.0f);
        vec2<F> ww(p.x - 1.0f, p.y);
        vec2<F> nw(p.x - 1.0f, p.y + 1.0f);
        vec2<F> cc(p.x, p.y);

        F sum = 0.0f;
        sum += randomNoise(nn);
        sum += randomNoise(ne);
        sum += randomNoise(ee);
        sum += randomNoise(se);
        sum += randomNoise(ss);
        sum += randomNoise(sw);
        sum += randomNoise(ww);
        sum += randomNoise(nw);
        sum += randomNoise(cc);
        sum /= 9.0f;

        return sum;
    }
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        vec2<F> position = in.gl_FragCoord.xy() / uniform<vec2<F>>(u, uResolution).xx();
        float tiles = 128.0f;
        position = floor(position * tiles);
        F n = smoothNoise(position);
        return vec4<F>(vec3<F>(n), 1.0f);
    }
};

struct EsSmooth5Tiles8 : EsTutorial {
    static constexpr ShaderInfo info{
        .name = "es_smooth5_tiles8",
        .description = "8 tiles, each half its own noise and 1/8 of each edge neighbour's (whole window)",
        .needs = kNeeds,
        .glsl_fragment = {"shaders/es_random_noise.glsl", "shaders/es_smooth5_tiles8.frag"},
        .uniforms = kUniforms,
        .wide_batches = true,
    };
    template <class F>
    static F smoothNoise(const vec2<F>& p) {
        vec2<F> nn(p.x, p.y + 1.0f);
        vec2<F> ee(p.x + 1.0f, p.y);
        vec2<F> ss(p.x, p.y - 1.0f);
        vec2<F> ww(p.x - 1.0f, p.y);
        vec2<F> cc(p.x, p.y);

        F sum = 0.0f;
        sum += randomNoise(nn) / 8.0f;
        sum += randomNoise(ee) / 8.0f;
        sum += randomNoise(ss) / 8.0f;
        sum += randomNoise(ww) / 8.0f;
        sum += randomNoise(cc) / 2.0f;

        return sum;
    }
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        vec2<F> position = in.gl_FragCoord.xy() / uniform<vec2<F>>(u, uResolution).xx();
        float tiles = 8.0f;
        position = floor(position * tiles);
        F n = smoothNoise(position);
        return vec4<F>(vec3<F>(n), 1.0f);
    }
};

QUADSHADE_SHADERS_IN(kOpenGlEsTutorial, EsRandomSquare, EsRandomSquareMinus1, EsRandomSquarePlus1, EsTiles2, EsTiles128,
                     EsSmooth9Tiles128, EsSmooth5Tiles8)

}  // namespace qs::shaders
