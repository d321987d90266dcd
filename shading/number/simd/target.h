#pragma once
// Which of the SIMD layer's targets this build compiles for: the widest one whose instructions
// the compiler may use (-march). The only place that reads the compiler's ISA macros; everything
// above the layer asks Target (and simd.h's register_bytes, register_floats) instead.
//
//   avx512.h   AVX-512 F, BW, DQ and VL    64-byte registers   the native build on Zen 4
//   avx2.h     AVX2, FMA and BMI2          32-byte registers   -march=znver3, haswell, ...
//   sse.h      x86-64 (SSE2, SSE4.1 used where present)  16 bytes  the portable x86-64 build
//   portable.h any other CPU               16 bytes, GCC's own vector lowering
//
// Each includes the one below it and overloads its operations for its own registers; a CPU with
// AVX but not AVX2 and FMA, or AVX-512 without BW, DQ and VL, builds for the target below.

#if defined(__AVX512F__) && defined(__AVX512BW__) && defined(__AVX512DQ__) && defined(__AVX512VL__) && \
    defined(__AVX2__) && defined(__FMA__) && defined(__BMI2__)
#include "shading/number/simd/avx512.h"
namespace qs::simd {
using Target = isa::Avx512;
}
#elif defined(__AVX2__) && defined(__FMA__) && defined(__BMI2__)
#include "shading/number/simd/avx2.h"
namespace qs::simd {
using Target = isa::Avx2;
}
#elif defined(__SSE2__) && (defined(__x86_64__) || defined(__i386__))
#include "shading/number/simd/sse.h"
namespace qs::simd {
using Target = isa::Sse;
}
#else
#include "shading/number/simd/portable.h"
namespace qs::simd {
using Target = isa::Portable;
}
#endif
