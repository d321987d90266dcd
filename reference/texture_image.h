#pragma once
// A texture's image decoded as the reference's own (stb_image: the only file that includes it is
// texture_image.cpp), not through the renderer's decoder (images/image_io.h, OpenImageIO), so
// that a decoding error of either shows as a difference.

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "scenes/scene.h"

namespace qs {

// Pixels as glTexImage2D takes them: RGBA, rows in the file's order, alpha as stored (grey and
// RGB expanded, alpha opaque); 8 bits per channel, or 16 for 16-bit files (GL makes RGBA8 of
// them).
struct DecodedImage {
    int width = 0, height = 0;
    bool sixteen_bits = false;
    std::vector<std::uint8_t> bytes;  // width * height * 4 channels of 1 or 2 bytes (native order)
};

// Throws std::runtime_error naming the file, or the embedded image's kind, when it cannot be
// read or decoded.
DecodedImage decode_texture_image(const ImageSource& source);

}  // namespace qs
