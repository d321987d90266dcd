#pragma once
// A batch's lanes grouped by the triangle they hit, and per-triangle values spread over the
// lanes of each group. A 4x4 block of primary rays meets one to a few triangles, so its set-up
// moves each triangle's plane and vertex attributes into all its lanes at once (one masked
// broadcast per register on AVX-512) rather than lane by lane, whose scalar stores the vector
// arithmetic that follows cannot load back without stalling.

#include <bit>
#include <cstdint>
#include <cstring>

#if defined(__AVX512F__)
#include <immintrin.h>
#endif

#include "raycast/double_lanes.h"

namespace qs {

struct PrimitiveGroups {
    int count = 0;
    std::uint32_t primitive[kBatchLanes];  // group g's triangle, in the order of first lanes
    std::uint32_t lanes[kBatchLanes];      // group g's lanes: bit i for lane i
#if !defined(__AVX512F__)
    std::uint8_t group_of[kBatchLanes];  // lane i's group
#endif

    explicit PrimitiveGroups(const std::uint32_t (&lane_primitive)[kBatchLanes]) {
#if defined(__AVX512F__)
        // Each group's lanes by one comparison of all sixteen: as many steps as triangles.
        const __m512i all = _mm512_loadu_si512(lane_primitive);
        for (std::uint32_t left = (1u << kBatchLanes) - 1; left != 0; ++count) {
            const std::uint32_t p = lane_primitive[std::countr_zero(left)];
            primitive[count] = p;
            lanes[count] = _mm512_cmpeq_epi32_mask(all, _mm512_set1_epi32(int(p)));
            left &= ~lanes[count];
        }
#else
        for (int i = 0; i < kBatchLanes; ++i) {
            int g = 0;
            while (g < count && primitive[g] != lane_primitive[i]) ++g;
            if (g == count) primitive[count++] = lane_primitive[i], lanes[g] = 0;
            lanes[g] |= 1u << i;
            group_of[i] = std::uint8_t(g);
        }
#endif
    }

    // Lane i holds value(g) of its group g.
    template <class Value>
    lanes16::Doubles spread_doubles(Value value) const {
        lanes16::Doubles r;
#if defined(__AVX512F__)
        static_assert(sizeof r == 2 * sizeof(__m512d));
        // Every lane is in a group: the first group's value first, unmasked (a block on one
        // triangle needs nothing more).
        __m512d half[2] = {_mm512_set1_pd(value(0)), _mm512_set1_pd(value(0))};
        for (int g = 1; g < count; ++g) {
            const __m512d v = _mm512_set1_pd(value(g));
            half[0] = _mm512_mask_mov_pd(half[0], __mmask8(lanes[g]), v);
            half[1] = _mm512_mask_mov_pd(half[1], __mmask8(lanes[g] >> 8), v);
        }
        std::memcpy(&r, half, sizeof r);
#else
        for (int i = 0; i < kBatchLanes; ++i) r[i] = value(group_of[i]);
#endif
        return r;
    }
    template <class Value>
    lanes16::Floats spread_floats(Value value) const {
        lanes16::Floats r;
#if defined(__AVX512F__)
        static_assert(sizeof r == sizeof(__m512));
        __m512 all = _mm512_set1_ps(value(0));
        for (int g = 1; g < count; ++g) all = _mm512_mask_mov_ps(all, __mmask16(lanes[g]), _mm512_set1_ps(value(g)));
        std::memcpy(&r, &all, sizeof r);
#else
        for (int i = 0; i < kBatchLanes; ++i) r[i] = value(group_of[i]);
#endif
        return r;
    }
};

}  // namespace qs
