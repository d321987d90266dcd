#include "render/memory_plan.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

#include "scenes/scene.h"
#include "scenes/scene_files.h"

namespace qs {

namespace {

// The number after `key` in a "key value unit" file such as /proc/meminfo, in bytes; 0 if absent.
std::uint64_t meminfo_bytes(const char* key) {
    std::ifstream in("/proc/meminfo");
    std::string name, unit;
    std::uint64_t value = 0;
    while (in >> name >> value) {
        std::getline(in, unit);
        if (name == key) return value * 1024;  // kB
    }
    return 0;
}

// A single number in a file (cgroup files); nothing for "max", a missing file or anything else.
std::optional<std::uint64_t> file_number(const char* path) {
    std::ifstream in(path);
    std::uint64_t v = 0;
    if (in >> v) return v;
    return std::nullopt;
}

std::uint64_t headroom(std::uint64_t limit, std::uint64_t used) { return limit > used ? limit - used : 0; }

// A "Name:   123 kB" line of /proc/self/status, in bytes; 0 if absent.
std::uint64_t status_bytes(const char* key) {
    std::ifstream in("/proc/self/status");
    std::string name, unit;
    std::uint64_t value = 0;
    while (in >> name) {
        if (name == key && in >> value) return value * 1024;  // kB
        std::getline(in, unit);
    }
    return 0;
}

}  // namespace

std::uint64_t available_memory() {
    std::uint64_t available = meminfo_bytes("MemAvailable:");
    if (available == 0) available = std::numeric_limits<std::uint64_t>::max();
    // cgroup v2, then v1: a container's own limit, which MemAvailable does not see.
    if (auto max = file_number("/sys/fs/cgroup/memory.max")) {
        available = std::min(available, headroom(*max, file_number("/sys/fs/cgroup/memory.current").value_or(0)));
    } else if (auto max1 = file_number("/sys/fs/cgroup/memory/memory.limit_in_bytes")) {
        available = std::min(available, headroom(*max1, file_number("/sys/fs/cgroup/memory/memory.usage_in_bytes").value_or(0)));
    }
    // ulimit -v and -d: what this process has mapped already counts against them.
    long pages_total = 0, pages_resident = 0, pages_shared = 0, pages_text = 0, pages_lib = 0, pages_data = 0;
    std::ifstream statm("/proc/self/statm");
    statm >> pages_total >> pages_resident >> pages_shared >> pages_text >> pages_lib >> pages_data;
    const std::uint64_t page = std::uint64_t(::sysconf(_SC_PAGESIZE));
    rlimit r{};
    if (::getrlimit(RLIMIT_AS, &r) == 0 && r.rlim_cur != RLIM_INFINITY) {
        available = std::min(available, headroom(r.rlim_cur, std::uint64_t(pages_total) * page));
    }
    if (::getrlimit(RLIMIT_DATA, &r) == 0 && r.rlim_cur != RLIM_INFINITY) {
        available = std::min(available, headroom(r.rlim_cur, std::uint64_t(pages_data) * page));
    }
    return available;
}

std::uint64_t resident_bytes() { return status_bytes("VmRSS:"); }

std::uint64_t peak_resident_bytes() { return status_bytes("VmHWM:"); }

void reset_peak_resident() {
    // Linux 4.0 and later: "5" sets the peak to the resident memory now.
    std::ofstream("/proc/self/clear_refs") << "5";
}

std::uint64_t parse_byte_size(const std::string& text) {
    std::istringstream in(text);
    double number = 0.0;
    if (!(in >> number) || !std::isfinite(number) || number < 0.0) {
        throw std::invalid_argument("expected a size such as 512M or 8G, got '" + text + "'");
    }
    std::string unit, rest;
    in >> unit;
    if (in >> rest) throw std::invalid_argument("expected a size such as 512M or 8G, got '" + text + "'");
    std::transform(unit.begin(), unit.end(), unit.begin(), [](unsigned char c) { return char(std::toupper(c)); });
    static const std::pair<const char*, double> units[] = {{"", 1.0}, {"B", 1.0}, {"K", 0x1p10}, {"KB", 0x1p10},
                                                           {"KIB", 0x1p10}, {"M", 0x1p20}, {"MB", 0x1p20}, {"MIB", 0x1p20},
                                                           {"G", 0x1p30}, {"GB", 0x1p30}, {"GIB", 0x1p30}, {"T", 0x1p40},
                                                           {"TB", 0x1p40}, {"TIB", 0x1p40}};
    for (const auto& [name, scale] : units) {
        if (unit == name) {
            const double bytes = number * scale;
            if (bytes >= 0x1p63) throw std::invalid_argument("size '" + text + "' is too large");
            return std::uint64_t(bytes);
        }
    }
    throw std::invalid_argument("unknown unit in size '" + text + "' (use K, M, G or T)");
}

std::uint64_t scene_bytes(const Scene& scene) {
    std::uint64_t bytes = 0;
    for (const Mesh& m : scene.meshes) {
        bytes += m.vertices.capacity() * sizeof(Vertex) + m.indices.capacity() * sizeof(std::uint32_t);
    }
    for (const Texture& t : scene.textures) bytes += t.image.bytes.capacity();
    return bytes;
}

std::vector<RowBand> plan_bands(const MemoryPlanInput& in) {
    const std::uint64_t limit = in.limit > in.held ? in.limit - in.held : 0;  // what the frame may use
    const std::uint64_t whole = in.bytes_for_rows(in.height);
    const std::uint64_t budget = std::min(limit, in.band_budget);
    if (whole <= budget || (!in.can_band && whole <= limit)) return {RowBand{0, in.height}};
    const int smallest = std::min(in.height, kTileSize);
    if (!in.can_band || in.bytes_for_rows(smallest) > limit) {
        throw MemoryError("this render needs " +
                          byte_size_text(in.held + (in.can_band ? in.bytes_for_rows(smallest) : whole)) +
                          (in.can_band ? " for a band of " + std::to_string(smallest) + " rows" : " for the whole frame") +
                          ", more than the " + byte_size_text(in.limit) + " available (--memory-limit sets it" +
                          (in.can_band ? ")" : "; .png, .exr and .tif outputs are written in bands of rows and need less)"));
    }
    // The most tile rows per band that fit, found by halving (bytes grow with rows): one tile
    // row always does (checked above), the whole height does not.
    int lo = 1, hi = (in.height + kTileSize - 1) / kTileSize;
    while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        (in.bytes_for_rows(mid * kTileSize) <= budget ? lo : hi) = mid;
    }
    return image_bands(in.height, in.pairing, lo * kTileSize);
}

MemoryBudget::MemoryBudget(std::uint64_t limit) : limit_(limit) {}

MemoryBudget::Reservation MemoryBudget::reserve(std::uint64_t bytes, const std::string& what) {
    if (bytes > limit_) {
        throw MemoryError(what + " needs " + byte_size_text(bytes) + ", more than the " + byte_size_text(limit_) +
                          " available (--memory-limit sets it)");
    }
    std::unique_lock lock(mutex_);
    released_.wait(lock, [&] { return limit_ - held_ >= bytes; });
    held_ += bytes;
    return Reservation(this, bytes);
}

void MemoryBudget::release(std::uint64_t bytes) {
    {
        const std::lock_guard lock(mutex_);
        held_ -= bytes;
    }
    released_.notify_all();
}

MemoryBudget::Reservation::Reservation(Reservation&& r) noexcept : budget_(r.budget_), bytes_(r.bytes_) {
    r.budget_ = nullptr;
}

MemoryBudget::Reservation::~Reservation() {
    if (budget_) budget_->release(bytes_);
}

}  // namespace qs
