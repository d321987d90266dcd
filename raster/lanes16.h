#pragma once
// The rasterizer's per-lane arithmetic on one batch: sixteen floats as a GCC/Clang generic
// vector. One register on AVX-512, several on narrower ISAs; plain IEEE operations lane by lane
// (the build does not contract a * b + c). Written with these instead of loops over arrays, the
// compiler needs no run-time checks that the arrays overlap, and nothing falls back to scalar
// code, whose stores a vector load cannot take straight from the store buffer.

#include <cmath>
#include <cstdint>
#include <cstring>

#if defined(__AVX512F__)
#include <immintrin.h>
#endif

#include "shading/program.h"

namespace qs::lanes16 {

typedef float Floats __attribute__((vector_size(kBatchLanes * sizeof(float))));
typedef std::int32_t Ints __attribute__((vector_size(kBatchLanes * sizeof(std::int32_t))));

inline Floats broadcast(float v) { return Floats{} + v; }

inline Floats load(const float* p) {
    Floats v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
inline Ints load(const int* p) {
    Ints v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
inline void store(float* p, const Floats& v) { std::memcpy(p, &v, sizeof v); }

inline Floats to_float(const Ints& v) { return __builtin_convertvector(v, Floats); }

// a * b + c rounded once on every lane, as std::fma.
inline Floats fma(const Floats& a, const Floats& b, const Floats& c) {
#if defined(__AVX512F__)
    static_assert(sizeof(Floats) == sizeof(__m512));
    return Floats(_mm512_fmadd_ps(__m512(a), __m512(b), __m512(c)));
#else
    Floats r;
    for (int i = 0; i < kBatchLanes; ++i) r[i] = std::fma(a[i], b[i], c[i]);
    return r;
#endif
}

}  // namespace qs::lanes16
