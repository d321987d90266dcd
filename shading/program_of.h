#pragma once
// ProgramOf<Shader>: a shader translation (a struct with `info`, its `VertexStage` (shading/
// varyings.h) and a `fragment` template over the number type) as a Program: where the number
// types meet the batch layout. A file that registers shaders (QUADSHADE_SHADERS) includes it.
//
// Instantiations per shader: per pixel (float, double) when it takes no derivatives, quads for
// each DerivativeRule (float; Fine also double), and Dual2 (float, double); for the undefined-case
// mask, Checked float pixels and quads; and on AVX-512, for shaders that ask for wide batches,
// float pixels two batches wide (shade_pair). A shader struct with `static constexpr ShadeModes
// compiled_modes` (shade_choice.h) gets only those: a GLSL shader compiled for one run
// (render/compiled_glsl.h) compiles what the run shades, and shading it another way throws.

#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "shading/catalogue.h"
#include "shading/glsl.h"
#include "shading/number/simd/simd.h"
#include "shading/program.h"
#include "shading/shade_choice.h"
#include "shading/varyings.h"

// `flatten` inlines the whole shader into ProgramOf::run: one straight-line SIMD body per number
// type, as a GPU compiler would make it, instead of calls passing vectors through memory (it
// doubled the noise shaders' throughput). On every target: the number types' operations are
// always-inlined operators on register-wide parts (number/wide_vector.h), so the flattened body
// costs the compiler little more than the calls did.
#define QS_FLATTEN [[gnu::flatten]]

namespace qs {

// Whether Program::shade_pair shades two batches as one number of twice the width. Only where a
// batch is one register: with narrower vectors a batch already spans several registers, whose
// instructions the CPU overlaps anyway.
inline constexpr bool kWidePairs = simd::register_floats >= kBatchLanes;

// How many lanes of float a shader that does not ask for wide batches is run on at once: one
// register's worth where a batch would take two (AVX2: the batch's halves, two quads or eight
// pixels each, one after the other). It is the choice ShaderInfo::wide_batches makes on AVX-512,
// one width down: one register per value, or two for the shaders whose dependency chains gain
// more from two independent instructions per operation than they lose to values that no longer
// fit the sixteen registers. 5x Perlin's and Worley's bodies (no wide batches) take 0.67 and 0.85
// of their time as two runs of eight; Perlin's (wide batches) 1.3x as long (GCC 12, Zen 4, an
// AVX2 build).
inline constexpr int kNarrowLanes = simd::register_floats == kBatchLanes / 2 ? kBatchLanes / 2 : kBatchLanes;

// What a fragment stage that may discard returns (one that never does returns its colour).
template <class F>
struct FragmentOut {
    glsl::vec4<F> gl_FragColor;
    Bool<F> discarded = Bool<F>(false);

