#include "interpreter/glsl_program.h"

#include <stdexcept>

#include "interpreter/native_blocks.h"
#include "interpreter/run_stage.h"

namespace qs::interpreter {

namespace {

using frontend::GlslError;

// The catalogue's uniform type for a user uniform: bools as ints (their 32-bit words are the
// same: 0 or 1).
UniformType uniform_type(const ir::Uniform& u) {
    if (u.columns > 1) {
        constexpr UniformType t[3][3] = {{UniformType::Mat2, UniformType::Mat2x3, UniformType::Mat2x4},
                                         {UniformType::Mat3x2, UniformType::Mat3, UniformType::Mat3x4},
                                         {UniformType::Mat4x2, UniformType::Mat4x3, UniformType::Mat4}};
        return t[u.columns - 2][u.components / u.columns - 2];
    }
    const std::size_t n = std::size_t(u.components - 1);
    constexpr UniformType floats[] = {UniformType::Float, UniformType::Vec2, UniformType::Vec3, UniformType::Vec4};
    constexpr UniformType uints[] = {UniformType::Uint, UniformType::UVec2, UniformType::UVec3, UniformType::UVec4};
    constexpr UniformType ints[] = {UniformType::Int, UniformType::IVec2, UniformType::IVec3, UniformType::IVec4};
    return u.bank == ir::Bank::Float ? floats[n] : u.bank == ir::Bank::Uint ? uints[n] : ints[n];
}

}  // namespace

GlslProgram::GlslProgram(std::string name, frontend::CompiledProgram compiled, Blocks blocks)
    : compiled_(std::move(compiled)) {
    const ir::Program& p = compiled_.program;
    const std::string& file = strings_.emplace_back(compiled_.vertex.file);
    (void)file;
    const std::string where = p.fragment.code.empty() ? "" : name + ": ";
    info_.name = strings_.emplace_back(std::move(name));
    info_.description = strings_.emplace_back("GLSL");
    info_.glsl_version = p.version;
    Needs& needs = info_.needs;
    needs.derivatives = p.fragment.derivatives;
    needs.time = p.reads_time;
    needs.frag_coord = p.reads_frag_coord;
    if (p.varyings.size() > std::size_t(kMaxVaryings)) {
        throw frontend::GlslUnsupported(where + "the shaders pass " + std::to_string(p.varyings.size()) + " varying floats; quadshade interpolates " +
                        std::to_string(kMaxVaryings));
    }
    needs.varyings = int(p.varyings.size());
    for (std::size_t i = 0; i < p.varyings.size(); ++i) {
        if (p.varyings[i].flat) needs.flat_varyings |= 1u << i;
        if (p.varyings[i].noperspective) needs.noperspective_varyings |= 1u << i;
    }
    bool texcoords = false;
    for (ir::Attribute a : p.attributes) texcoords = texcoords || a == ir::Attribute::Texcoord0;
    needs.coordinates = p.varyings.empty() ? Coordinates::None : texcoords ? Coordinates::Texcoord2D : Coordinates::Object3D;
    needs.texture = false;
    samplers_.fill(-1);
    int other = 0;
    for (std::size_t s = 0; s < p.samplers.size(); ++s) {
        if (p.samplers[s].name == "teximage" && p.samplers[s].dims == 2 && !p.samplers[s].shadow) {
            needs.texture = true;
            teximage_ = int(s);
            continue;
        }
        if (other == kMaxSamplers) {
            throw frontend::GlslUnsupported(where + "more than " + std::to_string(kMaxSamplers) + " samplers besides teximage");
        }
        needs.samplers[std::size_t(other)] = {strings_.emplace_back(p.samplers[s].name), p.samplers[s].dims,
                                              p.samplers[s].shadow};
        samplers_[std::size_t(other++)] = int(s);
    }
    for (const ir::Uniform& u : p.uniforms) {
        UniformDecl d{strings_.emplace_back(u.name), uniform_type(u), {}};
        for (int i = 0; i < u.components; ++i) d.initial[std::size_t(i)] = std::bit_cast<float>(u.initial[std::size_t(i)]);
        if (is_integer(d.type)) {
            for (int i = 0; i < u.components; ++i) {
                d.initial[std::size_t(i)] = u.bank == ir::Bank::Uint ? float(u.initial[std::size_t(i)])
                                                                      : float(std::int32_t(u.initial[std::size_t(i)]));
            }
        }
        uniforms_.push_back(d);
    }
    info_.uniforms = uniforms_;
    if (blocks == Blocks::Compiled) {
        try {
            blocks_ = compile_blocks(compiled_.program.fragment);
        } catch (const jit::JitError& e) {
            compiled_.warnings.push_back("warning: " + std::string(info_.name) + ": its float arithmetic runs interpreted (" +
                                         e.what() + ")");
        }
    }
}

void GlslProgram::vertex(const VertexIn& in, const Uniforms& u, VertexOut& out) const {
    TextureSlots t{};
    if (teximage_ >= 0) t[std::size_t(teximage_)] = u.teximage;
    for (int i = 0; i < kMaxSamplers; ++i) {
        if (samplers_[std::size_t(i)] >= 0) t[std::size_t(samplers_[std::size_t(i)])] = u.samplers[std::size_t(i)];
    }
    const RunResult r = run_vertex(compiled_.program, in, u, t, out);
    if (r.loop_limit) loop_limit_.store(true, std::memory_order_relaxed);
}

void GlslProgram::shade(ShadeMode mode, const FragmentBatch& in, const Uniforms& u, ColorBatch& out) const {
    const FragmentBatch* batches[] = {&in};
    ColorBatch* outs[] = {&out};
    shade_batches(mode, batches, 1, u, outs);
}

void GlslProgram::shade_pair(ShadeMode mode, const FragmentBatch& a, const FragmentBatch& b, const Uniforms& u,
                             ColorBatch& out_a, ColorBatch& out_b) const {
    const FragmentBatch* batches[] = {&a, &b};
    ColorBatch* outs[] = {&out_a, &out_b};
    shade_batches(mode, batches, 2, u, outs);
}

void GlslProgram::shade_batches(ShadeMode mode, const FragmentBatch* const* in, int count, const Uniforms& u,
                                ColorBatch* const* out) const {
    TextureSlots t{};
    if (teximage_ >= 0) t[std::size_t(teximage_)] = u.teximage;
    for (int i = 0; i < kMaxSamplers; ++i) {
        if (samplers_[std::size_t(i)] >= 0) t[std::size_t(samplers_[std::size_t(i)])] = u.samplers[std::size_t(i)];
    }
    const ir::Program& p = compiled_.program;
    const bool dbl = mode.precision == Precision::Double;
    // One run of number type F for `n` batches from `first`.
    const auto run = [&]<class F>(int first, int n) {
        const RunResult r = interpreter::shade_batches<F>(p, in + first, n, u, t, out + first, blocks_.get());
        if (r.loop_limit) loop_limit_.store(true, std::memory_order_relaxed);
    };
    // The single-batch number type of `mode`, batch by batch.
    const auto each = [&]<class F>() {
        for (int k = 0; k < count; ++k) run.template operator()<F>(k, 1);
    };
    if (mode.derivatives == Derivatives::None && info_.needs.derivatives) {
        throw std::logic_error(std::string(info_.name) + " takes derivatives: it cannot be shaded per pixel");
    }
    if (mode.check_undefined) {
        switch (mode.derivatives) {
            case Derivatives::None: return each.template operator()<Checked<Pixels<float, kBatchLanes>>>();
            case Derivatives::Fine: return each.template operator()<Checked<Quads<float, kBatchQuads, DerivativeRule::Fine>>>();
            case Derivatives::CoarseLower:
                return each.template operator()<Checked<Quads<float, kBatchQuads, DerivativeRule::CoarseLower>>>();
            case Derivatives::CoarseUpper:
                return each.template operator()<Checked<Quads<float, kBatchQuads, DerivativeRule::CoarseUpper>>>();
            case Derivatives::Analytic: break;
        }
        throw std::logic_error("undefined-case checking shades float pixels or quads, not Dual2");
    }
    // Two batches as one number of twice the width where the rasterizer hands a pair: one
    // dispatch for both (float pixels, and quads by llvmpipe's rule, whose derivatives stay
    // inside each quad's lanes).
    const bool pair = count == 2 && !dbl;
    switch (mode.derivatives) {
        case Derivatives::None:
            if (pair) return run.template operator()<Pixels<float, 2 * kBatchLanes>>(0, 2);
            return dbl ? each.template operator()<Pixels<double, kBatchLanes>>() : each.template operator()<Pixels<float, kBatchLanes>>();
        case Derivatives::Fine:
            if (pair) return run.template operator()<Quads<float, 2 * kBatchQuads, DerivativeRule::Fine>>(0, 2);
            return dbl ? each.template operator()<Quads<double, kBatchQuads, DerivativeRule::Fine>>()
                       : each.template operator()<Quads<float, kBatchQuads, DerivativeRule::Fine>>();
        case Derivatives::CoarseLower: return each.template operator()<Quads<float, kBatchQuads, DerivativeRule::CoarseLower>>();
        case Derivatives::CoarseUpper: return each.template operator()<Quads<float, kBatchQuads, DerivativeRule::CoarseUpper>>();
        case Derivatives::Analytic:
            return dbl ? each.template operator()<Dual2<Pixels<double, kBatchLanes>>>()
                       : each.template operator()<Dual2<Pixels<float, kBatchLanes>>>();
    }
}

}  // namespace qs::interpreter
