// The ThreadSanitizer build's canary (ctest expects TSan's report): two chunks of parallel_chunks
// write the same variable without synchronisation. If TSan stopped seeing the renderers' threads
// (core/parallel.h), test_threads would pass without checking anything; this would then fail.
#include <tbb/global_control.h>

#include <atomic>
#include <cstdio>

#include "core/parallel.h"

int main() {
    const tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
    long shared = 0;
    // Each chunk waits for the other to start, so the two run on two threads at once. Then the
    // second writes only after the first has: TSan can miss two accesses made at the same
    // instant (each checks the other's record before either is stored; a .ci/run here saw it),
    // not two made in turn. The flags are relaxed, which orders nothing for TSan, as two tiles
    // of a frame are ordered by nothing.
    std::atomic<int> started{0};
    std::atomic<bool> first_wrote{false};
    qs::parallel_chunks<int>(0, 2, 1, [&](const auto& r) {
        started.fetch_add(1, std::memory_order_relaxed);
        while (started.load(std::memory_order_relaxed) < 2) {
        }
        if (r.begin() == 0) {
            shared += 1;  // the race
            first_wrote.store(true, std::memory_order_relaxed);
        } else {
            while (!first_wrote.load(std::memory_order_relaxed)) {
            }
            shared += 2;
        }
    });
    std::printf("canary: %ld\n", shared);
    return 0;
}
