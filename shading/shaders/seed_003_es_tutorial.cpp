// Seed 003's shaders, instantiated for every number type (see program_of.h).
#include "shading/shaders/collections.h"
#include "shading/shaders/seed_003_es_tutorial.h"

namespace qs::shaders {

QUADSHADE_SHADERS_IN(kSeed003, EsRandomSquare, EsRandomSquareMinus1, EsRandomSquarePlus1, EsTiles2, EsTiles128,
                     EsSmooth9Tiles128, EsSmooth5Tiles8)

}  // namespace qs::shaders
