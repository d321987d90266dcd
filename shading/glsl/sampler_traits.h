#pragma once
// What the texture lookups need of each number type, in one place: the sampler works on float
// lanes (llvmpipe samples in float whatever the shader's precision), so a lookup converts its
// coordinates to them and its results back; a checked lane's result carries the cases of what it
// read; Dual2 carries the derivative of the filter's interpolant through the chain rule; and the
// implicit level of detail comes from the quad (Quads, Checked Quads) or from Dual2's partials,
// while per-pixel types (float, double, Pixels) have none to give.
//
// sampler_traits<N> says it for each number type N and for its integers (int_t<N>); the lookups
// (texture.h, texture_cube.h, texture_queries.h, texture_shadow.h) are written once over it.

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "shading/number/number.h"

namespace qs::glsl::texture_detail {

[[noreturn]] void throw_lod_without_quads();

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
struct float_lanes {
    using type = F;
};
template <class T, int N, class L>
struct float_lanes<Lanes<T, N, L>> {
    using type = Lanes<float, N, L>;
};

// The lanes of F's quads: upper-left, upper-right, lower-left, lower-right in GL's window (the
// layout quad_rho2 reads).
inline constexpr int quad_tl(int i) { return (i & ~3) | 2; }
inline constexpr int quad_tr(int i) { return (i & ~3) | 3; }
inline constexpr int quad_bl(int i) { return i & ~3; }
inline constexpr int quad_br(int i) { return (i & ~3) | 1; }

template <class N>
struct sampler_traits;

// quad_rho2 of coordinates given as float lanes in F's layout, computed in float lanes.
template <class F, std::size_t Dims>
void quad_rho2_of_floats(const std::array<const float*, Dims>& c, const std::array<float, 3>& size, float* rho2) {
    if constexpr (!QuadNumber<F>) {
        throw_lod_without_quads();
    } else {
        using V = typename float_lanes<F>::type;
        std::array<V, Dims> narrow;
        for (std::size_t k = 0; k < Dims; ++k) narrow[k] = sampler_traits<V>::from_floats(c[k]);
        sampler_traits<V>::to_floats(quad_rho2(narrow, size), rho2);
    }
}

// What the types without carried derivatives share: float, double, Pixels and Quads, and their
// Checked forms (`Self` gives the conversions and the cases). A result is the sampled value; the
// implicit level of detail is the quad's, which per-pixel types cannot take.
template <class F, class Self>
struct lane_sampler_traits {
    static constexpr bool carries_partials = false;
    struct Partials {};  // a coordinate's derivatives as a result carries them: none
    static Partials partials(const F&) { return {}; }
    static Partials partials(const float*, const float*) { return {}; }

    // A value that does not vary with the coordinates (a fetched or gathered texel, a level).
    static F constant(const float* v, LaneCases cases) { return Self::with_cases(Self::from_floats(v), cases); }
    // A filtered colour channel.
    template <std::size_t Dims>
    static F sampled(const float* value, const std::array<const float*, Dims>&, const std::array<Partials, Dims>&,
                     LaneCases cases) {
        return constant(value, cases);
    }

