#pragma once
// How fragments are shaded, whichever backend produces them: the settings the rasterizer and
// the ray caster share. Each backend's own settings are its own (raster/rasterizer.h:
// RasterSettings); the ray caster has none.

#include "core/tile_grid.h"
#include "shading/shade_mode.h"

namespace qs {

struct ShadingSettings {
    // A quad rule for shaders that take derivatives, or Analytic (Dual2; for the ray caster, ray
    // differentials).
    Derivatives derivatives = Derivatives::Fine;
    Precision precision = Precision::Float;
    QuadPairing pairing = QuadPairing::TopDown;  // which rows form quads in odd-sized images
    // Fill Framebuffer::undefined: shade with Checked numbers (float only; not with Analytic
    // derivatives or Double precision: shade_choice.h). Same colours, slower.
    bool check_undefined = false;
    int threads = 0;  // 0: all cores
};

}  // namespace qs
