#pragma once
// What a study measures on images: the box filter that turns a supersampled render into pixels,
// and the error of one image against another.

#include <span>

#include "images/image_io.h"

namespace qs::study {

// The mean of each k x k block of a width x height RGBA image (width and height multiples of k),
// summed in double.
Image box_filter(std::span<const float> rgba, int width, int height, int k);

struct Error {
    double rms = 0.0, max = 0.0;
};
// Over RGB, in [0, 1] units, each image clamped to [0, 1] as an 8-bit target clamps it (NaN as 0). Throws
// std::invalid_argument for images of different sizes.
Error error_of(const Image& a, const Image& b);

}  // namespace qs::study
