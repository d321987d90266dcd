#pragma once
// The float environment fragments are shaded in: denormals flushed to zero (FTZ) and read as
// zero (DAZ), as GPUs and Mesa llvmpipe do (measured: llvmpipe turns 1e-41 * 1e30 into 0; the
// float_env_probe test pins it). A scoped setting of the calling thread, set by whoever runs
// shading on a thread (the rasterizer's and the ray caster's tile tasks); restored on exit.

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

namespace qs {

class FlushDenormals {
public:
#if defined(__SSE__) || defined(__x86_64__)
    FlushDenormals() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | kFlushToZero | kDenormalsAreZero); }
    ~FlushDenormals() { _mm_setcsr(saved_); }

private:
    static constexpr unsigned kFlushToZero = 1u << 15, kDenormalsAreZero = 1u << 6;
    unsigned saved_;
#else
    FlushDenormals() = default;  // elsewhere: the platform's default, documented as such
#endif
public:
    FlushDenormals(const FlushDenormals&) = delete;
    FlushDenormals& operator=(const FlushDenormals&) = delete;
};

}  // namespace qs
