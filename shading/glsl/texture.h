#pragma once
// sampler2D and sampler3D, and GLSL's lookups in them, as Mesa's llvmpipe samples a GL_RGBA8
// GL_TEXTURE_2D or GL_TEXTURE_3D, to the bit: wrap modes (REPEAT, MIRRORED_REPEAT,
// CLAMP_TO_EDGE), filters (NEAREST, LINEAR and the four mipmapped minification filters), one
// level of detail per 2x2 quad from the quad's derivatives (texture2D, texture3D), a bias or an
// explicit level per pixel (textureLod), and mipmaps made as glGenerateMipmap makes them. Texels
// are 8-bit; loading them from an image file is the renderer's job (render/), which also makes
// sure a texture that needs a level of detail is sampled from quads.
//
// The arithmetic, and the OSMesa experiments that pinned it, are in docs/design.md ("Textures");
// the lanes' work is done by texture_detail::sample, or sample_plain for the plain lookup most
// shaders make (texture.cpp), eight lanes to an AVX2 register (sixteen to an AVX-512 register for
// the plain lookup): texel fetches are gathers, four per register for a bilinear level, eight
// for a trilinear lookup, or loads of neighbouring texels and permutes where the lanes read them.
//
// The lookups are written over the number type like any shader code. Per-pixel types (float,
// double, Pixels) have no neighbours: they can only take an implicit level of detail from a
// texture that needs none (textureLod they can always do). Quads compute it per quad, as
// llvmpipe does; Dual2 from its carried partials, and its result carries the exact derivative of
// the filter's interpolant (texels are constants).

#include <array>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "shading/glsl/vec.h"
#include "shading/number/number.h"

