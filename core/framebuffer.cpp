#include "core/framebuffer.h"

#include <cmath>

namespace qs {

std::uint8_t unorm8(float v) {
    // NaN clamps to 0, as min/max with a NaN operand return the other one.
    float c = std::isnan(v) ? 0.0f : std::fmin(std::fmax(v, 0.0f), 1.0f);
    return std::uint8_t(std::lrint(c * 255.0f));
}

}  // namespace qs