    // if (c) discard;  The lanes of c write nothing. As in GL they keep running, as helpers for
    // their neighbours' derivatives (in a loop, discard through the loop: Loop::discard_if), and
    // the values they compute are those llvmpipe's derivatives see (discard_probe).
    void discard_if(const Bool<F>& c) { discarded = discarded || c; }
};

namespace program_detail {

template <class F>
F load(const float* values, const float* ddx, const float* ddy) {
    if constexpr (is_dual2<F>::value) {
        using T = typename F::value_type;
        return F(load<T>(values, nullptr, nullptr), load<T>(ddx, nullptr, nullptr),
                 load<T>(ddy, nullptr, nullptr));
    } else {
        using T = typename F::value_type;
        if constexpr (std::is_same_v<T, float>) {
            return F::load(values);
        } else {
            T wide[kBatchLanes];
            for (int i = 0; i < kBatchLanes; ++i) wide[i] = T(values[i]);
            return F::load(wide);
        }
    }
}

// Lanes 0..kBatchLanes-1 from `a`, the next kBatchLanes from `b`: two batches as one number.
template <class F>
F load_pair(const float* a, const float* b) {
    static_assert(F::size == 2 * kBatchLanes && std::is_same_v<typename F::value_type, float>);
    alignas(64) float both[2 * kBatchLanes];
    std::memcpy(both, a, kBatchLanes * sizeof(float));
    std::memcpy(both + kBatchLanes, b, kBatchLanes * sizeof(float));
    return F::load(both);
}

template <class F>
void store_pair(const F& v, float* a, float* b) {
    alignas(64) float both[2 * kBatchLanes];
    v.store(both);
    std::memcpy(a, both, kBatchLanes * sizeof(float));
    std::memcpy(b, both + kBatchLanes, kBatchLanes * sizeof(float));
}

// How many fragments one F holds.
template <class F>
inline constexpr int lanes_of = F::size;
template <class G>
inline constexpr int lanes_of<Dual2<G>> = lanes_of<G>;
template <class L>
inline constexpr int lanes_of<Checked<L>> = lanes_of<L>;

// A fragment stage's colour and discarded lanes (bit i: lane i), whichever it returns.
template <class F>
const glsl::vec4<F>& color_of(const glsl::vec4<F>& c) { return c; }
template <class F>
const glsl::vec4<F>& color_of(const FragmentOut<F>& out) { return out.gl_FragColor; }
template <class F>
std::uint32_t discarded_of(const glsl::vec4<F>&) { return 0; }
template <class F>
std::uint32_t discarded_of(const FragmentOut<F>& out) {
    if constexpr (is_checked_mask<Bool<F>>::value) {
        return lane_bits(out.discarded.m);
    } else {
        return lane_bits(out.discarded);
    }
}

template <class F>
void store(const F& v, float* out) {
    if constexpr (is_dual2<F>::value) {
        store(v.val, out);
    } else if constexpr (std::is_same_v<typename F::value_type, float>) {
        v.store(out);
    } else {
        for (int i = 0; i < kBatchLanes; ++i) out[i] = float(v[i]);
    }
}

// Shader::info with what its vertex stage declares: its varyings and its GLSL.
template <class Shader>
constexpr ShaderInfo completed_info() {
    using Stage = typename Shader::VertexStage;
    static_assert(Shader::info.needs.varyings == 0 && Shader::info.needs.flat_varyings == 0,
                  "Needs::varyings follows from the vertex stage's Varyings: leave it unset");
    static_assert(Shader::info.glsl_vertex[0].empty() && !Shader::info.stock_vertex_glsl,
                  "the vertex GLSL is the vertex stage's: static constexpr GlslFiles glsl{...} in the stage");
    static_assert(requires { Stage::glsl; },
                  "a vertex stage names the GLSL it translates: static constexpr GlslFiles glsl{\"my.vert\"};");
    ShaderInfo info = Shader::info;
    info.needs.varyings = varying_count<Stage>();
    info.needs.flat_varyings = flat_varying_mask<Stage>();
    info.glsl_vertex = Stage::glsl;
    if constexpr (requires { Stage::stock; }) info.stock_vertex_glsl = Stage::stock;
    return info;
}

}  // namespace program_detail

template <class Shader>
class ProgramOf final : public Program {
    static_assert(requires { typename Shader::VertexStage; },
                  "a shader struct names its vertex stage: using VertexStage = ...; (shading/varyings.h)");
    using Stage = typename Shader::VertexStage;

    static constexpr ShaderInfo kInfo = program_detail::completed_info<Shader>();
    static constexpr Needs kNeeds = kInfo.needs;
    static constexpr ShadeModes kModes = [] {
        if constexpr (requires { Shader::compiled_modes; }) return Shader::compiled_modes;
        else return ShadeModes{};
    }();
    static_assert(kNeeds.varyings <= kMaxVaryings, "a vertex stage writes at most kMaxVaryings floats");
    static_assert((kNeeds.coordinates == Coordinates::None) == (kNeeds.varyings == 0),
                  "Needs::coordinates: None exactly when the vertex stage hands the fragment stage no varying");

public:
    const ShaderInfo& info() const override { return kInfo; }

