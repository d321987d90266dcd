// Texture storage: a texture's levels, laid out one after another in one array of texels (RGBA8,
// or a depth texture's floats), and the levels below the base made as glGenerateMipmap makes them
// on llvmpipe (Mesa's util_gen_mipmap and u_blitter.c), for 2D, 3D and cube map textures; and the
// level sizes textureSize reports.

#include "shading/glsl/texture.h"
#include "shading/glsl/texture_cube.h"
#include "shading/number/sin_cos.h"

#include <algorithm>
#include <bit>
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
    int i0, i1, w;  // w: the 8-bit path's weight
    float f = 0.0f;  // the float path's
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

// A depth texture's level (GL_DEPTH_COMPONENT32F) from the one above, as llvmpipe blits it: the
// float path's LINEAR, CLAMP_TO_EDGE lookup (soa_axis, lerp) at texture coordinates llvmpipe
// interpolates over the blit's rectangle. Its two triangles, (0, 0) (W, 0) (W, H) and (0, 0)
// (W, H) (0, H) with coordinates (0, 0) (1, 0) (1, 1) (0, 1), reach the setup second vertex first;
// each coordinate's plane equation is set up and evaluated in float as the rasterizer's
// (raster/plane_equation.h, the same arithmetic, which the renderer keeps apart from textures),
// fused where llvmpipe's JIT fuses; a pixel centre on the diagonal belongs to the first triangle.
// Where the 8-bit path's weights hide an ulp of the coordinates, a float depth does not: with
// the exact centres (x + 0.5) / W instead, 142 of 236 texels of a 37x21 texture's levels differ.
struct BlitPlane {
    float a0, dadx, dady;
    BlitPlane(const float (&x)[3], const float (&y)[3], const float (&a)[3]) {
        const float dx01 = x[0] - x[1], dy01 = y[0] - y[1], dx20 = x[2] - x[0], dy20 = y[2] - y[0];
        const float ooa = 1.0f / (dx01 * dy20 - dy01 * dx20);
        const float da01 = a[0] - a[1], da20 = a[2] - a[0];
        dadx = da01 * (dy20 * ooa) - da20 * (dy01 * ooa);
        dady = da20 * (dx01 * ooa) - da01 * (dx20 * ooa);
        a0 = a[0] - (dadx * (x[0] - 0.5f) + dady * (y[0] - 0.5f));
    }
    float at(int x, int y) const {
        if (llvmpipe_math::host_fuses()) return std::fma(dady, float(y), std::fma(dadx, float(x), a0));
        return (a0 + dadx * float(x)) + dady * float(y);
    }
};
// soa_axis's CLAMP_TO_EDGE, LINEAR taps of an axis of `size` at coordinate s.
Tap float_clamp_tap(float s, int size) {
    const float fsize = float(size);
    const float c = std::max((s * fsize < fsize ? s * fsize : fsize) - 0.5f, 0.0f);
    const float fl = std::floor(c);
    const int i = int(fl);
    return {i, std::min(i + 1, size - 1), 0, c - fl};
}
void next_depth_level(const std::uint32_t* src, const Texture::Level& s, std::uint32_t* dst, const Texture::Level& d) {
    const float w = float(d.width), h = float(d.height);
    const float x0[3] = {w, 0.0f, w}, y0[3] = {0.0f, 0.0f, h}, s0[3] = {1.0f, 0.0f, 1.0f}, t0[3] = {0.0f, 0.0f, 1.0f};
    const float x1[3] = {w, 0.0f, 0.0f}, y1[3] = {h, 0.0f, h}, s1[3] = {1.0f, 0.0f, 0.0f}, t1[3] = {1.0f, 0.0f, 1.0f};
    const BlitPlane planes[2][2] = {{{x0, y0, s0}, {x0, y0, t0}}, {{x1, y1, s1}, {x1, y1, t1}}};
    const auto lerp = [](float t, float a, float b) {
        return llvmpipe_math::host_fuses() ? std::fma(t, b - a, a) : t * (b - a) + a;
    };
    const auto at = [&](int x, int y) {
        return std::bit_cast<float>(src[std::size_t(y) * std::size_t(s.width) + std::size_t(x)]);
    };
    for (int y = 0; y < d.height; ++y) {
        for (int x = 0; x < d.width; ++x) {
            // below the diagonal from (0, 0) to (W, H): the second triangle (exact in 64 bits)
            const bool second = std::int64_t(2 * y + 1) * d.width > std::int64_t(2 * x + 1) * d.height;
            const Tap tx = float_clamp_tap(planes[second][0].at(x, y), s.width);
            const Tap ty = float_clamp_tap(planes[second][1].at(x, y), s.height);
            const float r0 = lerp(tx.f, at(tx.i0, ty.i0), at(tx.i1, ty.i0));
            const float r1 = lerp(tx.f, at(tx.i0, ty.i1), at(tx.i1, ty.i1));
            dst[std::size_t(y) * std::size_t(d.width) + std::size_t(x)] = std::bit_cast<std::uint32_t>(lerp(ty.f, r0, r1));
        }
    }
}

