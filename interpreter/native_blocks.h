#pragma once
// The compiled blocks of a stage the interpreter runs (jit/compiled_blocks.h): its straight runs of
// float arithmetic, compiled for float lanes, each marked in the code by an ir::Op::Native
// before its first instruction. Float lanes run the block's machine code and jump past its
// instructions; the other number types (double, Dual2, the undefined-case check) run the
// instructions as before, so a marker changes no value any of them computes.

#include <memory>

#include "frontend/ir.h"
#include "jit/compiled_blocks.h"
#include "shading/number/integer.h"
#include "shading/number/lanes.h"
#include "shading/number/number.h"

namespace qs::interpreter {

// The fewest instructions a block takes: a shorter run costs more in the call than it saves.
inline constexpr std::uint32_t kShortestBlock = 2;
// The most a block takes: LLVM's register allocation takes more than linear time in a block's
// length (5x Perlin's 768 instructions compile in 0.15 s a width), so a longer run is cut.
inline constexpr std::uint32_t kLongestBlock = 1024;
// The most instructions a stage compiles, about a second of LLVM's time (a 104-line shader of 30
// inlined noises: 1.2 s to its first 16x16 image): past them a huge shader runs interpreted, its
// first image not held up longer.
inline constexpr std::uint32_t kMostCompiled = 2048;

// Finds the blocks of `stage`, prepares them for LLVM (jit::CompiledBlocks, which compiles each
// width when it is first asked for) and marks them in its code, jump targets moved onto each
// block's marker. Returns nullptr, the stage unchanged, where it has no block. Throws
// jit::JitError where LLVM cannot start, the stage unchanged.
std::unique_ptr<jit::CompiledBlocks> compile_blocks(ir::Stage& stage);

// F's lanes where the compiled blocks run for F: plain float lanes of one of jit::kWidths
// (pixels or quads under any rule), laid out as a float array, their ints and masks as one
// 32-bit word a lane; 0 for the others.
template <class F>
inline constexpr int native_lanes = 0;
template <int N, class Layout>
    requires(N == jit::kWidths[0] || N == jit::kWidths[1])
inline constexpr int native_lanes<Lanes<float, N, Layout>> =
    sizeof(Lanes<float, N, Layout>) == N * 4 && sizeof(int_t<Lanes<float, N, Layout>>) == N * 4 &&
            sizeof(Bool<Lanes<float, N, Layout>>) == N * 4
        ? N
        : 0;

}  // namespace qs::interpreter
