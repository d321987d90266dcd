#pragma once
// The ways of shading a same-pixels test runs a shader under: every derivative rule, and double
// precision, since a translation and the interpreter are both written over the number type.

#include "shading/shade_mode.h"

namespace qs::test {

struct ShadingMode {
    const char* what;
    Derivatives derivatives;
    Precision precision;
};
inline constexpr ShadingMode kShadingModes[] = {{"fine", Derivatives::Fine, Precision::Float},
                                                {"coarse-lower", Derivatives::CoarseLower, Precision::Float},
                                                {"coarse-upper", Derivatives::CoarseUpper, Precision::Float},
                                                {"analytic", Derivatives::Analytic, Precision::Float},
                                                {"double", Derivatives::Fine, Precision::Double}};

}  // namespace qs::test
