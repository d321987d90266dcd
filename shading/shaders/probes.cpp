// The probe shaders, instantiated for every number type (see program_of.h).
#include "shading/shaders/collections.h"
#include "shading/shaders/probes.h"

namespace qs::shaders {

QUADSHADE_SHADERS_IN(kProbes, DerivativeProbe, StDerivativeProbe, PositionDerivativeProbe, SmoothstepProbe, ArithmeticProbe,
                     FloatEnvironmentProbe)

}  // namespace qs::shaders
