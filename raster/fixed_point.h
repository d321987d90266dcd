#pragma once
// Sub-pixel fixed point, as llvmpipe: 8 fractional bits, vertices snapped to the nearest 1/256
// after moving pixel centres onto integers (x - 0.5), so a pixel centre is (i << 8, j << 8).

#include <cmath>
#include <cstdint>

namespace qs::fixed {

inline constexpr int kSubpixelBits = 8;
inline constexpr std::int64_t kOne = std::int64_t(1) << kSubpixelBits;

inline std::int64_t snap(float window_coord) {
    return std::int64_t(std::lrint((window_coord - 0.5f) * float(kOne)));
}

}  // namespace qs::fixed
