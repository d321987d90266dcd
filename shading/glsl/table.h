#pragma once
// Constant tables indexed per lane: GLSL's `const int perm[256] = int[](...)` read as perm[i]
// with i an int or uint of the fragment (a permutation table, a gradient table).
//
//     const int perm[256] = int[](151, 160, ...);     static constexpr table<int, 256> perm{{151, 160, ...}};
//     int h = perm[i & 255];                           int_t<F> h = perm[i & 255];
//
// A table holds 32-bit int, uint or float; perm[i] is an int_t<F>, uint_t<F> or F, the type of
// the index's fragments. Each lane reads its own element with one gather instruction per
// register on AVX2 and AVX-512, element by element elsewhere. An index outside the table reads
// 0 (GLSL leaves it undefined; Checked numbers flag it as Argument).

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "shading/number/simd/simd.h"

#include "shading/number/number.h"

namespace qs::glsl {

template <class T, std::size_t N>
struct table {
    static_assert(sizeof(T) == 4 && (std::is_same_v<T, int> || std::is_same_v<T, unsigned> || std::is_same_v<T, float>),
                  "a table holds 32-bit ints, uints or floats");
    static_assert(N > 0 && N <= 0x7FFFFFFF);

    T values[N];

    // An index the same for every lane.
    constexpr const T& operator[](std::size_t i) const { return values[i]; }

    // Each lane's element.
    template <class U, class F>
    auto operator[](const IntLanes<U, F>& index) const {
        using Bits = IntLanes<std::uint32_t, F>;
        const Bits raw = gather(Bits(index));
        if constexpr (std::is_same_v<T, float>) {
            return bits_float(raw);
        } else {
            return IntLanes<std::conditional_t<std::is_same_v<T, int>, std::int32_t, std::uint32_t>, F>(raw);
        }
    }
    template <class L>
    auto operator[](const Checked<L>& index) const {
        using R = decltype((*this)[index.v]);
        const auto outside = !(index.v < L(std::int32_t(N)) && index.v >= L(0));
        return Checked<R>((*this)[index.v], index.cases | LaneCases::on(lane_bits(outside), Undefined::Argument));
    }

private:
    // The elements at the lanes' indices (taken as unsigned, so negative ones are outside), 0
    // outside the table.
    template <class F>
    IntLanes<std::uint32_t, F> gather(const IntLanes<std::uint32_t, F>& index) const {
        using Bits = IntLanes<std::uint32_t, F>;
        constexpr int n = Bits::size;
        const auto inside = index < Bits(std::uint32_t(N));
        const Bits safe = select(inside, index, Bits(0u));
        alignas(64) std::uint32_t at[n];
        alignas(64) std::uint32_t out[n];
        safe.store(at);
        // A register of indices per gather instruction, where the target has them.
        constexpr int w = n % simd::register_floats == 0 ? simd::register_floats : 8;
        if constexpr (simd::register_floats >= 8 && n % w == 0) {
            using Index = simd::Vector<std::int32_t, w>;
            for (int k = 0; k < n; k += w) {
                const Index i = simd::load<Index>(reinterpret_cast<const std::int32_t*>(at + k));
                simd::store(out + k, simd::gather(reinterpret_cast<const std::uint32_t*>(values), i));
            }
            return select(inside, Bits::load(out), Bits(0u));
        }
        for (int k = 0; k < n; ++k) std::memcpy(&out[k], &values[at[k]], sizeof out[k]);
        return select(inside, Bits::load(out), Bits(0u));
    }
};

}  // namespace qs::glsl
