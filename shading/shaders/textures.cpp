// The shaders that sample named textures, instantiated for every number type (see program_of.h).
#include "shading/shaders/collections.h"
#include "shading/shaders/textures.h"

namespace qs::shaders {

QUADSHADE_SHADERS_IN(kProbes, TextureLodProbe, TextureBiasProbe, Texture3dProbe, Texture3dLodProbe, TexelFetchProbe,
                     TexelFetch3dProbe)
QUADSHADE_SHADERS_IN(kSeed001, FastNoise)

}  // namespace qs::shaders
