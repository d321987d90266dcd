// Texture storage: a texture's levels, laid out one after another in one array of RGBA8 texels,
// and the levels below the base made as glGenerateMipmap makes them on llvmpipe (Mesa's
// util_gen_mipmap and u_blitter.c), for 2D, 3D and cube map textures; and the level sizes
// textureSize reports.

#include "shading/glsl/texture.h"
#include "shading/glsl/texture_cube.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace qs::glsl {

namespace {

// ---- glGenerateMipmap ----------------------------------------------------------------------
// llvmpipe has no mipmap generator of its own: Mesa's state tracker blits each level from the
// one above (util_gen_mipmap) through a quad that samples it with LINEAR, CLAMP_TO_EDGE at the
// destination texel's centre, on the 8-bit path (texture_filter_8bit.h). For even sizes that is
// avg(avg(a, b), avg(c, d)) rounded half up, not a box filter; for odd sizes the weights are
// not one half (37 -> 18 samples at 37 (x + 0.5) / 18). A 3D level is drawn slice by slice, each
// sampling the level above trilinearly at r = (z Ds/Dd + 0.5 Ds/Dd) / Ds (u_blitter.c's
// src_z_step and depth_center_offset, the latter computed in double), then along r as the 8-bit
// path's lerp_3d.
struct Tap {
    int i0, i1, w;
};
// The 8-bit path's linear taps, CLAMP_TO_EDGE, of a source axis of `size` at coordinate s.
Tap clamp_tap(float s, int size) {
    const int u = int(std::nearbyint(s * float(size << 8))) - 128;  // rounds to even, as cvtps2dq
    const int i0 = u >> 8;
    const int l0 = std::clamp(i0, 0, size - 1);
    return {l0, (i0 >= 0 && i0 < size - 1) ? l0 + 1 : l0, u & 255};
}
std::vector<Tap> taps(int src_size, int dst_size) {
    std::vector<Tap> r{std::size_t(dst_size)};
    for (int x = 0; x < dst_size; ++x) r[std::size_t(x)] = clamp_tap((float(x) + 0.5f) / float(dst_size), src_size);
    return r;
}
std::vector<Tap> depth_taps(int src_size, int dst_size) {
    std::vector<Tap> r{std::size_t(dst_size)};
    const float step = float(src_size) / float(dst_size);
    const float center = float(0.5 / dst_size * src_size);
    for (int z = 0; z < dst_size; ++z) {
        const float layer = float(z) * step + center;
        r[std::size_t(z)] = clamp_tap(layer / float(src_size), src_size);
    }
    return r;
}

void next_level(const std::uint32_t* src, const Texture::Level& s, std::uint32_t* dst, const Texture::Level& d, int dims) {
    const std::vector<Tap> xs = taps(s.width, d.width), ys = taps(s.height, d.height);
    const std::vector<Tap> zs = dims == 3 ? depth_taps(s.depth, d.depth) : std::vector<Tap>{Tap{0, 0, 0}};
    auto lerp = [](int w, int a, int b) { return a + ((w * (b - a) + 128) >> 8); };
    auto at = [&](int x, int y, int z) {
        return src[(std::size_t(z) * std::size_t(s.height) + std::size_t(y)) * std::size_t(s.width) + std::size_t(x)];
    };
    std::size_t out_index = 0;
    for (const Tap& tz : zs) {
        for (const Tap& ty : ys) {
            for (const Tap& tx : xs) {
                std::uint32_t out = 0;
                for (int c = 0; c < 4; ++c) {
                    const auto ch = [c](std::uint32_t k) { return int((k >> (8 * c)) & 255u); };
                    auto slice = [&](int z) {
                        const int r0 = lerp(tx.w, ch(at(tx.i0, ty.i0, z)), ch(at(tx.i1, ty.i0, z)));
                        const int r1 = lerp(tx.w, ch(at(tx.i0, ty.i1, z)), ch(at(tx.i1, ty.i1, z)));
                        return lerp(ty.w, r0, r1);
                    };
                    const int v = dims == 3 ? lerp(tz.w, slice(tz.i0), slice(tz.i1)) : slice(0);
                    out |= std::uint32_t(v) << (8 * c);
                }
                dst[out_index++] = out;
            }
        }
    }
}

}  // namespace