    void vertex(const VertexIn& in, const Uniforms& given, VertexOut& out) const override {
        Uniforms scratch;
        const Uniforms& u = with_user_uniforms(given, scratch);
        VertexOutputs<Stage> named;
        Stage::vertex(in, u, named);
        out.clip = named.gl_Position;
        varyings_detail::for_each_component(named.fields(), [&](float c, int v) { out.varyings[std::size_t(v)] = c; });
    }

    void shade(ShadeMode mode, const FragmentBatch& in, const Uniforms& given, ColorBatch& out) const override {
        Uniforms scratch;
        const Uniforms& u = with_user_uniforms(given, scratch);
        if (mode.check_undefined) return shade_checked(mode, in, u, out);
        using enum Derivatives;
        const bool dbl = mode.precision == Precision::Double;
        switch (mode.derivatives) {
            case Derivatives::None:
                if constexpr (!kNeeds.derivatives) {
                    return dbl ? shade_as<Pixels<double, kBatchLanes>, None, Precision::Double>(in, u, out)
                               : shade_as<Pixels<float, kFloatLanes>, None>(in, u, out);
                } else {
                    throw std::logic_error(std::string(kInfo.name) +
                                           " takes derivatives: it cannot be shaded per pixel");
                }
            case Derivatives::Fine:
                return dbl ? shade_as<Quads<double, kBatchQuads, DerivativeRule::Fine>, Fine, Precision::Double>(in, u, out)
                           : shade_as<Quads<float, kFloatQuads, DerivativeRule::Fine>, Fine>(in, u, out);
            case Derivatives::CoarseLower:
                return shade_as<Quads<float, kFloatQuads, DerivativeRule::CoarseLower>, CoarseLower>(in, u, out);
            case Derivatives::CoarseUpper:
                return shade_as<Quads<float, kFloatQuads, DerivativeRule::CoarseUpper>, CoarseUpper>(in, u, out);
            case Derivatives::Analytic:
                return dbl ? shade_as<Dual2<Pixels<double, kBatchLanes>>, Analytic, Precision::Double>(in, u, out)
                           : shade_as<Dual2<Pixels<float, kBatchLanes>>, Analytic>(in, u, out);
        }
    }

    void shade_pair(ShadeMode mode, const FragmentBatch& a, const FragmentBatch& b, const Uniforms& given,
                    ColorBatch& out_a, ColorBatch& out_b) const override {
        Uniforms scratch;
        const Uniforms& u = with_user_uniforms(given, scratch);
        // A build for some ways of shading (kModes) holds the pair where it holds the way paired.
        if constexpr (kWidePairs && kInfo.wide_batches) {
            const bool wide_float = !mode.check_undefined && mode.precision == Precision::Float;
            if constexpr (!kNeeds.derivatives && kModes.has({Derivatives::None, Precision::Float, false})) {
                if (wide_float && mode.derivatives == Derivatives::None) {
                    return run_pair<Pixels<float, 2 * kBatchLanes>>(a, b, u, out_a, out_b);
                }
            } else if constexpr (kNeeds.derivatives && kModes.has({Derivatives::Fine, Precision::Float, false})) {
                // llvmpipe's rule only: each quad's lanes stay in one register, so its
                // derivatives shuffle inside that register as on one batch.
                if (wide_float && mode.derivatives == Derivatives::Fine) {
                    return run_pair<Quads<float, 2 * kBatchQuads, DerivativeRule::Fine>>(a, b, u, out_a, out_b);
                }
            }
        }
        shade(mode, a, u, out_a);
        shade(mode, b, u, out_b);
    }

private:
    // The lanes and quads of one run in float pixels and quads (kNarrowLanes above).
    static constexpr int kFloatLanes = kInfo.wide_batches ? kBatchLanes : kNarrowLanes;
    static constexpr int kFloatQuads = kFloatLanes / 4;

