#pragma once
// Cellular noise's 2D search (cellular_vectors, cellular.h) on AVX-512 lanes whose cells lie
// close together: the cells around them hashed once, as a table, instead of once per lane.

#include <cstdint>

#include "shading/glsl.h"
#include "shading/noise/flow_noise.h"

namespace qs::noise {
using namespace qs::glsl;

// The constants of cellular.glsl, which the search shares with the translation.
namespace cellular_constants {
inline constexpr float K = 0.142857142857f;      // 1/7
inline constexpr float Ko = 0.428571428571f;     // 3/7
inline constexpr float K2 = 0.020408163265306f;  // 1/49
inline constexpr float Kz = 0.166666666667f;     // 1/6
inline constexpr float Kzo = 0.416666666667f;    // 1/2-1/6*2
}  // namespace cellular_constants

namespace cellular_detail {
// Lanes of float a 512-bit register's worth at a time (the SIMD layer's AVX-512 target).
template <class F>
inline constexpr bool kAvx512FloatLanes = false;
template <int N, class Layout>
inline constexpr bool kAvx512FloatLanes<Lanes<float, N, Layout>> = Lanes<float, N, Layout>::Vector::part_size == 16;

// The cells of a 5x5 table, cell k at (k % 5 - 2, k / 5 - 2) from its centre; k >= 25 repeat
// the centre.
alignas(64) inline constexpr float kTableDx[32] = {-2, -1, 0, 1, 2, -2, -1, 0, 1, 2, -2, -1, 0, 1, 2, -2,
                                                   -1, 0,  1, 2, -2, -1, 0, 1, 2, 0,  0,  0, 0, 0, 0, 0};
alignas(64) inline constexpr float kTableDy[32] = {-2, -2, -2, -2, -2, -1, -1, -1, -1, -1, 0, 0, 0, 0, 0, 1,
                                                   1,  1,  1,  1,  2,  2,  2,  2,  2,  0,  0, 0, 0, 0, 0, 0};
}  // namespace cellular_detail

// cellular_vectors' 3x3 search where the lanes' cells lie close together, each cell's squared
// distance and vector handed to keep(d, v) (its insert); false (nothing done) where they do not,
// or where F is not AVX-512 float lanes.
//
// A cell's feature point (the hash p and the offsets ox, oy below) depends on the cell alone,
// and the lanes of a block mostly share their cells (a cell of st * 64 spans 7.8 pixels of a
// 500x500 plane): hashing the same cells over for each lane, Worley tiles took 1.6x as long
// on the Table 1.1 plane (docs/results.md).
// Where every lane's cell is within one of lane 0's, the 5x5 cells around lane 0's are hashed
// once, as 32 lanes, and each lane reads its nine from that table. The cells' coordinates are
// whole numbers below 2^24, so the table's x0 + dx and permute_mod(.) + (y0 + dy) are each
// lane's Pi.x + i and permute_mod(Pi.x + i) + Pi.y + j exactly: the same operations on the same
// values, the same bits (tests/shading/test_noise.cpp compares every lane with the scalar code).
template <class F, class Keep>
bool cellular_search_nearby(const vec2<F>& Pi, const vec2<F>& Pf, Keep&& keep) {
    if constexpr (cellular_detail::kAvx512FloatLanes<F>) {
        using namespace cellular_constants;
        using Table = Lanes<float, 32>;
        using Index = simd::Vector<std::int32_t, 16>;
        const float jitter = 1.0f;
        const float x0 = lane(Pi.x, 0), y0 = lane(Pi.y, 0);
        if (!all(abs(Pi.x - x0) <= 1.0f) || !all(abs(Pi.y - y0) <= 1.0f)) return false;
        const Table p = permute_mod(permute_mod(x0 + Table::load(cellular_detail::kTableDx)) +
                                    (y0 + Table::load(cellular_detail::kTableDy)));
        const Table ox = fract(p * K) - Ko;
        const Table oy = mod_whole(floor(p * K), 7.0f) * K - Ko;
        // Each lane's own cell in the table; cell (i, j) from it is i + 5 j further.
        const F own = (Pi.x - x0 + 2.0f) + 5.0f * (Pi.y - y0 + 2.0f);
        Index at[F::Vector::parts];
        for (int q = 0; q < F::Vector::parts; ++q) at[q] = __builtin_convertvector(own.v.part[q], Index);
        for (int i = -1; i <= 1; i++) {
            for (int j = -1; j <= 1; j++) {
                F oxl, oyl;
                for (int q = 0; q < F::Vector::parts; ++q) {
                    oxl.v.part[q] = simd::lookup(ox.v.part[0], ox.v.part[1], at[q] + (i + 5 * j));
                    oyl.v.part[q] = simd::lookup(oy.v.part[0], oy.v.part[1], at[q] + (i + 5 * j));
                }
                vec2<F> d(Pf.x - (float(i) + 0.5f) + jitter * oxl, Pf.y - (float(j) + 0.5f) + jitter * oyl);
                keep(dot(d, d), d);
            }
        }
        return true;
    }
    (void)Pi, (void)Pf, (void)keep;
    return false;
}

}  // namespace qs::noise
