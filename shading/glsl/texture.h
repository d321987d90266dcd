#pragma once
// sampler2D and sampler3D, and GLSL's lookups in them, as Mesa's llvmpipe samples a GL_RGBA8
// GL_TEXTURE_2D or GL_TEXTURE_3D, to the bit: wrap modes (REPEAT, MIRRORED_REPEAT,
// CLAMP_TO_EDGE), filters (NEAREST, LINEAR and the four mipmapped minification filters), one
// level of detail per 2x2 quad from the quad's derivatives (texture2D, texture3D), a bias or an
// explicit level per pixel (textureLod), and mipmaps made as glGenerateMipmap makes them. Texels
// are 8-bit (a depth comparison texture's floats, texture_shadow.h); loading them from an image
// file is the renderer's job (render/), which also makes sure a texture that needs a level of
// detail is sampled from quads.
//
// The arithmetic, and the OSMesa experiments that pinned it, are in docs/design.md ("Textures");
// the lanes' work is done by texture_detail::sample (texture.cpp), or sample_plain for the plain
// lookup most shaders make (texture_plain.cpp), eight lanes to an AVX2 register (sixteen to an
// AVX-512 register for the plain lookup): texel fetches are gathers, four per register for a
// bilinear level, eight for a trilinear lookup, or loads of neighbouring texels and permutes
// where the lanes read them.
//
// The lookups are written over the number type like any shader code, what differs between the
// types said once (sampler_traits.h). Per-pixel types (float, double, Pixels) have no
// neighbours: they can only take an implicit level of detail from a texture that needs none
// (textureLod they can always do). Quads compute it per quad, as llvmpipe does; Dual2 from its
// carried partials, and its result carries the exact derivative of the filter's interpolant
// (texels are constants).

#include <array>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "shading/glsl/sampler_traits.h"
#include "shading/glsl/vec.h"
#include "shading/number/number.h"

namespace qs::glsl {

enum class Wrap : std::uint8_t { Repeat, MirroredRepeat, ClampToEdge };
enum class Filter : std::uint8_t { Nearest, Linear };
enum class MipFilter : std::uint8_t { None, Nearest, Linear };

// A shadow lookup's test of a depth texel (GL_TEXTURE_COMPARE_FUNC): it passes where
// `reference FUNC depth` holds.
enum class CompareFunc : std::uint8_t { Never, Less, Equal, LessEqual, Greater, NotEqual, GreaterEqual, Always };
struct SamplerState {
    Wrap wrap_s = Wrap::ClampToEdge, wrap_t = Wrap::ClampToEdge, wrap_r = Wrap::ClampToEdge;  // r: 3D only
    Filter mag = Filter::Linear, min = Filter::Linear;
    MipFilter mip = MipFilter::None;                // the minification filter's mipmap part
    CompareFunc compare = CompareFunc::LessEqual;  // read by the shadow samplers only (GL's default)
};

// What a texel holds: GL_RGBA8's four bytes, red in the lowest; or, in a depth comparison texture
// (a shadow sampler's), a GL_DEPTH_COMPONENT32F depth as a float's bits.
enum class TexelFormat : std::uint8_t { Rgba8, Depth32F };

// A texture of two or three dimensions with its sampler: what sampler2D and sampler3D share.
// Texel (x, y, z) of a level is at texels[level.offset + (z * level.height + y) * level.width +
// x]; row 0 is t = 0, which glTF makes the image's first (top) row, and slice 0 is r = 0.
class Texture {
public:
    struct Level {
        // Four ints: lookups gather a lane's offset from them.
        std::int32_t width, height, depth, offset;
    };
    int dims = 2;
    int width = 0, height = 0, depth = 1;  // the base level's size (textureSize(s, 0))
    SamplerState sampler;
    TexelFormat format = TexelFormat::Rgba8;
    std::vector<Level> levels;
    std::vector<std::uint32_t> texels;

    // Whether an implicit lookup needs the level of detail, i.e. derivatives of its coordinates:
    // to pick a mipmap level, or to choose between different minification and magnification
    // filters. (A lookup with an explicit level or a bias also lays its lanes out as llvmpipe
    // does only when shaded in quads: the renderer shades such a texture in quads either way.)
    bool needs_lod() const { return sampler.mip != MipFilter::None || sampler.min != sampler.mag; }

