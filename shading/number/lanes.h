#pragma once
// SIMD lanes as a shading number type, on register-wide GCC vectors (number/wide_vector.h).
//
// `Lanes<T, N, Layout>` holds N values that the shader code treats as one GLSL `float`.
// The Layout says what the lanes are:
//  - `PixelLanes`: N independent fragments. No derivatives (dFdx does not compile): the per-pixel
//    path for shaders that use none, with no helper lanes at all.
//  - `QuadLanes<Rule>`: N/4 whole 2x2 pixel quads. dFdx/dFdy are lane differences inside a quad,
//    taken by the DerivativeRule. Lane layout of every quad (window coordinates, y up):
//
//        y+1: | 2 | 3 |
//        y  : | 0 | 1 |        x on the left, x+1 on the right, (x, y) even-aligned to the quad grid
//
//    Fine        dFdx: row y -> v1-v0, row y+1 -> v3-v2      dFdy: column x -> v2-v0, x+1 -> v3-v1
//                (Mesa llvmpipe, for dFdx, dFdxFine and dFdxCoarse alike)
//    CoarseLower dFdx = v1-v0, dFdy = v2-v0 on all four lanes: the lower row and left column, i.e.
//                the quad's first pixel in y-up order (Mesa softpipe into OSMesa's buffer)
//    CoarseUpper dFdx = v3-v2, dFdy = v2-v0 on all four lanes: the upper row and left column, i.e.
//                the first pixel of a quad stored top-down (SwiftShader: lane1-lane0, lane2-lane0)
//
// Arithmetic is plain IEEE (no FMA contraction in the build; see CMakeLists.txt); sin and cos on
// float are llvmpipe's polynomial (number/sin_cos.h). Comparisons
// yield masks; `select(mask, a, b)` picks per lane. min/max return the non-NaN operand.

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#include "shading/number/lane_mask.h"
#include "shading/number/wide_vector.h"
#include "shading/number/sin_cos.h"

namespace qs {

enum class DerivativeRule { Fine, CoarseLower, CoarseUpper };

struct PixelLanes {};
template <DerivativeRule R>
struct QuadLanes {
    static constexpr DerivativeRule rule = R;
};

template <class T, int N, class Layout = PixelLanes>
class Lanes {
    static_assert(std::is_same_v<T, float> || std::is_same_v<T, double>);

public:
    using value_type = T;
    using Vector = simd::Wide<T, N>;  // register-wide GCC vectors (wide_vector.h)
    using Mask = LaneMask<int(sizeof(T)), N>;
    using layout = Layout;
    static constexpr int size = N;

    Vector v;

    Lanes() = default;
    Lanes(T x) : v(Vector::splat(x)) {}  // NOLINT: broadcast, as GLSL promotes a literal
    template <class S>
        requires(std::is_arithmetic_v<S> && !std::is_same_v<S, T>)
    Lanes(S x) : v(Vector::splat(static_cast<T>(x))) {}  // NOLINT
    explicit Lanes(const Vector& x) : v(x) {}
    // GLSL float(i) of the integers of these lanes (number/integer.h), rounded to nearest.
    template <class I>
        requires std::is_same_v<typename I::float_type, Lanes>
    explicit Lanes(const I& i) : v(simd::convert<T>(i.v)) {}
    // GLSL float(b): 1 or 0.
    explicit Lanes(const Mask& m) : v(simd::select(m.bits, Vector::splat(T(1)), Vector{})) {}

    static Lanes load(const T* p) { return Lanes(Vector::load(p)); }
    void store(T* p) const { v.store(p); }
    T operator[](int i) const { return v[i]; }

    // Lane i takes the value of lane Index{}(i): a stateless function object, evaluated at
    // compile time, so the move is one shuffle instruction (a generator reading v[index(i)]
    // lane by lane became sixteen scalar loads, and a function pointer a call per lane).
    template <class Index>
    Lanes permute(Index) const { return Lanes(simd::permute<Index>(v)); }

    // The lanes through a function of arrays (number/sin_cos.h).
    template <void (*Function)(const T*, T*)>
    Lanes through() const {
        alignas(64) T in[N], out[N];
        store(in);
        Function(in, out);
        return load(out);
    }

    friend Lanes operator-(const Lanes& a) { return Lanes(-a.v); }
    friend Lanes operator+(const Lanes& a, const Lanes& b) { return Lanes(a.v + b.v); }
    friend Lanes operator-(const Lanes& a, const Lanes& b) { return Lanes(a.v - b.v); }
    friend Lanes operator*(const Lanes& a, const Lanes& b) { return Lanes(a.v * b.v); }
    friend Lanes operator/(const Lanes& a, const Lanes& b) { return Lanes(a.v / b.v); }
    Lanes& operator+=(const Lanes& b) { v += b.v; return *this; }
    Lanes& operator-=(const Lanes& b) { v -= b.v; return *this; }
    Lanes& operator*=(const Lanes& b) { v *= b.v; return *this; }
    Lanes& operator/=(const Lanes& b) { v /= b.v; return *this; }

