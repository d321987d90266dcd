#pragma once
// What a backend did to render a frame, for summaries and tests.

#include <cstdint>

namespace qs {

struct RenderStats {
    std::uint64_t triangles_in = 0, triangles_setup = 0;  // set up: rasterized, or in the ray caster's BVH
    std::uint64_t quads = 0;          // quads shaded (quad path)
    std::uint64_t lanes_shaded = 0;   // lanes run through a shader, helpers included
    std::uint64_t pixels_written = 0;
    bool depth_buffer = false;        // the frame was depth tested (raster/depth_buffer.h)

    // Adds a thread's counts.
    void add_work(std::uint64_t q, std::uint64_t lanes, std::uint64_t written) {
        quads += q, lanes_shaded += lanes, pixels_written += written;
    }
};

}  // namespace qs
