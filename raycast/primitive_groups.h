#pragma once
// A batch's lanes grouped by the triangle they hit, and per-triangle values spread over the
// lanes of each group. A 4x4 block of primary rays meets one to a few triangles, so its set-up
// moves each triangle's plane and vertex attributes into all its lanes at once (one masked
// broadcast per register on AVX-512) rather than lane by lane, whose scalar stores the vector
// arithmetic that follows cannot load back without stalling.

#include <bit>
#include <cstdint>
#include <cstring>

#include "raycast/double_lanes.h"

namespace qs {

struct PrimitiveGroups {
    // Whether a batch's sixteen lanes are one register: each group's lanes then come from one
    // comparison of all of them, and its values are spread by masked moves.
    static constexpr bool kOneRegister = simd::register_floats >= kBatchLanes;

    int count = 0;
    std::uint32_t primitive[kBatchLanes];  // group g's triangle, in the order of first lanes
    std::uint32_t lanes[kBatchLanes];      // group g's lanes: bit i for lane i
    std::uint8_t group_of[kBatchLanes];  // lane i's group (where sixteen lanes are several registers)

    explicit PrimitiveGroups(const std::uint32_t (&lane_primitive)[kBatchLanes]) {
        if constexpr (kOneRegister) {
            // Each group's lanes by one comparison of all sixteen: as many steps as triangles.
            const lanes16::Ints all = lanes16::load(reinterpret_cast<const int*>(lane_primitive));
            for (std::uint32_t left = (1u << kBatchLanes) - 1; left != 0; ++count) {
                const std::uint32_t p = lane_primitive[std::countr_zero(left)];
                primitive[count] = p;
                lanes[count] = lanes16::equal(all, simd::splat<lanes16::Ints>(int(p)));
                left &= ~lanes[count];
            }
            return;
        }
        for (int i = 0; i < kBatchLanes; ++i) {
            int g = 0;
            while (g < count && primitive[g] != lane_primitive[i]) ++g;
            if (g == count) primitive[count++] = lane_primitive[i], lanes[g] = 0;
            lanes[g] |= 1u << i;
            group_of[i] = std::uint8_t(g);
        }
    }

    // Lane i holds value(g) of its group g.
    template <class Value>
    lanes16::Doubles spread_doubles(Value value) const {
        lanes16::Doubles r;
        if constexpr (kOneRegister) {
            using Half = simd::Vector<double, kBatchLanes / 2>;
            // Every lane is in a group: the first group's value first, unmasked (a block on one
            // triangle needs nothing more).
            Half half[2] = {simd::splat<Half>(value(0)), simd::splat<Half>(value(0))};
            for (int g = 1; g < count; ++g) {
                const Half v = simd::splat<Half>(value(g));
                half[0] = simd::select(lanes[g], v, half[0]);
                half[1] = simd::select(lanes[g] >> 8, v, half[1]);
            }
            std::memcpy(&r, half, sizeof r);
            return r;
        }
        for (int i = 0; i < kBatchLanes; ++i) r[i] = value(group_of[i]);
        return r;
    }
    template <class Value>
    lanes16::Floats spread_floats(Value value) const {
        lanes16::Floats r;
        if constexpr (kOneRegister) {
            r = simd::splat<lanes16::Floats>(value(0));
            for (int g = 1; g < count; ++g) r = simd::select(lanes[g], simd::splat<lanes16::Floats>(value(g)), r);
            return r;
        }
        for (int i = 0; i < kBatchLanes; ++i) r[i] = value(group_of[i]);
        return r;
    }
};

}  // namespace qs
