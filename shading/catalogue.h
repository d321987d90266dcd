#pragma once
// The shader catalogue: every translated shader, looked up by the name scenes use.

#include <string_view>
#include <vector>

#include "shading/program.h"

namespace qs {

using ProgramList = std::vector<const Program*>;

// All programs, in a stable order: Figure 1.1, Table 1.1, the other chapter patterns, the seeds'
// shaders, probes.
const ProgramList& catalogue();
// nullptr when no shader has that name.
const Program* find_program(std::string_view name);

// Registration, one function per translation unit of shaders.
void register_figure_1_1(ProgramList& list);
void register_table_1_1(ProgramList& list);
void register_patterns(ProgramList& list);
void register_probes(ProgramList& list);
void register_aa_variants(ProgramList& list);
void register_seed_patterns(ProgramList& list);
void register_vocabulary_probes(ProgramList& list);

}  // namespace qs
