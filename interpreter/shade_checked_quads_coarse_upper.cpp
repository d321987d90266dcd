// The interpreter instantiated for one number type: Checked<Quads<float, kBatchQuads, DerivativeRule::CoarseUpper>>.
#include "interpreter/run_stage_impl.h"

namespace qs::interpreter {
template RunResult shade_batches<Checked<Quads<float, kBatchQuads, DerivativeRule::CoarseUpper>>>(const ir::Program&, const FragmentBatch* const*, int, const Uniforms&,
                                        const TextureSlots&, ColorBatch* const*, const jit::CompiledBlocks*);
}  // namespace qs::interpreter
