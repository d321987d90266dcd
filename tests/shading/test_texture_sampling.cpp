// The texture lookups' lanes (shading/glsl/texture*.cpp, vectorised over 16 lanes) against a
// scalar oracle written from the rules in docs/design.md ("Textures") one lane at a time: 2D and
// 3D, every wrap and filter, power-of-two and other sizes, mipmaps, an implicit level from rho^2,
// a bias and an explicit level, coordinates from texel centres to NaN; textureSize and texelFetch.
// Exact float equality: the oracle states llvmpipe's arithmetic (x86's conversions, 8-bit lerps,
// fused float lerps where the host has FMA), not an approximation of it. Lanes stand alone here
// (no 4x2 vectors: those are the OSMesa tests' business, tests/reference).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "shading/glsl.h"
#include "shading/glsl/texture_cube.h"
#include "shading/glsl/texture_shadow.h"
#include "shading/number/simd/simd.h"
#include "shading/program.h"

namespace qs {

namespace {

using namespace glsl;

// ---- scalar llvmpipe --------------------------------------------------------------------------
int32_t cvt_rne(float f) { return simd::convert_nearest(simd::Vector<float, 1>{f})[0]; }
int32_t cvt_trunc(float f) { return simd::convert_truncate(simd::Vector<float, 1>{f})[0]; }
int32_t ifloor(float f) { return cvt_trunc(std::floor(f)); }
float minps(float a, float b) { return a < b ? a : b; }
float maxps(float a, float b) { return a > b ? a : b; }
int32_t wrapadd(int32_t a, int32_t b) { return int32_t(uint32_t(a) + uint32_t(b)); }
float unorm8(int v) { return float(v) * float(1.0 / 255.0); }
int lerp8(int w, int a, int b) { return a + ((w * (b - a) + 128) >> 8); }
float flerp(float w, float a, float b) {
    static const bool fma = __builtin_cpu_supports("fma");
    return fma ? std::fma(w, b - a, a) : w * (b - a) + a;
}
uint32_t bits(float f) { return std::bit_cast<uint32_t>(f); }
int exponent(float x, int bias) { return int((bits(x) >> 23) & 255) - (127 - bias); }
float fast_log2(float x) { return float(exponent(x, -1)) + std::bit_cast<float>((bits(x) & 0x7fffffu) | 0x3f800000u); }

struct Taps {
    int i0, i1;
    int w8;   // 8-bit path
    float w;  // float path
};

Taps aos_linear(float s, int size, bool pot, Wrap wrap) {
    Taps r{};
    if (wrap == Wrap::Repeat && !pot) {
        const float f = s - std::floor(s);
        const int u = wrapadd(cvt_rne((f * float(size)) * 256.0f), -128);
        r.w8 = u & 255;
        int i0 = u >> 8;
        if (i0 < 0) i0 = size - 1;
        i0 = std::min(i0, size - 1);
        r.i0 = i0, r.i1 = i0 != size - 1 ? i0 + 1 : 0;
        return r;
    }
    const int u = wrapadd(cvt_rne(s * float(size * 256)), -128);
    r.w8 = u & 255;
    const int i0 = u >> 8;
    if (wrap == Wrap::Repeat) {
        r.i0 = i0 & (size - 1), r.i1 = r.i0 != size - 1 ? r.i0 + 1 : 0;
    } else {
        r.i0 = std::clamp(i0, 0, size - 1), r.i1 = (i0 >= 0 && i0 < size - 1) ? r.i0 + 1 : r.i0;
    }
    return r;
}
int aos_nearest(float s, int size, bool pot, Wrap wrap) {
    if (wrap == Wrap::Repeat && !pot) return cvt_trunc(minps(s - std::floor(s), 0x1.fffffep-1f) * float(size));
    const int i = ifloor(s * float(size));
    return wrap == Wrap::Repeat ? (i & (size - 1)) : std::clamp(i, 0, size - 1);
}
float mirror(float s) {
    const float h = s * 0.5f;
    float c = h - std::nearbyint(h);
    c = c + c;
    return maxps(std::fabs(c), 0.0f);
}
Taps soa_linear(float s, int size, bool pot, Wrap wrap) {
    Taps r{};
    float c = 0;
    switch (wrap) {
        case Wrap::Repeat:
            if (pot) {
                c = s * float(size) - 0.5f;
                const int i = ifloor(c);
                r.i0 = i & (size - 1), r.i1 = wrapadd(i, 1) & (size - 1);
            } else {
                c = (s - std::floor(s)) * float(size) - 0.5f;
                r.i0 = !(c >= 0.0f) ? size - 1 : ifloor(c);  // unordered: NaN takes the last texel
                r.i1 = r.i0 != size - 1 ? r.i0 + 1 : 0;
            }
            break;
        case Wrap::ClampToEdge:
            c = maxps(minps(s * float(size), float(size)) - 0.5f, 0.0f);
            r.i0 = ifloor(c), r.i1 = std::min(r.i0 + 1, size - 1);
            break;
        case Wrap::MirroredRepeat:
            c = mirror(s) * float(size) - 0.5f;
            r.i0 = std::max(ifloor(c), 0), r.i1 = std::min(ifloor(c) + 1, size - 1);
            break;
    }
    r.w = c - std::floor(c);
    return r;
}
int soa_nearest(float s, int size, bool pot, Wrap wrap) {
    switch (wrap) {
        case Wrap::Repeat:
            return pot ? ifloor(s * float(size)) & (size - 1) : cvt_trunc(minps(s - std::floor(s), 0x1.fffffep-1f) * float(size));
        case Wrap::ClampToEdge: return std::clamp(cvt_trunc(s * float(size)), 0, size - 1);
        case Wrap::MirroredRepeat: return std::min(cvt_trunc(mirror(s) * float(size)), size - 1);
    }
    return 0;
}

// One lane: the texture's colour at coordinates c, the level of detail from rho2 (+ bias) or lod.
std::array<float, 4> oracle(const Texture& tex, const std::array<float, 3>& c, const float* rho2, const float* bias, const float* lod) {
    const SamplerState& st = tex.sampler;
    const int last = int(tex.levels.size()) - 1;
    const bool per_pixel = bias || lod;
    // Level of detail (lp_build_lod_selector, default state).
    int level0 = 0, level1 = 0;
    float blend = 0.0f;
    bool linear = st.min == Filter::Linear;
    if (rho2 || lod) {
        bool positive;
        int ipart = 0;
        float fpart = 0.0f;
        if (!per_pixel && st.mip != MipFilter::Linear) {
            ipart = exponent(*rho2, 1) >> 1;
            positive = *rho2 > 1.0f;
        } else {
            float l = lod ? *lod : fast_log2(*rho2) * 0.5f;
            if (bias && !lod) l = l + *bias;
            positive = l > 0.0f;
            if (st.mip == MipFilter::Nearest) {
                ipart = cvt_rne(l);
            } else {
                ipart = ifloor(l);
                fpart = l - std::floor(l);
            }
        }
        if (st.mip == MipFilter::Nearest) level0 = level1 = std::clamp(ipart, 0, last);
        if (st.mip == MipFilter::Linear) {
            if (ipart < 0) level0 = level1 = 0;
            else if (ipart >= last) level0 = level1 = last;
            else level0 = ipart, level1 = ipart + 1, blend = fpart;
        }
        const bool minified = st.min == st.mag || positive;
        if (!minified) blend = 0.0f;
        linear = (minified ? st.min : st.mag) == Filter::Linear;
    }
    bool aos = st.wrap_s != Wrap::MirroredRepeat && st.wrap_t != Wrap::MirroredRepeat &&
               (tex.dims == 2 || st.wrap_r != Wrap::MirroredRepeat) && (st.min == st.mag || !per_pixel);
    const bool pot[3] = {std::has_single_bit(unsigned(tex.width)), std::has_single_bit(unsigned(tex.height)),
                         std::has_single_bit(unsigned(tex.depth))};
    const Wrap wraps[3] = {st.wrap_s, st.wrap_t, st.wrap_r};
    auto texel = [&](int level, int x, int y, int z, int ch) {
        const Texture::Level& lv = tex.levels[std::size_t(level)];
        const uint32_t t = tex.texels[std::size_t(lv.offset) + (std::size_t(z) * std::size_t(lv.height) + std::size_t(y)) * std::size_t(lv.width) + std::size_t(x)];
        return int((t >> (8 * ch)) & 255u);
    };
    struct Level {
        std::array<int, 4> q;
        std::array<float, 4> f;
    };
    auto sample_level = [&](int level) {
        const Texture::Level& lv = tex.levels[std::size_t(level)];
        const int size[3] = {lv.width, lv.height, lv.depth};
        Taps t[3] = {{0, 0, 0, 0.0f}, {0, 0, 0, 0.0f}, {0, 0, 0, 0.0f}};
        for (int a = 0; a < tex.dims; ++a) {
            if (linear) {
                t[a] = aos ? aos_linear(c[std::size_t(a)], size[a], pot[a], wraps[a]) : soa_linear(c[std::size_t(a)], size[a], pot[a], wraps[a]);
            } else {
                const int n = aos ? aos_nearest(c[std::size_t(a)], size[a], pot[a], wraps[a]) : soa_nearest(c[std::size_t(a)], size[a], pot[a], wraps[a]);
                t[a] = {n, n, 0, 0.0f};
            }
        }
        Level r{};
        for (int ch = 0; ch < 4; ++ch) {
            auto slice_q = [&](int z) {
                const int r0 = lerp8(t[0].w8, texel(level, t[0].i0, t[1].i0, z, ch), texel(level, t[0].i1, t[1].i0, z, ch));
                const int r1 = lerp8(t[0].w8, texel(level, t[0].i0, t[1].i1, z, ch), texel(level, t[0].i1, t[1].i1, z, ch));
                return lerp8(t[1].w8, r0, r1);
            };
            auto slice_f = [&](int z) {
                const float r0 = flerp(t[0].w, unorm8(texel(level, t[0].i0, t[1].i0, z, ch)), unorm8(texel(level, t[0].i1, t[1].i0, z, ch)));
                const float r1 = flerp(t[0].w, unorm8(texel(level, t[0].i0, t[1].i1, z, ch)), unorm8(texel(level, t[0].i1, t[1].i1, z, ch)));
                return flerp(t[1].w, r0, r1);
            };
            if (tex.dims == 3) {
                r.q[std::size_t(ch)] = lerp8(t[2].w8, slice_q(t[2].i0), slice_q(t[2].i1));
                r.f[std::size_t(ch)] = flerp(t[2].w, slice_f(t[2].i0), slice_f(t[2].i1));
            } else {
                r.q[std::size_t(ch)] = slice_q(0);
                r.f[std::size_t(ch)] = slice_f(0);
            }
        }
        return r;
    };
    const Level l0 = sample_level(level0);
    std::array<float, 4> out{};
    if (aos) {
        std::array<int, 4> q = l0.q;
        if (blend > 0.0f) {
            const Level l1 = sample_level(level1);
            const int w = std::max(cvt_trunc(blend * 256.0f), 0);
            for (std::size_t ch = 0; ch < 4; ++ch) q[ch] = lerp8(w, q[ch], l1.q[ch]);
        }
        for (std::size_t ch = 0; ch < 4; ++ch) out[ch] = unorm8(q[ch]);
    } else {
        out = l0.f;
        if (blend > 0.0f) {
            const Level l1 = sample_level(level1);
            for (std::size_t ch = 0; ch < 4; ++ch) out[ch] = flerp(blend, out[ch], l1.f[ch]);
        }
    }
    return out;
}

// ---- cases ----------------------------------------------------------------------------------

std::vector<std::uint8_t> random_texels(std::mt19937& rng, std::size_t n) {
    std::vector<std::uint8_t> v(n * 4);
    for (auto& b : v) b = std::uint8_t(rng() & 255u);
    return v;
}

SamplerState random_sampler(std::mt19937& rng) {
    const Wrap wraps[3] = {Wrap::Repeat, Wrap::MirroredRepeat, Wrap::ClampToEdge};
    SamplerState s;
    s.wrap_s = wraps[rng() % 3], s.wrap_t = wraps[rng() % 3], s.wrap_r = wraps[rng() % 3];
    s.mag = rng() % 2 ? Filter::Linear : Filter::Nearest;
    s.min = rng() % 2 ? Filter::Linear : Filter::Nearest;
    s.mip = MipFilter(rng() % 3);
    return s;
}

float random_coordinate(std::mt19937& rng) {
    const int kind = int(rng() % 16);
    std::uniform_real_distribution<float> unit(-0.25f, 1.25f), wide(-40.0f, 40.0f);
    switch (kind) {
        case 0: return std::numeric_limits<float>::quiet_NaN();
        case 1: return (rng() % 2 ? 1.0f : -1.0f) * std::numeric_limits<float>::infinity();
        case 2: return (rng() % 2 ? 1.0f : -1.0f) * 1e9f;
        case 3: return float(int(rng() % 64) - 16) / 8.0f;  // texel edges and centres of small sizes
        case 4: case 5: case 6: return wide(rng);
        default: return unit(rng);
    }
}

struct Case {
    const Texture* tex;
    std::array<std::array<float, kBatchLanes>, 3> c;
    std::array<float, kBatchLanes> rho2, extra;
    int lod_kind;  // 0 implicit, 1 bias, 2 explicit
    int lanes = kBatchLanes;  // the lookup's first lanes (the sampler works a register of 8 at a time)
};

void check_case(const Case& k) {
    std::array<std::array<float, kBatchLanes>, 4> rgba{};
    texture_detail::Lookup l;
    l.lanes = k.lanes;
    l.s = k.c[0].data(), l.t = k.c[1].data();
    if (k.tex->dims == 3) l.r = k.c[2].data();
    const bool implicit = k.lod_kind != 2 && k.tex->needs_lod();
    l.rho2 = implicit ? k.rho2.data() : nullptr;
    l.bias = k.lod_kind == 1 ? k.extra.data() : nullptr;
    l.lod = k.lod_kind == 2 ? k.extra.data() : nullptr;
    for (std::size_t ch = 0; ch < 4; ++ch) l.rgba[ch] = rgba[ch].data();
    texture_detail::sample(*k.tex, l);
    for (std::size_t i = 0; i < std::size_t(k.lanes); ++i) {
        const std::array<float, 3> c{k.c[0][i], k.c[1][i], k.c[2][i]};
        const auto want = oracle(*k.tex, c, l.rho2 ? &k.rho2[i] : nullptr, l.bias ? &k.extra[i] : nullptr, l.lod ? &k.extra[i] : nullptr);
        for (std::size_t ch = 0; ch < 4; ++ch) {
            INFO("dims " << k.tex->dims << " size " << k.tex->width << "x" << k.tex->height << "x" << k.tex->depth << " wraps "
                         << int(k.tex->sampler.wrap_s) << int(k.tex->sampler.wrap_t) << int(k.tex->sampler.wrap_r) << " mag "
                         << int(k.tex->sampler.mag) << " min " << int(k.tex->sampler.min) << " mip " << int(k.tex->sampler.mip)
                         << " lod kind " << k.lod_kind << " lane " << i << " str (" << c[0] << ", " << c[1] << ", " << c[2]
                         << ") rho2 " << k.rho2[i] << " extra " << k.extra[i] << " channel " << ch);
            if (std::isnan(want[ch])) {
                REQUIRE(std::isnan(rgba[ch][i]));  // the float path's NaN weight (REPEAT on other sizes, NaN s)
            } else {
                REQUIRE(std::bit_cast<std::uint32_t>(rgba[ch][i]) == std::bit_cast<std::uint32_t>(want[ch]));
            }
        }
    }
}

}  // namespace

TEST_CASE("texture lookups: the lanes equal a scalar oracle of llvmpipe's rules, 2D and 3D", "[textures]") {
    std::mt19937 rng(20240611);
    const int sizes2d[][2] = {{8, 8}, {16, 4}, {5, 3}, {13, 7}, {1, 1}, {64, 32}};
    const int sizes3d[][3] = {{4, 4, 4}, {8, 4, 2}, {5, 3, 7}, {6, 6, 1}, {32, 32, 32}, {3, 8, 5}};
    std::uniform_real_distribution<float> log_rho(-12.0f, 16.0f), lods(-2.0f, 9.0f);
    int cases = 0;
    for (int round = 0; round < 300; ++round) {
        const bool three = round % 2 == 1;
        const SamplerState s = random_sampler(rng);
        const int* size = three ? sizes3d[rng() % 6] : sizes2d[rng() % 6];
        const int w = size[0], h = size[1], d = three ? size[2] : 1;
        const auto texels = random_texels(rng, std::size_t(w) * std::size_t(h) * std::size_t(d));
        const sampler2D t2 = three ? sampler2D() : sampler2D(w, h, texels.data(), s);
        const sampler3D t3 = three ? sampler3D(w, h, d, texels.data(), s) : sampler3D();
        const Texture& tex = three ? static_cast<const Texture&>(t3) : t2;
        for (int lod_kind = 0; lod_kind < 3; ++lod_kind) {
            constexpr int kLanes[] = {kBatchLanes, kBatchLanes, 5, kBatchLanes, 12, 1, 8, 9};
            Case k{&tex, {}, {}, {}, lod_kind, kLanes[(round * 3 + lod_kind) % 8]};
            for (std::size_t i = 0; i < kBatchLanes; ++i) {
                for (auto& axis : k.c) axis[i] = random_coordinate(rng);
                k.rho2[i] = std::exp2(log_rho(rng));
                if (rng() % 8 == 0) k.rho2[i] = float(1 << (rng() % 10)) * (rng() % 2 ? 2.0f : 1.0f);  // level thresholds
                k.extra[i] = rng() % 4 == 0 ? float(int(rng() % 20) - 4) * 0.5f : lods(rng);       // halves: ties
            }
            check_case(k);
            ++cases;
        }
    }
    CHECK(cases == 900);
}

// The plain 2D lookup (one level, one filter, 8-bit path) reads a column or row of texels only
// where some lane of the register weighs it, and texels close together by one load and a
// permute: lookups at texel centres, where every lane's weight is 0 along x, y or both (the
// halftone's explicit bilinear filter), next to registers where one lane is off centre, and
// ramps of a fraction of a texel a lane along one row or column (a magnified texture), up to
// the texture's last texels, each against the oracle.
// Every sampler the plain lookup takes (REPEAT or CLAMP_TO_EDGE on each axis, LINEAR or NEAREST
// for both filters) over a texture of random texels of each size: f(texture, width, height).
template <class F>
void for_each_plain_sampler(std::mt19937& rng, std::initializer_list<std::array<int, 2>> sizes, F f) {
    const Wrap wraps[2] = {Wrap::Repeat, Wrap::ClampToEdge};
    for (const auto& [w, h] : sizes) {
        const auto texels = random_texels(rng, std::size_t(w) * std::size_t(h));
        for (int variant = 0; variant < 8; ++variant) {
            SamplerState st;
            st.wrap_s = wraps[variant & 1], st.wrap_t = wraps[(variant >> 1) & 1];
            st.min = st.mag = variant & 4 ? Filter::Nearest : Filter::Linear;
            f(sampler2D(w, h, texels.data(), st), w, h);
        }
    }
}

TEST_CASE("texture lookups: texel centres and magnified ramps equal the oracle", "[textures]") {
    std::mt19937 rng(20261124);
    int cases = 0;
    for_each_plain_sampler(rng, {{256, 256}, {8, 16}, {5, 3}, {13, 7}, {1, 1}, {64, 32}}, [&](const sampler2D& tex, int w, int h) {
        // Per axis: 0 texel centres (as the halftone computes them, (i + 0.5) * (1 / size)),
        // 1 centres but one lane off centre, 2 anywhere, 3 a ramp from a random texel, 0.3
        // texel a lane, 4 one coordinate for every lane.
        for (int kind = 0; kind < 25; ++kind) {
            for (int lanes : {kBatchLanes, 8, 5}) {
                Case k{&tex, {}, {}, {}, 0, lanes};
                const int size_of[2] = {w, h};
                for (std::size_t axis = 0; axis < 2; ++axis) {
                    const int how = axis == 0 ? kind % 5 : kind / 5;
                    const float one = 1.0f / float(size_of[axis]);
                    std::uniform_int_distribution<int> texel(-2, size_of[axis] + 1);
                    std::uniform_real_distribution<float> anywhere(-0.25f, 1.25f);
                    const float start = float(texel(rng)) * one, same = anywhere(rng);
                    for (std::size_t i = 0; i < kBatchLanes; ++i) {
                        k.c[axis][i] = how == 2   ? anywhere(rng)
                                       : how == 3 ? start + float(i) * 0.3f * one
                                       : how == 4 ? same
                                                  : (float(texel(rng)) + 0.5f) * one;
                    }
                    if (how == 1) k.c[axis][rng() % std::size_t(lanes)] += 0.3f * one;
                }
                check_case(k);
                ++cases;
            }
        }
    });
    CHECK(cases == 6 * 8 * 25 * 3);
}

// Lookups as the renderers make them: two 4x4 blocks of pixels side by side (32 lanes), each
// laid out as core/block_layout.h lays out a block (four quads of a 2x2 arrangement; y down), or
// row by row, or with s or t running backwards, over a texture seen at a fraction of a texel per
// pixel up to several texels per pixel, anywhere on it and past its ends. The plain lookup reads
// a magnified block's texels from one window of four rows of eight texels opened at the block's
// corners, else by windows of neighbouring texels, one per texel row, and gathers what they do
// not hold: each lane the oracle's whichever way it was read. The sizes include the least a
// window fits in (8x4) and ones just past it, where the window moves back from the far edges.
TEST_CASE("texture lookups: blocks of pixels magnified and minified equal the oracle", "[textures]") {
    constexpr int kBlockDx[16] = {0, 1, 0, 1, 2, 3, 2, 3, 0, 1, 0, 1, 2, 3, 2, 3};
    constexpr int kBlockDy[16] = {1, 1, 0, 0, 1, 1, 0, 0, 3, 3, 2, 2, 3, 3, 2, 2};
    std::mt19937 rng(20261129);
    int cases = 0;
    for_each_plain_sampler(rng, {{256, 256}, {64, 32}, {13, 7}, {8, 4}, {9, 5}, {1, 1}}, [&](const sampler2D& tex, int w, int h) {
        for (const float texels_per_pixel : {0.25f, 0.5f, 1.0f, 1.5f, 3.0f, 5.0f, 17.0f}) {
            for (int layout = 0; layout < 4; ++layout) {
                std::uniform_real_distribution<float> origin(-0.3f, 1.3f);
                const float x0 = origin(rng), y0 = origin(rng);
                float s[32], t[32], rgba[4][32];
                for (int i = 0; i < 32; ++i) {
                    const int lane = i % 16, block = i / 16;
                    const int dx = layout == 1 ? lane % 4 : kBlockDx[lane], dy = layout == 1 ? lane / 4 : kBlockDy[lane];
                    const float px = float(4 * block + dx) + 0.5f, py = float(3 - dy) + 0.5f;  // GL's y up
                    s[i] = x0 + (layout == 2 ? -px : px) * texels_per_pixel / float(w);
                    t[i] = y0 + (layout == 3 ? -py : py) * texels_per_pixel / float(h);
                }
                REQUIRE(texture_detail::sample_plain(tex, {32, s, t, {rgba[0], rgba[1], rgba[2], rgba[3]}}));
                for (std::size_t i = 0; i < 32; ++i) {
                    const auto want = oracle(tex, {s[i], t[i], 0.0f}, nullptr, nullptr, nullptr);
                    for (std::size_t ch = 0; ch < 4; ++ch) {
                        INFO("size " << w << "x" << h << " wraps " << int(tex.sampler.wrap_s) << int(tex.sampler.wrap_t) << " mag "
                                     << int(tex.sampler.mag) << " texels per pixel " << texels_per_pixel << " layout " << layout
                                     << " lane " << i << " st (" << s[i] << ", " << t[i] << ") channel " << ch);
                        REQUIRE(std::bit_cast<std::uint32_t>(rgba[ch][i]) == std::bit_cast<std::uint32_t>(want[ch]));
                    }
                }
                ++cases;
            }
        }
    });
    CHECK(cases == 6 * 8 * 7 * 4);
}

// sample_plain, the entry shaders' plain lookups take (texture.h): any number of lanes in one
// call (a pair of batches is 32; odd counts end in part of a register), each lane the oracle's;
// a texture whose lookups are not plain ones is refused and nothing written.
TEST_CASE("texture lookups: the plain entry takes any number of lanes and refuses other samplers", "[textures]") {
    std::mt19937 rng(20261125);
    int cases = 0;
    for_each_plain_sampler(rng, {{256, 256}, {13, 7}, {1, 1}, {64, 32}}, [&](const sampler2D& tex, int w, int h) {
        for (int lanes : {32, 37, 17, 3}) {
            std::vector<float> s(static_cast<std::size_t>(lanes), 0.0f), t(s);
            for (int i = 0; i < lanes; ++i) s[std::size_t(i)] = random_coordinate(rng), t[std::size_t(i)] = random_coordinate(rng);
            std::array<std::vector<float>, 4> rgba;
            for (auto& c : rgba) c.assign(std::size_t(lanes), -1.0f);
            REQUIRE(texture_detail::sample_plain(tex, {lanes, s.data(), t.data(), {rgba[0].data(), rgba[1].data(), rgba[2].data(), rgba[3].data()}}));
            for (std::size_t i = 0; i < std::size_t(lanes); ++i) {
                const auto want = oracle(tex, {s[i], t[i], 0.0f}, nullptr, nullptr, nullptr);
                for (std::size_t ch = 0; ch < 4; ++ch) {
                    INFO("size " << w << "x" << h << " wraps " << int(tex.sampler.wrap_s) << int(tex.sampler.wrap_t) << " mag "
                                 << int(tex.sampler.mag) << " lanes " << lanes << " lane " << i << " st (" << s[i]
                                 << ", " << t[i] << ") channel " << ch);
                    REQUIRE(std::bit_cast<std::uint32_t>(rgba[ch][i]) == std::bit_cast<std::uint32_t>(want[ch]));
                }
            }
            ++cases;
        }
    });
    CHECK(cases == 4 * 8 * 4);
    // Not plain: a mirrored axis, mipmaps, different min and mag filters.
    const auto texels = random_texels(rng, 8 * 8);
    SamplerState mirrored, mipmapped, mixed;
    mirrored.wrap_t = Wrap::MirroredRepeat;
    mipmapped.mip = MipFilter::Nearest;
    mixed.min = Filter::Nearest;
    for (const SamplerState& st : {mirrored, mipmapped, mixed}) {
        const sampler2D tex(8, 8, texels.data(), st);
        float s[4] = {0.1f, 0.2f, 0.3f, 0.4f}, rgba[4][4];
        for (auto& c : rgba) std::fill_n(c, 4, -1.0f);
        CHECK_FALSE(texture_detail::sample_plain(tex, {4, s, s, {rgba[0], rgba[1], rgba[2], rgba[3]}}));
        for (auto& c : rgba) CHECK(std::count(c, c + 4, -1.0f) == 4);
    }
}

TEST_CASE("texture lookups: a 3D texture of one slice with CLAMP_TO_EDGE on r samples as its 2D image", "[textures]") {
    std::mt19937 rng(7);
    const auto texels = random_texels(rng, 12 * 5);
    SamplerState s;
    s.wrap_s = Wrap::Repeat, s.wrap_t = Wrap::ClampToEdge, s.wrap_r = Wrap::ClampToEdge;
    const sampler2D flat(12, 5, texels.data(), s);
    const sampler3D thick(12, 5, 1, texels.data(), s);
    for (int i = 0; i < 200; ++i) {
        const float u = random_coordinate(rng), v = random_coordinate(rng), r = random_coordinate(rng);
        const vec4<float> a = texture2D(flat, vec2<float>(u, v)), b = texture3D(thick, vec3<float>(u, v, r));
        for (int c = 0; c < 4; ++c) CHECK(std::bit_cast<std::uint32_t>(a[c]) == std::bit_cast<std::uint32_t>(b[c]));
    }
}

TEST_CASE("3D mipmaps: each level is the trilinear 8-bit sample of the one above at its texel centres", "[textures]") {
    // An 8x4x2 volume: level 1 is 4x2x1, every texel the average of 2x2x2 as lerps of one half
    // (the rounded 8-bit lerp, x first, then y, then r), as llvmpipe's blit makes it.
    std::mt19937 rng(11);
    const auto texels = random_texels(rng, 8 * 4 * 2);
    SamplerState s;
    s.mip = MipFilter::Linear;
    const sampler3D v(8, 4, 2, texels.data(), s);
    REQUIRE(v.levels.size() == 4);  // 8x4x2, 4x2x1, 2x1x1, 1x1x1
    CHECK(v.levels[1].width == 4);
    CHECK(v.levels[1].height == 2);
    CHECK(v.levels[1].depth == 1);
    CHECK(v.levels[3].depth == 1);
    auto avg = [](int a, int b) { return (a + b + 1) >> 1; };
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 4; ++x) {
            for (int c = 0; c < 4; ++c) {
                auto at = [&](int xx, int yy, int zz) { return int(texels[std::size_t(((zz * 4 + yy) * 8 + xx) * 4 + c)]); };
                auto slice = [&](int z) {
                    return avg(avg(at(2 * x, 2 * y, z), at(2 * x + 1, 2 * y, z)), avg(at(2 * x, 2 * y + 1, z), at(2 * x + 1, 2 * y + 1, z)));
                };
                const int want = avg(slice(0), slice(1));
                const std::uint32_t got = v.texels[std::size_t(v.levels[1].offset + y * 4 + x)];
                CHECK(int((got >> (8 * c)) & 255u) == want);
            }
        }
    }
}

