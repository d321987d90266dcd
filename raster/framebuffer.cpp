#include "framebuffer.h"

#include <cmath>

namespace qs {

Framebuffer::Framebuffer(int w, int h, glm::vec4 clear, bool with_depth) : width(w), height(h) {
    rgba.resize(std::size_t(w) * std::size_t(h) * 4);
    for (std::size_t i = 0; i < rgba.size(); i += 4) {
        rgba[i] = clear.r, rgba[i + 1] = clear.g, rgba[i + 2] = clear.b, rgba[i + 3] = clear.a;
    }
    if (with_depth) depth.assign(std::size_t(w) * std::size_t(h), 1.0f);
}

std::uint8_t unorm8(float v) {
    // NaN clamps to 0, as min/max with a NaN operand return the other one.
    float c = std::isnan(v) ? 0.0f : std::fmin(std::fmax(v, 0.0f), 1.0f);
    return std::uint8_t(std::lrint(c * 255.0f));
}

std::vector<std::uint8_t> Framebuffer::to_rgba8() const {
    std::vector<std::uint8_t> out(rgba.size());
    for (std::size_t i = 0; i < rgba.size(); ++i) out[i] = unorm8(rgba[i]);
    return out;
}

}  // namespace qs
