#pragma once
// The rasterizer's per-lane arithmetic on one batch: sixteen floats as a GCC/Clang generic
// vector. One register on AVX-512, several on narrower ISAs; plain IEEE operations lane by lane
// (the build does not contract a * b + c). Written with these instead of loops over arrays, the
// compiler needs no run-time checks that the arrays overlap, and nothing falls back to scalar
// code, whose stores a vector load cannot take straight from the store buffer. Every function
// here is always inlined: where sixteen floats are more than a register (AVX2), a call takes and
// returns them through memory, stored in pieces that a whole load then waits for (an out-of-line
// fma was a third of a constant-colour frame's time on the general path).

#include <bit>
#include <cstdint>
#include <cstring>

#include "shading/batches.h"
#include "shading/number/simd/simd.h"
#include "shading/number/wide_vector.h"

namespace qs::lanes16 {

using Floats = simd::Vector<float, kBatchLanes>;
using Ints = simd::Vector<std::int32_t, kBatchLanes>;
// Sixteen 64-bit integers: the edge functions' values (raster/edge_function.h).
using Longs = simd::Vector<std::int64_t, kBatchLanes>;

// v in every lane, -0 included (simd::splat: a register broadcast, copied where sixteen floats
// are more than one).
[[gnu::always_inline]] inline Floats broadcast(float v) { return simd::splat<Floats>(v); }

[[gnu::always_inline]] inline Floats load(const float* p) {
    Floats v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
[[gnu::always_inline]] inline Ints load(const int* p) {
    Ints v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
// Sixteen lanes of T (float or int) stored at p, a register at a time (a copy of the whole went
// through general registers where it is more than one).
template <class T, class Lanes>
[[gnu::always_inline]] inline void store_lanes(T* p, const Lanes& v) {
    static_assert(sizeof v == kBatchLanes * sizeof(T));
    if constexpr (simd::pieces_v<Lanes> == 1) {
        std::memcpy(p, &v, sizeof v);
    } else {
        simd::store_pieces(p, v);
    }
}
[[gnu::always_inline]] inline void store(float* p, const Floats& v) { store_lanes(p, v); }
[[gnu::always_inline]] inline void store(int* p, const Ints& v) { store_lanes(p, v); }

[[gnu::always_inline]] inline Floats to_float(const Ints& v) { return __builtin_convertvector(v, Floats); }

// a * b + c rounded once on every lane, as std::fma: a register at a time (a loop of std::fma
// compiled to sixteen scalar instructions).
[[gnu::always_inline]] inline Floats fma(const Floats& a, const Floats& b, const Floats& c) { return simd::fma(a, b, c); }

// Sixteen floats as register-wide parts (shading/number/wide_vector.h): one AVX-512 register or
// two AVX2 ones, each part a value the compiler keeps in a register. A Floats wider than the
// registers has none: kept across a loop, it is copied through the stack in 16-byte pieces on
// every use. Values a tile's loop reuses are held as these (FragmentInputs::ColumnVaryings).
using Wide = simd::Wide<float, kBatchLanes>;

[[gnu::always_inline]] inline Wide to_wide(const Floats& v) { return Wide::load(reinterpret_cast<const float*>(&v)); }

// fma above on register-wide parts.
[[gnu::always_inline]] inline Wide fma(const Wide& a, const Wide& b, const Wide& c) {
    return Wide::map([](const Wide::Part& x, const Wide::Part& y, const Wide::Part& z) { return simd::fma(x, y, z); }, a, b, c);
}

// Lane masks (bit i for lane i) of comparisons, on whole registers: GCC splits a comparison of
// these vectors wider than a register into one scalar comparison per lane.
// a < b
[[gnu::always_inline]] inline std::uint32_t less(const Floats& a, const Floats& b) { return simd::less_bits(a, b); }
// a == b
[[gnu::always_inline]] inline std::uint32_t equal(const Ints& a, const Ints& b) { return simd::equal_bits(a, b); }
// a + b > 0, a the same for every lane
[[gnu::always_inline]] inline std::uint32_t sum_positive(std::int64_t a, const Longs& b) {
    return simd::bits_by_pieces(
        [a](const auto& x, const auto& zero) {
            using Piece = std::remove_cvref_t<decltype(x)>;
            return simd::greater_bits(simd::splat<Piece>(a) + x, zero);
        },
        b, Longs{});
}

// `to` with the lanes of v at the set bits of `lanes` packed into its lanes first, first + 1, ...
// (in order; first + popcount(lanes) <= kBatchLanes), its other lanes as they were. Computed in
// registers, so that a batch gathered block by block is stored whole each time and its next
// (whole) load is forwarded from that store: gathered with scalar or variable-length copies, the
// load waited for every older store to reach the cache.
[[gnu::always_inline]] inline Ints append(const Ints& to, int first, std::uint32_t lanes, const Ints& v) {
    return simd::append(to, first, lanes, v);
}

// The lowest n set bits of `mask` (all of them when it has n or fewer).
inline std::uint32_t lowest_bits(std::uint32_t mask, int n) { return simd::lowest_bits(mask, n); }

// The bits of `bits` at the set bits of `mask`, packed from bit 0 up (BMI2's pext).
inline std::uint32_t compress_bits(std::uint32_t bits, std::uint32_t mask) { return simd::compress_bits(bits, mask); }

}  // namespace qs::lanes16