    friend Mask operator<(const Lanes& a, const Lanes& b) { return Mask(simd::less(a.v, b.v)); }
    friend Mask operator<=(const Lanes& a, const Lanes& b) { return Mask(simd::less_equal(a.v, b.v)); }
    friend Mask operator>(const Lanes& a, const Lanes& b) { return Mask(simd::less(b.v, a.v)); }
    friend Mask operator>=(const Lanes& a, const Lanes& b) { return Mask(simd::less_equal(b.v, a.v)); }
    friend Mask operator==(const Lanes& a, const Lanes& b) { return Mask(simd::equal(a.v, b.v)); }
    friend Mask operator!=(const Lanes& a, const Lanes& b) { return Mask(simd::not_equal(a.v, b.v)); }

    friend Lanes select(const Mask& m, const Lanes& a, const Lanes& b) { return Lanes(simd::select(m.bits, a.v, b.v)); }
    friend Mask isnan(const Lanes& a) { return a != a; }
    friend Mask isinf(const Lanes& a) { return abs(a) == Lanes(std::numeric_limits<T>::infinity()); }
    // GLSL min/max as llvmpipe evaluates them: a NaN operand loses to the other one, i.e.
    // select(isnan(b) || a < b, a, b). minps gives a < b ? a : b, so only a NaN b needs the
    // select, which a constant b (max(x, 0.0)) leaves out: one instruction where a compare, a
    // second one on b and a blend were.
    friend Lanes min(const Lanes& a, const Lanes& b) { return select(isnan(b), a, Lanes(simd::extremum_or_second<simd::Extremum::Min>(a.v, b.v))); }
    friend Lanes max(const Lanes& a, const Lanes& b) { return select(isnan(b), a, Lanes(simd::extremum_or_second<simd::Extremum::Max>(a.v, b.v))); }

    friend Lanes floor(const Lanes& a) { return Lanes(simd::round<simd::Rounding::Floor>(a.v)); }
    friend Lanes ceil(const Lanes& a) { return Lanes(simd::round<simd::Rounding::Ceil>(a.v)); }
    friend Lanes trunc(const Lanes& a) { return Lanes(simd::round<simd::Rounding::Trunc>(a.v)); }
    // To nearest, halves to even: the rounding mode shading threads never change.
    friend Lanes roundEven(const Lanes& a) { return Lanes(simd::round<simd::Rounding::NearestEven>(a.v)); }
    friend Lanes abs(const Lanes& a) {
        using Bits = typename Mask::Bits;  // the sign bit cleared
        return Lanes(simd::bit_cast<T>(simd::bit_cast<Bits>(a.v) & Mask::Vector::splat(std::numeric_limits<Bits>::max())));
    }
    friend Lanes sqrt(const Lanes& a) { return Lanes(simd::sqrt(a.v)); }
    // a * b + c where a * b is exact: fused or not, the same bits (simd/simd.h).
    friend Lanes exact_product_add(const Lanes& a, const Lanes& b, const Lanes& c) {
        return Lanes(simd::exact_product_add(a.v, b.v, c.v));
    }
    // On float, llvmpipe's sin and cos to the bit (number/sin_cos.h); double keeps the library's.
    friend Lanes sin(const Lanes& a) {
        if constexpr (std::is_same_v<T, float>) return a.through<llvmpipe_math::sin_or_cos<false, N>>();
        else return a.map([](T x) { return std::sin(x); });
    }
    friend Lanes cos(const Lanes& a) {
        if constexpr (std::is_same_v<T, float>) return a.through<llvmpipe_math::sin_or_cos<true, N>>();
        else return a.map([](T x) { return std::cos(x); });
    }
    // The rest, with no vector instruction: the library's functions lane by lane.
    friend Lanes tan(const Lanes& a) { return a.map([](T x) { return std::tan(x); }); }
    friend Lanes asin(const Lanes& a) { return a.map([](T x) { return std::asin(x); }); }
    friend Lanes acos(const Lanes& a) { return a.map([](T x) { return std::acos(x); }); }
    friend Lanes atan(const Lanes& a) { return a.map([](T x) { return std::atan(x); }); }
    friend Lanes atan(const Lanes& y, const Lanes& x) { return y.map(x, [](T a, T b) { return std::atan2(a, b); }); }
    friend Lanes exp(const Lanes& a) { return a.map([](T x) { return std::exp(x); }); }
    friend Lanes log(const Lanes& a) { return a.map([](T x) { return std::log(x); }); }
    friend Lanes exp2(const Lanes& a) { return a.map([](T x) { return std::exp2(x); }); }
    friend Lanes log2(const Lanes& a) { return a.map([](T x) { return std::log2(x); }); }
    friend Lanes pow(const Lanes& a, const Lanes& b) { return a.map(b, [](T x, T y) { return std::pow(x, y); }); }

    friend T lane(const Lanes& a, int i) { return a.v[i]; }

private:
    template <class F>
    Lanes map(F f) const { return Lanes(simd::per_element(v, f)); }
    template <class F>
    Lanes map(const Lanes& b, F f) const { return Lanes(simd::per_element(v, b.v, f)); }
};

// Number types the renderer instantiates shaders with.
template <class T, int N>
using Pixels = Lanes<T, N, PixelLanes>;
template <class T, int K, DerivativeRule R = DerivativeRule::Fine>
using Quads = Lanes<T, 4 * K, QuadLanes<R>>;
template <class T = float, DerivativeRule R = DerivativeRule::Fine>
using Quad = Quads<T, 1, R>;

}  // namespace qs
