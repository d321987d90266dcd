#pragma once
// sampler2D and texture2D as Mesa's llvmpipe samples a GL_RGBA8 2D texture, to the bit: wrap
// modes (REPEAT, MIRRORED_REPEAT, CLAMP_TO_EDGE), filters (NEAREST, LINEAR and the four
// mipmapped minification filters), one level of detail per 2x2 quad from the quad's
// derivatives, and mipmaps made as glGenerateMipmap makes them. Texels are 8-bit; loading them
// from an image file is the renderer's job (render/), which also makes sure a texture that
// needs a level of detail is sampled from quads.
//
// The arithmetic, and the OSMesa experiments that pinned it, are in docs/design.md ("Textures");
// the lanes' work is done by texture_detail::sample (texture.cpp), vectorised over a batch: texel
// fetches are gathers, four per lane for a bilinear level.
//
// texture2D is written over the number type like any shader code. Per-pixel types (float,
// double, Pixels) have no neighbours: they can only sample a texture that needs no level of
// detail. Quads compute it per quad, as llvmpipe does; Dual2 from its carried partials, and its
// result carries the exact derivative of the filter's interpolant (texels are constants).

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
    Wrap wrap_s = Wrap::ClampToEdge, wrap_t = Wrap::ClampToEdge;
    Filter mag = Filter::Linear, min = Filter::Linear;
    MipFilter mip = MipFilter::None;  // the minification filter's mipmap part
};

// A GL_RGBA8 2D texture with its sampler. Texel (x, y) of a level is at
// texels[level.offset + y * level.width + x], red in the lowest byte; row 0 is t = 0, which glTF
// makes the image's first (top) row.
struct sampler2D {
    struct Level {
        std::int32_t width, height, offset;  // three ints: lookups gather a lane's offset from them
    };
    int width = 0, height = 0;  // the base level's size (GLSL 1.30's textureSize(s, 0))
    SamplerState sampler;
    std::vector<Level> levels;
    std::vector<std::uint32_t> texels;

    sampler2D() = default;
    // The base level from `rgba` (4 bytes per texel, rows from t = 0), and the levels below it
    // down to 1x1 when the sampler's minification filter reads mipmaps, each made from the one
    // above as llvmpipe's glGenerateMipmap makes it. Throws std::invalid_argument for a size
    // outside 1..32768.
    sampler2D(int width, int height, const std::uint8_t* rgba, SamplerState sampler);

    // Whether a lookup needs the level of detail, i.e. derivatives of its coordinates: to pick
    // a mipmap level, or to choose between different minification and magnification filters.
    bool needs_lod() const { return sampler.mip != MipFilter::None || sampler.min != sampler.mag; }
};

namespace texture_detail {

inline constexpr int kMaxLanes = 16;

// One call's lanes, structure of arrays.
struct Lookup {
    int lanes = 0;  // 1..kMaxLanes
    const float* s = nullptr;
    const float* t = nullptr;
    // Per lane, llvmpipe's squared scale factor rho^2 = max((W ds/dx)^2 + (H dt/dx)^2,
    // (W ds/dy)^2 + (H dt/dy)^2) (W, H: the base level's size); required when the texture
    // needs_lod().
    const float* rho2 = nullptr;
    // Lanes 8k..8k+7 are the two side-by-side quads llvmpipe shades as one vector (quads from a
    // 4x4 block); otherwise each lane stands alone. Decides how MIRRORED_REPEAT with different
    // minification and magnification filters blends (llvmpipe decides that per vector).
    bool quad_vectors = false;
    std::array<float*, 4> rgba{};  // out
    // Out when set (Dual2): the derivative of the colour along s and t of the filter's
    // interpolant; zero for nearest filtering.
    std::array<float*, 4> d_ds{}, d_dt{};
};
void sample(const sampler2D& tex, const Lookup& lookup);

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
// order, no fused multiply-adds; max as maxps.
template <QuadNumber V>
V quad_rho2(const V& s, const V& t, float width, float height) {
    constexpr auto tl = [](std::size_t i) { return (i & ~std::size_t(3)) | 2; };
    constexpr auto tr = [](std::size_t i) { return (i & ~std::size_t(3)) | 3; };
    constexpr auto bl = [](std::size_t i) { return i & ~std::size_t(3); };
    const V s_tl = s.permute(tl), t_tl = t.permute(tl);
    V a = V(width) * (s.permute(tr) - s_tl), b = V(width) * (s.permute(bl) - s_tl);
    V c = V(height) * (t.permute(tr) - t_tl), d = V(height) * (t.permute(bl) - t_tl);
    a = a * a, b = b * b, c = c * c, d = d * d;
    const V x = a + c, y = b + d;
    return select(x > y, x, y);
}

// The float lanes of F's layout, for the level of detail (llvmpipe computes it in float).
template <class F>
struct float_lanes { using type = F; };
template <class T, int N, class L>
struct float_lanes<Lanes<T, N, L>> { using type = Lanes<float, N, L>; };

}  // namespace texture_detail

