#pragma once
// How a Program shades a batch: the derivative rule its quads follow and the number type it runs in.

namespace qs {

// How a batch's lanes relate and so how dFdx/dFdy are formed.
enum class Derivatives {
    None,         // independent pixels; only for shaders that take no derivatives
    Fine,         // 2x2 quads, llvmpipe's rule
    CoarseLower,  // 2x2 quads, softpipe's rule in OSMesa's buffer
    CoarseUpper,  // 2x2 quads, first pixel of a top-down quad
    Analytic,     // Dual2: exact partials carried from the interpolated varyings
};
enum class Precision { Float, Double };

struct ShadeMode {
    Derivatives derivatives = Derivatives::Fine;
    Precision precision = Precision::Float;
    // Also report, per lane, the GLSL cases with undefined results the colour depends on
    // (ColorBatch::undefined; number/checked.h). Float pixels or quads only: not with Analytic
    // or Double. The colours are the same as without.
    bool check_undefined = false;
};

}  // namespace qs
