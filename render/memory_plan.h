#pragma once
// Memory checked before a render allocates it. A frame either fits in what the process may use,
// or is rendered in row bands (image_bands, rasterizer.h) when its output can be written band by
// band, or is refused with a message giving the size it needs.

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "raster/rasterizer.h"

namespace qs {

struct Scene;

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
// optional "iB" or "B" after them), nothing after it. Throws std::invalid_argument.
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

// What a scene holds as loaded: its meshes' vertices and indices and its embedded images.
std::uint64_t scene_bytes(const Scene& scene);

struct MemoryPlanInput {
    int height = 0;
    QuadPairing pairing = QuadPairing::TopDown;
    std::function<std::uint64_t(int rows)> bytes_for_rows;  // everything a band of `rows` holds
    std::uint64_t limit = 0;                                // what may be used
    std::uint64_t held = 0;  // of `limit`, held for the whole render (the scene, its textures, kRenderOverheadBytes)
    std::uint64_t band_budget = std::uint64_t(1) << 30;     // band when a whole frame needs more
    bool can_band = false;                                  // the outputs can be written band by band
};

// The bands to render a frame in: one for the whole image when it fits in band_budget (or can
// only be written whole and fits in what `held` leaves of limit), else the fewest bands whose rows
// each fit in min(limit - held, band_budget). Throws MemoryError giving the size needed (held
// included) and the limit otherwise.
std::vector<RowBand> plan_bands(const MemoryPlanInput& in);

// Memory shared by tasks that run at once (a suite's cases, check's cases): each reserves what it
// needs before allocating it and waits while the others hold too much of it, so that N jobs
// never need N times what one may use; a task that could not fit even alone is refused.
class MemoryBudget {
public:
    explicit MemoryBudget(std::uint64_t limit);
    MemoryBudget(const MemoryBudget&) = delete;
    MemoryBudget& operator=(const MemoryBudget&) = delete;

    // Held bytes, given back when destroyed.
    class Reservation {
    public:
        Reservation(Reservation&& r) noexcept;
        Reservation& operator=(Reservation&&) = delete;
        ~Reservation();

    private:
        friend class MemoryBudget;
        Reservation(MemoryBudget* budget, std::uint64_t bytes) : budget_(budget), bytes_(bytes) {}
        MemoryBudget* budget_;
        std::uint64_t bytes_;
    };

    // Waits until `bytes` are free, then holds them. Throws MemoryError ("WHAT needs ..., more
    // than the ... available") when `bytes` exceed the whole limit.
    Reservation reserve(std::uint64_t bytes, const std::string& what);
    std::uint64_t limit() const { return limit_; }

private:
    void release(std::uint64_t bytes);
    const std::uint64_t limit_;
    std::uint64_t held_ = 0;
    std::mutex mutex_;
    std::condition_variable released_;
};

}  // namespace qs