TEST_CASE("textureSize and texelFetch: the level's size, zero outside, texels as stored, zero outside", "[textures]") {
    std::mt19937 rng(3);
    const auto texels = random_texels(rng, 10 * 6 * 3);
    SamplerState mipmapped;
    mipmapped.mip = MipFilter::Nearest;
    const sampler3D v(10, 6, 3, texels.data(), mipmapped);
    REQUIRE(v.levels.size() == 4);  // 10x6x3, 5x3x1, 2x1x1, 1x1x1
    CHECK(v.size(0) == std::array<int, 3>{10, 6, 3});
    CHECK(v.size(1) == std::array<int, 3>{5, 3, 1});
    CHECK(v.size(3) == std::array<int, 3>{1, 1, 1});
    CHECK(v.size(4) == std::array<int, 3>{0, 0, 0});
    CHECK(v.size(-1) == std::array<int, 3>{0, 0, 0});
    const sampler2D flat(10, 6, texels.data(), {});
    CHECK(flat.size(0) == std::array<int, 3>{10, 6, 0});
    CHECK(flat.size(1) == std::array<int, 3>{0, 0, 0});  // no mipmaps: one level

    const std::int32_t x[6] = {0, 9, 10, -1, 3, 0}, y[6] = {0, 5, 0, 0, 2, 0}, z[6] = {0, 2, 0, 0, 0, 0}, level[6] = {0, 0, 0, 0, 1, 4};
    float rgba[4][6];
    texture_detail::Fetch f;
    f.lanes = 6, f.x = x, f.y = y, f.z = z, f.level = level;
    for (std::size_t c = 0; c < 4; ++c) f.rgba[c] = rgba[c];
    texture_detail::fetch(v, f);
    for (int c = 0; c < 4; ++c) {
        CHECK(rgba[c][0] == float(texels[std::size_t(c)]) * float(1.0 / 255.0));
        CHECK(rgba[c][1] == float(texels[std::size_t(((2 * 6 + 5) * 10 + 9) * 4 + c)]) * float(1.0 / 255.0));
        CHECK(rgba[c][2] == 0.0f);  // x = width
        CHECK(rgba[c][3] == 0.0f);  // x < 0
        const std::uint32_t t = v.texels[std::size_t(v.levels[1].offset + 2 * 5 + 3)];
        CHECK(rgba[c][4] == float((t >> (8 * c)) & 255u) * float(1.0 / 255.0));
        CHECK(rgba[c][5] == 0.0f);  // no level 4
    }
}

