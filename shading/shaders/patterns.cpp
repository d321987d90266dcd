// The chapter's other patterns, instantiated for every number type (see program_of.h).
#include "shading/shaders/collections.h"
#include "shading/shaders/patterns.h"

namespace qs::shaders {

QUADSHADE_SHADERS_IN(kSeed000, PatternS, Lines, Ridges, Checker, Wave, WaveAA, Bricks, BricksAA<>, DotsAA<>, Facets, Blobs, Rings,
                     Simplex2d<noise::Simplex2dCorner::Correct>, Simplex2d<noise::Simplex2dCorner::SeedTypo>, Cellular2x2,
                     GradientAA)

}  // namespace qs::shaders
