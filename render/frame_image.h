#pragma once
// A frame's colour as an Image (images/image_io.h), to write or compare: the rows the framebuffer
// holds, top-down (the whole image, or the band rendered).

#include "core/framebuffer.h"
#include "images/image_io.h"

namespace qs {

inline Image colour_image(const Framebuffer& fb) { return {fb.width, fb.rows, {fb.rgba.begin(), fb.rgba.end()}}; }

}  // namespace qs
