// The Table 1.1 shaders, instantiated for every number type (see program_of.h).
#include "shading/shaders/collections.h"
#include "shading/shaders/table_1_1.h"

namespace qs::shaders {

QUADSHADE_SHADERS_IN(kSeed000, ConstantColor, SingleTexture, Dots, Perlin, Perlin5, Worley, WorleyTiles<>, Halftone<>)

}  // namespace qs::shaders
