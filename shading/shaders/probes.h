#pragma once
// Probes that pin down driver behaviour the GLSL specification leaves open, so that tests can
// compare quadshade's answer with llvmpipe's and softpipe's. Translated from the .frag files.

#include "shading/glsl.h"
#include "shading/program.h"
#include "shading/program_of.h"
#include "shading/shaders/collections.h"
#include "shading/shaders/vertex_stages.h"

namespace qs::shaders {
using namespace qs::glsl;

struct DerivativeProbe {
    static constexpr ShaderInfo info{
        .name = "derivative_probe",
        .description = "probe: dFdx, dFdy of x^2 + 100 y^2 + 10 x y in window space",
        .needs = {.coordinates = Coordinates::None, .derivatives = true, .frag_coord = true},
        .glsl_fragment = {"shaders/derivative_probe.frag"},
        .wide_batches = true,
    };
    using VertexStage = PlanePosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> p = in.gl_FragCoord.xy();
        F v = p.x * p.x + 100.0f * p.y * p.y + 10.0f * p.x * p.y;
        return vec4<F>(dFdx(v), dFdy(v), v, 1.0f);
    }
};

struct StDerivativeProbe {
    static constexpr ShaderInfo info{
        .name = "st_derivative_probe",
        .description = "probe: dFdx(st) in red, green; dFdy(st) in blue, alpha",
        .needs = {.derivatives = true},
        .glsl_fragment = {"shaders/st_derivative_probe.frag"},
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> st = in.st;
        return vec4<F>(dFdx(st), dFdy(st));
    }
};

struct PositionDerivativeProbe {
    static constexpr ShaderInfo info{
        .name = "position_derivative_probe",
        .description = "probe: dFdx(P) in RGB, |dFdy(P)| in alpha, P the object position (Figure 1.1 spots' P)",
        .needs = {.coordinates = Coordinates::Object3D, .derivatives = true, .time = true},
        .glsl_fragment = {"shaders/position_derivative_probe.frag"},
        .wide_batches = true,
    };
    using VertexStage = Sphere<4, -1>;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec3<F> P = in.P;
        return vec4<F>(dFdx(P), length(dFdy(P)));
    }
};

struct SmoothstepProbe {
    static constexpr ShaderInfo info{
        .name = "smoothstep_probe",
        .description = "probe: smoothstep(e - w, e + w, x) with w = 0 at run time (aastep's case)",
        .needs = {.coordinates = Coordinates::None, .derivatives = true, .frag_coord = true},
        .glsl_fragment = {"shaders/smoothstep_probe.frag"},
        .wide_batches = true,
    };
    using VertexStage = PlanePosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        F e = floor(in.gl_FragCoord.x / 4.0f) * 4.0f + 2.5f;
        F w = 0.7f * length(vec2<F>(dFdx(e), dFdy(e)));
        return vec4<F>(smoothstep(e - w, e + w, in.gl_FragCoord.x), step(e, in.gl_FragCoord.x), w, 1.0f);
    }
};

struct ArithmeticProbe {
    static constexpr ShaderInfo info{
        .name = "arithmetic_probe",
        .description = "probe: a / b, mod(a, 289), mod(a, b), a / 7 of run-time values",
        .needs = {.coordinates = Coordinates::None, .frag_coord = true},
        .glsl_fragment = {"shaders/arithmetic_probe.frag"},
    };
    using VertexStage = PlanePosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        F a = in.gl_FragCoord.x * 7.13f + in.gl_FragCoord.y * 289.0f;
        F b = in.gl_FragCoord.y * 0.37f + 1.0f;
        return vec4<F>(a / b, mod(a, 289.0f), mod(a, b), a / 7.0f);
    }
};

struct FloatEnvironmentProbe {
    static constexpr ShaderInfo info{
        .name = "float_env_probe",
        .description = "probe: GLSL's undefined float cases and denormals, one per column (x = 0..7)",
        .needs = {.coordinates = Coordinates::None, .frag_coord = true},
        .glsl_fragment = {"shaders/float_env_probe.frag"},
        .wide_batches = true,
    };
    using VertexStage = PlanePosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        F z = floor(in.gl_FragCoord.x / 4096.0f);
        F column = floor(in.gl_FragCoord.x);
        // GLSL's if/else chain, as selects from the last case back to the first.
        F v = z * inversesqrt(z);
        v = select(column < 7.0f, log(z), v);
        v = select(column < 6.0f, sqrt(-1.0f + z), v);
        v = select(column < 5.0f, ((1e-38f + z) * 1e-3f) * 1e30f, v);
        v = select(column < 4.0f, mod(1.0f + z, z), v);
        v = select(column < 3.0f, pow(-2.0f + z, F(1.5f)), v);
        v = select(column < 2.0f, inversesqrt(z), v);
        v = select(column < 1.0f, normalize(vec3<F>(z)).x, v);
        return vec4<F>(v, 0.0f, 0.0f, 1.0f);
    }
};

QUADSHADE_SHADERS_IN(kProbes, DerivativeProbe, StDerivativeProbe, PositionDerivativeProbe, SmoothstepProbe, ArithmeticProbe,
                     FloatEnvironmentProbe)

}  // namespace qs::shaders