    // The size of level `lod` (0: the base), as GLSL's textureSize; (0, 0, 0) outside the
    // levels, as llvmpipe answers (texel_fetch_probe). A texture whose sampler reads no mipmaps
    // has one level, as GL's texture view of it has.
    std::array<int, 3> size(int lod) const;

protected:
    Texture() = default;
    // The base level from `rgba` (4 bytes per texel, rows from t = 0, slices from r = 0; a
    // Depth32F texture's depth is the red byte, red / 255 as llvmpipe turns a unorm8 into a
    // float), and the levels below it down to 1x1(x1) when the sampler's minification filter
    // reads mipmaps, each made from the one above as llvmpipe's glGenerateMipmap makes it. Throws
    // std::invalid_argument for a size outside 1..32768 (1..2048 for 3D, GL_MAX_3D_TEXTURE_SIZE).
    Texture(int dims, int width, int height, int depth, const std::uint8_t* rgba, SamplerState sampler,
            TexelFormat format = TexelFormat::Rgba8);
};

// A 2D texture: a sampler2D's, or with a Depth32F format a sampler2DShadow's.
struct sampler2D : Texture {
    sampler2D() = default;
    sampler2D(int width, int height, const std::uint8_t* rgba, SamplerState sampler,
              TexelFormat format = TexelFormat::Rgba8)
        : Texture(2, width, height, 1, rgba, sampler, format) {}
};

struct sampler3D : Texture {
    sampler3D() { dims = 3; }
    sampler3D(int width, int height, int depth, const std::uint8_t* rgba, SamplerState sampler)
        : Texture(3, width, height, depth, rgba, sampler) {}
};

namespace texture_detail {

inline constexpr int kMaxLanes = 16;

// One call's lanes, structure of arrays.
struct Lookup {
    int lanes = 0;  // 1..kMaxLanes
    const float* s = nullptr;
    const float* t = nullptr;
    const float* r = nullptr;  // 3D only
    // Per lane, llvmpipe's squared scale factor rho^2 = max((W ds/dx)^2 + (H dt/dx)^2 [+ (D
    // dr/dx)^2], the same along y) (W, H, D: the base level's size); required for an implicit
    // level of detail when the texture needs_lod().
    const float* rho2 = nullptr;
    // Per lane, GLSL's bias, added to the level of detail rho2 gives (texture2D(s, st, bias)).
    const float* bias = nullptr;
    // Per lane, an explicit level of detail (textureLod); rho2 and bias unused.
    const float* lod = nullptr;
    // Whether rho2 is each lane's own, from explicit derivatives (textureGrad): a level of detail
    // per pixel, as a bias or an explicit level is, where an implicit one is per quad.
    bool rho2_per_pixel = false;
    // Per lane, GLSL's texel offsets along s, t (and r) (textureOffset and its kin), added at
    // every level as llvmpipe adds them; null for none.
    std::array<const std::int32_t*, 3> offset{};
    // Per lane, a shadow lookup's reference value, null for a colour lookup: each texel read
    // (a Depth32F texture's) passes or fails the sampler's compare function, and the passes (1)
    // and failures (0) are filtered as colours are (lp_build_sample_compare), into rgba[0]; the
    // other channels get 0, no derivatives.
    const float* ref = nullptr;
    // Lanes 8k..8k+7 are the two side-by-side quads llvmpipe shades as one vector (quads from a
    // 4x4 block); otherwise each lane stands alone. Decides how lookups on the float path with
    // different minification and magnification filters blend (llvmpipe decides that per vector).
    bool quad_vectors = false;
    std::array<float*, 4> rgba{};  // out
    // Out when set (Dual2): the derivative of the colour along s, t (and r) of the filter's
    // interpolant; zero for nearest filtering.
    std::array<float*, 4> d_ds{}, d_dt{}, d_dr{};
};
void sample(const Texture& tex, const Lookup& lookup);

// The plain lookup, the kind most shaders make (single_texture's, the halftone's four): a 2D
// texture whose sampler needs no level of detail (one level, min == mag) and mirrors no axis,
// read with no derivatives carried and no explicit level. `sample` takes it for such a Lookup;
// this entry takes any number of lanes in one call and no descriptor beyond the arrays, since
// for a lookup this cheap the call itself and filling a Lookup were most of the cost. Returns
// false, writing nothing, for a texture whose lookups are not plain ones.
struct PlainLookup {
    int lanes;  // any number
    const float* s;
    const float* t;
    std::array<float*, 4> rgba;  // out
};
bool sample_plain(const Texture& tex, const PlainLookup& lookup);

// texelFetch's lanes: integer texel coordinates and level, no filter and no wrap; a lane outside
// the level, or a level outside the texture's, reads (0, 0, 0, 0) as on llvmpipe.
struct Fetch {
    int lanes = 0;
    const std::int32_t *x = nullptr, *y = nullptr, *z = nullptr, *level = nullptr;  // z: 3D only
    std::array<float*, 4> rgba{};
};
void fetch(const Texture& tex, const Fetch& fetch);

enum class Lod { Implicit, Bias, Explicit, Gradient };

// What a lookup takes beside its coordinates, as `kind` says: a bias or an explicit level
// (`lod_or_bias`), or the coordinates' explicit derivatives along x and y (`ddx`, `ddy`:
// textureGrad); GLSL's texel offsets, or none; a shadow lookup's reference value, or none.
template <Number F, std::size_t Dims>
struct LookupArgs {
    Lod kind = Lod::Implicit;
    const F* lod_or_bias = nullptr;
    const std::array<F, Dims>* ddx = nullptr;
    const std::array<F, Dims>* ddy = nullptr;
    const std::array<int_t<F>, Dims>* offset = nullptr;
    const F* ref = nullptr;
};

// llvmpipe's rho^2 from explicit derivatives (lp_build_rho with derivatives), lane by lane:
// max((W ddx.s)^2 + (H ddx.t)^2 [+ (D ddx.r)^2], the same of ddy) in float, in that order, with
// an infinite or NaN result taken as 0. One per pixel, in a fragment shader too (measured on
// llvmpipe 22.3: derivatives that differ within a quad give each pixel its own level).
template <std::size_t Dims, int N>
void gradient_rho2(const float (&ddx)[3][N], const float (&ddy)[3][N], const std::array<float, 3>& size, float (&rho2)[N]) {
    for (int i = 0; i < N; ++i) {
        float x = 0.0f, y = 0.0f;
        for (std::size_t k = 0; k < Dims; ++k) {
            float a = size[k] * ddx[k][i], b = size[k] * ddy[k][i];
            a = a * a, b = b * b;
            x = k == 0 ? a : x + a;
            y = k == 0 ? b : y + b;
        }
        const float r = x > y ? x : y;
        rho2[i] = std::isfinite(r) ? r : 0.0f;
    }
}

// Every lookup: Dims coordinates, and what `args` adds to them.
template <Number F, std::size_t Dims>
vec4<F> lookup(const Texture& tex, const std::array<F, Dims>& coord, const LookupArgs<F, Dims>& args) {
    using Traits = sampler_traits<F>;
    constexpr int N = lanes_of<F>();
    alignas(64) float c[3][N], rho2[N], extra[N], ref[N], rgba[4][N], d_dc[3][4][N];
    alignas(64) std::int32_t offset[3][N];
    const Lod kind = args.kind;
    for (std::size_t k = 0; k < Dims; ++k) to_floats(coord[k], c[k]);
    if (kind == Lod::Bias || kind == Lod::Explicit) to_floats(*args.lod_or_bias, extra);
    if (args.ref) to_floats(*args.ref, ref);
    if (args.offset) {
        for (std::size_t k = 0; k < Dims; ++k) to_ints((*args.offset)[k], offset[k]);
    }
    const bool implicit = kind != Lod::Explicit && tex.needs_lod();
    const std::array<float, 3> size{float(tex.width), float(tex.height), float(tex.depth)};
    LaneCases lod_cases;  // the quad's lanes a Checked level of detail read
    if (implicit && kind == Lod::Gradient) {
        alignas(64) float gx[3][N], gy[3][N];
        for (std::size_t k = 0; k < Dims; ++k) to_floats((*args.ddx)[k], gx[k]), to_floats((*args.ddy)[k], gy[k]);
        gradient_rho2<Dims>(gx, gy, size, rho2);
    } else if (implicit) {
        Traits::implicit_rho2(coord, size, rho2, lod_cases);
    }
    // Dual2 carries the interpolant's derivatives, which the plain lookup does not give; a
    // comparison's result is a step of it, whose derivatives are 0.
    const bool derivatives = Traits::carries_partials && !args.ref;
    const bool plain = Dims == 2 && !Traits::carries_partials && kind != Lod::Explicit && !implicit && !args.offset &&
                       !args.ref && sample_plain(tex, {N, c[0], c[1], {rgba[0], rgba[1], rgba[2], rgba[3]}});
    for (int i = 0; !plain && i < N; i += kMaxLanes) {
        Lookup l;
        l.lanes = N - i < kMaxLanes ? N - i : kMaxLanes;
        l.s = c[0] + i, l.t = c[1] + i;
        if (Dims == 3) l.r = c[2] + i;
        l.rho2 = implicit ? rho2 + i : nullptr;
        l.bias = kind == Lod::Bias ? extra + i : nullptr;
        l.lod = kind == Lod::Explicit ? extra + i : nullptr;
        l.rho2_per_pixel = kind == Lod::Gradient;
        if (args.offset) {
            for (std::size_t k = 0; k < Dims; ++k) l.offset[k] = offset[k] + i;
        }
        l.quad_vectors = QuadNumber<F>;
        l.ref = args.ref ? ref + i : nullptr;
        for (std::size_t ch = 0; ch < 4; ++ch) {
            l.rgba[ch] = rgba[ch] + i;
            if (derivatives) {
                l.d_ds[ch] = d_dc[0][ch] + i, l.d_dt[ch] = d_dc[1][ch] + i;
                if (Dims == 3) l.d_dr[ch] = d_dc[2][ch] + i;
            }
        }
        sample(tex, l);
    }
    LaneCases cases = lod_cases;
    std::array<typename Traits::Partials, Dims> dcoord;
    for (std::size_t k = 0; k < Dims; ++k) cases = cases | cases_of(coord[k]), dcoord[k] = Traits::partials(coord[k]);
    if (kind == Lod::Bias || kind == Lod::Explicit) cases = cases | cases_of(*args.lod_or_bias);
    if (kind == Lod::Gradient) {
        for (std::size_t k = 0; k < Dims; ++k) cases = cases | cases_of((*args.ddx)[k]) | cases_of((*args.ddy)[k]);
    }
    if (args.offset) {
        for (std::size_t k = 0; k < Dims; ++k) cases = cases | cases_of((*args.offset)[k]);
    }
    if (args.ref) cases = cases | cases_of(*args.ref);
    vec4<F> out;
    for (int ch = 0; ch < 4; ++ch) {
        if (args.ref) {
            out[ch] = Traits::constant(rgba[ch], cases);
            continue;
        }
        std::array<const float*, Dims> d_dcoord;
        for (std::size_t k = 0; k < Dims; ++k) d_dcoord[k] = d_dc[k][ch];
        out[ch] = Traits::sampled(rgba[ch], d_dcoord, dcoord, cases);
    }
    return out;
}

// textureSize of every lane's level. GLSL leaves a level outside the texture's undefined:
// Checked numbers flag it as Argument.
template <Number F, std::size_t Dims>
std::array<int_t<F>, Dims> size_query(const Texture& tex, const int_t<F>& lod) {
    constexpr int N = lanes_of<F>();
    alignas(64) std::int32_t level[N], size[3][N];
    to_ints(lod, level);
    std::uint32_t outside = 0;
    for (int i = 0; i < N; ++i) {
        const std::array<int, 3> s = tex.size(level[i]);
        for (std::size_t k = 0; k < Dims; ++k) size[k][i] = s[k];
        if (level[i] < 0 || level[i] >= int(tex.levels.size())) outside |= 1u << i;
    }
    const LaneCases cases = cases_of(lod) | LaneCases::on(outside, Undefined::Argument);
    std::array<int_t<F>, Dims> out;
    for (std::size_t k = 0; k < Dims; ++k) out[k] = from_ints<int_t<F>>(size[k], cases);
    return out;
}

// texelFetch of every lane's texel: (0, 0, 0, 0) outside the level or the levels, which GLSL
// leaves undefined and Checked numbers flag as Argument. The texels are constants: under Dual2
// their derivatives are 0.
template <Number F, std::size_t Dims>
vec4<F> texel_fetch(const Texture& tex, const std::array<int_t<F>, Dims>& p, const int_t<F>& lod) {
    constexpr int N = lanes_of<F>();
    alignas(64) std::int32_t c[3][N], level[N];
    alignas(64) float rgba[4][N];
    for (std::size_t k = 0; k < Dims; ++k) to_ints(p[k], c[k]);
    to_ints(lod, level);
    Fetch f;
    f.lanes = N;
    f.x = c[0], f.y = c[1], f.z = Dims == 3 ? c[2] : nullptr, f.level = level;
    for (std::size_t ch = 0; ch < 4; ++ch) f.rgba[ch] = rgba[ch];
    fetch(tex, f);
    const LaneCases outside = sampler_traits<F>::flag(Undefined::Argument, [&] {
        std::uint32_t lanes = 0;
        for (int i = 0; i < N; ++i) {
            const std::array<int, 3> s = tex.size(level[i]);
            bool in = s[0] > 0;
            for (std::size_t k = 0; k < Dims; ++k) in = in && c[k][i] >= 0 && c[k][i] < s[k];
            if (!in) lanes |= 1u << i;
        }
        return lanes;
    });
    LaneCases cases = cases_of(lod) | outside;
    for (std::size_t k = 0; k < Dims; ++k) cases = cases | cases_of(p[k]);
    vec4<F> out;
    for (int ch = 0; ch < 4; ++ch) out[ch] = constant_lanes<F>(rgba[ch], cases);
    return out;
}

}  // namespace texture_detail

namespace texture_detail {

template <Number F>
std::array<F, 2> coords(const vec2<F>& p) { return {p.x, p.y}; }
template <Number F>
std::array<F, 3> coords(const vec3<F>& p) { return {p.x, p.y, p.z}; }
template <Number F>
std::array<int_t<F>, 2> coords(const ivec2<F>& p) { return {p.x, p.y}; }
template <Number F>
std::array<int_t<F>, 3> coords(const ivec3<F>& p) { return {p.x, p.y, p.z}; }

template <Number F, std::size_t Dims>
vec4<F> implicit(const Texture& tex, const std::array<F, Dims>& p, const std::array<int_t<F>, Dims>* offset = nullptr) {
    return lookup<F, Dims>(tex, p, {Lod::Implicit, nullptr, nullptr, nullptr, offset});
}
template <Number F, std::size_t Dims>
vec4<F> biased(const Texture& tex, const std::array<F, Dims>& p, const F& bias,
               const std::array<int_t<F>, Dims>* offset = nullptr) {
    return lookup<F, Dims>(tex, p, {Lod::Bias, &bias, nullptr, nullptr, offset});
}
template <Number F, std::size_t Dims>
vec4<F> at_level(const Texture& tex, const std::array<F, Dims>& p, const F& lod,
                 const std::array<int_t<F>, Dims>* offset = nullptr) {
    return lookup<F, Dims>(tex, p, {Lod::Explicit, &lod, nullptr, nullptr, offset});
}
template <Number F, std::size_t Dims>
vec4<F> gradient(const Texture& tex, const std::array<F, Dims>& p, const std::array<F, Dims>& ddx,
                 const std::array<F, Dims>& ddy, const std::array<int_t<F>, Dims>* offset = nullptr) {
    return lookup<F, Dims>(tex, p, {Lod::Gradient, nullptr, &ddx, &ddy, offset});
}

// A projective lookup's coordinates: the first ones times the reciprocal of the last, as Mesa
// lowers them (nir_lower_tex's projector: a reciprocal and products, not quotients).
template <Number F>
std::array<F, 2> projected2(const vec3<F>& p) {
    const F q = F(1.0f) / p.z;
    return {p.x * q, p.y * q};
}
template <Number F>
std::array<F, 2> projected2(const vec4<F>& p) {
    const F q = F(1.0f) / p.w;
    return {p.x * q, p.y * q};
}
template <Number F>
std::array<F, 3> projected3(const vec4<F>& p) {
    const F q = F(1.0f) / p.w;
    return {p.x * q, p.y * q, p.z * q};
}

}  // namespace texture_detail

// A 2D projective lookup's coordinates: a vec3 or a vec4.
template <class P>
concept ProjCoords2 = std::same_as<P, vec3<typename P::value_type>> || std::same_as<P, vec4<typename P::value_type>>;

// GLSL 1.20's lookups with the level of detail from the quad (implicit), and with a bias added
// to it.
template <Number F>
vec4<F> texture2D(const sampler2D& tex, const vec2<F>& st) {
    return texture_detail::implicit<F, 2>(tex, texture_detail::coords(st));
}
template <Number F>
vec4<F> texture2D(const sampler2D& tex, const vec2<F>& st, const F& bias) {
    return texture_detail::biased<F, 2>(tex, texture_detail::coords(st), bias);
}
template <Number F>
vec4<F> texture3D(const sampler3D& tex, const vec3<F>& str) {
    return texture_detail::implicit<F, 3>(tex, texture_detail::coords(str));
}
template <Number F>
vec4<F> texture3D(const sampler3D& tex, const vec3<F>& str, const F& bias) {
    return texture_detail::biased<F, 3>(tex, texture_detail::coords(str), bias);
}
// GLSL 1.30's overloaded names.
template <Number F>
vec4<F> texture(const sampler2D& tex, const vec2<F>& st) { return texture2D(tex, st); }
template <Number F>
vec4<F> texture(const sampler2D& tex, const vec2<F>& st, const F& bias) { return texture2D(tex, st, bias); }
template <Number F>
vec4<F> texture(const sampler3D& tex, const vec3<F>& str) { return texture3D(tex, str); }
template <Number F>
vec4<F> texture(const sampler3D& tex, const vec3<F>& str, const F& bias) { return texture3D(tex, str, bias); }

// An explicit level of detail per pixel (GLSL 1.30, and texture2DLod of
// GL_ARB_shader_texture_lod, which llvmpipe compiles to the same bits).
template <Number F>
vec4<F> textureLod(const sampler2D& tex, const vec2<F>& st, const F& lod) {
    return texture_detail::at_level<F, 2>(tex, texture_detail::coords(st), lod);
}
template <Number F>
vec4<F> textureLod(const sampler3D& tex, const vec3<F>& str, const F& lod) {
    return texture_detail::at_level<F, 3>(tex, texture_detail::coords(str), lod);
}
template <Number F>
vec4<F> texture2DLod(const sampler2D& tex, const vec2<F>& st, const F& lod) { return textureLod(tex, st, lod); }
template <Number F>
vec4<F> texture3DLod(const sampler3D& tex, const vec3<F>& str, const F& lod) { return textureLod(tex, str, lod); }

// The level of detail from explicit derivatives of the coordinates along x and y (GLSL 1.30's
// textureGrad, and texture2DGradARB): llvmpipe's, one per pixel from its own derivatives, so
// any number type takes it, quads or not.
template <Number F>
vec4<F> textureGrad(const sampler2D& tex, const vec2<F>& st, const vec2<F>& dPdx, const vec2<F>& dPdy) {
    return texture_detail::gradient<F, 2>(tex, texture_detail::coords(st), texture_detail::coords(dPdx),
                                          texture_detail::coords(dPdy));
}
template <Number F>
vec4<F> textureGrad(const sampler3D& tex, const vec3<F>& str, const vec3<F>& dPdx, const vec3<F>& dPdy) {
    return texture_detail::gradient<F, 3>(tex, texture_detail::coords(str), texture_detail::coords(dPdx),
                                          texture_detail::coords(dPdy));
}

// Projective lookups: the coordinates divided by the last component (a vec3 or vec4 for a 2D
// texture, a vec4 for a 3D one).
template <ProjCoords2 P, Number F = typename P::value_type>
vec4<F> textureProj(const sampler2D& tex, const P& p) {
    return texture_detail::implicit<F, 2>(tex, texture_detail::projected2(p));
}
template <ProjCoords2 P, Number F = typename P::value_type>
vec4<F> textureProj(const sampler2D& tex, const P& p, const F& bias) {
    return texture_detail::biased<F, 2>(tex, texture_detail::projected2(p), bias);
}
template <Number F>
vec4<F> textureProj(const sampler3D& tex, const vec4<F>& p) {
    return texture_detail::implicit<F, 3>(tex, texture_detail::projected3(p));
}
template <Number F>
vec4<F> textureProj(const sampler3D& tex, const vec4<F>& p, const F& bias) {
    return texture_detail::biased<F, 3>(tex, texture_detail::projected3(p), bias);
}
template <ProjCoords2 P, Number F = typename P::value_type>
vec4<F> textureProjLod(const sampler2D& tex, const P& p, const F& lod) {
    return texture_detail::at_level<F, 2>(tex, texture_detail::projected2(p), lod);
}
template <Number F>
vec4<F> textureProjLod(const sampler3D& tex, const vec4<F>& p, const F& lod) {
    return texture_detail::at_level<F, 3>(tex, texture_detail::projected3(p), lod);
}
template <ProjCoords2 P, Number F = typename P::value_type>
vec4<F> textureProjGrad(const sampler2D& tex, const P& p, const vec2<F>& dPdx, const vec2<F>& dPdy) {
    return texture_detail::gradient<F, 2>(tex, texture_detail::projected2(p), texture_detail::coords(dPdx),
                                          texture_detail::coords(dPdy));
}
template <Number F>
vec4<F> textureProjGrad(const sampler3D& tex, const vec4<F>& p, const vec3<F>& dPdx, const vec3<F>& dPdy) {
    return texture_detail::gradient<F, 3>(tex, texture_detail::projected3(p), texture_detail::coords(dPdx),
                                          texture_detail::coords(dPdy));
}
// GLSL 1.20's names of the projective lookups.
template <ProjCoords2 P, Number F = typename P::value_type>
vec4<F> texture2DProj(const sampler2D& tex, const P& p) { return textureProj(tex, p); }
template <ProjCoords2 P, Number F = typename P::value_type>
vec4<F> texture2DProj(const sampler2D& tex, const P& p, const F& bias) { return textureProj(tex, p, bias); }
template <ProjCoords2 P, Number F = typename P::value_type>
vec4<F> texture2DProjLod(const sampler2D& tex, const P& p, const F& lod) { return textureProjLod(tex, p, lod); }
template <Number F>
vec4<F> texture3DProj(const sampler3D& tex, const vec4<F>& p) { return textureProj(tex, p); }
template <Number F>
vec4<F> texture3DProj(const sampler3D& tex, const vec4<F>& p, const F& bias) { return textureProj(tex, p, bias); }
template <Number F>
vec4<F> texture3DProjLod(const sampler3D& tex, const vec4<F>& p, const F& lod) { return textureProjLod(tex, p, lod); }

// Constant texel offsets (GLSL 1.30): added to the texel coordinates at whichever level is read,
// before the wrap, as llvmpipe adds them (to the unnormalised coordinate; to the normalised one,
// divided by the level's size, for REPEAT on a size that is not a power of two and for
// MIRRORED_REPEAT).
template <Number F>
vec4<F> textureOffset(const sampler2D& tex, const vec2<F>& st, const ivec2<F>& offset) {
    const auto o = texture_detail::coords<F>(offset);
    return texture_detail::implicit<F, 2>(tex, texture_detail::coords(st), &o);
}
template <Number F>
vec4<F> textureOffset(const sampler2D& tex, const vec2<F>& st, const ivec2<F>& offset, const F& bias) {
    const auto o = texture_detail::coords<F>(offset);
    return texture_detail::biased<F, 2>(tex, texture_detail::coords(st), bias, &o);
}
template <Number F>
vec4<F> textureOffset(const sampler3D& tex, const vec3<F>& str, const ivec3<F>& offset) {
    const auto o = texture_detail::coords<F>(offset);
    return texture_detail::implicit<F, 3>(tex, texture_detail::coords(str), &o);
}
template <Number F>
vec4<F> textureOffset(const sampler3D& tex, const vec3<F>& str, const ivec3<F>& offset, const F& bias) {
    const auto o = texture_detail::coords<F>(offset);
    return texture_detail::biased<F, 3>(tex, texture_detail::coords(str), bias, &o);
}
template <Number F>
vec4<F> textureLodOffset(const sampler2D& tex, const vec2<F>& st, const F& lod, const ivec2<F>& offset) {
    const auto o = texture_detail::coords<F>(offset);
    return texture_detail::at_level<F, 2>(tex, texture_detail::coords(st), lod, &o);
}
template <Number F>
vec4<F> textureLodOffset(const sampler3D& tex, const vec3<F>& str, const F& lod, const ivec3<F>& offset) {
    const auto o = texture_detail::coords<F>(offset);
    return texture_detail::at_level<F, 3>(tex, texture_detail::coords(str), lod, &o);
}
template <Number F>
vec4<F> textureGradOffset(const sampler2D& tex, const vec2<F>& st, const vec2<F>& dPdx, const vec2<F>& dPdy,
                          const ivec2<F>& offset) {
    const auto o = texture_detail::coords<F>(offset);
    return texture_detail::gradient<F, 2>(tex, texture_detail::coords(st), texture_detail::coords(dPdx),
                                          texture_detail::coords(dPdy), &o);
}
template <Number F>
vec4<F> textureGradOffset(const sampler3D& tex, const vec3<F>& str, const vec3<F>& dPdx, const vec3<F>& dPdy,
                          const ivec3<F>& offset) {
    const auto o = texture_detail::coords<F>(offset);
    return texture_detail::gradient<F, 3>(tex, texture_detail::coords(str), texture_detail::coords(dPdx),
                                          texture_detail::coords(dPdy), &o);
}
template <ProjCoords2 P, Number F = typename P::value_type>
vec4<F> textureProjOffset(const sampler2D& tex, const P& p, const ivec2<F>& offset) {
    const auto o = texture_detail::coords<F>(offset);
    return texture_detail::implicit<F, 2>(tex, texture_detail::projected2(p), &o);
}
template <ProjCoords2 P, Number F = typename P::value_type>
vec4<F> textureProjOffset(const sampler2D& tex, const P& p, const ivec2<F>& offset, const F& bias) {
    const auto o = texture_detail::coords<F>(offset);
    return texture_detail::biased<F, 2>(tex, texture_detail::projected2(p), bias, &o);
}
template <Number F>
vec4<F> textureProjOffset(const sampler3D& tex, const vec4<F>& p, const ivec3<F>& offset) {
    const auto o = texture_detail::coords<F>(offset);
    return texture_detail::implicit<F, 3>(tex, texture_detail::projected3(p), &o);
}
template <Number F>
vec4<F> textureProjOffset(const sampler3D& tex, const vec4<F>& p, const ivec3<F>& offset, const F& bias) {
    const auto o = texture_detail::coords<F>(offset);
    return texture_detail::biased<F, 3>(tex, texture_detail::projected3(p), bias, &o);
}
template <ProjCoords2 P, Number F = typename P::value_type>
vec4<F> textureProjLodOffset(const sampler2D& tex, const P& p, const F& lod, const ivec2<F>& offset) {
    const auto o = texture_detail::coords<F>(offset);
    return texture_detail::at_level<F, 2>(tex, texture_detail::projected2(p), lod, &o);
}
template <Number F>
vec4<F> textureProjLodOffset(const sampler3D& tex, const vec4<F>& p, const F& lod, const ivec3<F>& offset) {
    const auto o = texture_detail::coords<F>(offset);
    return texture_detail::at_level<F, 3>(tex, texture_detail::projected3(p), lod, &o);
}
template <ProjCoords2 P, Number F = typename P::value_type>
vec4<F> textureProjGradOffset(const sampler2D& tex, const P& p, const vec2<F>& dPdx, const vec2<F>& dPdy,
                              const ivec2<F>& offset) {
    const auto o = texture_detail::coords<F>(offset);
    return texture_detail::gradient<F, 2>(tex, texture_detail::projected2(p), texture_detail::coords(dPdx),
                                          texture_detail::coords(dPdy), &o);
}
template <Number F>
vec4<F> textureProjGradOffset(const sampler3D& tex, const vec4<F>& p, const vec3<F>& dPdx, const vec3<F>& dPdy,
                              const ivec3<F>& offset) {
    const auto o = texture_detail::coords<F>(offset);
    return texture_detail::gradient<F, 3>(tex, texture_detail::projected3(p), texture_detail::coords(dPdx),
                                          texture_detail::coords(dPdy), &o);
}

// GLSL 1.30's size query and unfiltered fetch, with the integer level per fragment. Their
// arguments are integers, so the float type is named: textureSize<F>(teximage, 0),
// texelFetch<F>(teximage, ivec2<F>(p), level), texelFetchOffset<F>(teximage, p, level, offset).
template <Number F>
ivec2<F> textureSize(const sampler2D& tex, const int_t<F>& lod) {
    const auto s = texture_detail::size_query<F, 2>(tex, lod);
    return ivec2<F>(s[0], s[1]);
}
template <Number F>
ivec3<F> textureSize(const sampler3D& tex, const int_t<F>& lod) {
    const auto s = texture_detail::size_query<F, 3>(tex, lod);
    return ivec3<F>(s[0], s[1], s[2]);
}
template <Number F>
vec4<F> texelFetch(const sampler2D& tex, const ivec2<F>& p, const int_t<F>& lod) {
    return texture_detail::texel_fetch<F, 2>(tex, texture_detail::coords<F>(p), lod);
}
template <Number F>
vec4<F> texelFetch(const sampler3D& tex, const ivec3<F>& p, const int_t<F>& lod) {
    return texture_detail::texel_fetch<F, 3>(tex, texture_detail::coords<F>(p), lod);
}
// The offset is added to the texel coordinates before the fetch, which reads (0, 0, 0, 0) outside
// the level as texelFetch does (llvmpipe's lp_build_fetch_texel).
template <Number F>
vec4<F> texelFetchOffset(const sampler2D& tex, const ivec2<F>& p, const int_t<F>& lod, const ivec2<F>& offset) {
    return texelFetch<F>(tex, p + offset, lod);
}
template <Number F>
vec4<F> texelFetchOffset(const sampler3D& tex, const ivec3<F>& p, const int_t<F>& lod, const ivec3<F>& offset) {
    return texelFetch<F>(tex, p + offset, lod);
}

}  // namespace qs::glsl
