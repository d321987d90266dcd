// The shaders with a height and the lit baked-atlas shader, instantiated for every number type
// (program_of.h), and the heights registered (height_field_of.h).
#include "shading/height_field_of.h"
#include "shading/shaders/collections.h"
#include "shading/shaders/heights.h"

namespace qs::shaders {

QUADSHADE_SHADERS_IN(kSeed001, NoiseBumps, NoiseBumpsHeightMap, NoiseBumpsLit, BakedLit)
QUADSHADE_HEIGHT_FIELD(NoiseBumps, NoiseBumpsHeightMap)

}  // namespace qs::shaders
