// The seed shaders, instantiated for every number type (see program_of.h).
#include "shading/shaders/seed_patterns.h"

namespace qs::shaders {

QUADSHADE_SHADERS(PcgValueNoise, Mandelbrot)

}  // namespace qs::shaders
