// Seed 002's float hashes, instantiated for every number type (see program_of.h).
#include "shading/shaders/collections.h"
#include "shading/shaders/seed_002_hashes.h"

namespace qs::shaders {

QUADSHADE_SHADERS_IN(kSeed002, HashSin, HashHoskins)

}  // namespace qs::shaders
