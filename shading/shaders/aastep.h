#pragma once
// Listing 1.1, translated from aastep.glsl beside this file, with the two alternatives the error
// study compares (selected in GLSL by #define AASTEP_FWIDTH or AASTEP_STEP).

#include <string_view>

#include "shading/glsl.h"

namespace qs::shaders {
using namespace qs::glsl;

// How wide aastep's smoothstep is: the book's 0.7 |gradient| (Length), the cheaper 0.7 fwidth,
// which is |dx| + |dy| and so up to 1.41 times wider on diagonals, or no anti-aliasing at all.
enum class AAWidth { Length, Fwidth, Step };

// Shader names and GLSL defines of the three forms of an aastep shader.
constexpr std::string_view aa_variant_name(AAWidth w, std::string_view length, std::string_view fwidth,
                                           std::string_view step) {
    return w == AAWidth::Length ? length : w == AAWidth::Fwidth ? fwidth : step;
}
constexpr std::string_view aa_variant_defines(AAWidth w) {
    return w == AAWidth::Length ? "" : w == AAWidth::Fwidth ? "#define AASTEP_FWIDTH\n" : "#define AASTEP_STEP\n";
}

// Anisotropic anti-aliased step: a smoothstep as wide as 0.7 times the gradient's length.
// With a zero gradient the edges meet and the result is llvmpipe's `value > threshold`.
template <AAWidth W = AAWidth::Length, class F>
F aastep(const F& threshold, const F& value) {
    if constexpr (W == AAWidth::Step) {
        return step(threshold, value);
    } else {
        F afwidth = W == AAWidth::Length ? 0.7f * length(vec2<F>(dFdx(value), dFdy(value)))
                                         // GLSL's fwidth(value) is abs(dFdx(value)) + abs(dFdy(value))
                                         : 0.7f * fwidth(value);
        return smoothstep(threshold - afwidth, threshold + afwidth, value);
    }
}

}  // namespace qs::shaders
