#pragma once
// The most loop iterations one run of a stage can take, read from its syntax tree.
//
// llvmpipe leaves a shader's loops once they have gone round 65,535 times together, and the
// interpreter does as it does (interpreter/executor.h), so a loop that never ends still gives an
// image. A C++ loop has no such limit: a translation runs as llvmpipe does only where its loops
// cannot reach it. A loop is bounded where its counter starts at a constant, moves by a constant
// step (++, --, +=, -=, *=, /=) that nothing else in the loop changes, and is compared with a
// constant: its iterations are counted by running the counter. Every other loop (a while loop on
// a value the body computes, say) may run to the limit.

#include <glslang/MachineIndependent/localintermediate.h>

namespace qs::frontend {

inline constexpr long long kLoopLimit = 65535;  // llvmpipe's LP_MAX_TGSI_LOOP_ITERATIONS

struct LoopBound {
    long long iterations = 0;                    // at most, of main() and what it calls
    const TIntermNode* unbounded_loop = nullptr;  // the first loop that has no bound, if any
    bool within_limit() const { return !unbounded_loop && iterations < kLoopLimit; }
};

LoopBound loop_bound(glslang::TIntermediate& stage);

}  // namespace qs::frontend
