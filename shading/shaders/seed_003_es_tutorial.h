#pragma once
// Seed 003: the OpenGL ES pixel shaders tutorial, page 4 (RWTNoise.fsh), drawn over the whole
// window from gl_FragCoord and uResolution. The square viewport (gl_FragCoord over the window's
// width) discards what lies above it in a window taller than wide. Translated from the .frag
// files beside this header and es_random_noise.glsl, line for line.
//
// randomNoise is fract(sin(x) * 43758.5453): quadshade's sin is glibc's and llvmpipe's its own
// polynomial, an ulp apart on about 15% of arguments, which the factor makes up to 1/255 and,
// across fract's wrap, a full step. With a few tiles (2x2, 8x8) every tile agrees with llvmpipe;
// the tutorial's per-pixel noise and its 128 tiles do not (measured at 320x568: 77-86 and 139
// pixels over 1/255, 23-37 of them full steps), and wait for llvmpipe's sin.

#include "shading/glsl.h"
#include "shading/program.h"
#include "shading/program_of.h"
#include "shading/shaders/table_1_1.h"

namespace qs::shaders {
using namespace qs::glsl;

// What every shader of the family reads and declares: gl_FragCoord and uResolution.
struct EsTutorial {
    static constexpr UniformDecl kUniforms[] = {
        // Always the frame's size in both renderers; this is only for a draw without a scene.
        {"uResolution", UniformType::Vec2, {64.0f, 96.0f}},
    };
    enum : int { uResolution };
    static constexpr Needs kNeeds{.coordinates = Coordinates::None, .derivatives = false, .texture = false, .time = false,
                                  .frag_coord = true};
    static constexpr ShaderInfo shader(std::string_view name, std::string_view description, std::string_view frag) {
        return with_uniforms(ShaderInfo{name, description, kNeeds, {"shaders/plane_st.vert"}, {"shaders/es_random_noise.glsl", frag}},
                             kUniforms);
    }
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
    static constexpr ShaderInfo info = shader("es_tiles2", "seed 003, ES tutorial: the square viewport in 2x2 random tiles",
                                              "shaders/es_tiles2.frag");
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

struct EsSmooth5Tiles8 : EsTutorial {
    static constexpr ShaderInfo info = shader("es_smooth5_tiles8", "seed 003, ES tutorial: 8 tiles, each half its own noise and 1/8 of each edge neighbour's (whole window)",
                                              "shaders/es_smooth5_tiles8.frag");
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

}  // namespace qs::shaders
