#include "render/undefined_mask.h"

#include <stdexcept>

namespace qs {

namespace {
void require_mask(const Framebuffer& fb) {
    if (fb.undefined.size() != std::size_t(fb.width) * std::size_t(fb.rows)) {
        throw std::logic_error("the framebuffer has no undefined-case mask: render with check_undefined");
    }
}
}  // namespace

Image undefined_mask_image(const Framebuffer& fb) {
    require_mask(fb);
    Image image{fb.width, fb.rows, std::vector<float>(fb.undefined.size() * 4)};
    for (std::size_t i = 0; i < fb.undefined.size(); ++i) {
        const std::uint8_t u = fb.undefined[i];
        float* p = &image.rgba[4 * i];
        const float under = (u & std::uint8_t(Undefined::Overflow)) ? 0.5f : 0.0f;
        p[0] = (u & std::uint8_t(Undefined::NaN)) ? 1.0f : under;
        p[1] = (u & std::uint8_t(Undefined::DivisionByZero)) ? 1.0f : under;
        p[2] = (u & std::uint8_t(Undefined::Argument)) ? 1.0f : under;
        p[3] = 1.0f;
    }
    return image;
}

UndefinedCounts count_undefined(const Framebuffer& fb) {
    require_mask(fb);
    UndefinedCounts counts;
    for (const std::uint8_t u : fb.undefined) {
        counts.pixels += u != 0;
        for (int k = 0; k < kUndefinedCases; ++k) counts.per_case[std::size_t(k)] += (u >> k) & 1u;
    }
    return counts;
}

}  // namespace qs
