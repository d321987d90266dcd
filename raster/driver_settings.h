#pragma once
// The rasterizer set up as a Mesa driver renders: what makes quadshade's images comparable with
// an OSMesa reference (tests/reference, quadshade check).

#include "raster/rasterizer.h"

namespace qs {

enum class MesaDriver { Llvmpipe, Softpipe };

// llvmpipe: fine derivatives, the left-bottom fill rule and (on FMA hosts) fused interpolation;
// softpipe: coarse-lower derivatives, the right-top fill rule and separately rounded
// interpolation.
inline RasterOptions raster_options_as(MesaDriver driver) {
    RasterOptions r;
    const bool softpipe = driver == MesaDriver::Softpipe;
    r.derivatives = softpipe ? Derivatives::CoarseLower : Derivatives::Fine;
    r.fill_rule = softpipe ? FillRule::RightTop : FillRule::LeftBottom;
    r.fused_interpolation = softpipe ? false : fused_interpolation_default();
    return r;
}

}  // namespace qs
