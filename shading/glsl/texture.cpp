// The texture lookups' entry points, lanes in and lanes out, as Mesa 22.3's llvmpipe samples
// GL_RGBA8 2D, 3D and cube map textures (lp_bld_sample.c, lp_bld_sample_soa.c): the general
// lookup (levels of detail, mipmaps, texel offsets, carried derivatives), which takes the 8-bit
// or the float filtering path as lp_build_sample_soa_code chooses; texelFetch, textureGather,
// the depth comparison of shadow samplers, and textureQueryLod. The plain 2D lookup most shaders
// make has its own code (texture_plain.cpp), the levels' storage and mipmaps theirs
// (texture_mipmaps.cpp). Every rule here was checked bit for bit against OSMesa (docs/design.md,
// "Textures").

#include "shading/glsl/texture.h"
#include "shading/glsl/texture_cube.h"
#include "shading/glsl/texture_filter_8bit.h"
#include "shading/glsl/texture_filter_float.h"
#include "shading/glsl/texture_lanes.h"
#include "shading/glsl/texture_lod.h"
#include "shading/glsl/texture_queries.h"
#include "shading/glsl/texture_shadow.h"
#include "shading/glsl/texture_texels.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>

namespace qs::glsl {

namespace {

struct Sample {
    Floats rgba[4];
    Floats d[3][4];  // d(colour channel)/d(coordinate)
};

// The 8-bit path (lp_bld_sample_aos.c) when llvmpipe takes it (lp_build_sample_soa_code): every
// wrap REPEAT or CLAMP_TO_EDGE, and min == mag or one level of detail per quad (a bias or an
// explicit level is one per pixel).
template <int Dims>
bool takes_8bit_path(const Texture& tex, bool per_pixel_lod) {
    const SamplerState& st = tex.sampler;
    for (int i = 0; i < Dims; ++i) {
        if (wrap_of(st, i) == Wrap::MirroredRepeat) return false;
    }
    return st.min == st.mag || !per_pixel_lod;
}

template <int Dims>
Sample sample_lanes(const Texture& tex, const Coords<Dims>& co, const Floats* rho2, const Floats* bias, const Floats* lod,
                    bool rho2_per_pixel, bool quad_vectors, bool gradient) {
    const SamplerState& st = tex.sampler;
    const LevelChoice lc = choose_levels(tex, rho2, bias, lod);
    const bool blend = st.mip == MipFilter::Linear && any(bits(lc.blend) != 0);
    Sample out;  // out.d only written (and read) with `gradient`
    if (!co.ref && takes_8bit_path<Dims>(tex, bias || lod || rho2_per_pixel)) {
        // The second level blends in with an 8-bit weight truncated from the fraction
        // (lp_build_sample_mipmap).
        Pairs q = aos_level(tex, co, lc.level0, lc.linear, gradient, out.d);
        if (blend) {
            Floats d1[3][4];
            const Pairs q1 = aos_level(tex, co, lc.level1, lc.linear, gradient, d1);
            q = lerp8(imax(cvt_trunc(lc.blend * 256.0f), Ints{}), q, q1);
            if (gradient) {
                for (int i = 0; i < Dims; ++i) {
                    for (int c = 0; c < 4; ++c) out.d[i][c] += lc.blend * (d1[i][c] - out.d[i][c]);
                }
            }
        }
        for (int c = 0; c < 4; ++c) out.rgba[c] = unorm(channel(q, c));
        return out;
    }
    // The float path: lp_build_sample_mipmap, or lp_build_sample_mipmap_both when min and mag
    // filters differ.
    const Ints weights_only = st.min != st.mag ? any_per_vector(lc.linear, quad_vectors) & ~lc.linear : Ints{};
    soa_level(tex, co, lc.level0, lc.linear, weights_only, gradient, out.rgba, out.d);
    if (blend) {
        Floats c1[4], d1[3][4];
        soa_level(tex, co, lc.level1, lc.linear, weights_only, gradient, c1, d1);
        const Floats f = maxps(lc.blend, Floats{});
        for (int c = 0; c < (co.ref ? 1 : 4); ++c) {
            out.rgba[c] = lerp(f, out.rgba[c], c1[c]);
            if (gradient) {
                for (int i = 0; i < Dims; ++i) out.d[i][c] += f * (d1[i][c] - out.d[i][c]);
            }
        }
    }
    return out;
}

}  // namespace

namespace texture_detail {

void throw_lod_without_quads() {
    throw std::logic_error("texture lookup: this texture's sampler needs a level of detail, i.e. the quad's "
                           "derivatives, but the shader was run on independent pixels");
}

namespace {
// A shadow lookup reads a depth texture and a colour lookup any other, as the renderer binds them:
// a slip would read a float's bits as bytes, or bytes as a float.
void check_format(const Texture& tex, bool compared) {
    if (compared != (tex.format == TexelFormat::Depth32F)) {
        throw std::logic_error(compared ? "texture lookup: a depth comparison on a colour texture"
                                        : "texture lookup: colours read from a depth comparison texture");
    }
}

// One register's worth of a lookup's lanes, from `base`.
template <int Dims>
[[gnu::always_inline]] inline void sample_register(const Texture& tex, const Lookup& l, int base,
                                                   const std::int32_t* faces = nullptr) {
    const int n = std::min(l.lanes - base, L);
    const Floats rho2 = l.rho2 ? load_lanes(l.rho2, base, n) : Floats{};
    const Floats bias = l.bias ? load_lanes(l.bias, base, n) : Floats{};
    const Floats lod = l.lod ? load_lanes(l.lod, base, n) : Floats{};
    Coords<Dims> co;
    co.c[0] = load_lanes(l.s, base, n), co.c[1] = load_lanes(l.t, base, n);
    if constexpr (Dims == 3) co.c[2] = load_lanes(l.r, base, n);
    Ints offset[Dims];
    for (int i = 0; i < Dims; ++i) {
        if (l.offset[std::size_t(i)]) offset[i] = load_lanes<Ints>(l.offset[std::size_t(i)], base, n), co.offset[i] = &offset[i];
    }
    Ints face{};
    if (faces) face = load_lanes<Ints>(faces, base, n), co.face = &face;
    Floats ref{};
    if (l.ref) ref = load_lanes(l.ref, base, n), co.ref = &ref;
    const bool gradient = l.d_ds[0] != nullptr;
    const Sample r = sample_lanes<Dims>(tex, co, l.rho2 ? &rho2 : nullptr, l.bias ? &bias : nullptr, l.lod ? &lod : nullptr,
                                        l.rho2_per_pixel, l.quad_vectors, gradient);
    const std::array<float*, 4>* d_out[3] = {&l.d_ds, &l.d_dt, &l.d_dr};
    for (int c = 0; c < 4; ++c) {
        store_lanes(l.rgba[std::size_t(c)], base, n, c > 0 && l.ref ? Floats{} : r.rgba[c]);
        if (gradient) {
            for (int i = 0; i < Dims; ++i) store_lanes((*d_out[i])[std::size_t(c)], base, n, r.d[i][c]);
        }
    }
}
template <int Dims>
[[gnu::always_inline]] inline void sample_dims(const Texture& tex, const Lookup& l) {
    for (int base = 0; base < l.lanes; base += L) sample_register<Dims>(tex, l, base);
}

}  // namespace

// Flattened: the helpers above become one straight body (called as functions, their vectors
// would travel through memory). A descriptor of a plain lookup takes sample_plain, as shaders do.
[[gnu::flatten]] void sample(const Texture& tex, const Lookup& l) {
    check_format(tex, l.ref != nullptr);
    if (!l.rho2 && !l.lod && !l.d_ds[0] && !l.offset[0] && !l.ref && sample_plain(tex, {l.lanes, l.s, l.t, l.rgba})) {
        return;
    }
    if (tex.dims == 3) {
        sample_dims<3>(tex, l);
    } else {
        sample_dims<2>(tex, l);
    }
}

void sample_cube(const Texture& tex, const Lookup& l, const std::int32_t* face) {
    check_format(tex, l.ref != nullptr);
    for (int base = 0; base < l.lanes; base += L) sample_register<2>(tex, l, base, face);
}

// lp_build_fetch_texel: the level is lod + first level (0); a lane outside the level's size or
// a level outside the texture's reads zero, alpha included. A gather per register, from texel 0
// where the lane reads nothing.
void fetch(const Texture& tex, const Fetch& f) {
    check_format(tex, false);
    const Ints last = splat(int(tex.levels.size()) - 1);
    for (int base = 0; base < f.lanes; base += L) {
        const int n = std::min(f.lanes - base, L);
        const Ints level = load_lanes<Ints>(f.level, base, n);
        const Ints x = load_lanes<Ints>(f.x, base, n), y = load_lanes<Ints>(f.y, base, n);
        const Ints z = f.z ? load_lanes<Ints>(f.z, base, n) : Ints{};
        const Ints in_levels = (level >= 0) & (level <= last);
        const LevelLanes lv = level_lanes(tex, level & in_levels);
        const Ints in = in_levels & (x >= 0) & (x < lv.width) & (y >= 0) & (y < lv.height) & (z >= 0) & (z < lv.depth);
        const Ints index = lv.offset + ((z & in) * lv.height + (y & in)) * lv.width + (x & in);
        const Uints texel = gather(tex.texels.data(), index & in) & Uints(in);
        for (int c = 0; c < 4; ++c) store_lanes(f.rgba[std::size_t(c)], base, n, unorm(channel(texel, c)));
    }
}

namespace {
// One axis of a gather: the bilinear lookup's two texels (lp_build_sample_wrap_linear with
// is_gather). REPEAT is the lookup's. CLAMP_TO_EDGE and MIRRORED_REPEAT take their own code
// there, so that a coordinate within half a texel of an edge reads the edge texel twice:
// CLAMP_TO_EDGE i0 = trunc(c - 0.5), i1 = min(trunc(c + 0.5), size - 1) from c = s size (+
// offset) clamped to [0, size]; MIRRORED_REPEAT mirrors s once, signed (2 (s/2 - round_even(s/2)),
// negative in a mirrored period), then i0 = floor(c size - 0.5), i1 = i0 + 1, each negative one
// complemented (-1 is 0, -2 is 1) and clamped to size - 1.
Axis gather_axis(const Floats& s, const Ints& size, Wrap wrap, bool pot, const Ints* offset) {
    if (wrap == Wrap::Repeat) return soa_axis(s, size, wrap, pot, splat(-1), Ints{}, offset);
    const Floats fsize = to_float(size);
    Axis a{};
    if (wrap == Wrap::MirroredRepeat) {
        const Floats half = (offset ? s + to_float(*offset) / fsize : s) * 0.5f;
        const Floats m = half - round_even(half);
        const Ints i0 = cvt_trunc(floor((m + m) * fsize - 0.5f)), i1 = i0 + 1;
        a.i0 = imin(i0 ^ (i0 < 0), size - 1);
        a.i1 = imin(i1 ^ (i1 < 0), size - 1);
        return a;
    }
    Floats c = s * fsize;
    if (offset) c = c + to_float(*offset);
    c = maxps(c < fsize ? c : fsize, Floats{});
    a.i0 = cvt_trunc(c - 0.5f);
    a.i1 = imin(cvt_trunc(c + 0.5f), size - 1);
    return a;
}

// Level 0's lanes [base, base + n), on the faces `faces` gives them (or none).
LevelLanes level0_lanes(const Texture& tex, const std::int32_t* faces, int base, int n) {
    if (!faces) return level_lanes(tex, Ints{});
    const Ints face = load_lanes<Ints>(faces, base, n);
    return face_level_lanes(tex, Ints{}, &face);
}

// The two axes of a lookup's lanes [base, base + n): its s and t (and texel offsets, where it has
// them) handed to `axis(i, coordinate, offset or null)`.
template <class Lookup, class Axis>
Axes<2> axes_of(const Lookup& l, int base, int n, const Axis& axis) {
    Axes<2> ax;
    for (int i = 0; i < 2; ++i) {
        const std::int32_t* given = l.offset[std::size_t(i)];
        Ints offset;
        if (given) offset = load_lanes<Ints>(given, base, n);
        ax.a[i] = axis(i, load_lanes(i == 0 ? l.s : l.t, base, n), given ? &offset : nullptr);
    }
    return ax;
}
}  // namespace

void gather_channel(const Texture& tex, const Gather& g) {
    check_format(tex, g.ref != nullptr);
    const std::array<bool, 3> pot = pot_sizes<2>(tex);
    for (int base = 0; base < g.lanes; base += L) {
        const int n = std::min(g.lanes - base, L);
        const LevelLanes lv = level0_lanes(tex, g.face, base, n);
        const Axes<2> ax = axes_of(g, base, n, [&](int i, const Floats& c, const Ints* offset) {
            return gather_axis(c, size_of(lv, i), wrap_of(tex.sampler, i), pot[std::size_t(i)], offset);
        });
        const Texels<2> k = fetch_texels(tex, lv, ax);  // k[0][row j][column i]
        const Uints order[4] = {k.k[0][1][0], k.k[0][1][1], k.k[0][0][1], k.k[0][0][0]};
        if (g.ref) {
            // each texel's comparison, as a shadow lookup's
            const Floats ref = load_lanes(g.ref, base, n);
            for (std::size_t c = 0; c < 4; ++c) {
                store_lanes(g.out[c], base, n, depth_passes(tex.sampler.compare, ref, order[c]));
            }
            continue;
        }
        for (std::size_t c = 0; c < 4; ++c) store_lanes(g.out[c], base, n, unorm(channel(order[c], g.component)));
    }
}

// lp_build_lod_selector with is_lodq (no fast path: log2 of rho^2 halved), and
// lp_build_sample_common's level: 0 without mipmaps, lp_build_round (to even) then clamped to
// [0, last] with NEAREST ones, clamped with LINEAR.
void query_lod(const Texture& tex, const LodQuery& q) {
    const Floats last = splat(float(int(tex.levels.size()) - 1));
    for (int base = 0; base < q.lanes; base += L) {
        const int n = std::min(q.lanes - base, L);
        const Floats lod = fast_log2(load_lanes(q.rho2, base, n)) * 0.5f;
        Floats level{};
        if (tex.sampler.mip == MipFilter::Nearest) level = minps(maxps(round_even(lod), Floats{}), last);
        if (tex.sampler.mip == MipFilter::Linear) level = minps(maxps(lod, Floats{}), last);
        store_lanes(q.level, base, n, level);
        store_lanes(q.lod, base, n, lod);
    }
}

}  // namespace texture_detail

}  // namespace qs::glsl
