#pragma once
// A quantity linear in framebuffer coordinates, a(x, y) = a0 + dadx x + dady y, with (x, y) the
// integer pixel index (pixel centres), set up and evaluated in float as llvmpipe does:
//   dadx = (a0 - a1) dy20/A - (a2 - a0) dy01/A,  dady = (a2 - a0) dx01/A - (a0 - a1) dx20/A,
//   a0'  = a0 - (dadx x0c + dady y0c)            with (x0c, y0c) vertex 0 minus the pixel centre,
//   a(x, y) = (a0' + dadx x) + dady y            or, fused, fma(dady, y, fma(dadx, x, a0')).
// llvmpipe evaluates with llvm.fmuladd, which LLVM fuses on hosts with FMA: measured, the fused
// form gives llvmpipe's interpolated values bit for bit (the separate one differs by an ulp on a
// quarter of the pixels), while softpipe, C code built for baseline x86-64, rounds separately.

#include <cmath>

#include "shading/number/sin_cos.h"

namespace qs {

// Whether interpolation should fuse its multiply-adds to match llvmpipe on this machine: LLVM
// fuses llvm.fmuladd when the CPU has FMA, whatever quadshade itself was compiled for (std::fma is
// exact either way; without -mfma it is a library call, slower but the same numbers).
inline bool fused_interpolation_default() { return llvmpipe_math::host_fuses(); }

// The triangle-wide factors every plane of one triangle shares.
struct PlaneSetup {
    float dx01_ooa, dy01_ooa, dx20_ooa, dy20_ooa;  // edge deltas over the doubled area
    float x0_center, y0_center;                    // vertex 0 relative to pixel (0, 0)'s centre
    bool valid = false;                            // false for zero (float) area

    PlaneSetup() = default;
    PlaneSetup(const float x[3], const float y[3]) {
        const float dx01 = x[0] - x[1], dy01 = y[0] - y[1];
        const float dx20 = x[2] - x[0], dy20 = y[2] - y[0];
        const float e = dx01 * dy20, f = dy01 * dx20;
        const float ooa = 1.0f / (e - f);
        valid = std::isfinite(ooa);
        dx01_ooa = dx01 * ooa, dy01_ooa = dy01 * ooa, dx20_ooa = dx20 * ooa, dy20_ooa = dy20 * ooa;
        x0_center = x[0] - 0.5f, y0_center = y[0] - 0.5f;
    }
};

struct PlaneEquation {
    float a0 = 0.0f, dadx = 0.0f, dady = 0.0f;

    PlaneEquation() = default;
    PlaneEquation(const PlaneSetup& s, float v0, float v1, float v2) {
        const float da01 = v0 - v1, da20 = v2 - v0;
        dadx = da01 * s.dy20_ooa - da20 * s.dy01_ooa;
        dady = da20 * s.dx01_ooa - da01 * s.dx20_ooa;
        a0 = v0 - (dadx * s.x0_center + dady * s.y0_center);
    }

    float at(float x, float y) const { return (a0 + dadx * x) + dady * y; }
    float at_fused(float x, float y) const { return std::fma(dady, y, std::fma(dadx, x, a0)); }
    float at(float x, float y, bool fused) const { return fused ? at_fused(x, y) : at(x, y); }
};

}  // namespace qs
