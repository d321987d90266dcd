#pragma once
// Comparing quadshade with an OSMesa reference image: quadshade set up as the driver, pixels
// counted by their largest 8-bit channel difference, and a side-by-side image for a person.

#include <cstddef>
#include <filesystem>

#include "core/framebuffer.h"
#include "images/image_io.h"
#include "raster/driver_settings.h"
#include "reference/gl_context.h"

namespace qs::test {

// quadshade's rasterizer set up as the reference's driver renders (raster/driver_settings.h).
RasterOptions raster_options_as(GlDriver driver);

struct Counts {
    std::size_t pixels = 0, covered = 0;  // covered: in the reference (alpha > 1/2)
    std::size_t coverage_mismatch = 0, over_1 = 0, over_2 = 0;
    int max_steps = 0;
};

// Differences in 8-bit steps after GL's unorm conversion of both; alpha marks coverage.
Counts count(const Framebuffer& ours, const Image& reference);

// quadshade | reference | |difference| (full scale 8/255), side by side.
void write_comparison(const Framebuffer& ours, const Image& reference, const std::filesystem::path& file);

}  // namespace qs::test