TEST_CASE("texelFetch: every lane as a scalar reading of the level, zero outside, any count of lanes", "[textures]") {
    std::mt19937 rng(11);
    const auto texels = random_texels(rng, 13 * 7 * 5);
    SamplerState mipmapped;
    mipmapped.mip = MipFilter::Linear;
    const sampler2D flat(13, 7, texels.data(), {}), flat_mips(13, 7, texels.data(), mipmapped);
    const sampler3D volume(13, 7, 5, texels.data(), mipmapped);
    const std::int32_t extremes[] = {std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max(),
                                     -1, 1 << 20, -(1 << 20), 65536};
    int lanes_checked = 0;
    for (int round = 0; round < 300; ++round) {
        const Texture* choices[3] = {&flat, &flat_mips, &volume};
        const Texture& tex = *choices[round % 3];
        const int lanes = 1 + round % kBatchLanes;
        std::array<std::int32_t, kBatchLanes> c[3], level;
        auto coordinate = [&](int size) {
            const int kind = int(rng() % 8);
            return kind == 0 ? extremes[rng() % 6] : std::int32_t(int(rng() % unsigned(size + 4)) - 2);
        };
        for (int i = 0; i < kBatchLanes; ++i) {
            c[0][std::size_t(i)] = coordinate(tex.width), c[1][std::size_t(i)] = coordinate(tex.height);
            c[2][std::size_t(i)] = coordinate(tex.depth);
            level[std::size_t(i)] = rng() % 8 == 0 ? extremes[rng() % 6] : std::int32_t(int(rng() % 6) - 1);
        }
        std::array<std::array<float, kBatchLanes>, 4> rgba;
        for (auto& ch : rgba) ch.fill(-1.0f);  // lanes past the lookup's end stay as they were
        texture_detail::Fetch f;
        f.lanes = lanes, f.x = c[0].data(), f.y = c[1].data(), f.z = tex.dims == 3 ? c[2].data() : nullptr, f.level = level.data();
        for (std::size_t ch = 0; ch < 4; ++ch) f.rgba[ch] = rgba[ch].data();
        texture_detail::fetch(tex, f);
        for (std::size_t i = 0; i < kBatchLanes; ++i) {
            const int x = c[0][i], y = c[1][i], z = tex.dims == 3 ? c[2][i] : 0, l = level[i];
            std::uint32_t want = 0;
            if (l >= 0 && l < int(tex.levels.size())) {
                const Texture::Level& lv = tex.levels[std::size_t(l)];
                if (x >= 0 && x < lv.width && y >= 0 && y < lv.height && z >= 0 && z < lv.depth) {
                    want = tex.texels[std::size_t(lv.offset) + (std::size_t(z) * std::size_t(lv.height) + std::size_t(y)) * std::size_t(lv.width) + std::size_t(x)];
                }
            }
            for (std::size_t ch = 0; ch < 4; ++ch) {
                INFO("dims " << tex.dims << " levels " << tex.levels.size() << " lanes " << lanes << " lane " << i << " texel (" << x
                             << ", " << y << ", " << z << ") level " << l << " channel " << ch);
                const float expected = int(i) < lanes ? float((want >> (8 * ch)) & 255u) * float(1.0 / 255.0) : -1.0f;
                REQUIRE(std::bit_cast<std::uint32_t>(rgba[ch][i]) == std::bit_cast<std::uint32_t>(expected));
            }
            lanes_checked += int(i) < lanes;
        }
    }
    static_assert(kBatchLanes == 16);
    CHECK(lanes_checked == 18 * (16 * 17 / 2) + 12 * 13 / 2);  // 1..16 lanes, 300 rounds
}