    // The shader's own uniforms at their initial values, for callers that set none (tests and
    // benchmarks drawing without a scene).
    static constexpr std::size_t kUserUniforms = kInfo.uniforms.size();
    static constexpr std::array<std::uint32_t, kUserUniforms * kUniformWords> kInitialUniforms =
        initial_uniform_words(std::span<const UniformDecl, kUserUniforms>(kInfo.uniforms.data(), kUserUniforms));
    static const Uniforms& with_user_uniforms(const Uniforms& given, Uniforms& scratch) {
        if (kUserUniforms == 0 || given.user) return given;
        scratch = given;
        scratch.user = kInitialUniforms.data();
        return scratch;
    }

    // The same shader over Checked numbers: colours as above, and each lane's undefined cases.
    static void shade_checked(ShadeMode mode, const FragmentBatch& in, const Uniforms& u, ColorBatch& out) {
        if (mode.precision == Precision::Double || mode.derivatives == Derivatives::Analytic) {
            throw std::logic_error("undefined-case checking shades float pixels or quads, not double or Dual2");
        }
        using enum Derivatives;
        switch (mode.derivatives) {
            case Derivatives::None:
                if constexpr (!kNeeds.derivatives) {
                    return shade_as<Checked<Pixels<float, kBatchLanes>>, None>(in, u, out);
                } else {
                    throw std::logic_error(std::string(kInfo.name) +
                                           " takes derivatives: it cannot be shaded per pixel");
                }
            case Derivatives::Fine:
                return shade_as<Checked<Quads<float, kBatchQuads, DerivativeRule::Fine>>, Fine>(in, u, out);
            case Derivatives::CoarseLower:
                return shade_as<Checked<Quads<float, kBatchQuads, DerivativeRule::CoarseLower>>, CoarseLower>(in, u, out);
            case Derivatives::CoarseUpper:
                return shade_as<Checked<Quads<float, kBatchQuads, DerivativeRule::CoarseUpper>>, CoarseUpper>(in, u, out);
            case Derivatives::Analytic:
                break;
        }
    }

    // Shading in a mode this build left out (kModes): a caller that asked for the wrong build.
    [[noreturn]] static void not_compiled() {
        throw std::logic_error(std::string(kInfo.name) + " was compiled for other ways of shading than this one");
    }

    // run<F>, or run_checked<F> for Checked numbers, where the build holds mode (D, P).
    template <class F, Derivatives D, Precision P = Precision::Float>
    static void shade_as(const FragmentBatch& in, const Uniforms& u, ColorBatch& out) {
        if constexpr (!is_checked_mask<Bool<F>>::value && kModes.has({D, P, false})) {
            run<F>(in, u, out);
        } else if constexpr (is_checked_mask<Bool<F>>::value && kModes.has({D, P, true})) {
            run_checked<F>(in, u, out);
        } else {
            not_compiled();
        }
    }

    // The batch through the shader, in runs of F's lanes. Flattened: a whole batch is the
    // shader's body itself, halves one body that the loop enters twice.
    template <class F>
    QS_FLATTEN static void run(const FragmentBatch& in, const Uniforms& u, ColorBatch& out) {
        constexpr int lanes = program_detail::lanes_of<F>;
        static_assert(kBatchLanes % lanes == 0 && lanes % 4 == 0, "runs of whole quads");
        out.discarded = 0;
        for (int first = 0; first < kBatchLanes; first += lanes) run_lanes<F>(in, first, u, out);
    }

    // Lanes first .. first + F's lanes - 1 of the batch.
    template <class F>
    QS_FLATTEN static void run_lanes(const FragmentBatch& in, int first, const Uniforms& u, ColorBatch& out) {
        const auto result = fragment<F>(in, first, u);
        const glsl::vec4<F>& c = program_detail::color_of(result);
        for (int k = 0; k < 4; ++k) program_detail::store(c[k], out.rgba[k] + first);
        out.discarded |= program_detail::discarded_of(result) << first;
    }

