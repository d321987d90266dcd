// Seed 004's shaders, instantiated for every number type (see program_of.h).
#include "shading/shaders/collections.h"
#include "shading/shaders/seed_004_lawlor.h"

namespace qs::shaders {

QUADSHADE_SHADERS_IN(kSeed004, LawlorChecker, LawlorDots, LawlorDotsTexture, LawlorDotsCenterColor, LawlorDotsMoved, LawlorDotsSearch,
                     LawlorVoronoiF1, LawlorVoronoiF2, LawlorStainedGlass, LawlorTextureHigh, LawlorTextureLow,
                     LawlorTextureTwoOctaves, LawlorTextureOctaves, LawlorMandelbrot)

}  // namespace qs::shaders
