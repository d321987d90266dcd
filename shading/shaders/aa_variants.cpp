// The error study's anti-aliasing alternatives of the aastep shaders: 0.7 fwidth instead of the
// gradient's length, and no anti-aliasing (a plain step; the pattern supersampling filters).
// Instantiated apart from the originals so that the two build in parallel.
#include "shading/shaders/collections.h"
#include "shading/shaders/figure_1_1.h"
#include "shading/shaders/patterns.h"
#include "shading/shaders/table_1_1.h"

namespace qs::shaders {

QUADSHADE_SHADERS_IN(kSeed000, DotsAA<AAWidth::Fwidth>, DotsAA<AAWidth::Step>, BricksAA<AAWidth::Fwidth>, BricksAA<AAWidth::Step>,
                     WorleyTiles<AAWidth::Fwidth>, WorleyTiles<AAWidth::Step>, Halftone<AAWidth::Fwidth>,
                     Halftone<AAWidth::Step>, Spots<AAWidth::Length>, Spots<AAWidth::Step>)

}  // namespace qs::shaders
