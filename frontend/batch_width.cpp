#include "frontend/batch_width.h"

#include <algorithm>
#include <vector>

#include "frontend/ir_operands.h"

namespace qs::frontend {

namespace {

bool is_texture(ir::Op op) { return op >= ir::Op::Texture && op <= ir::Op::TextureQueryLevels; }

}  // namespace

BatchWidthTraits batch_width_traits(const ir::Stage& fragment) {
    BatchWidthTraits t;
    const std::size_t floats = fragment.registers[std::size_t(ir::Bank::Float)];
    // Each float register's first and last operation: its live range in code order, which a
    // loop's body keeps whole (the values it carries round are read and written inside it).
    std::vector<int> first(floats, -1), last(floats, -1);
    int loop_depth = 0;
    for (std::size_t k = 0; k < fragment.code.size(); ++k) {
        const ir::Instr& in = fragment.code[k];
        if (in.op == ir::Op::LoopBegin) ++loop_depth;
        if (in.op == ir::Op::LoopEnd) --loop_depth;
        if (is_texture(in.op) && loop_depth > 0) t.texture_in_loop = true;
        if (in.op == ir::Op::LoadIndexed) t.largest_table = std::max(t.largest_table, int(in.count));
        for (const ir::Operand& o : ir::operands(in)) {
            if (o.bank != ir::Bank::Float) continue;
            const std::uint32_t r0 = ir::field(in, o.field);
            for (std::uint32_t r = r0; r < r0 + o.span && r < floats; ++r) {
                if (first[r] < 0) first[r] = int(k);
                last[r] = int(k);
            }
        }
    }
    std::vector<int> change(fragment.code.size() + 1, 0);
    for (std::size_t r = 0; r < floats; ++r) {
        if (first[r] < 0) continue;
        ++change[std::size_t(first[r])];
        --change[std::size_t(last[r]) + 1];
    }
    int live = 0;
    for (int c : change) t.peak_live_floats = std::max(t.peak_live_floats, live += c);
    return t;
}

bool wide_batches_pay(const BatchWidthTraits& t) {
    return t.peak_live_floats <= 128 && t.largest_table < 64 && !t.texture_in_loop;
}

}  // namespace qs::frontend