template <Number F>
vec4<F> texture2D(const sampler2D& tex, const vec2<F>& st) {
    using namespace texture_detail;
    constexpr int N = lanes_of<F>();
    alignas(64) float s[N], t[N], rho2[N], rgba[4][N], d_ds[4][N], d_dt[4][N];
    to_floats(st.x, s);
    to_floats(st.y, t);
    const bool lod = tex.needs_lod();
    [[maybe_unused]] LaneCases lod_cases;  // the quad's lanes a Checked level of detail read
    if (lod) {
        if constexpr (is_dual2<F>::value) {
            // The analytic scale factor from the carried partials, in llvmpipe's formula.
            using T = typename F::value_type;
            const T w(float(tex.width)), h(float(tex.height));
            T a = w * st.x.dx, b = w * st.x.dy, c = h * st.y.dx, d = h * st.y.dy;
            a = a * a, b = b * b, c = c * c, d = d * d;
            const T x = a + c, y = b + d;
            to_floats(T(select(x > y, x, y)), rho2);
        } else if constexpr (QuadNumber<F>) {
            using V = typename float_lanes<F>::type;
            if constexpr (std::is_same_v<V, F>) {
                const F r = quad_rho2(st.x, st.y, float(tex.width), float(tex.height));
                to_floats(r, rho2);
                if constexpr (is_checked_v<F>) lod_cases = r.cases;
            } else {
                to_floats(quad_rho2(from_floats<V>(s), from_floats<V>(t), float(tex.width), float(tex.height)), rho2);
            }
        } else {
            throw_lod_without_quads();
        }
    }
    constexpr bool derivatives = is_dual2<F>::value;
    for (int i = 0; i < N; i += kMaxLanes) {
        Lookup l;
        l.lanes = N - i < kMaxLanes ? N - i : kMaxLanes;
        l.s = s + i, l.t = t + i, l.rho2 = lod ? rho2 + i : nullptr;
        l.quad_vectors = QuadNumber<F>;
        for (int c = 0; c < 4; ++c) {
            l.rgba[std::size_t(c)] = rgba[c] + i;
            if (derivatives) l.d_ds[std::size_t(c)] = d_ds[c] + i, l.d_dt[std::size_t(c)] = d_dt[c] + i;
        }
        sample(tex, l);
    }
    vec4<F> out;
    for (int c = 0; c < 4; ++c) {
        if constexpr (is_dual2<F>::value) {
            // d(colour) = d(colour)/ds ds + d(colour)/dt dt
            using T = typename F::value_type;
            const T cs = from_floats<T>(d_ds[c]), ct = from_floats<T>(d_dt[c]);
            out[c] = F(from_floats<T>(rgba[c]), cs * st.x.dx + ct * st.y.dx, cs * st.x.dy + ct * st.y.dy);
        } else if constexpr (is_checked_v<F>) {
            out[c] = F(from_floats<F>(rgba[c]).v, st.x.cases | st.y.cases | lod_cases);
        } else {
            out[c] = from_floats<F>(rgba[c]);
        }
    }
    return out;
}

}  // namespace qs::glsl
