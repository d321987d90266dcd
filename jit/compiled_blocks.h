#pragma once
// A stage's straight runs of float arithmetic compiled to machine code with LLVM, for the
// interpreter's float lanes (docs/design.md, "Compiled blocks"). Inside a block each value stays
// in a machine register from the operation that computes it to the ones that read it, where the
// interpreter stores every result in its register file and loads it back. The only folder that
// includes LLVM.
//
// Every operation computes what the vocabulary's function of its name computes (shading/glsl/),
// in the same order, with no contraction into fused multiply-adds and no fast-math: a block
// gives the interpreter's bits, and the tests compare the two on every catalogue shader.

#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <vector>

#include "frontend/ir.h"

namespace qs::jit {

// Whether `in` may be part of a compiled block: float arithmetic and comparisons, the dot
// products and lengths of vectors, moves and selects, bool logic, int-to-float conversions and
// int's wrapping arithmetic and comparisons, whose every lane a block computes as the vocabulary
// does.
bool compilable(const ir::Instr& in);

// Instructions [first, end) of a stage, every one compilable.
struct Block {
    std::uint32_t first = 0, end = 0;
};

// A compiled block: runs the block's instructions on the float, int and bool banks of a register
// file (register r of a bank at its start + r * lanes; a bool one 32-bit word a lane, -1 or 0,
// as the interpreter's masks hold it), a variable written only in the lanes where `running` (a
// mask as well) is set (ir::Instr::masked), as the interpreter writes it.
using BlockCode = void (*)(float* floats, std::int32_t* ints, std::int32_t* bools, const std::int32_t* running);

// The lane widths blocks are compiled for: a batch, and a pair of batches as one number.
inline constexpr int kWidths[] = {16, 32};

// LLVM could not compile a stage's blocks: the interpreter runs their instructions instead.
class JitError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class CompiledBlocks {
public:
    // Compiles `blocks` of `stage` for each of kWidths. A block stores the registers it writes
    // that the stage may read after it. Throws JitError with LLVM's message where it cannot.
    CompiledBlocks(const ir::Stage& stage, std::span<const Block> blocks);
    ~CompiledBlocks();
    CompiledBlocks(const CompiledBlocks&) = delete;
    CompiledBlocks& operator=(const CompiledBlocks&) = delete;

    // The code of every block for `lanes` (one of kWidths), in the order they were given.
    std::span<const BlockCode> code(int lanes) const { return lanes == kWidths[0] ? narrow_ : wide_; }

private:
    struct Session;
    std::unique_ptr<Session> session_;
    std::vector<BlockCode> narrow_, wide_;
};

}  // namespace qs::jit
