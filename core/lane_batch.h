#pragma once
// Fragments gathered for one shader call: the positions of up to kBatchLanes lanes and which of
// them write. Partial 4x4 blocks are gathered into batches (covered pixels, or whole running
// quads appended four lanes at a time, so quads stay aligned in the batch) rather than shaded
// with mostly idle lanes.

#include <cstdint>

#include "shading/batches.h"

namespace qs {

struct LaneBatch {
    alignas(64) int x[kBatchLanes] = {};  // framebuffer coordinates
    alignas(64) int y[kBatchLanes] = {};
    std::uint32_t write = 0;  // bit i: lane i writes (a helper lane does not)
    int count = 0;

    // Adds a lane; true when the batch is then full.
    bool add(int px, int py, bool writes) {
        x[count] = px, y[count] = py;
        write |= std::uint32_t(writes) << count;
        return ++count == kBatchLanes;
    }
    void clear() { count = 0, write = 0; }
    // Fills the unused lanes with lane 0's position (a valid one); they write nothing.
    void pad() {
        for (int i = count; i < kBatchLanes; ++i) x[i] = x[0], y[i] = y[0];
    }
};

}  // namespace qs
