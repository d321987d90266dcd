// The interpreter instantiated for one number type: Dual2<Pixels<float, kBatchLanes>>.
#include "interpreter/run_stage_impl.h"

namespace qs::interpreter {
template RunResult shade_batches<Dual2<Pixels<float, kBatchLanes>>>(const ir::Program&, const FragmentBatch* const*, int, const Uniforms&,
                                        const TextureSlots&, ColorBatch* const*, const jit::CompiledBlocks*);
}  // namespace qs::interpreter
