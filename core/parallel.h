#pragma once
// The one place the renderers hand work to threads (their tile loop is core/tile_loop.h): parallel_chunks(begin, end, grain, body) runs
// body(tbb::blocked_range<Index>) over [begin, end) in pieces of at most `grain`, concurrently, as
// tbb::parallel_for does, on as many threads as tbb::global_control allows.
//
// In a ThreadSanitizer build (tools/ci-sanitizers) the pieces run on std::threads instead of
// TBB's: Debian's libtbb is not built with TSan, so TSan cannot see its hand-over of a task to a
// worker and back, and reports TBB's own task objects and every read of data the caller wrote
// before the loop as races. Threads it starts and joins itself it understands, so what it checks
// is quadshade's code: the chunk bodies, run concurrently, sharing what they share under TBB.
// tests/sanitize/tsan_canary.cpp checks that a race between two chunks is reported.

#include <cstddef>
#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#if defined(__SANITIZE_THREAD__)  // GCC
#define QUADSHADE_TSAN_THREADS 1
#elif defined(__has_feature)  // clang
#if __has_feature(thread_sanitizer)
#define QUADSHADE_TSAN_THREADS 1
#endif
#endif

#if defined(QUADSHADE_TSAN_THREADS)
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>
#endif

namespace qs {

// parallel_chunks runs on at most `threads` threads (0: as many as there are cores) while this lives.
class ThreadLimit {
public:
    explicit ThreadLimit(int threads) {
        if (threads > 0) limit_.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    }

private:
    std::optional<tbb::global_control> limit_;
};

template <class Index, class Body>
void parallel_chunks(Index begin, Index end, Index grain, const Body& body) {
#if defined(QUADSHADE_TSAN_THREADS)
    if (end <= begin) return;
    const Index chunks = (end - begin + grain - 1) / grain;
    // Relaxed: the counter only deals out chunks. Were it ordered, TSan would see every chunk as
    // following the one dealt before it and miss races between them.
    std::atomic<Index> next{0};
    std::exception_ptr failure;
    std::mutex failure_lock;
    auto work = [&] {
        try {
            for (Index c; (c = next.fetch_add(1, std::memory_order_relaxed)) < chunks;) {
                const Index first = begin + c * grain;
                body(tbb::blocked_range<Index>(first, std::min(end, Index(first + grain)), grain));
            }
        } catch (...) {
            const std::lock_guard<std::mutex> hold(failure_lock);
            if (!failure) failure = std::current_exception();
        }
    };
    const std::size_t threads = std::min<std::size_t>(
        tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism), std::size_t(chunks));
    {
        std::vector<std::jthread> helpers;
        for (std::size_t t = 1; t < threads; ++t) helpers.emplace_back(work);
        work();
    }  // joined
    if (failure) std::rethrow_exception(failure);
#else
    tbb::parallel_for(tbb::blocked_range<Index>(begin, end, grain), body);
#endif
}

}  // namespace qs
