#pragma once
// OpenEXR through the OpenEXR library: image_library.h's Decoder and Encoder for the format of
// float renders and of every reference image, so that they never load OpenImageIO (image_io.cpp
// picks them by format). They decode the pixels OpenImageIO 2.4 does over the same library: part 0
// of a multi-part file, the data window (not the display window), the highest-resolution level of
// a tiled file, channels in OpenImageIO's order (by layer, then R, G, B, Y, A..., then as stored),
// half, float and unsigned samples converted as OpenImageIO converts them; and they write what its
// writer does: float R, G, B(, A) channels, ZIP compression, string attributes in the header
// (tests/images/test_exr_codec.cpp checks all of it against OpenImageIO). OpenEXR's exceptions stop
// at this edge and come back as messages.

#include <memory>
#include <span>
#include <string>

#include "images/image_library.h"

namespace qs::image_library {

// An OpenEXR decoder on `bytes` (which must outlive it), its header read; nullptr, with `error`
// set, when it cannot be read. `name` names the file in OpenEXR's messages.
std::unique_ptr<Decoder> open_exr(std::span<const unsigned char> bytes, const std::string& name, std::string& error);

// An OpenEXR encoder of float samples.
std::unique_ptr<Encoder> create_exr();

}  // namespace qs::image_library
