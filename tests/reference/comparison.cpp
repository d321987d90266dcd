#include "tests/reference/comparison.h"
#include "render/frame_image.h"

#include <algorithm>
#include <cstdlib>

namespace qs::test {

RasterOptions raster_options_as(GlDriver driver) {
    return qs::raster_options_as(driver == GlDriver::Softpipe ? MesaDriver::Softpipe : MesaDriver::Llvmpipe);
}

Counts count(const Framebuffer& a, const Image& b) {
    Counts c;
    c.pixels = std::size_t(a.width) * std::size_t(a.height);
    for (std::size_t p = 0; p < c.pixels; ++p) {
        c.covered += b.rgba[p * 4 + 3] > 0.5f;
        if ((a.rgba[p * 4 + 3] > 0.5f) != (b.rgba[p * 4 + 3] > 0.5f)) ++c.coverage_mismatch;
        int worst = 0;
        for (std::size_t ch = 0; ch < 3; ++ch) {
            worst = std::max(worst, std::abs(int(unorm8(a.rgba[p * 4 + ch])) - int(unorm8(b.rgba[p * 4 + ch]))));
        }
        c.over_1 += worst > 1;
        c.over_2 += worst > 2;
        c.max_steps = std::max(c.max_steps, worst);
    }
    return c;
}

void write_comparison(const Framebuffer& ours, const Image& reference, const std::filesystem::path& file) {
    const Image mine = colour_image(ours);
    const Image heat = difference_heat_map(mine, reference, 8.0f / 255.0f);
    std::filesystem::create_directories(file.parent_path());
    write_image(file, side_by_side({&mine, &reference, &heat}));
}

}  // namespace qs::test
