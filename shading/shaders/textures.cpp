// The shaders that sample named textures, instantiated for every number type (see program_of.h).
#include "shading/shaders/textures.h"

namespace qs::shaders {

QUADSHADE_SHADERS(TextureLodProbe, TextureBiasProbe, Texture3dProbe, Texture3dLodProbe, TexelFetchProbe, TexelFetch3dProbe,
                  FastNoise)

}  // namespace qs::shaders
