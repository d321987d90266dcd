#pragma once
// The one tile loop of both backends, as pbrt-v4 has one loop over image tiles for every
// integrator: the tiles of a TileGrid in parallel (parallel.h), each rendered whole by one
// thread, with denormals flushed as the GPU's and llvmpipe's shading has them
// (float_environment.h). Each thread renders its tiles with a worker of its own, made on its
// first tile rather than per tile (a worker holds a tile's buffers), so a tile's pixels depend
// on nothing another thread does: the output is the same for any thread count. Workers may
// write the frame with streaming stores (cache_lines.h); each chunk of tiles fences them.

#include <memory>
#include <utility>
#include <vector>

#include <tbb/enumerable_thread_specific.h>

#include "core/cache_lines.h"
#include "core/float_environment.h"
#include "core/parallel.h"
#include "core/tile_grid.h"

namespace qs {

// Runs work(worker, i) for every tile i of `grid`; `make()` returns a std::unique_ptr<Worker>
// for a thread. Returns the workers once every tile is done (to collect their counts).
template <class Worker, class Make, class Work>
std::vector<std::unique_ptr<Worker>> for_each_tile(const TileGrid& grid, const Make& make, const Work& work) {
    tbb::enumerable_thread_specific<std::unique_ptr<Worker>> workers;
    parallel_chunks<int>(0, grid.count(), 1, [&](const tbb::blocked_range<int>& tiles) {
        const FlushDenormals ftz;
        std::unique_ptr<Worker>& worker = workers.local();
        if (!worker) worker = make();
        for (int i = tiles.begin(); i != tiles.end(); ++i) work(*worker, i);
        streaming_stores_done();  // the tiles' frame lines, before the chunk is reported done
    });
    std::vector<std::unique_ptr<Worker>> done;
    for (std::unique_ptr<Worker>& worker : workers) {
        if (worker) done.push_back(std::move(worker));
    }
    return done;
}

}  // namespace qs
