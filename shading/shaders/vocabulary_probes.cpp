// Explicit instantiation of the vocabulary probes (see program_of.h), in their own translation
// unit so that they compile beside the other shader groups.
#include "shading/shaders/vocabulary_probes.h"

#include "shading/catalogue.h"

namespace qs {

void register_vocabulary_probes(ProgramList& list) {
    static const ProgramOf<shaders::IntegerProbe> integer_probe;
    static const ProgramOf<shaders::IntegerUndefinedProbe> integer_undefined_probe;
    static const ProgramOf<shaders::BoolProbe> bool_probe;
    static const ProgramOf<shaders::LoopProbe> loop_probe;
    static const ProgramOf<shaders::DiscardProbe> discard_probe;
    static const ProgramOf<shaders::MatrixProbe> matrix_probe;
    static const ProgramOf<shaders::BuiltinsProbe> builtins_probe;
    list.insert(list.end(), {&integer_probe, &integer_undefined_probe, &bool_probe, &loop_probe, &discard_probe,
                             &matrix_probe, &builtins_probe});
}

}  // namespace qs
