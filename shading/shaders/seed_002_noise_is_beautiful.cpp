// Seed 002's shaders, instantiated for every number type (see program_of.h).
#include "shading/shaders/collections.h"
#include "shading/shaders/seed_002_noise_is_beautiful.h"

namespace qs::shaders {

QUADSHADE_SHADERS_IN(kSeed002, HashPcg, HashPerm289, Perlin2dPerm, Perlin3dPerm, Simplex2dSkew, Simplex3dFibonacci, Simplex2dDnoise,
                     Simplex3dDnoise, FbmSimplex2d, MultifractalSimplex2d, WarpDnoise, Scattering3d)

}  // namespace qs::shaders
