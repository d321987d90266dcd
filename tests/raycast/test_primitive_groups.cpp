// A batch's lanes grouped by the triangle they hit (raycast/primitive_groups.h): every lane in
// exactly one group, and values spread over the groups land in each lane as a per-lane copy
// would put them.
#include <catch2/catch.hpp>

#include <bit>
#include <cstdint>
#include <random>

#include "raycast/primitive_groups.h"

namespace qs {

TEST_CASE("primitive groups: each lane takes its own triangle's values", "[raycast][layout]") {
    std::mt19937 random(11);
    for (int trial = 0; trial < 200; ++trial) {
        // From one triangle for the whole batch (a block inside one) to sixteen different ones.
        const int distinct = 1 + trial % kBatchLanes;
        std::uniform_int_distribution<std::uint32_t> pick(0, std::uint32_t(distinct - 1));
        std::uint32_t primitive[kBatchLanes];
        for (std::uint32_t& p : primitive) p = 1000 + 7 * pick(random);
        const PrimitiveGroups groups(primitive);
        std::uint32_t seen = 0;
        for (int g = 0; g < groups.count; ++g) {
            CHECK((seen & groups.lanes[g]) == 0);
            seen |= groups.lanes[g];
            for (int i = 0; i < kBatchLanes; ++i) {
                if (groups.lanes[g] >> i & 1) CHECK(primitive[i] == groups.primitive[g]);
            }
        }
        CHECK(seen == 0xFFFFu);
        CHECK(groups.count <= distinct);
        // A value per triangle: NaNs whose sign and payload name it, which only a copy keeps.
        auto value = [](std::uint32_t p) {
            return std::bit_cast<double>((p % 2 ? 0xFFF8000000000000ull : 0x7FF8000000000000ull) | p);
        };
        const lanes16::Doubles d = groups.spread_doubles([&](int g) { return value(groups.primitive[g]); });
        const lanes16::Floats f = groups.spread_floats([&](int g) { return -float(groups.primitive[g]) * 0.25f; });
        for (int i = 0; i < kBatchLanes; ++i) {
            CHECK(std::bit_cast<std::uint64_t>(d[i]) == std::bit_cast<std::uint64_t>(value(primitive[i])));
            CHECK(f[i] == -float(primitive[i]) * 0.25f);
        }
    }
}

}  // namespace qs