namespace {

// GLSL's textureSize and texelFetch over every number type: each lane is what the core gives
// (Texture::size, texture_detail::fetch) for that lane's level and texel, and a Checked number
// flags exactly the lanes GLSL leaves undefined (a level or a texel outside the texture's).
template <class I>
I int_lanes(const std::int32_t* v) {
    if constexpr (is_checked_v<I>) {
        return I(decltype(I::v)::load(v), {});
    } else {
        return I::load(v);
    }
}
template <class I>
std::int32_t int_lane(const I& x, int k) {
    if constexpr (is_checked_v<I>) {
        return lane(x.v, k);
    } else {
        return lane(x, k);
    }
}
template <class F>
float float_lane(const F& x, int k) {
    if constexpr (is_dual2<F>::value) {
        CHECK(float(lane(x.dx, k)) == 0.0f);  // texels are constants
        CHECK(float(lane(x.dy, k)) == 0.0f);
        return float(lane(x.val, k));
    } else if constexpr (is_checked_v<F>) {
        return float(lane(x.v, k));
    } else {
        return float(lane(x, k));
    }
}

}  // namespace

#define FETCH_NUMBER_TYPES float, double, (Pixels<float, 16>), (Quads<float, 4>), (Pixels<double, 8>), Dual2<float>, \
                           (Dual2<Pixels<float, 16>>), (Checked<Pixels<float, 16>>), (Checked<Quads<float, 4>>)

