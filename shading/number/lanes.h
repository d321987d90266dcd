#pragma once
// SIMD lanes as a shading number type, on std::experimental::simd.
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

#include <cstddef>
#include <cstring>
#include <experimental/simd>
#include <type_traits>
#include <utility>

#include "shading/number/sin_cos.h"

namespace qs {

namespace stdx = std::experimental;

enum class DerivativeRule { Fine, CoarseLower, CoarseUpper };

struct PixelLanes {};
template <DerivativeRule R>
struct QuadLanes {
    static constexpr DerivativeRule rule = R;
};

template <class T, int N, class Layout = PixelLanes>
class Lanes {
public:
    using value_type = T;
    using Simd = stdx::simd<T, stdx::simd_abi::deduce_t<T, N>>;
    using Mask = typename Simd::mask_type;
    using layout = Layout;
    static constexpr int size = N;
    static_assert(Simd::size() == std::size_t(N), "std::experimental::simd gave a different width");

    Simd v;

    Lanes() = default;
    Lanes(T x) : v(x) {}  // NOLINT: broadcast, as GLSL promotes a literal
    template <class S>
        requires(std::is_arithmetic_v<S> && !std::is_same_v<S, T>)
    Lanes(S x) : v(static_cast<T>(x)) {}  // NOLINT
    explicit Lanes(const Simd& s) : v(s) {}
    // GLSL float(i) of the integers of these lanes (number/integer.h), rounded to nearest.
    template <class I>
        requires std::is_same_v<typename I::float_type, Lanes>
    explicit Lanes(const I& i) : v(i.template to_simd<T>()) {}
    // GLSL float(b): 1 or 0.
    explicit Lanes(const Mask& m) : v(T(0)) { stdx::where(m, v) = T(1); }

    static Lanes load(const T* p) {
        Lanes r;
        r.v.copy_from(p, stdx::element_aligned);
        return r;
    }
    void store(T* p) const { v.copy_to(p, stdx::element_aligned); }
    T operator[](int i) const { return v[i]; }

    // Lane i takes the value of lane Index{}(i): a stateless function object, evaluated at
    // compile time, so the move is one shuffle instruction (a generator reading v[index(i)]
    // lane by lane became sixteen scalar loads, and a function pointer a call per lane).
    template <class Index>
    Lanes permute(Index) const {
        const Vector x = vector();
        Vector moved;
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            moved = __builtin_shufflevector(x, x, Index{}(I)...);
        }(std::make_index_sequence<std::size_t(N)>());
        return from_vector(moved);
    }

    // The lanes through a function of arrays (number/sin_cos.h).
    template <void (*Function)(const T*, T*)>
    Lanes through() const {
        alignas(64) T in[N], out[N];
        store(in);
        Function(in, out);
        return load(out);
    }

