// Seed 000's remaining shaders, instantiated for every number type (see program_of.h).
#include "shading/shaders/collections.h"
#include "shading/shaders/seed_000_gustavson.h"

namespace qs::shaders {

QUADSHADE_SHADERS_IN(kSeed000, Simplex3dContourAa, Simplex4dAnimated, SimplexBump)

}  // namespace qs::shaders
