#pragma once
// Image files through OpenImageIO (the only file that includes it is image_io.cpp): decoding
// textures, writing renders atomically (a temporary file renamed into place, so a failed write
// leaves no partial file), and comparing two images.

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "scenes/scene.h"

namespace qs {

class ImageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// An RGBA float image, rows top-down.
struct Image {
    int width = 0, height = 0;
    std::vector<float> rgba;
};

using Metadata = std::vector<std::pair<std::string, std::string>>;

// Reads any format OpenImageIO knows; grey/RGB are expanded to RGBA (alpha 1).
Image read_image(const std::filesystem::path& path);

// An RGBA image of 8-bit unorm channels, rows top-down: what a GL_RGBA8 texture holds.
struct Image8 {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;
};

// A texture's image decoded as a GL application uploads it: rows in the file's order (glTF puts
// UV (0, 0) at the first row), alpha as stored (never premultiplied), grey and RGB expanded to
// RGBA (alpha 255), deeper channels rounded to 8 bits. Throws ImageError naming the file (or
// the embedded image's kind) when it cannot be read.
Image8 read_texture_image(const ImageSource& source);

// Writes RGB, or RGBA with `alpha`: 8-bit unorm for formats without float (PNG, ...), float for
// EXR/TIFF/HDR/PFM. `metadata` becomes string attributes (PNG text chunks, EXR headers).
void write_image(const std::filesystem::path& path, const Image& image, const Metadata& metadata = {},
                 bool alpha = false);

// Writes 8-bit RGB, or RGBA with `alpha`, as they are (for formats without float).
void write_image(const std::filesystem::path& path, const Image8& image, const Metadata& metadata = {},
                 bool alpha = false);

// Whether a file name's format stores float.
bool is_float_format(const std::filesystem::path& path);

// What OpenImageIO's ImageBufAlgo::compare reports, over RGB (alpha ignored), in [0, 1] units.
struct Comparison {
    double mean_error = 0.0, rms_error = 0.0, psnr = 0.0, max_error = 0.0;
    int max_x = 0, max_y = 0, max_channel = 0;
    std::uint64_t pixels_over_fail = 0;  // pixels with some channel over the fail threshold
    std::uint64_t pixels_over_warn = 0;
};
Comparison compare_images(const Image& a, const Image& b, float fail_threshold, float warn_threshold);

// |a - b| per pixel (max over RGB) as a heat map, and a side-by-side strip a | b | heat map.
Image difference_heat_map(const Image& a, const Image& b, float full_scale);
Image side_by_side(const std::vector<const Image*>& images);

}  // namespace qs
