#include "interpreter/native_blocks.h"

#include <limits>
#include <vector>

#include "frontend/ir_operands.h"

namespace qs::interpreter {

namespace {

// A marker names its block in Instr::count.
static_assert(kMostCompiled / kShortestBlock <= std::numeric_limits<decltype(ir::Instr::count)>::max());

// The maximal runs of compilable instructions that nothing jumps into but at their first, cut
// at kLongestBlock, up to kMostCompiled instructions in all.
std::vector<jit::Block> find_blocks(const ir::Stage& stage) {
    const std::vector<ir::Instr>& code = stage.code;
    std::vector<bool> target(code.size() + 1, false);
    for (const ir::Instr& in : code) {
        if (ir::jumps(in.op)) target[in.target] = true;
    }
    std::vector<jit::Block> blocks;
    std::uint32_t compiled = 0;
    for (std::uint32_t first = 0; first < code.size();) {
        if (!jit::compilable(code[first])) {
            ++first;
            continue;
        }
        std::uint32_t end = first + 1;
        while (end < code.size() && end - first < kLongestBlock && jit::compilable(code[end]) && !target[end]) ++end;
        if (end - first >= kShortestBlock && compiled + (end - first) <= kMostCompiled) {
            blocks.push_back({first, end});
            compiled += end - first;
        }
        first = end;
    }
    return blocks;
}

}  // namespace

std::unique_ptr<jit::CompiledBlocks> compile_blocks(ir::Stage& stage) {
    const std::vector<jit::Block> blocks = find_blocks(stage);
    if (blocks.empty()) return nullptr;
    auto compiled = std::make_unique<jit::CompiledBlocks>(stage, blocks);
    // Each instruction's index in the marked code, and each block's marker's, by the index of
    // its first instruction: a jump to a block's start lands on its marker.
    const std::vector<ir::Instr>& code = stage.code;
    std::vector<std::uint32_t> moved(code.size() + 1);
    std::vector<std::int64_t> marker(code.size() + 1, -1);
    std::uint32_t added = 0;
    std::size_t next = 0;
    for (std::uint32_t i = 0; i <= code.size(); ++i) {
        if (next < blocks.size() && blocks[next].first == i) {
            marker[i] = i + added;
            ++added, ++next;
        }
        moved[i] = i + added;
    }
    const auto land = [&](std::uint32_t t) { return marker[t] >= 0 ? std::uint32_t(marker[t]) : moved[t]; };
    std::vector<ir::Instr> marked;
    marked.reserve(code.size() + blocks.size());
    next = 0;
    for (std::uint32_t i = 0; i < code.size(); ++i) {
        if (next < blocks.size() && blocks[next].first == i) {
            ir::Instr native{ir::Op::Native};
            native.count = std::uint16_t(next);
            native.target = land(blocks[next].end);
            native.line = code[i].line;
            marked.push_back(native);
            ++next;
        }
        ir::Instr in = code[i];
        if (ir::jumps(in.op)) in.target = land(in.target);
        marked.push_back(in);
    }
    stage.code = std::move(marked);
    return compiled;
}

}  // namespace qs::interpreter
