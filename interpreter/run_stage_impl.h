#pragma once
// shade_batches (run_stage.h), for the .cpp that instantiates it for one number type.

#include <unordered_map>

#include "interpreter/run_stage.h"
#include "interpreter/stage_io.h"

namespace qs::interpreter {

// This thread's registers for `stage`, its constants in place: kept per stage, since a frame's
// draws alternate between programs tile by tile.
template <class F>
Registers<F>& thread_registers(const ir::Stage& stage) {
    thread_local std::unordered_map<std::uint64_t, Registers<F>> cache;
    thread_local std::uint64_t last_serial = 0;
    thread_local Registers<F>* last = nullptr;
    if (last && last_serial == stage.serial) return *last;
    Registers<F>& r = cache[stage.serial];
    r.prepare(stage);
    last_serial = stage.serial, last = &r;
    return r;
}

template <class F>
RunResult shade_batches(const ir::Program& program, const FragmentBatch* const* in, int count, const Uniforms& u,
                        const TextureSlots& textures, ColorBatch* const* out, const jit::CompiledBlocks* blocks) {
    const ir::Stage& stage = program.fragment;
    Registers<F>& r = thread_registers<F>(stage);
    fill_uniforms(program, stage, u, r);
    fill_fragment(stage, in, count, r);
    std::span<const jit::BlockCode> native;
    if constexpr (native_lanes<F> > 0) {
        if (blocks) native = blocks->code(native_lanes<F>);
    }
    const RunResult result = Executor<F>::run(stage, r, textures, native);
    read_color(stage, r, out, count);
    for (int k = 0; k < count; ++k) out[k]->discarded = (result.discarded >> (k * kBatchLanes)) & 0xFFFFu;
    return result;
}

}  // namespace qs::interpreter
