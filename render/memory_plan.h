#pragma once
// Memory checked before a render allocates it. A frame either fits in what the process may use,
// or is rendered in row bands (image_bands, rasterizer.h) when its output can be written band by
// band, or is refused with a message giving the size it needs.

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "raster/rasterizer.h"

namespace qs {

// What this process can still allocate without swapping or being killed: the system's
// MemAvailable, less where a cgroup memory limit or an address-space/data rlimit is tighter.
std::uint64_t available_memory();

// The process's resident memory now, and its peak since the last reset_peak_resident() (since
// the process started where the kernel does not let it reset its peak): Linux's VmRSS and VmHWM.
// A render reports its measured peak beside its plan's.
std::uint64_t resident_bytes();
std::uint64_t peak_resident_bytes();
void reset_peak_resident();

// A size such as "512M", "8G", "1.5GiB", "1000000" (bytes; K, M, G, T in binary units, an
// optional "iB" or "B" after them). Throws std::invalid_argument.
std::uint64_t parse_byte_size(const std::string& text);

class MemoryError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// What a render touches beside what it allocates and plans: the code it runs for the first time,
// its threads' stacks, the scene parser's and the image writer's own state, and for the ray caster
// Embree's device. Measured at 4.0 to 6.0 MiB over renders of every kind (docs/results.md, "The
// cost of one call"), rounded up.
inline constexpr std::uint64_t kRenderOverheadBytes = std::uint64_t(8) << 20;

struct MemoryPlanInput {
    int height = 0;
    QuadPairing pairing = QuadPairing::TopDown;
    std::function<std::uint64_t(int rows)> bytes_for_rows;  // everything a band of `rows` holds
    std::uint64_t limit = 0;                                // what may be used
    std::uint64_t held = 0;  // of `limit`, held for the whole render (the scene, its textures, kRenderOverheadBytes)
    std::uint64_t band_budget = std::uint64_t(1) << 30;     // band when a whole frame needs more
    bool can_band = false;                                  // the outputs can be written band by band
};

// The most a bake of a size x size atlas holds at once beside the scene and kRenderOverheadBytes:
// the colour atlas's frame and its flipped copy, then the height's beside it, then the normal
// map's texels (atlas_texels, every texel taken as covered), normals, image and its skirt copy,
// then the maps held while each is converted for its file (`conversion_bytes` of one map). A bake
// is not banded: one larger than its limit is refused.
struct AtlasBakePlanInput {
    int size = 0;
    bool height = false, normal = false;
    int skirt = 0;
    std::uint64_t conversion_bytes = 0;
};
std::uint64_t atlas_bake_bytes(const AtlasBakePlanInput& in);

// The bands to render a frame in: one for the whole image when it fits in band_budget (or can
// only be written whole and fits in what `held` leaves of limit), else the fewest bands whose rows
// each fit in min(limit - held, band_budget). Throws MemoryError giving the size needed (held
// included) and the limit otherwise.
std::vector<RowBand> plan_bands(const MemoryPlanInput& in);

}  // namespace qs