TEMPLATE_TEST_CASE("textureSize and texelFetch of every number type: each lane as the core, undefined lanes flagged",
                   "[textures]", FETCH_NUMBER_TYPES) {
    using F = TestType;
    using I = int_t<F>;
    constexpr int n = lanes_of<F>();
    std::mt19937 rng(11);
    const auto texels = random_texels(rng, 10 * 6 * 3);
    SamplerState mipmapped;
    mipmapped.mip = MipFilter::Nearest;
    const sampler3D volume(10, 6, 3, texels.data(), mipmapped);  // levels 10x6x3, 5x3x1, 2x1x1, 1x1x1
    const sampler2D image(10, 6, texels.data(), mipmapped);      // 10x6, 5x3, 2x1, 1x1
    // Lanes through levels -1..4 and texels from 2 before each axis to 2 past it.
    for (int start = 0; start < 96; start += n) {
        std::int32_t level[16], x[16], y[16], z[16];
        for (int k = 0; k < n; ++k) {
            const int i = start + k;
            level[k] = i % 6 - 1, x[k] = (i * 7) % 15 - 2, y[k] = (i * 5) % 11 - 2, z[k] = (i * 3) % 7 - 2;
        }
        const I lod = int_lanes<I>(level);
        const ivec2<F> size2 = textureSize<F>(image, lod);
        const ivec3<F> size3 = textureSize<F>(volume, lod);
        const vec4<F> c2 = texelFetch<F>(image, ivec2<F>(int_lanes<I>(x), int_lanes<I>(y)), lod);
        const vec4<F> c3 = texelFetch<F>(volume, ivec3<F>(int_lanes<I>(x), int_lanes<I>(y), int_lanes<I>(z)), lod);
        for (int k = 0; k < n; ++k) {
            INFO("level " << level[k] << ", texel " << x[k] << ", " << y[k] << ", " << z[k]);
            const auto s2 = image.size(level[k]), s3 = volume.size(level[k]);
            CHECK(int_lane(size2.x, k) == s2[0]);
            CHECK(int_lane(size2.y, k) == s2[1]);
            CHECK(int_lane(size3.x, k) == s3[0]);
            CHECK(int_lane(size3.y, k) == s3[1]);
            CHECK(int_lane(size3.z, k) == s3[2]);
            float want2[4], want3[4];
            texture_detail::Fetch f;
            f.lanes = 1, f.x = &x[k], f.y = &y[k], f.level = &level[k];
            for (std::size_t c = 0; c < 4; ++c) f.rgba[c] = &want2[c];
            texture_detail::fetch(image, f);
            f.z = &z[k];
            for (std::size_t c = 0; c < 4; ++c) f.rgba[c] = &want3[c];
            texture_detail::fetch(volume, f);
            for (int c = 0; c < 4; ++c) {
                CHECK(float_lane(c2[c], k) == want2[c]);
                CHECK(float_lane(c3[c], k) == want3[c]);
            }
            const bool level_outside = level[k] < 0 || level[k] > 3;
            const bool in2 = !level_outside && x[k] >= 0 && x[k] < s2[0] && y[k] >= 0 && y[k] < s2[1];
            const bool in3 = !level_outside && x[k] >= 0 && x[k] < s3[0] && y[k] >= 0 && y[k] < s3[1] && z[k] >= 0 && z[k] < s3[2];
            if (!in2) CHECK(want2[3] == 0.0f);  // llvmpipe's answer outside: (0, 0, 0, 0)
            if constexpr (is_checked_v<F>) {
                const auto argument = std::uint8_t(Undefined::Argument);
                CHECK(size2.x.cases.at(k) == (level_outside ? argument : 0));
                CHECK(size3.z.cases.at(k) == (level_outside ? argument : 0));
                CHECK(c2[0].cases.at(k) == (in2 ? 0 : argument));
                CHECK(c3[3].cases.at(k) == (in3 ? 0 : argument));
            }
        }
    }
}