namespace qs::glsl {

enum class Wrap : std::uint8_t { Repeat, MirroredRepeat, ClampToEdge };
enum class Filter : std::uint8_t { Nearest, Linear };
enum class MipFilter : std::uint8_t { None, Nearest, Linear };

struct SamplerState {
    Wrap wrap_s = Wrap::ClampToEdge, wrap_t = Wrap::ClampToEdge, wrap_r = Wrap::ClampToEdge;  // r: 3D only
    Filter mag = Filter::Linear, min = Filter::Linear;
    MipFilter mip = MipFilter::None;  // the minification filter's mipmap part
};

// A GL_RGBA8 texture of two or three dimensions with its sampler: what sampler2D and sampler3D
// share. Texel (x, y, z) of a level is at texels[level.offset + (z * level.height + y) *
// level.width + x], red in the lowest byte; row 0 is t = 0, which glTF makes the image's first
// (top) row, and slice 0 is r = 0.
class Texture {
public:
    struct Level {
        // Four ints: lookups gather a lane's offset from them.
        std::int32_t width, height, depth, offset;
    };
    int dims = 2;
    int width = 0, height = 0, depth = 1;  // the base level's size (textureSize(s, 0))
    SamplerState sampler;
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
    // The base level from `rgba` (4 bytes per texel, rows from t = 0, slices from r = 0), and
    // the levels below it down to 1x1(x1) when the sampler's minification filter reads mipmaps,
    // each made from the one above as llvmpipe's glGenerateMipmap makes it. Throws
    // std::invalid_argument for a size outside 1..32768 (1..2048 for 3D, GL_MAX_3D_TEXTURE_SIZE).
    Texture(int dims, int width, int height, int depth, const std::uint8_t* rgba, SamplerState sampler);
};

struct sampler2D : Texture {
    sampler2D() = default;
    sampler2D(int width, int height, const std::uint8_t* rgba, SamplerState sampler)
        : Texture(2, width, height, 1, rgba, sampler) {}
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

[[noreturn]] void throw_lod_without_quads();

// Values of F as floats, lane by lane, and back.
template <class F>
void to_floats(const F& x, float* out) {
    if constexpr (is_dual2<F>::value) {
        to_floats(x.val, out);
    } else if constexpr (is_checked_v<F>) {
        x.v.store(out);
    } else if constexpr (std::is_floating_point_v<F>) {
        out[0] = float(x);
    } else if constexpr (std::is_same_v<typename F::value_type, float>) {
        x.store(out);
    } else {
        for (int i = 0; i < F::size; ++i) out[i] = float(x[i]);
    }
}
template <class F>
F from_floats(const float* in) {
    if constexpr (std::is_floating_point_v<F>) {
        return F(in[0]);
    } else if constexpr (is_checked_v<F>) {
        return F(decltype(F::v)::load(in), {});
    } else if constexpr (std::is_same_v<typename F::value_type, float>) {
        return F::load(in);
    } else {
        using T = typename F::value_type;
        T wide[F::size];
        for (int i = 0; i < F::size; ++i) wide[i] = T(in[i]);
        return F::load(wide);
    }
}

// llvmpipe's rho^2 of each quad (lp_build_rho, exact and squared), on all four of its lanes:
// coarse differences from the quad's upper-left pixel, TR - TL and BL - TL, where "upper" is
// the upper row in GL window coordinates (llvmpipe's first row in OSMesa's top-down buffer):
// lanes 2 (TL), 3 (TR) and 0 (BL) of number/lanes.h's layout. Float arithmetic in llvmpipe's
// order, no fused multiply-adds: ((W ds)^2 + (H dt)^2) + (D dr)^2 along x and along y; max as
// maxps.
template <QuadNumber V, std::size_t Dims>
V quad_rho2(const std::array<V, Dims>& coord, const std::array<float, 3>& size) {
    constexpr auto tl = [](std::size_t i) { return (i & ~std::size_t(3)) | 2; };
    constexpr auto tr = [](std::size_t i) { return (i & ~std::size_t(3)) | 3; };
    constexpr auto bl = [](std::size_t i) { return i & ~std::size_t(3); };
    V x, y;
    for (std::size_t k = 0; k < Dims; ++k) {
        const V c_tl = coord[k].permute(tl);
        V a = V(size[k]) * (coord[k].permute(tr) - c_tl), b = V(size[k]) * (coord[k].permute(bl) - c_tl);
        a = a * a, b = b * b;
        x = k == 0 ? a : x + a;
        y = k == 0 ? b : y + b;
    }
    return select(x > y, x, y);
}

// The float lanes of F's layout, for the level of detail (llvmpipe computes it in float).
template <class F>
struct float_lanes { using type = F; };
template <class T, int N, class L>
struct float_lanes<Lanes<T, N, L>> { using type = Lanes<float, N, L>; };

enum class Lod { Implicit, Bias, Explicit };

// Every lookup: Dims coordinates, and a bias or an explicit level of detail as `kind` says.
template <Number F, std::size_t Dims>
vec4<F> lookup(const Texture& tex, const std::array<F, Dims>& coord, Lod kind, const F& lod_or_bias) {
    constexpr int N = lanes_of<F>();
    alignas(64) float c[3][N], rho2[N], extra[N], rgba[4][N], d_dc[3][4][N];
    for (std::size_t k = 0; k < Dims; ++k) to_floats(coord[k], c[k]);
    if (kind != Lod::Implicit) to_floats(lod_or_bias, extra);
    const bool implicit = kind != Lod::Explicit && tex.needs_lod();
    const std::array<float, 3> size{float(tex.width), float(tex.height), float(tex.depth)};
    [[maybe_unused]] LaneCases lod_cases;  // the quad's lanes a Checked level of detail read
    if (implicit) {
        if constexpr (is_dual2<F>::value) {
            // The analytic scale factor from the carried partials, in llvmpipe's formula.
            using T = typename F::value_type;
            T x, y;
            for (std::size_t k = 0; k < Dims; ++k) {
                const T w(size[k]);
                T a = w * coord[k].dx, b = w * coord[k].dy;
                a = a * a, b = b * b;
                x = k == 0 ? a : x + a;
                y = k == 0 ? b : y + b;
            }
            to_floats(T(select(x > y, x, y)), rho2);
        } else if constexpr (QuadNumber<F>) {
            using V = typename float_lanes<F>::type;
            if constexpr (std::is_same_v<V, F>) {
                const F r = quad_rho2(coord, size);
                to_floats(r, rho2);
                if constexpr (is_checked_v<F>) lod_cases = r.cases;
            } else {
                std::array<V, Dims> narrow;
                for (std::size_t k = 0; k < Dims; ++k) narrow[k] = from_floats<V>(c[k]);
                to_floats(quad_rho2(narrow, size), rho2);
            }
        } else {
            throw_lod_without_quads();
        }
    }
    constexpr bool derivatives = is_dual2<F>::value;
    bool plain = false;
    if constexpr (Dims == 2 && !derivatives) {
        plain = kind != Lod::Explicit && !implicit && sample_plain(tex, {N, c[0], c[1], {rgba[0], rgba[1], rgba[2], rgba[3]}});
    }
    for (int i = 0; !plain && i < N; i += kMaxLanes) {
        Lookup l;
        l.lanes = N - i < kMaxLanes ? N - i : kMaxLanes;
        l.s = c[0] + i, l.t = c[1] + i;
        if (Dims == 3) l.r = c[2] + i;
        l.rho2 = implicit ? rho2 + i : nullptr;
        l.bias = kind == Lod::Bias ? extra + i : nullptr;
        l.lod = kind == Lod::Explicit ? extra + i : nullptr;
        l.quad_vectors = QuadNumber<F>;
        for (std::size_t ch = 0; ch < 4; ++ch) {
            l.rgba[ch] = rgba[ch] + i;
            if (derivatives) {
                l.d_ds[ch] = d_dc[0][ch] + i, l.d_dt[ch] = d_dc[1][ch] + i;
                if (Dims == 3) l.d_dr[ch] = d_dc[2][ch] + i;
            }
        }
        sample(tex, l);
    }
    vec4<F> out;
    for (int ch = 0; ch < 4; ++ch) {
        if constexpr (is_dual2<F>::value) {
            // d(colour) = sum over the coordinates of d(colour)/dc dc
            using T = typename F::value_type;
            T dx, dy;
            for (std::size_t k = 0; k < Dims; ++k) {
                const T g = from_floats<T>(d_dc[k][ch]);
                dx = k == 0 ? g * coord[k].dx : dx + g * coord[k].dx;
                dy = k == 0 ? g * coord[k].dy : dy + g * coord[k].dy;
            }
            out[ch] = F(from_floats<T>(rgba[ch]), dx, dy);
        } else if constexpr (is_checked_v<F>) {
            LaneCases cases = lod_cases;
            for (std::size_t k = 0; k < Dims; ++k) cases = cases | coord[k].cases;
            if (kind != Lod::Implicit) cases = cases | lod_or_bias.cases;
            out[ch] = F(from_floats<F>(rgba[ch]).v, cases);
        } else {
            out[ch] = from_floats<F>(rgba[ch]);
        }
    }
    return out;
}

// GLSL ints of the lanes of an integer number type, lane by lane, and back.
template <class I>
void to_ints(const I& x, std::int32_t* out) {
    if constexpr (is_checked_v<I>) {
        x.v.store(out);
    } else {
        x.store(out);
    }
}
template <class I>
I from_ints(const std::int32_t* in, LaneCases cases = {}) {
    if constexpr (is_checked_v<I>) {
        return I(decltype(I::v)::load(in), cases);
    } else {
        return I::load(in);
    }
}
template <class I>
LaneCases cases_of([[maybe_unused]] const I& x) {
    if constexpr (is_checked_v<I>) {
        return x.cases;
    } else {
        return {};
    }
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
    vec4<F> out;
    for (int ch = 0; ch < 4; ++ch) {
        if constexpr (is_dual2<F>::value) {
            using T = typename F::value_type;
            out[ch] = F(from_floats<T>(rgba[ch]), T(0.0f), T(0.0f));
        } else if constexpr (is_checked_v<F>) {
            std::uint32_t outside = 0;
            for (int i = 0; i < N; ++i) {
                const std::array<int, 3> s = tex.size(level[i]);
                bool in = s[0] > 0;
                for (std::size_t k = 0; k < Dims; ++k) in = in && c[k][i] >= 0 && c[k][i] < s[k];
                if (!in) outside |= 1u << i;
            }
            LaneCases cases = cases_of(lod) | LaneCases::on(outside, Undefined::Argument);
            for (std::size_t k = 0; k < Dims; ++k) cases = cases | cases_of(p[k]);
            out[ch] = F(from_floats<F>(rgba[ch]).v, cases);
        } else {
            out[ch] = from_floats<F>(rgba[ch]);
        }
    }
    return out;
}

}  // namespace texture_detail

// GLSL 1.20's lookups with the level of detail from the quad (implicit), and with a bias added
// to it.
template <Number F>
vec4<F> texture2D(const sampler2D& tex, const vec2<F>& st) {
    return texture_detail::lookup<F, 2>(tex, {st.x, st.y}, texture_detail::Lod::Implicit, F(0.0f));
}
template <Number F>
vec4<F> texture2D(const sampler2D& tex, const vec2<F>& st, const F& bias) {
    return texture_detail::lookup<F, 2>(tex, {st.x, st.y}, texture_detail::Lod::Bias, bias);
}
template <Number F>
vec4<F> texture3D(const sampler3D& tex, const vec3<F>& str) {
    return texture_detail::lookup<F, 3>(tex, {str.x, str.y, str.z}, texture_detail::Lod::Implicit, F(0.0f));
}
template <Number F>
vec4<F> texture3D(const sampler3D& tex, const vec3<F>& str, const F& bias) {
    return texture_detail::lookup<F, 3>(tex, {str.x, str.y, str.z}, texture_detail::Lod::Bias, bias);
}
// GLSL 1.30's overloaded names.
template <Number F>
vec4<F> texture(const sampler2D& tex, const vec2<F>& st) { return texture2D(tex, st); }
template <Number F>
vec4<F> texture(const sampler3D& tex, const vec3<F>& str) { return texture3D(tex, str); }

// An explicit level of detail per pixel (GLSL 1.30, and texture2DLod of
// GL_ARB_shader_texture_lod, which llvmpipe compiles to the same bits).
template <Number F>
vec4<F> textureLod(const sampler2D& tex, const vec2<F>& st, const F& lod) {
    return texture_detail::lookup<F, 2>(tex, {st.x, st.y}, texture_detail::Lod::Explicit, lod);
}
template <Number F>
vec4<F> textureLod(const sampler3D& tex, const vec3<F>& str, const F& lod) {
    return texture_detail::lookup<F, 3>(tex, {str.x, str.y, str.z}, texture_detail::Lod::Explicit, lod);
}
template <Number F>
vec4<F> texture2DLod(const sampler2D& tex, const vec2<F>& st, const F& lod) { return textureLod(tex, st, lod); }

// GLSL 1.30's size query and unfiltered fetch, with the integer level per fragment. Their
// arguments are integers, so the float type is named: textureSize<F>(teximage, 0),
// texelFetch<F>(teximage, ivec2<F>(p), level).
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
    return texture_detail::texel_fetch<F, 2>(tex, {p.x, p.y}, lod);
}
template <Number F>
vec4<F> texelFetch(const sampler3D& tex, const ivec3<F>& p, const int_t<F>& lod) {
    return texture_detail::texel_fetch<F, 3>(tex, {p.x, p.y, p.z}, lod);
}
template <Number F>
vec4<F> texture3DLod(const sampler3D& tex, const vec3<F>& str, const F& lod) { return textureLod(tex, str, lod); }

}  // namespace qs::glsl
