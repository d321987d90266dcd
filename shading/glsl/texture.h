#pragma once
// sampler2D and texture2D for the chapter's Table 1.1 shaders: bilinear filtering, clamp to
// edge, no mipmaps (what the benchmark sets up). Texels are RGBA float; loading them from an
// image file is the scenes/ layer's job.
//
// The filter is written over the number type like any shader code: the texel indices come from
// floor() (no derivatives) and the blend weights from fract() of the texel coordinate, so a
// Dual2 lookup carries the exact derivative of the bilinear interpolant.

#include <algorithm>
#include <cstdint>
#include <vector>

#include "glsl/builtins.h"

namespace qs::glsl {

struct sampler2D {
    int width = 0, height = 0;
    std::vector<float> rgba;  // row 0 is t = 0 (GL's first row), 4 floats per texel

    const float* texel(int x, int y) const {
        x = std::clamp(x, 0, width - 1);
        y = std::clamp(y, 0, height - 1);
        return &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4];
    }
};

namespace texture_detail {
// A number whose lane i is texel channel c at the integer coordinates held by (ix, iy).
template <Number F, class I>
F gather(const sampler2D& tex, const I& ix, const I& iy, int dx, int dy, int c) {
    if constexpr (std::is_floating_point_v<F>) {
        return F(tex.texel(int(ix) + dx, int(iy) + dy)[c]);
    } else if constexpr (is_dual2<F>::value) {
        return F(gather<typename F::value_type>(tex, ix.val, iy.val, dx, dy, c));
    } else {
        typename F::value_type vals[F::size];
        for (int i = 0; i < F::size; ++i) vals[i] = tex.texel(int(ix[i]) + dx, int(iy[i]) + dy)[c];
        return F::load(vals);
    }
}
}  // namespace texture_detail

template <Number F>
vec4<F> texture2D(const sampler2D& tex, const vec2<F>& st) {
    // Texel centres sit at (i + 0.5) / size.
    F u = st.x * F(float(tex.width)) - F(0.5f);
    F v = st.y * F(float(tex.height)) - F(0.5f);
    F iu = floor(u), iv = floor(v);
    F fu = u - iu, fv = v - iv;
    vec4<F> out;
    for (int c = 0; c < 4; ++c) {
        using texture_detail::gather;
        F t00 = gather<F>(tex, iu, iv, 0, 0, c), t10 = gather<F>(tex, iu, iv, 1, 0, c);
        F t01 = gather<F>(tex, iu, iv, 0, 1, c), t11 = gather<F>(tex, iu, iv, 1, 1, c);
        out[c] = mix(mix(t00, t10, fu), mix(t01, t11, fu), fv);
    }
    return out;
}

}  // namespace qs::glsl
