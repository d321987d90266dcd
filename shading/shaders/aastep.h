#pragma once
// Listing 1.1, translated from aastep.glsl beside this file.

#include "glsl.h"

namespace qs::shaders {
using namespace qs::glsl;

// Anisotropic anti-aliased step: a smoothstep as wide as 0.7 times the gradient's length.
// With a zero gradient the edges meet and the result is llvmpipe's `value > threshold`.
template <class F>
F aastep(const F& threshold, const F& value) {
    F afwidth = 0.7f * length(vec2<F>(dFdx(value), dFdy(value)));
    // GLSL's fwidth(value) is abs(dFdx(value)) + abs(dFdy(value))
    return smoothstep(threshold - afwidth, threshold + afwidth, value);
}

}  // namespace qs::shaders
