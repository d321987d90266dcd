// The seed shaders, instantiated for every number type (see program_of.h).
#include "shading/shaders/collections.h"
#include "shading/shaders/seed_patterns.h"

namespace qs::shaders {

QUADSHADE_SHADERS_IN(kSeed002, PcgValueNoise)
QUADSHADE_SHADERS_IN(kSeed004, Mandelbrot)

}  // namespace qs::shaders
