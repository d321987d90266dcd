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

// What this process can still allocate without swapping or being killed: the system's
// MemAvailable, less where a cgroup memory limit or an address-space/data rlimit is tighter.
std::uint64_t available_memory();

// A size such as "512M", "8G", "1.5GiB", "1000000" (bytes; K, M, G, T in binary units, an
// optional "iB" or "B" after them), nothing after it. Throws std::invalid_argument.
std::uint64_t parse_byte_size(const std::string& text);

class MemoryError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct MemoryPlanInput {
    int height = 0;
    QuadPairing pairing = QuadPairing::TopDown;
    std::function<std::uint64_t(int rows)> bytes_for_rows;  // everything a band of `rows` holds
    std::uint64_t limit = 0;                                // what may be used
    std::uint64_t band_budget = std::uint64_t(1) << 30;     // band when a whole frame needs more
    bool can_band = false;                                  // the outputs can be written band by band
};

// The bands to render a frame in: one for the whole image when it fits in band_budget (or can
// only be written whole and fits in limit), else the fewest bands whose rows each fit in
// min(limit, band_budget). Throws MemoryError giving the size needed and the limit otherwise.
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
