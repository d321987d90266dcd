#pragma once
// A loop nest's iterations as lanes. Where a part of a loop's body reads nothing but the loop
// counters and values that are the same in every lane (a cellular noise's cell, once a batch lies
// in one cell), that part can run once before the loop for all its iterations at once, iteration
// k in lane k, and each iteration then reads its own lane back in every lane. Each lane gets what
// it would have computed itself: the same operations on the same bits. The C++ writer uses it for
// loops that run a constant number of times (docs/design.md, "A generated translation runs a loop
// nest's head for all its iterations at once where the lanes agree").

#include <array>
#include <cstdint>
#include <type_traits>

#include "shading/glsl/vec.h"
#include "shading/number/integer.h"
#include "shading/number/lanes.h"
#include "shading/number/number.h"

namespace qs::glsl {

namespace iteration_detail {

// Whether every lane of `a` holds lane 0's bits (-0 and +0 differ, a NaN is alike only to itself).
template <class T, class Wide>
bool same_bits(const Wide& a) {
    using Bits = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
    const auto bits = simd::bit_cast<Bits>(a);
    return simd::all_set(simd::equal(bits, decltype(bits)::splat(bits[0])));
}

template <class V>
bool alike(const V& v) {
    if constexpr (is_lanes<V>::value) {
        return same_bits<typename V::value_type>(v.v);
    } else if constexpr (is_integer_lanes<V>::value && !is_checked_v<V>) {
        return same_bits<typename V::value_type>(v.v);
    } else if constexpr (requires { V::N; v[0]; }) {
        for (int i = 0; i < V::N; ++i) {
            if (!alike(v[i])) return false;
        }
        return true;
    } else {
        return false;  // derivatives or checks ride along with the values: lanes are never alike
    }
}

}  // namespace iteration_detail

// Whether each value (a float, int or vector of them over lanes) is the same in every lane.
template <class... V>
bool lanes_alike(const V&... v) {
    return (iteration_detail::alike(v) && ...);
}

// The iterations of a nest of loops, Counts... of them at each level from the outermost, their
// counters from `first` up by one, as the lanes of F: iteration k, the last counter the fastest,
// in lane k. `alike` says the nest's part runs here; it is false where F is not plain lanes of at
// least as many iterations, which then run as written.
template <class F, int... Counts>
class IterationLanes {
public:
    static constexpr int kLevels = int(sizeof...(Counts));
    static constexpr int kIterations = (Counts * ...);
    static constexpr bool kFits = is_lanes<F>::value && lanes_of<F>() >= kIterations;

    IterationLanes(const std::array<int, kLevels>& first, bool values_alike)
        : alike(kFits && values_alike), first_(first) {}

    const bool alike;

    // The counter of `level` in each iteration's lane (lanes past the last iteration repeat it).
    int_t<F> counter(int level) const {
        if constexpr (kFits) {
            alignas(64) std::int32_t c[lanes_of<F>()];
            for (int k = 0; k < lanes_of<F>(); ++k) c[k] = counters_of(k < kIterations ? k : kIterations - 1)[std::size_t(level)];
            return int_t<F>::load(c);
        } else {
            return int_t<F>(first_[std::size_t(level)]);
        }
    }

    // What the iteration with these counters computed into `each`, in every lane.
    template <class V, class... Counter>
    V at(const V& each, Counter... counters) const {
        static_assert(sizeof...(Counter) == kLevels);
        if constexpr (kFits) {
            const std::array<int, kLevels> c{int(counters)...};
            int k = 0;
            for (int l = 0; l < kLevels; ++l) k = k * kCount[std::size_t(l)] + (c[std::size_t(l)] - first_[std::size_t(l)]);
            return broadcast(each, k);
        } else {
            return each;
        }
    }

private:
    static constexpr std::array<int, kLevels> kCount{Counts...};
    std::array<int, kLevels> first_;

    std::array<int, kLevels> counters_of(int k) const {
        std::array<int, kLevels> c{};
        for (int l = kLevels - 1; l >= 0; --l) {
            c[std::size_t(l)] = first_[std::size_t(l)] + k % kCount[std::size_t(l)];
            k /= kCount[std::size_t(l)];
        }
        return c;
    }

    template <class V>
    static V broadcast(const V& v, int k) {
        if constexpr (requires { V::N; v[0]; }) {
            V r = v;
            for (int i = 0; i < V::N; ++i) r[i] = broadcast(v[i], k);
            return r;
        } else {
            return V(lane(v, k));
        }
    }
};

}  // namespace qs::glsl
