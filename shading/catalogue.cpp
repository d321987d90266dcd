#include "shading/catalogue.h"

namespace qs {

const ProgramList& catalogue() {
    static const ProgramList list = [] {
        ProgramList l;
        register_figure_1_1(l);
        register_table_1_1(l);
        register_patterns(l);
        register_aa_variants(l);
        register_seed_patterns(l);
        register_probes(l);
        register_vocabulary_probes(l);
        return l;
    }();
    return list;
}

const Program* find_program(std::string_view name) {
    for (const Program* p : catalogue()) {
        if (p->info().name == name) return p;
    }
    return nullptr;
}

}  // namespace qs
