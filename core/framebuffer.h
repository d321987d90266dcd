#pragma once
// Colour (RGBA float) and optional depth, stored top-down: row 0 is the top of the image, the
// order of OSMesa's buffer and of image files. GL window coordinates have y up: the pixel at
// window (x, y) is row height-1-y.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/cache_lines.h"
#include "core/tile_grid.h"

namespace qs {

struct Framebuffer {
    int width = 0, height = 0;  // the image's size
    // The rows held: [first_row, first_row + rows) of the image. The whole image, unless it was
    // rendered band by band (RowBand, tile_grid.h); the vectors below hold these rows only.
    int first_row = 0, rows = 0;
    // 4 per pixel, top-down; from a cache line on, so that a block's row of four pixels fills one
    // where the width is a multiple of 4 (cache_lines.h)
    std::vector<float, CacheLineAllocator<float>> rgba;
    // Empty when the frame needed no depth buffer; else 1 per pixel, cleared to 1: window depth
    // as a 24-bit depth buffer holds it (depth_buffer.h).
    std::vector<float> depth;
    // Empty unless the render checked for undefined GLSL cases; else 1 per pixel, top-down: the
    // Undefined bits (number/checked.h) of the fragment that wrote the pixel, 0 where cleared.
    std::vector<std::uint8_t> undefined;

    // Made to hold `band` (resolved: checked_band) of a width x height image, with a depth and an
    // undefined-case buffer or without; keeps the vectors' memory, not their contents.
    void hold(int image_width, int image_height, RowBand band, bool with_depth, bool with_undefined) {
        width = image_width, height = image_height;
        first_row = band.begin, rows = band.end - band.begin;
        const std::size_t pixels = std::size_t(width) * std::size_t(rows);
        rgba.resize(pixels * 4);
        depth.resize(with_depth ? pixels : 0);
        undefined.resize(with_undefined ? pixels : 0);
    }

    // Index of image pixel (x, row), which must lie in the rows held.
    std::size_t index(int x, int row) const {
        return std::size_t(row - first_row) * std::size_t(width) + std::size_t(x);
    }
    float* pixel(int x, int row) { return &rgba[index(x, row) * 4]; }
    const float* pixel(int x, int row) const { return &rgba[index(x, row) * 4]; }
};

// GL's conversion to an 8-bit unorm target: clamp to [0, 1] (NaN to 0), scale by 255, round to
// nearest.
std::uint8_t unorm8(float v);

}  // namespace qs
