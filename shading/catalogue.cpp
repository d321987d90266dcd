#include "shading/catalogue.h"

namespace qs {

const ProgramList& catalogue() {
    static const ProgramList list = [] {
        ProgramList l;  // the groups built (QUADSHADE_SHADER_GROUPS; all unless a checking build)
#if defined(QUADSHADE_SHADERS_figure_1_1)
        register_figure_1_1(l);
#endif
#if defined(QUADSHADE_SHADERS_table_1_1)
        register_table_1_1(l);
#endif
#if defined(QUADSHADE_SHADERS_patterns)
        register_patterns(l);
#endif
#if defined(QUADSHADE_SHADERS_aa_variants)
        register_aa_variants(l);
#endif
#if defined(QUADSHADE_SHADERS_probes)
        register_probes(l);
#endif
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
