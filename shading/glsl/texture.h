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

#include "shading/glsl/builtins.h"

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
// The four texels around each lane's lower-left texel (iu, iv), clamped to the edge: t[dy][dx].
template <Number F>
void gather_2x2(const sampler2D& tex, const F& iu, const F& iv, vec4<F> (&t)[2][2]) {
    if constexpr (is_dual2<F>::value) {
        // Texel values are constants: their derivatives are zero (the weights carry them).
        using T = typename F::value_type;
        vec4<T> v[2][2];
        gather_2x2<T>(tex, iu.val, iv.val, v);
        for (int dy = 0; dy < 2; ++dy) {
            for (int dx = 0; dx < 2; ++dx) t[dy][dx] = vec4<F>(F(v[dy][dx].x), F(v[dy][dx].y), F(v[dy][dx].z), F(v[dy][dx].w));
        }
    } else if constexpr (std::is_floating_point_v<F>) {
        for (int dy = 0; dy < 2; ++dy) {
            for (int dx = 0; dx < 2; ++dx) {
                const float* p = tex.texel(int(iu) + dx, int(iv) + dy);
                t[dy][dx] = vec4<F>(F(p[0]), F(p[1]), F(p[2]), F(p[3]));
            }
        }
    } else {
        using T = typename F::value_type;
        alignas(64) T lanes[2][2][4][F::size];
        for (int i = 0; i < F::size; ++i) {
            const int x = int(iu[i]), y = int(iv[i]);
            for (int dy = 0; dy < 2; ++dy) {
                for (int dx = 0; dx < 2; ++dx) {
                    const float* p = tex.texel(x + dx, y + dy);
                    for (int c = 0; c < 4; ++c) lanes[dy][dx][c][i] = T(p[c]);
                }
            }
        }
        for (int dy = 0; dy < 2; ++dy) {
            for (int dx = 0; dx < 2; ++dx) {
                t[dy][dx] = vec4<F>(F::load(lanes[dy][dx][0]), F::load(lanes[dy][dx][1]), F::load(lanes[dy][dx][2]),
                                    F::load(lanes[dy][dx][3]));
            }
        }
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
    vec4<F> t[2][2];
    texture_detail::gather_2x2(tex, iu, iv, t);
    return mix(mix(t[0][0], t[0][1], fu), mix(t[1][0], t[1][1], fu), fv);
}

}  // namespace qs::glsl