Texture::Texture(int n, int w, int h, int d, const std::uint8_t* rgba, SamplerState s)
    : dims(n), width(w), height(h), depth(d), sampler(s) {
    const int max_size = n == 3 ? 2048 : (1 << 15);
    if (w < 1 || h < 1 || d < 1 || w > max_size || h > max_size || d > max_size || (n == 2 && d != 1)) {
        throw std::invalid_argument("texture size " + std::to_string(w) + "x" + std::to_string(h) +
                                    (n == 3 ? "x" + std::to_string(d) : std::string()) + " is outside 1.." +
                                    std::to_string(max_size));
    }
    std::int64_t total = 0;
    for (int lw = w, lh = h, ld = d;; lw = std::max(1, lw / 2), lh = std::max(1, lh / 2), ld = std::max(1, ld / 2)) {
        levels.push_back({lw, lh, ld, std::int32_t(total)});
        total += std::int64_t(lw) * lh * ld;
        if (sampler.mip == MipFilter::None || (lw == 1 && lh == 1 && ld == 1)) break;
    }
    // Texel indices are int32 lanes.
    if (total > std::int64_t(1) << 30) {
        throw std::invalid_argument("texture of " + std::to_string(total) + " texels with its mipmaps: more than 2^30");
    }
    // A single level makes a mipmap filter a plain one (llvmpipe: level_zero_only).
    if (levels.size() == 1) sampler.mip = MipFilter::None;
    texels.resize(std::size_t(total));
    for (std::size_t i = 0; i < std::size_t(w) * std::size_t(h) * std::size_t(d); ++i) {
        texels[i] = std::uint32_t(rgba[4 * i]) | std::uint32_t(rgba[4 * i + 1]) << 8 |
                    std::uint32_t(rgba[4 * i + 2]) << 16 | std::uint32_t(rgba[4 * i + 3]) << 24;
    }
    for (std::size_t l = 1; l < levels.size(); ++l) {
        const Level& a = levels[l - 1];
        const Level& b = levels[l];
        next_level(&texels[std::size_t(a.offset)], a, &texels[std::size_t(b.offset)], b, dims);
    }
}

samplerCube::samplerCube(int size, const std::array<const std::uint8_t*, 6>& faces, SamplerState s) {
    dims = kCubeDims;
    width = height = size;
    // llvmpipe clamps a cube map's faces to their edges whatever the sampler's wraps
    // (lp_build_sample_soa_code's derived sampler state); without seamless filtering (GL's
    // default) a lookup never leaves its face.
    s.wrap_s = s.wrap_t = s.wrap_r = Wrap::ClampToEdge;
    sampler = s;
    if (size < 1 || size > 16384) {
        throw std::invalid_argument("cube map face size " + std::to_string(size) + " is outside 1..16384");
    }
    std::int64_t total = 0;
    for (int l = size;; l = std::max(1, l / 2)) {
        levels.push_back({l, l, 1, std::int32_t(total)});
        total += std::int64_t(6) * l * l;
        if (sampler.mip == MipFilter::None || l == 1) break;
    }
    if (total > std::int64_t(1) << 30) {
        throw std::invalid_argument("cube map of " + std::to_string(total) + " texels with its mipmaps: more than 2^30");
    }
    if (levels.size() == 1) sampler.mip = MipFilter::None;
    texels.resize(std::size_t(total));
    const std::size_t face_texels = std::size_t(size) * std::size_t(size);
    for (std::size_t f = 0; f < 6; ++f) {
        const std::uint8_t* rgba = faces[f];
        for (std::size_t i = 0; i < face_texels; ++i) {
            texels[f * face_texels + i] = std::uint32_t(rgba[4 * i]) | std::uint32_t(rgba[4 * i + 1]) << 8 |
                                          std::uint32_t(rgba[4 * i + 2]) << 16 | std::uint32_t(rgba[4 * i + 3]) << 24;
        }
    }
    // Each face's levels as a 2D texture's (Mesa's mipmap blit draws the faces one by one).
    for (std::size_t l = 1; l < levels.size(); ++l) {
        const Level& a = levels[l - 1];
        const Level& b = levels[l];
        for (std::size_t f = 0; f < 6; ++f) {
            next_level(&texels[std::size_t(a.offset) + f * std::size_t(a.width * a.height)], a,
                       &texels[std::size_t(b.offset) + f * std::size_t(b.width * b.height)], b, 2);
        }
    }
}

std::array<int, 3> Texture::size(int lod) const {
    // lp_build_size_query with is_sviewinfo (NIR's txs): a level outside the texture's gives 0.
    if (lod < 0 || lod >= int(levels.size())) return {0, 0, 0};
    return {std::max(width >> lod, 1), std::max(height >> lod, 1), dims == 3 ? std::max(depth >> lod, 1) : 0};
}

}  // namespace qs::glsl
