#pragma once
// The error study's anti-aliasing alternatives of the aastep shaders (aastep_shaders.h): 0.7
// fwidth instead of the gradient's length, and no anti-aliasing (a plain step; the pattern
// supersampling filters). A family apart from the chapter's forms so that the two build in
// parallel.

#include "shading/program_of.h"
#include "shading/shaders/aastep_shaders.h"
#include "shading/shaders/collections.h"

namespace qs::shaders {

QUADSHADE_SHADERS_IN(kGustavson, DotsAA<AAWidth::Fwidth>, DotsAA<AAWidth::Step>, BricksAA<AAWidth::Fwidth>, BricksAA<AAWidth::Step>,
                     WorleyTiles<AAWidth::Fwidth>, WorleyTiles<AAWidth::Step>, Halftone<AAWidth::Fwidth>,
                     Halftone<AAWidth::Step>, Spots<AAWidth::Length>, Spots<AAWidth::Step>)

}  // namespace qs::shaders
