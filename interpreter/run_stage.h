#pragma once
// One stage run for number type F: registers from this thread's cache, inputs filled, the
// executor run, outputs read. Declared for every F the program shades with; defined in
// run_stage_impl.h and instantiated, one number type per .cpp, by shade_<type>.cpp.

#include "frontend/ir.h"
#include "interpreter/executor.h"
#include "shading/program.h"

namespace qs::interpreter {

// Shades batches in[0..count) into out[0..count): F's lanes are count batches' (1, or 2 for the
// wide types of the paired path); the fragment stage's compiled blocks run where `blocks` has
// them and F has float lanes (native_blocks.h).
template <class F>
RunResult shade_batches(const ir::Program& program, const FragmentBatch* const* in, int count, const Uniforms& u,
                        const TextureSlots& textures, ColorBatch* const* out, const jit::CompiledBlocks* blocks);

// Runs the vertex stage on one vertex.
RunResult run_vertex(const ir::Program& program, const VertexIn& in, const Uniforms& u, const TextureSlots& textures,
                     VertexOut& out);

}  // namespace qs::interpreter
