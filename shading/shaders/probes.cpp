// Explicit instantiation of the probe shaders (see program_of.h).
#include "shading/shaders/probes.h"

#include "shading/catalogue.h"

namespace qs {

void register_probes(ProgramList& list) {
    static const ProgramOf<shaders::DerivativeProbe> derivative_probe;
    static const ProgramOf<shaders::StDerivativeProbe> st_derivative_probe;
    static const ProgramOf<shaders::PositionDerivativeProbe> position_derivative_probe;
    static const ProgramOf<shaders::SmoothstepProbe> smoothstep_probe;
    static const ProgramOf<shaders::ArithmeticProbe> arithmetic_probe;
    static const ProgramOf<shaders::FloatEnvironmentProbe> float_env_probe;
    list.insert(list.end(), {&derivative_probe, &st_derivative_probe, &position_derivative_probe, &smoothstep_probe, &arithmetic_probe, &float_env_probe});
}

}  // namespace qs
