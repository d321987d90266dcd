#pragma once
// The float environment fragments are shaded in: denormals flushed to zero (FTZ) and read as
// zero (DAZ), as GPUs and Mesa llvmpipe do (measured: llvmpipe turns 1e-41 * 1e30 into 0; the
// float_env_probe test pins it). A scoped setting of the calling thread, set by whoever runs
// shading on a thread (the rasterizer's and the ray caster's tile tasks); restored on exit.

#include "shading/number/simd/simd.h"

namespace qs {

// Where the target has no control of denormals (simd::kControlsDenormals), the platform's
// default, documented as such.
class FlushDenormals {
public:
    FlushDenormals() : saved_(simd::float_control()) { simd::set_float_control(simd::flush_denormals(saved_)); }
    ~FlushDenormals() { simd::set_float_control(saved_); }
    FlushDenormals(const FlushDenormals&) = delete;
    FlushDenormals& operator=(const FlushDenormals&) = delete;

private:
    unsigned saved_;
};

}  // namespace qs
