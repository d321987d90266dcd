#pragma once
// Rewrites of a stage's code that change no value it computes and leave the interpreter fewer
// operations to dispatch (docs/design.md, "The interpreter"). Run on the finished code, its
// registers laid out.

#include <vector>

#include "frontend/ir.h"

namespace qs::frontend {

// Removes the markers of inlined functions that set no lanes aside: a Return just before its
// function's end, or main's, and a CallBegin and CallEnd with no Return of their own between.
void drop_idle_calls(ir::Stage& stage);

// Joins each run of a component-wise operation (ir::component_wise) whose destinations are
// consecutive registers and whose operands each step by one register or stay on one into a
// single operation of n components: GLSL's vector arithmetic, which the front end writes
// component by component, is dispatched once per vector.
void join_component_runs(ir::Stage& stage);

// Removes the instructions whose flag is set, moving each jump target onto the instruction that
// followed it.
void remove_instructions(ir::Stage& stage, const std::vector<bool>& removed);

}  // namespace qs::frontend
