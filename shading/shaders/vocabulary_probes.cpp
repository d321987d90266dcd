// The vocabulary probes, instantiated for every number type (see program_of.h), in their own
// translation unit so that they compile beside the other shader groups.
#include "shading/shaders/collections.h"
#include "shading/shaders/vocabulary_probes.h"

namespace qs::shaders {

QUADSHADE_SHADERS_IN(kProbes, IntegerProbe, IntegerUndefinedProbe, BoolProbe, LoopProbe, DiscardProbe, MatrixProbe, BuiltinsProbe,
                     UniformProbe, SinCosProbe)

}  // namespace qs::shaders