    // The implicit level's squared scale factor per lane; `cases`: the lanes a Checked quad read.
    template <std::size_t Dims>
    static void implicit_rho2(const std::array<F, Dims>& coord, const std::array<float, 3>& size, float* rho2,
                              LaneCases& cases) {
        using V = typename float_lanes<F>::type;
        if constexpr (!QuadNumber<F>) {
            throw_lod_without_quads();
        } else if constexpr (std::is_same_v<V, F>) {
            const F r = quad_rho2(coord, size);
            Self::to_floats(r, rho2);
            cases = Self::cases(r);
        } else {
            alignas(64) float c[Dims][F::size];
            std::array<const float*, Dims> lanes;
            for (std::size_t k = 0; k < Dims; ++k) Self::to_floats(coord[k], c[k]), lanes[k] = c[k];
            quad_rho2_of_floats<F>(lanes, size, rho2);
        }
    }
    // The derivatives of coordinates `c` (float lanes of p) along x and along y, where the lookup
    // computes them itself (lp_build_ddx and lp_build_ddy: along x the difference across the
    // pixel's row of its quad, along y across its column); `cases`: the lanes a Checked quad read.
    template <std::size_t Dims, int N>
    static void coordinate_derivatives(const std::array<F, Dims>& p, const float (&c)[Dims][N], float (&gx)[Dims][N],
                                       float (&gy)[Dims][N], LaneCases& cases) {
        if constexpr (!QuadNumber<F>) {
            throw_lod_without_quads();
        } else {
            for (std::size_t k = 0; k < Dims; ++k) {
                for (int i = 0; i < N; ++i) {
                    const bool upper = (i & 2) != 0, left = (i & 1) == 0;
                    gx[k][i] = upper ? c[k][quad_tr(i)] - c[k][quad_tl(i)] : c[k][quad_br(i)] - c[k][quad_bl(i)];
                    gy[k][i] = left ? c[k][quad_bl(i)] - c[k][quad_tl(i)] : c[k][quad_br(i)] - c[k][quad_tr(i)];
                }
            }
            LaneCases own;
            for (std::size_t k = 0; k < Dims; ++k) own = own | Self::cases(p[k]);
            cases = Self::across_quads(own);
        }
    }
};

// float and double: one pixel.
template <class F>
    requires std::is_floating_point_v<F>
struct sampler_traits<F> : lane_sampler_traits<F, sampler_traits<F>> {
    static void to_floats(const F& x, float* out) { out[0] = float(x); }
    static F from_floats(const float* in) { return F(in[0]); }
    static LaneCases cases(const F&) { return {}; }
    static F with_cases(const F& x, LaneCases) { return x; }
    template <class Lanes>
    static LaneCases flag(Undefined, Lanes) { return {}; }
    static LaneCases across_quads(LaneCases) { return {}; }
};

// Pixels and Quads, of float or double.
template <class T, int N, class L>
struct sampler_traits<Lanes<T, N, L>> : lane_sampler_traits<Lanes<T, N, L>, sampler_traits<Lanes<T, N, L>>> {
    using F = Lanes<T, N, L>;
    static void to_floats(const F& x, float* out) {
        if constexpr (std::is_same_v<T, float>) {
            x.store(out);
        } else {
            for (int i = 0; i < N; ++i) out[i] = float(x[i]);
        }
    }
    static F from_floats(const float* in) {
        if constexpr (std::is_same_v<T, float>) {
            return F::load(in);
        } else {
            T wide[N];
            for (int i = 0; i < N; ++i) wide[i] = T(in[i]);
            return F::load(wide);
        }
    }
    static LaneCases cases(const F&) { return {}; }
    static F with_cases(const F& x, LaneCases) { return x; }
    template <class Lanes>
    static LaneCases flag(Undefined, Lanes) { return {}; }
    static LaneCases across_quads(LaneCases) { return {}; }
};

// The integers of the types above (int_t<F>): lanes of int32, or one.
template <class T, class F>
struct sampler_traits<IntLanes<T, F>> {
    using I = IntLanes<T, F>;
    static void to_ints(const I& x, std::int32_t* out) { x.store(out); }
    static I from_ints(const std::int32_t* in, LaneCases) { return I::load(in); }
    static LaneCases cases(const I&) { return {}; }
};

// Checked lanes (float or integer): the values of L, and per lane the GLSL cases with undefined
// results they depend on (number/checked.h), which every result carries on.
template <class L>
struct sampler_traits<Checked<L>> : lane_sampler_traits<Checked<L>, sampler_traits<Checked<L>>> {
    using C = Checked<L>;
    static void to_floats(const C& x, float* out) { x.v.store(out); }
    static C from_floats(const float* in) { return C(L::load(in), {}); }
    static void to_ints(const C& x, std::int32_t* out) { x.v.store(out); }
    static C from_ints(const std::int32_t* in, LaneCases cases) { return C(L::load(in), cases); }
    static LaneCases cases(const C& x) { return x.cases; }
    static C with_cases(const C& x, LaneCases cases) { return C(x.v, cases); }
    // Case `c` on the lanes that `lanes()` sets (a bit per lane); only checked lanes compute them.
    template <class Lanes>
    static LaneCases flag(Undefined c, Lanes lanes) { return LaneCases::on(lanes(), c); }
    // What a lane computed from its whole quad reads: the cases of the quad's four lanes.
    static LaneCases across_quads(LaneCases own) {
        constexpr int N = C::size;
        const auto at = [](int (*lane)(int)) { return [lane](std::size_t i) { return std::size_t(lane(int(i))); }; };
        return own.permute(at(quad_tl), N) | own.permute(at(quad_tr), N) | own.permute(at(quad_bl), N) |
               own.permute(at(quad_br), N);
    }
};

// Dual2: values converted as its value type's, and d(result)/dx, /dy carried by the chain rule.
template <class T>
struct sampler_traits<Dual2<T>> {
    using F = Dual2<T>;
    using Value = sampler_traits<T>;
    static constexpr bool carries_partials = true;
    struct Partials {
        T dx, dy;
    };
    static Partials partials(const F& x) { return {x.dx, x.dy}; }
    static Partials partials(const float* dx, const float* dy) {
        return {Value::from_floats(dx), Value::from_floats(dy)};
    }

