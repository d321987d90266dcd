// The Figure 1.1 shaders, instantiated for every number type (see program_of.h).
#include "shading/shaders/collections.h"
#include "shading/shaders/figure_1_1.h"

namespace qs::shaders {

QUADSHADE_SHADERS_IN(kSeed000, FlowNoise, Simplex3d, Turbulence, Spots<>, Tiles3d)

}  // namespace qs::shaders
