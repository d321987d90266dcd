#pragma once
// PNG through libpng: image_library.h's Decoder and Encoder for the format that renders, bakes and
// most textures are, so that they never load OpenImageIO (image_io.cpp picks them by format).
// They decode and encode the pixels OpenImageIO 2.4 does over the same libpng, so that an image
// read or written is the same whichever library handles it: every PNG kind expanded to 8 or 16
// bits (palette to RGB, gray below 8 bits to 8, a tRNS chunk to alpha), no gamma or sRGB
// conversion, alpha associated on reading unless kept as stored, samples converted as OpenImageIO
// converts them, and string attributes written as text chunks (tests/images/test_png_codec.cpp
// checks all of it against OpenImageIO).

#include <memory>
#include <span>
#include <string>

#include "images/image_library.h"

namespace qs::image_library {

// A PNG decoder on `bytes` (which must outlive it), its header read; nullptr, with `error` set,
// when it cannot be read. `unassociated_alpha`: colours come back as stored, not premultiplied.
std::unique_ptr<Decoder> open_png(std::span<const unsigned char> bytes, bool unassociated_alpha, std::string& error);

// A PNG encoder of 8-bit samples.
std::unique_ptr<Encoder> create_png();

}  // namespace qs::image_library