// A base level's texel: RGBA8 packed red lowest, or a depth texture's red / 255 as llvmpipe turns
// a unorm8 into a float.
std::uint32_t base_texel(const std::uint8_t* rgba, TexelFormat format) {
    if (format == TexelFormat::Depth32F) return std::bit_cast<std::uint32_t>(float(rgba[0]) * float(1.0 / 255.0));
    return std::uint32_t(rgba[0]) | std::uint32_t(rgba[1]) << 8 | std::uint32_t(rgba[2]) << 16 | std::uint32_t(rgba[3]) << 24;
}

// A 2D level (or one face's) from the one above.
void next_level_2d(const std::uint32_t* src, const Texture::Level& s, std::uint32_t* dst, const Texture::Level& d,
                   TexelFormat format) {
    if (format == TexelFormat::Depth32F) {
        next_depth_level(src, s, dst, d);
    } else {
        next_level(src, s, dst, d, 2);
    }
}

}  // namespace

Texture::Texture(int n, int w, int h, int d, const std::uint8_t* rgba, SamplerState s, TexelFormat f)
    : dims(n), width(w), height(h), depth(d), sampler(s), format(f) {
    if (f == TexelFormat::Depth32F && n != 2) throw std::invalid_argument("a depth texture is 2D or a cube map");
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
    for (std::size_t i = 0; i < std::size_t(w) * std::size_t(h) * std::size_t(d); ++i) texels[i] = base_texel(rgba + 4 * i, f);
    for (std::size_t l = 1; l < levels.size(); ++l) {
        const Level& a = levels[l - 1];
        const Level& b = levels[l];
        if (dims == 3) {
            next_level(&texels[std::size_t(a.offset)], a, &texels[std::size_t(b.offset)], b, 3);
        } else {
            next_level_2d(&texels[std::size_t(a.offset)], a, &texels[std::size_t(b.offset)], b, f);
        }
    }
}

samplerCube::samplerCube(int size, const std::array<const std::uint8_t*, 6>& faces, SamplerState s, TexelFormat f) {
    dims = kCubeDims;
    format = f;
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
    for (std::size_t face = 0; face < 6; ++face) {
        for (std::size_t i = 0; i < face_texels; ++i) texels[face * face_texels + i] = base_texel(faces[face] + 4 * i, f);
    }
    // Each face's levels as a 2D texture's (Mesa's mipmap blit draws the faces one by one).
    for (std::size_t l = 1; l < levels.size(); ++l) {
        const Level& a = levels[l - 1];
        const Level& b = levels[l];
        for (std::size_t face = 0; face < 6; ++face) {
            next_level_2d(&texels[std::size_t(a.offset) + face * std::size_t(a.width * a.height)], a,
                          &texels[std::size_t(b.offset) + face * std::size_t(b.width * b.height)], b, f);
        }
    }
}

std::array<int, 3> Texture::size(int lod) const {
    // lp_build_size_query with is_sviewinfo (NIR's txs): a level outside the texture's gives 0.
    if (lod < 0 || lod >= int(levels.size())) return {0, 0, 0};
    return {std::max(width >> lod, 1), std::max(height >> lod, 1), dims == 3 ? std::max(depth >> lod, 1) : 0};
}

}  // namespace qs::glsl
