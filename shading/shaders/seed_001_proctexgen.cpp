// Seed 001's shaders, instantiated for every number type (see program_of.h).
#include "shading/shaders/seed_001_proctexgen.h"

namespace qs::shaders {

QUADSHADE_SHADERS(ImprovedNoise, ImprovedNoiseLoop, FastNoiseVolume)

}  // namespace qs::shaders
