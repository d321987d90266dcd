#pragma once
// One level's texels as both of llvmpipe's filtering paths read them: per axis, the two texels
// and the weight between them (texture_filter_8bit.h and texture_filter_float.h compute them,
// each by its own rules); the 2, 4 or 8 texels those name, gathered; and the derivative of the
// filter's interpolant across them, which Dual2 lookups carry.
//
// Private to the sampler's sources, as texture_lanes.h.

#include "shading/glsl/texture_lod.h"

#include <array>

namespace qs::glsl {

namespace {

// Two texels and a weight along one axis: (x0, x1, w) with w in 1/256 (8-bit path) or a float.
template <class F>
struct AxisLanes {
    IntsLike<F> i0, i1, w8;
    F w;
};
using Axis = AxisLanes<Floats>;

// The coordinates of a lookup's lanes, and the texture's sizes that are powers of two (llvmpipe
// decides that on the base level: a non-power-of-two base takes the npot code on every level).
template <int Dims>
struct Coords {
    Floats c[Dims];
    const Ints* offset[Dims] = {};  // texel offsets, or none
    const Ints* face = nullptr;     // a cube map's face per lane (its levels hold six faces each), or none
    const Floats* ref = nullptr;    // a shadow lookup's reference value per lane, or none
};
template <int Dims>
struct Axes {
    Axis a[Dims];
};

template <int Dims>
std::array<bool, 3> pot_sizes(const Texture& tex) {
    return {std::has_single_bit(unsigned(tex.width)), std::has_single_bit(unsigned(tex.height)),
            Dims == 3 && std::has_single_bit(unsigned(tex.depth))};
}
inline Wrap wrap_of(const SamplerState& st, int axis) { return axis == 0 ? st.wrap_s : axis == 1 ? st.wrap_t : st.wrap_r; }
inline const Ints& size_of(const LevelLanes& lv, int axis) { return axis == 0 ? lv.width : axis == 1 ? lv.height : lv.depth; }

// The 2^Dims texels of a lookup, k[z][y][x] (one slice in 2D).
template <int Dims>
struct Texels {
    Uints k[Dims == 3 ? 2 : 1][2][2];
};
template <int Dims>
Texels<Dims> fetch_texels(const Texture& tex, const LevelLanes& level, const Axes<Dims>& ax) {
    Texels<Dims> r;
    const std::uint32_t* t = tex.texels.data();
    for (int z = 0; z < (Dims == 3 ? 2 : 1); ++z) {
        Ints slice{};
        if constexpr (Dims == 3) slice = (z ? ax.a[2].i1 : ax.a[2].i0) * level.height;
        const Ints row0 = level.offset + (slice + ax.a[1].i0) * level.width;
        const Ints row1 = level.offset + (slice + ax.a[1].i1) * level.width;
        r.k[z][0][0] = gather(t, row0 + ax.a[0].i0), r.k[z][0][1] = gather(t, row0 + ax.a[0].i1);
        r.k[z][1][0] = gather(t, row1 + ax.a[0].i0), r.k[z][1][1] = gather(t, row1 + ax.a[0].i1);
    }
    return r;
}

// Channel c (0: red) of packed RGBA8 texels.
inline Ints channel(const Uints& texels, int c) { return Ints((texels >> (8 * c)) & 255u); }

// d(colour)/ds, /dt (and /dr) of the (bi/tri)linear interpolant (texels as floats), for Dual2:
// along each axis, the difference of the two texel planes, weighted by the other axes' weights,
// times the level's size; zero along an axis filtered nearest.
template <int Dims>
void interpolant_gradient(const Texels<Dims>& k, const Axes<Dims>& ax, const LevelLanes& level, int c, Floats (&d)[Dims]) {
    Floats v[2][2][2];
    for (int z = 0; z < (Dims == 3 ? 2 : 1); ++z) {
        for (int y = 0; y < 2; ++y) {
            for (int x = 0; x < 2; ++x) v[z][y][x] = unorm(channel(k.k[z][y][x], c));
        }
    }
    auto weight = [&](int axis, int side) { return side ? ax.a[axis].w : 1.0f - ax.a[axis].w; };
    for (int axis = 0; axis < Dims; ++axis) {
        Floats g{};
        for (int z = 0; z < (Dims == 3 ? 2 : 1); ++z) {
            for (int y = 0; y < 2; ++y) {
                for (int x = 0; x < 2; ++x) {
                    const int side = axis == 0 ? x : axis == 1 ? y : z;
                    if (side == 0) continue;  // each pair once: (side 1) - (side 0)
                    const Floats diff = v[z][y][x] - v[axis == 2 ? 0 : z][axis == 1 ? 0 : y][axis == 0 ? 0 : x];
                    Floats w = splat(1.0f);
                    if (axis != 0) w = w * weight(0, x);
                    if (axis != 1) w = w * weight(1, y);
                    if constexpr (Dims == 3) {
                        if (axis != 2) w = w * weight(2, z);
                    }
                    g = g + w * diff;
                }
            }
        }
        const Ints filtered = ax.a[axis].i0 != ax.a[axis].i1;
        d[axis] = from_bits(bits(g * to_float(size_of(level, axis))) & filtered);
    }
}

}  // namespace

}  // namespace qs::glsl