    static void to_floats(const F& x, float* out) { Value::to_floats(x.val, out); }
    static LaneCases cases(const F&) { return {}; }
    template <class Lanes>
    static LaneCases flag(Undefined, Lanes) { return {}; }
    static LaneCases across_quads(LaneCases) { return {}; }

    // Constant over the pixel's neighbourhood: no derivatives.
    static F constant(const float* v, LaneCases) { return F(Value::from_floats(v), T(0.0f), T(0.0f)); }
    // The filtered channel `value`, with d(channel) = sum over the coordinates of
    // d(channel)/d(coord[k]) (`d_dcoord[k]`, the interpolant's) times d(coord[k]), along x and y.
    template <std::size_t Dims>
    static F sampled(const float* value, const std::array<const float*, Dims>& d_dcoord,
                     const std::array<Partials, Dims>& dcoord, LaneCases) {
        T dx, dy;
        for (std::size_t k = 0; k < Dims; ++k) {
            const T g = Value::from_floats(d_dcoord[k]);
            dx = k == 0 ? g * dcoord[k].dx : dx + g * dcoord[k].dx;
            dy = k == 0 ? g * dcoord[k].dy : dy + g * dcoord[k].dy;
        }
        return F(Value::from_floats(value), dx, dy);
    }

    // The analytic scale factor from the carried partials, in llvmpipe's formula.
    template <std::size_t Dims>
    static void implicit_rho2(const std::array<F, Dims>& coord, const std::array<float, 3>& size, float* rho2,
                              LaneCases&) {
        T x, y;
        for (std::size_t k = 0; k < Dims; ++k) {
            const T w(size[k]);
            T a = w * coord[k].dx, b = w * coord[k].dy;
            a = a * a, b = b * b;
            x = k == 0 ? a : x + a;
            y = k == 0 ? b : y + b;
        }
        Value::to_floats(T(select(x > y, x, y)), rho2);
    }
    // The coordinates' derivatives: the carried partials.
    template <std::size_t Dims, int N>
    static void coordinate_derivatives(const std::array<F, Dims>& p, const float (&)[Dims][N], float (&gx)[Dims][N],
                                       float (&gy)[Dims][N], LaneCases&) {
        for (std::size_t k = 0; k < Dims; ++k) Value::to_floats(p[k].dx, gx[k]), Value::to_floats(p[k].dy, gy[k]);
    }
};

// Values of F as floats, lane by lane, and back; GLSL ints of an integer type's lanes, and back;
// a value's cases (none but Checked's).
template <class F>
void to_floats(const F& x, float* out) { sampler_traits<F>::to_floats(x, out); }
template <class F>
F from_floats(const float* in) { return sampler_traits<F>::from_floats(in); }
template <class I>
void to_ints(const I& x, std::int32_t* out) { sampler_traits<I>::to_ints(x, out); }
template <class I>
I from_ints(const std::int32_t* in, LaneCases cases = {}) { return sampler_traits<I>::from_ints(in, cases); }
template <class N>
LaneCases cases_of(const N& x) { return sampler_traits<N>::cases(x); }
// Floats as F, with a Checked result's cases; constants under Dual2 (a gathered texel, a level
// of detail taken once per quad).
template <class F>
F constant_lanes(const float* v, LaneCases cases) { return sampler_traits<F>::constant(v, cases); }

}  // namespace qs::glsl::texture_detail
