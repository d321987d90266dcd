#pragma once
// Colour (RGBA float) and optional depth, stored top-down: row 0 is the top of the image, the
// order of OSMesa's buffer and of image files. GL window coordinates have y up: the pixel at
// window (x, y) is row height-1-y.

#include <cstdint>
#include <vector>

namespace qs {

struct Framebuffer {
    int width = 0, height = 0;
    std::vector<float> rgba;   // 4 per pixel, top-down
    // Empty when the frame needed no depth buffer; else 1 per pixel, cleared to 1: window depth
    // as a 24-bit depth buffer holds it (depth_buffer.h).
    std::vector<float> depth;
    // Empty unless the render checked for undefined GLSL cases; else 1 per pixel, top-down: the
    // Undefined bits (number/checked.h) of the fragment that wrote the pixel, 0 where cleared.
    std::vector<std::uint8_t> undefined;

    float* pixel(int x, int row) { return &rgba[(std::size_t(row) * std::size_t(width) + std::size_t(x)) * 4]; }
    const float* pixel(int x, int row) const {
        return &rgba[(std::size_t(row) * std::size_t(width) + std::size_t(x)) * 4];
    }
};

// GL's conversion to an 8-bit unorm target: clamp to [0, 1] (NaN to 0), scale by 255, round to
// nearest.
std::uint8_t unorm8(float v);

}  // namespace qs