    template <class F>
    QS_FLATTEN static void run_pair(const FragmentBatch& a, const FragmentBatch& b, const Uniforms& u,
                                    ColorBatch& out_a, ColorBatch& out_b) {
        using program_detail::load_pair;
        FragmentIn<F, Stage> f;
        for (int k = 0; k < 4; ++k) f.gl_FragCoord[k] = load_pair<F>(a.frag_coord[k], b.frag_coord[k]);
        load_varyings(f, [&](int v) { return load_pair<F>(a.varying[v], b.varying[v]); });
        const auto result = Shader::template fragment<F>(f, u);
        const glsl::vec4<F>& c = program_detail::color_of(result);
        for (int k = 0; k < 4; ++k) program_detail::store_pair(c[k], out_a.rgba[k], out_b.rgba[k]);
        const std::uint64_t discarded = program_detail::discarded_of(result);
        out_a.discarded = std::uint32_t(discarded & 0xFFFFu);
        out_b.discarded = std::uint32_t(discarded >> kBatchLanes);
    }

    // Not flattened: a debugging mode, and flattening the checks would multiply compile time.
    template <class F>
    static void run_checked(const FragmentBatch& in, const Uniforms& u, ColorBatch& out) {
        const auto result = fragment<F>(in, 0, u);
        const glsl::vec4<F>& c = program_detail::color_of(result);
        for (int k = 0; k < 4; ++k) c[k].store(out.rgba[k]);
        out.discarded = program_detail::discarded_of(result);
        const LaneCases cases = c[0].cases | c[1].cases | c[2].cases | c[3].cases;
        for (int i = 0; i < kBatchLanes; ++i) out.undefined[i] = cases.at(i);
    }

    // The shader's inputs in number type F from lane `first` of the batch on, and its output: a
    // colour or a FragmentOut.
    template <class F>
    static auto fragment(const FragmentBatch& in, int first, const Uniforms& u) {
        using program_detail::load;
        FragmentIn<F, Stage> f;
        if constexpr (is_dual2<F>::value) {
            static_assert(program_detail::lanes_of<F> == kBatchLanes, "analytic derivatives: whole batches");
            // gl_FragCoord: d(x)/dx = 1, d(y)/dy = 1; z and 1/w come with their derivatives.
            alignas(64) float ones[kBatchLanes], zeros[kBatchLanes];
            for (int i = 0; i < kBatchLanes; ++i) ones[i] = 1.0f, zeros[i] = 0.0f;
            f.gl_FragCoord = {load<F>(in.frag_coord[0], ones, zeros), load<F>(in.frag_coord[1], zeros, ones),
                              load<F>(in.frag_coord[2], in.frag_coord_dx[0], in.frag_coord_dy[0]),
                              load<F>(in.frag_coord[3], in.frag_coord_dx[1], in.frag_coord_dy[1])};
        } else {
            f.gl_FragCoord = {load<F>(in.frag_coord[0] + first, nullptr, nullptr), load<F>(in.frag_coord[1] + first, nullptr, nullptr),
                              load<F>(in.frag_coord[2] + first, nullptr, nullptr), load<F>(in.frag_coord[3] + first, nullptr, nullptr)};
        }
        load_varyings(f, [&](int v) { return load<F>(in.varying[v] + first, in.varying_dx[v] + first, in.varying_dy[v] + first); });
        return Shader::template fragment<F>(f, u);
    }

    // Each varying float v of `f` from load(v).
    template <class F, class Load>
    static void load_varyings(FragmentIn<F, Stage>& f, Load load) {
        varyings_detail::for_each_component(f.fields(), [&](F& c, int v) { c = load(v); });
    }
};

// A registered shader's Program (catalogue.h's QUADSHADE_SHADERS): one per shader struct.
template <class... Shaders>
template <class S>
const Program& registration::Registrar<Shaders...>::program() {
    static const ProgramOf<S> program;
    return program;
}

}  // namespace qs
