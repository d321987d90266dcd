#include "study/image_error.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace qs::study {

Image box_filter(std::span<const float> rgba, int width, int height, int k) {
    Image out{width / k, height / k, std::vector<float>(std::size_t(width / k) * std::size_t(height / k) * 4, 0.0f)};
    for (int y = 0; y < out.height; ++y) {
        for (int x = 0; x < out.width; ++x) {
            double sum[4] = {0, 0, 0, 0};
            for (int j = 0; j < k; ++j) {
                const float* row = &rgba[((std::size_t(y) * k + j) * std::size_t(width) + std::size_t(x) * k) * 4];
                for (int i = 0; i < k * 4; ++i) sum[i % 4] += row[i];
            }
            for (int c = 0; c < 4; ++c) out.rgba[(std::size_t(y) * out.width + x) * 4 + c] = float(sum[c] / (k * k));
        }
    }
    return out;
}

Error error_of(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height) {
        throw std::invalid_argument("images of different sizes: " + std::to_string(a.width) + "x" +
                                    std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                                    std::to_string(b.height));
    }
    // NaN as 0, as unorm8 (core/framebuffer.h) stores it.
    auto stored = [](float v) { return std::isnan(v) ? 0.0 : std::clamp(double(v), 0.0, 1.0); };
    double sum = 0.0, worst = 0.0;
    const std::size_t n = std::size_t(a.width) * std::size_t(a.height);
    for (std::size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) {
            const double d = stored(a.rgba[i * 4 + c]) - stored(b.rgba[i * 4 + c]);
            sum += d * d, worst = std::max(worst, std::abs(d));
        }
    }
    return {n ? std::sqrt(sum / double(n * 3)) : 0.0, worst};
}

}  // namespace qs::study
