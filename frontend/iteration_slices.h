#pragma once
// The part of a loop nest's body the C++ writer may run once for all the nest's iterations
// (shading/glsl/iteration_lanes.h): declarations at the head of the innermost body that read
// only the nest's counters, constants and values declared before the nest that it never writes,
// through operations and functions that read and write nothing else (no derivatives, textures,
// globals or out parameters). A cellular noise's search is the case: each neighbour's feature
// point is a hash of the cell alone.
//
// The nest: `for (int i = A; i < B; i++)` (or `<=`) loops, each the only statement of the one
// around it, whose counters the writer keeps C++ ints (every lane runs them equally often), at
// most 32 iterations in all. The part: the longest run of those declarations that reads no
// per-lane values but those the first one to read any reads (the cell, not the point inside it),
// with at least kLeastOperations operations per iteration, callees' included: fewer do not pay
// for the check that the values are alike and the read of each iteration's lane.

#include <functional>
#include <optional>
#include <vector>

#include <glslang/Include/intermediate.h>

namespace qs::frontend {

struct IterationSlice {
    std::vector<glslang::TIntermLoop*> loops;        // outermost first
    std::vector<glslang::TIntermSymbol*> counters;
    std::vector<int> first, count;
    std::vector<glslang::TIntermBinary*> declarations;  // the part, in order
    std::vector<long long> inputs;                     // the per-lane values it reads, in order of first use
    int operations = 0;                                // per iteration
};

inline constexpr int kLeastOperations = 8;
inline constexpr int kMostIterations = 32;

// What the writer knows of a local at the nest: a C++ int counter of a loop around it (the same
// in every lane), a value declared before it, or neither.
enum class LocalAtNest { PlainCounter, DeclaredBefore, Other };

// The part of the nest `loop` (with its initialiser `init`) to run across iterations, if any.
// `plain_counter(id)` says whether the writer keeps a counter a C++ int; `local(id)` what it knows
// of any other local; `root` holds the functions the part may call.
std::optional<IterationSlice> iteration_slice(glslang::TIntermLoop* loop, glslang::TIntermBinary* init,
                                              glslang::TIntermAggregate* root,
                                              const std::function<bool(long long)>& plain_counter,
                                              const std::function<LocalAtNest(long long)>& local);

}  // namespace qs::frontend
