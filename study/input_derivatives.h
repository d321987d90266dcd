#pragma once
// A shader's inputs seen through the derivatives each rule gives them: a Program that runs
// another's vertex stage and, in its fragment stage, writes dFdx and dFdy of one of the varyings
// it receives (red, green), the varying itself (blue) and 1 (alpha), in the number type of the
// rule it is shaded with: quads under fine, coarse-lower and coarse-upper, Dual2 for the analytic
// partials. Rendered under each rule, the maps show where in the image the quad rules depart
// from the exact derivative (perspective, silhouettes where helper lanes extrapolate, coarse
// quads' shared derivative).

#include <memory>
#include <string>

#include "shading/program.h"

namespace qs::study {

// A Program for varying `varying` of `inner` (which must outlive it), named `name`. Throws
// std::invalid_argument for a varying `inner` does not write.
std::unique_ptr<Program> input_derivatives(const Program& inner, int varying, std::string name);

// A name for `info`'s varying `v` a reader knows: st.s, P.x, ... from its coordinates; else "varying v".
std::string varying_name(const ShaderInfo& info, int v);

}  // namespace qs::study
