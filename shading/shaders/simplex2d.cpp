// Listing 1.3's 2D simplex noise (and its seed's typo), a group of their own: see
// shading/CMakeLists.txt for why it is compiled without the other groups' scheduling.
#include "shading/shaders/collections.h"
#include "shading/shaders/patterns.h"

namespace qs::shaders {

QUADSHADE_SHADERS_IN(kSeed000, Simplex2d<noise::Simplex2dCorner::Correct>, Simplex2d<noise::Simplex2dCorner::SeedTypo>)

}  // namespace qs::shaders
