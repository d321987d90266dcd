#pragma once
// Whole cache lines: memory aligned to them, and streaming stores that write a line without
// reading it first. A plain store to a line the cache does not hold reads the line from memory
// before it changes it; a frame's colour (16 bytes a pixel, 16 MB at 1024x1024) is far larger
// than the caches, so every line of it would be read and written each frame, and the stores queue
// behind those reads until the store buffer is full. The backends write the lines that nothing
// writes again in a frame with streaming stores instead (core/block_rows.h; docs/design.md, The
// renderer core).

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <new>

#include "shading/number/simd/simd.h"

namespace qs {

inline constexpr std::size_t kCacheLine = 64;

// A std::allocator that aligns to a cache line: a 64-byte row of a frame then fills a line.
template <class T>
struct CacheLineAllocator {
    using value_type = T;
    CacheLineAllocator() = default;
    template <class U>
    constexpr CacheLineAllocator(const CacheLineAllocator<U>&) noexcept {}
    T* allocate(std::size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), std::align_val_t(kCacheLine))); }
    void deallocate(T* p, std::size_t) noexcept { ::operator delete(p, std::align_val_t(kCacheLine)); }
    friend bool operator==(const CacheLineAllocator&, const CacheLineAllocator&) { return true; }
};

inline bool starts_cache_line(const void* p) { return reinterpret_cast<std::uintptr_t>(p) % kCacheLine == 0; }

// Sixteen floats, a generic vector (lanes16::Floats), into the cache line at `line`
// (starts_cache_line), past the caches. Only the thread that stored them is sure to see them
// until streaming_stores_done().
template <class Floats>
inline void stream_line(float* line, const Floats& v) {
    static_assert(sizeof v == kCacheLine);
    simd::stream(line, v);
}

// Orders this thread's streaming stores before its later stores. Streaming stores are weakly
// ordered: a thread that hands its work on with a plain (release) store, as a task's completion
// does, must fence them first or the next reader may see lines still in flight.
inline void streaming_stores_done() { simd::streaming_stores_done(); }

}  // namespace qs
