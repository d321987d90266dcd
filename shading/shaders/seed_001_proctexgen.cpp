// Seed 001's shaders, instantiated for every number type (see program_of.h).
#include "shading/shaders/collections.h"
#include "shading/shaders/seed_001_proctexgen.h"

namespace qs::shaders {

QUADSHADE_SHADERS_IN(kSeed001, ImprovedNoise, ImprovedNoiseLoop, FastNoiseVolume,
                     Worley3d<WorleyShow::F1, false>, Worley3d<WorleyShow::F2, false>, Worley3d<WorleyShow::F2MinusF1, false>,
                     Worley3d<WorleyShow::Mean, false>, Worley3d<WorleyShow::F1, true>, Worley3d<WorleyShow::F2, true>,
                     Worley3d<WorleyShow::F2MinusF1, true>, Worley3d<WorleyShow::Mean, true>, Worley3dFbm)

}  // namespace qs::shaders
