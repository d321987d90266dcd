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

#include <array>
#include <atomic>
#include <cstdint>
#include <iterator>
#include <mutex>
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
    // Prepares `blocks` of `stage`, which it keeps a copy of: a block will store the registers it
    // writes that the stage may read after it. Throws JitError with LLVM's message where LLVM
    // cannot start. The blocks are compiled for a width when code() first asks for it.
    CompiledBlocks(const ir::Stage& stage, std::span<const Block> blocks);
    ~CompiledBlocks();
    CompiledBlocks(const CompiledBlocks&) = delete;
    CompiledBlocks& operator=(const CompiledBlocks&) = delete;

    // The code of every block for `lanes` (one of kWidths), in the order they were given,
    // compiled on the first call for that width (the others wait for it): a renderer that hands
    // pairs only compiles one width. Empty where LLVM could not compile them, and the instructions
    // are interpreted; failed() says so.
    std::span<const BlockCode> code(int lanes) const;
    bool failed() const { return failed_.load(std::memory_order_relaxed); }

private:
    struct Session;
    void compile(std::size_t width) const;

    std::unique_ptr<Session> session_;
    mutable std::array<std::once_flag, std::size(kWidths)> compiled_;
    mutable std::array<std::vector<BlockCode>, std::size(kWidths)> code_;
    mutable std::atomic<bool> failed_{false};
};

}  // namespace qs::jit