    // The lanes as a GCC vector, for shuffles.
    typedef T Vector __attribute__((vector_size(N * sizeof(T))));
    Vector vector() const {
        alignas(Vector) T lanes[N];
        v.copy_to(lanes, stdx::element_aligned);
        Vector x;
        std::memcpy(&x, lanes, sizeof x);
        return x;
    }
    static Lanes from_vector(const Vector& x) {
        alignas(Vector) T lanes[N];
        std::memcpy(lanes, &x, sizeof x);
        return load(lanes);
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

    friend Mask operator<(const Lanes& a, const Lanes& b) { return a.v < b.v; }
    friend Mask operator<=(const Lanes& a, const Lanes& b) { return a.v <= b.v; }
    friend Mask operator>(const Lanes& a, const Lanes& b) { return a.v > b.v; }
    friend Mask operator>=(const Lanes& a, const Lanes& b) { return a.v >= b.v; }
    friend Mask operator==(const Lanes& a, const Lanes& b) { return a.v == b.v; }
    friend Mask operator!=(const Lanes& a, const Lanes& b) { return a.v != b.v; }

    friend Lanes select(const Mask& m, const Lanes& a, const Lanes& b) {
        Simd r = b.v;
        stdx::where(m, r) = a.v;
        return Lanes(r);
    }
    friend Mask isnan(const Lanes& a) { return stdx::isnan(a.v); }
    friend Mask isinf(const Lanes& a) { return stdx::isinf(a.v); }
    // GLSL min/max as llvmpipe evaluates them: a NaN operand loses to the other one.
    friend Lanes min(const Lanes& a, const Lanes& b) { return select(isnan(b) || a < b, a, b); }
    friend Lanes max(const Lanes& a, const Lanes& b) { return select(isnan(b) || a > b, a, b); }

    friend Lanes floor(const Lanes& a) { return Lanes(stdx::floor(a.v)); }
    friend Lanes ceil(const Lanes& a) { return Lanes(stdx::ceil(a.v)); }
    friend Lanes trunc(const Lanes& a) { return Lanes(stdx::trunc(a.v)); }
    // To nearest, halves to even: the rounding mode shading threads never change.
    friend Lanes roundEven(const Lanes& a) { return Lanes(stdx::nearbyint(a.v)); }
    friend Lanes abs(const Lanes& a) { return Lanes(stdx::abs(a.v)); }
    friend Lanes sqrt(const Lanes& a) { return Lanes(stdx::sqrt(a.v)); }
    // On float, llvmpipe's sin and cos to the bit (number/sin_cos.h); double keeps the library's.
    friend Lanes sin(const Lanes& a) {
        if constexpr (std::is_same_v<T, float>) return a.through<llvmpipe_math::sin_or_cos<false, N>>();
        else return Lanes(stdx::sin(a.v));
    }
    friend Lanes cos(const Lanes& a) {
        if constexpr (std::is_same_v<T, float>) return a.through<llvmpipe_math::sin_or_cos<true, N>>();
        else return Lanes(stdx::cos(a.v));
    }
    friend Lanes tan(const Lanes& a) { return Lanes(stdx::tan(a.v)); }
    friend Lanes asin(const Lanes& a) { return Lanes(stdx::asin(a.v)); }
    friend Lanes acos(const Lanes& a) { return Lanes(stdx::acos(a.v)); }
    friend Lanes atan(const Lanes& a) { return Lanes(stdx::atan(a.v)); }
    friend Lanes atan(const Lanes& y, const Lanes& x) { return Lanes(stdx::atan2(y.v, x.v)); }
    friend Lanes exp(const Lanes& a) { return Lanes(stdx::exp(a.v)); }
    friend Lanes log(const Lanes& a) { return Lanes(stdx::log(a.v)); }
    friend Lanes exp2(const Lanes& a) { return Lanes(stdx::exp2(a.v)); }
    friend Lanes log2(const Lanes& a) { return Lanes(stdx::log2(a.v)); }
    friend Lanes pow(const Lanes& a, const Lanes& b) { return Lanes(stdx::pow(a.v, b.v)); }

    friend T lane(const Lanes& a, int i) { return a.v[i]; }
};

template <class T, class Abi>
bool lane(const stdx::simd_mask<T, Abi>& m, int i) { return m[i]; }
// GLSL bools are masks: selecting between two of them.
template <class T, class Abi>
stdx::simd_mask<T, Abi> select(const stdx::simd_mask<T, Abi>& m, const stdx::simd_mask<T, Abi>& a,
                               const stdx::simd_mask<T, Abi>& b) {
    return (m && a) || (!m && b);
}
template <class T, class Abi>
bool any(const stdx::simd_mask<T, Abi>& m) { return stdx::any_of(m); }
template <class T, class Abi>
bool all(const stdx::simd_mask<T, Abi>& m) { return stdx::all_of(m); }

// Number types the renderer instantiates shaders with.
template <class T, int N>
using Pixels = Lanes<T, N, PixelLanes>;
template <class T, int K, DerivativeRule R = DerivativeRule::Fine>
using Quads = Lanes<T, 4 * K, QuadLanes<R>>;
template <class T = float, DerivativeRule R = DerivativeRule::Fine>
using Quad = Quads<T, 1, R>;

}  // namespace qs