TEST_CASE("shadow lookups: a depth texture's comparisons, constant under Dual2; the wrong kind of texture refused",
          "[textures]") {
    // A 2x2 depth texture of 0, 1/255, 2/255, 3/255 (red bytes), nearest: each texel is compared alone.
    const std::uint8_t rgba[16] = {0, 9, 9, 9, 1, 9, 9, 9, 2, 9, 9, 9, 3, 9, 9, 9};
    SamplerState nearest;
    nearest.mag = nearest.min = Filter::Nearest;
    nearest.compare = CompareFunc::Less;
    const sampler2D depth(2, 2, rgba, nearest, TexelFormat::Depth32F);
    const sampler2D colour(2, 2, rgba, nearest);
    // texel (1, 1) holds 3/255: LESS passes below it, not at it
    CHECK(textureShadow(depth, vec3<float>(0.75f, 0.75f, 2.5f / 255.0f)) == 1.0f);
    CHECK(textureShadow(depth, vec3<float>(0.75f, 0.75f, 3.0f * float(1.0 / 255.0))) == 0.0f);  // the depth itself
    CHECK(textureShadow(depth, vec3<float>(0.25f, 0.25f, -1.0f)) == 1.0f);  // below texel (0, 0)'s 0
    using D = Dual2<float>;
    const D r = textureShadow(depth, vec3<D>(D(0.75f, 1.0f, 0.0f), D(0.75f, 0.0f, 1.0f), D(0.0f, 1.0f, 1.0f)));
    CHECK(r.val == 1.0f);
    CHECK(r.dx == 0.0f);
    CHECK(r.dy == 0.0f);
    CHECK_THROWS_AS(textureShadow(colour, vec3<float>(0.5f, 0.5f, 0.5f)), std::logic_error);
    CHECK_THROWS_AS(texture(depth, vec2<float>(0.5f, 0.5f)), std::logic_error);
}

