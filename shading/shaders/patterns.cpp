// The chapter's other patterns, instantiated for every number type (see program_of.h); Listing
// 1.3's simplex noise is in simplex2d.cpp.
#include "shading/shaders/collections.h"
#include "shading/shaders/patterns.h"

namespace qs::shaders {

QUADSHADE_SHADERS_IN(kSeed000, PatternS, Lines, Ridges, Checker, Wave, WaveAA, Bricks, BricksAA<>, DotsAA<>, Facets, Blobs, Rings,
                     Cellular2x2, GradientAA)

}  // namespace qs::shaders
