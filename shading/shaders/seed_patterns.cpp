// The seed shaders, instantiated for every number type (see program_of.h).
//
// Flattened on every target, not only AVX-512: both shaders are small, so it costs this file
// seconds of compile time, and on AVX2 it is what makes them fast (measured in
// quadshade-bench-core: see the README).
#define QS_FLATTEN_ON_EVERY_TARGET
#include "shading/shaders/collections.h"
#include "shading/shaders/seed_patterns.h"

namespace qs::shaders {

QUADSHADE_SHADERS_IN(kSeed002, PcgValueNoise)
QUADSHADE_SHADERS_IN(kSeed004, Mandelbrot)

}  // namespace qs::shaders