TEST_CASE("textureQueryLod on a depth comparison cube map is a colour cube map's, as GL defines it", "[textures]") {
    // 16x16 faces, trilinear and with different minification and magnification filters (where
    // the level of detail is carried per pixel), and one level (where it is the quad's).
    std::vector<std::uint8_t> face(16 * 16 * 4);
    for (std::size_t i = 0; i < face.size(); ++i) face[i] = std::uint8_t(i * 37);
    const std::array<const std::uint8_t*, 6> faces{face.data(), face.data(), face.data(), face.data(), face.data(), face.data()};
    for (const MipFilter mip : {MipFilter::Linear, MipFilter::Nearest, MipFilter::None}) {
        SamplerState s;
        s.mip = mip;
        s.min = Filter::Nearest;
        const samplerCube colour(16, faces, s), depth(16, faces, s, TexelFormat::Depth32F);
        using Q = Quads<float, 4>;
        float px[16], py[16], pz[16];
        for (int i = 0; i < 16; ++i) {
            px[i] = float(i % 4) * 0.3f - 0.5f, py[i] = 1.0f - float(i / 4) * 0.05f * float(i % 3), pz[i] = float(i) * 0.11f - 0.9f;
        }
        const Q x = Q::load(px), y = Q::load(py), z = Q::load(pz);
        const vec2<Q> a = textureQueryLod(colour, vec3<Q>(x, y, z)), b = textureQueryLod(depth, vec3<Q>(x, y, z));
        for (int i = 0; i < 16; ++i) {
            CHECK(a.x[i] == b.x[i]);
            CHECK(a.y[i] == b.y[i]);
        }
    }
}

}  // namespace qs
