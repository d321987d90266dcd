#pragma once
// A mask of N lanes: GLSL's `bool` where the number type holds N fragments.
//
// The mask of lanes of Bytes-wide values (4: float, int, uint; 8: double) holds integers of that
// width (simd::Wide), all ones where the lane holds true, as comparisons of GCC vectors yield
// them, so that select() is one blend per register. float and int lanes of the same fragments share one
// mask type; double lanes convert (IntLanes does, number/integer.h).

#include <cstdint>
#include <type_traits>

#include "shading/number/wide_vector.h"

namespace qs {

template <int Bytes, int N>
class LaneMask {
public:
    using Bits = std::conditional_t<Bytes == 8, std::int64_t, std::int32_t>;
    using Vector = simd::Wide<Bits, N>;
    static constexpr int lanes = N;

    Vector bits;  // -1 (true) or 0 per lane

    LaneMask() = default;
    explicit LaneMask(bool b) : bits(Vector::splat(b ? -1 : 0)) {}
    explicit LaneMask(const Vector& b) : bits(b) {}

    static constexpr int size() { return N; }
    bool operator[](int i) const { return bits[i] != 0; }

    friend LaneMask operator!(const LaneMask& a) { return LaneMask(~a.bits); }
    friend LaneMask operator&&(const LaneMask& a, const LaneMask& b) { return LaneMask(a.bits & b.bits); }
    friend LaneMask operator||(const LaneMask& a, const LaneMask& b) { return LaneMask(a.bits | b.bits); }
    friend LaneMask operator&(const LaneMask& a, const LaneMask& b) { return LaneMask(a.bits & b.bits); }
    friend LaneMask operator|(const LaneMask& a, const LaneMask& b) { return LaneMask(a.bits | b.bits); }
    friend LaneMask operator^(const LaneMask& a, const LaneMask& b) { return LaneMask(a.bits ^ b.bits); }
    friend LaneMask operator==(const LaneMask& a, const LaneMask& b) { return !(a ^ b); }
    friend LaneMask operator!=(const LaneMask& a, const LaneMask& b) { return a ^ b; }

    friend LaneMask select(const LaneMask& m, const LaneMask& a, const LaneMask& b) {
        return LaneMask(simd::select(m.bits, a.bits, b.bits));
    }
    friend bool any(const LaneMask& m) { return simd::any(m.bits); }
    friend bool all(const LaneMask& m) { return simd::all_set(m.bits); }
    friend bool none(const LaneMask& m) { return !any(m); }
    friend bool lane(const LaneMask& m, int i) { return m[i]; }
};

template <class M>
struct is_lane_mask : std::false_type {};
template <int Bytes, int N>
struct is_lane_mask<LaneMask<Bytes, N>> : std::true_type {};

}  // namespace qs
