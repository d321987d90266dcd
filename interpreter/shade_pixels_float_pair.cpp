// The interpreter instantiated for one number type: Pixels<float, 2 * kBatchLanes>, two batches as one.
#include "interpreter/run_stage_impl.h"

namespace qs::interpreter {
template RunResult shade_batches<Pixels<float, 2 * kBatchLanes>>(const ir::Program&, const FragmentBatch* const*, int, const Uniforms&,
                                        const TextureSlots&, ColorBatch* const*, const jit::CompiledBlocks*);
}  // namespace qs::interpreter
