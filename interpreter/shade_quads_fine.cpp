// The interpreter instantiated for one number type: Quads<float, kBatchQuads, DerivativeRule::Fine>.
#include "interpreter/run_stage_impl.h"

namespace qs::interpreter {
template RunResult shade_batches<Quads<float, kBatchQuads, DerivativeRule::Fine>>(const ir::Program&, const FragmentBatch* const*, int, const Uniforms&,
                                        const TextureSlots&, ColorBatch* const*, const jit::CompiledBlocks*);
}  // namespace qs::interpreter
