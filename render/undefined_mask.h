#pragma once
// The undefined-case mask of a render checked with RasterOptions::check_undefined, as an image
// and as counts: where the shader's colour depends on a GLSL case with an undefined result.
//   red    NaN produced (an operation made NaN from operands that were not NaN)
//   green  division by zero (also mod(x, 0))
//   blue   a built-in outside its domain (smoothstep with e0 >= e1, clamp with lo > hi,
//          sqrt/inversesqrt/log/log2/pow/atan where GLSL leaves them undefined)
//   grey   integer overflow GLSL leaves undefined (INT_MIN / -1): half of each channel the
//          other cases leave dark, so that it shows under them (with NaN: pink 1, 0.5, 0.5)
// Several cases mix their colours (red + green = yellow ...); black: no undefined case, or no
// fragment (clear colour).

#include <array>
#include <cstdint>

#include "core/framebuffer.h"
#include "images/image_io.h"
#include "shading/number/checked.h"

namespace qs {

// Precondition: fb.undefined is filled (the render checked for undefined cases). The image has
// the framebuffer's rows: the whole image, or the band rendered.
Image undefined_mask_image(const Framebuffer& fb);

struct UndefinedCounts {
    std::uint64_t pixels = 0;                // pixels with any case
    std::array<std::uint64_t, kUndefinedCases> per_case{};  // NaN, division by zero, argument, overflow
};
UndefinedCounts count_undefined(const Framebuffer& fb);

}  // namespace qs
