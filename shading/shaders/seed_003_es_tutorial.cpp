// Seed 003's shaders, instantiated for every number type (see program_of.h).
#include "shading/shaders/collections.h"
#include "shading/shaders/seed_003_es_tutorial.h"

namespace qs::shaders {

QUADSHADE_SHADERS_IN(kSeed003, EsTiles2, EsSmooth5Tiles8)

}  // namespace qs::shaders
