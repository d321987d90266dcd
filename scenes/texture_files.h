#pragma once
// A scene's textures' images, decoded as a GL application uploads them (images/ decodes them).

#include <cstdint>

#include "images/image_io.h"
#include "scenes/scene.h"

namespace qs {

// Whether decoding one of `scene`'s textures needs OpenImageIO (images/image_io.h).
bool needs_image_library(const Scene& scene);

// A texture's image decoded as a GL application uploads it: rows in the file's order (glTF puts
// UV (0, 0) at the first row), alpha as stored (never premultiplied), grey and RGB expanded to
// RGBA (alpha 255), deeper channels rounded to 8 bits. A file is read as read_image reads one
// (a regular file, the reader its extension names) and embedded bytes by their MIME type; both
// within the texture limits of scenes/limits.h, checked on the header. Throws ImageError naming
// the file (or the embedded image's kind) when it cannot be read. `decoding_bytes`, when given,
// receives the most the decoding held at once: the file, the samples as stored (when not 8-bit)
// and as 8-bit, and the RGBA image.
Image8 read_texture_image(const ImageSource& source, std::uint64_t* decoding_bytes = nullptr);

}  // namespace qs
