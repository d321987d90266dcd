#pragma once
// Between the renderer's batches and a stage's registers: the inputs a stage's bindings name
// (ir::Binding) filled from fragment batches and uniforms, and its outputs read back. F holds
// one batch, or two side by side (lanes 0-15 the first batch's, 16-31 the second's).

#include <cstring>

#include "interpreter/executor_run.h"
#include "interpreter/uniform_words.h"
#include "shading/program.h"

namespace qs::interpreter {

namespace stage_io_detail {

// The plain lanes under F (what Dual2 carries and Checked wraps), filled from `parts` arrays of
// kBatchLanes floats each.
template <class P>
P load_plain(const float* const* parts) {
    using T = typename P::value_type;
    alignas(64) T lanes[P::size];
    if constexpr (std::is_same_v<T, float> && P::size % kBatchLanes == 0) {
        for (int k = 0; k < P::size / kBatchLanes; ++k) {
            std::memcpy(lanes + k * kBatchLanes, parts[k], sizeof(float) * kBatchLanes);
        }
    } else {
        for (int i = 0; i < P::size; ++i) lanes[i] = T(parts[i / kBatchLanes][i % kBatchLanes]);
    }
    return P::load(lanes);
}

template <class F>
F load(const float* const* values, const float* const* ddx, const float* const* ddy) {
    if constexpr (is_dual2<F>::value) {
        using T = typename F::value_type;
        return F(load_plain<T>(values), load_plain<T>(ddx), load_plain<T>(ddy));
    } else if constexpr (is_checked_v<F>) {
        using L = decltype(F::v);
        alignas(64) float lanes[L::size];
        for (int i = 0; i < L::size; ++i) lanes[i] = values[i / kBatchLanes][i % kBatchLanes];
        return F::load(lanes);
    } else {
        return load_plain<F>(values);
    }
}

template <class F>
void store(const F& v, float* const* parts) {
    if constexpr (is_dual2<F>::value) {
        store(v.val, parts);
    } else if constexpr (is_checked_v<F>) {
        store(v.v, parts);
    } else {
        using T = typename F::value_type;
        alignas(64) T lanes[F::size];
        v.store(lanes);
        if constexpr (std::is_same_v<T, float> && F::size % kBatchLanes == 0) {
            for (int k = 0; k < F::size / kBatchLanes; ++k) {
                std::memcpy(parts[k], lanes + k * kBatchLanes, sizeof(float) * kBatchLanes);
            }
        } else {
            for (int i = 0; i < F::size; ++i) parts[i / kBatchLanes][i % kBatchLanes] = float(lanes[i]);
        }
    }
}

// Integer lanes from the bits of floats (a flat int varying travels as its bits).
template <class I>
I load_bits(const float* const* parts) {
    using T = typename I::value_type;
    alignas(64) T bits[I::size];
    for (int i = 0; i < I::size; ++i) std::memcpy(&bits[i], &parts[i / kBatchLanes][i % kBatchLanes], sizeof(T));
    return I::load(bits);
}

}  // namespace stage_io_detail

// Fills the registers bound to uniforms (the same for every fragment).
template <class F>
void fill_uniforms(const ir::Program& program, const ir::Stage& stage, const Uniforms& u, Registers<F>& r) {
    using namespace executor_detail;
    using M = Bool<F>;
    for (const ir::Binding& b : stage.inputs) {
        std::uint32_t word = 0;
        if (b.source == ir::Source::FragCoord || b.source == ir::Source::Varying) continue;  // most inputs, per batch
        if (!uniform_word(program, b, u, word)) continue;
        switch (b.bank) {
            case ir::Bank::Float: r.f[b.reg] = from_word<F, M>(word); break;
            case ir::Bank::Int: r.i[b.reg] = from_word<int_t<F>, M>(word); break;
            case ir::Bank::Uint: r.u[b.reg] = from_word<uint_t<F>, M>(word); break;
            case ir::Bank::Bool: r.b[b.reg] = from_word<M, M>(word); break;
        }
    }
}

// Fills the fragment inputs from `count` batches (F's lanes / kBatchLanes).
template <class F>
void fill_fragment(const ir::Stage& stage, const FragmentBatch* const* in, int count, Registers<F>& r) {
    using stage_io_detail::load;
    alignas(64) static constexpr float kOnes[kBatchLanes] = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
    alignas(64) static constexpr float kZeros[kBatchLanes] = {};
    constexpr int kMaxParts = 2;
    const float* values[kMaxParts];
    const float* dx[kMaxParts];
    const float* dy[kMaxParts];
    for (const ir::Binding& b : stage.inputs) {
        switch (b.source) {
            case ir::Source::FragCoord: {
                const int c = b.index;
                // d(x)/dx = 1, d(y)/dy = 1; z and 1/w with their derivatives (Dual2 only).
                for (int k = 0; k < count; ++k) {
                    values[k] = in[k]->frag_coord[c];
                    dx[k] = c == 0 ? kOnes : c == 1 ? kZeros : in[k]->frag_coord_dx[c - 2];
                    dy[k] = c == 0 ? kZeros : c == 1 ? kOnes : in[k]->frag_coord_dy[c - 2];
                }
                r.f[b.reg] = load<F>(values, dx, dy);
                break;
            }
            case ir::Source::FrontFacing: {
                std::uint32_t bits = 0;  // lane i of F is lane i % kBatchLanes of batch i / kBatchLanes
                for (int k = 0; k < count; ++k) bits |= in[k]->front_facing << (k * kBatchLanes);
                r.b[b.reg] = executor_detail::mask_of_bits<F>(bits);
                break;
            }
            case ir::Source::Varying:
                for (int k = 0; k < count; ++k) {
                    values[k] = in[k]->varying[b.index];
                    dx[k] = in[k]->varying_dx[b.index];
                    dy[k] = in[k]->varying_dy[b.index];
                }
                switch (b.bank) {
                    case ir::Bank::Float: r.f[b.reg] = load<F>(values, dx, dy); break;
                    case ir::Bank::Int: r.i[b.reg] = stage_io_detail::load_bits<int_t<F>>(values); break;
                    case ir::Bank::Uint: r.u[b.reg] = stage_io_detail::load_bits<uint_t<F>>(values); break;
                    case ir::Bank::Bool: break;
                }
                break;
            default: break;
        }
    }
}

// The colour of the batches, and their undefined cases where F is Checked.
template <class F>
void read_color(const ir::Stage& stage, const Registers<F>& r, ColorBatch* const* out, int count) {
    LaneCases cases;
    float* parts[2];
    for (const ir::Binding& b : stage.outputs) {
        if (b.source != ir::Source::Color) continue;
        const F& v = r.f[b.reg];
        for (int k = 0; k < count; ++k) parts[k] = out[k]->rgba[b.index];
        stage_io_detail::store(v, parts);
        if constexpr (is_checked_v<F>) cases |= v.cases;
    }
    if constexpr (is_checked_v<F>) {
        for (int i = 0; i < kBatchLanes; ++i) out[0]->undefined[i] = cases.at(i);
    }
}

}  // namespace qs::interpreter
