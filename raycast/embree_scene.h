#pragma once
// Embree 3 behind one small interface: a static scene of triangle meshes and packets of
// kBatchLanes rays. embree_scene.cpp is the only file that includes Embree; every rtc* call is
// there, and the device's errors come back as RayCastError.

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>

#include <glm/vec3.hpp>

#include "shading/program.h"

namespace qs {

class RayCastError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

inline constexpr std::uint32_t kNoHit = 0xFFFFFFFFu;  // RTC_INVALID_GEOMETRY_ID

// Rays origin + t direction for t in [tnear, 1]; lanes whose bit in `active` is clear are not cast.
struct RayPacket {
    alignas(64) float origin[3][kBatchLanes];
    alignas(64) float direction[3][kBatchLanes];
    alignas(64) float tnear[kBatchLanes] = {};
    std::uint32_t active = 0;
};

// The closest hit of each ray: geometry (mesh) and primitive (triangle) ids, kNoHit for a miss
// or an inactive lane, and the hit's t.
struct RayHits {
    alignas(64) std::uint32_t geometry[kBatchLanes];
    alignas(64) std::uint32_t primitive[kBatchLanes];
    alignas(64) float t[kBatchLanes];
};

class EmbreeScene {
public:
    // packet_width: rays per Embree call, 4, 8 or 16; 0 for the widest the CPU traces natively
    // (a wider packet is split into pieces of that width behind the call, at twice the cost).
    explicit EmbreeScene(int packet_width = 0);
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    // Adds a mesh; its geometry id is the number of meshes added before it. Triangles index
    // `positions`; both are copied.
    std::uint32_t add_mesh(std::span<const glm::vec3> positions, std::span<const std::array<std::uint32_t, 3>> triangles);
    // Builds the BVH; no meshes may be added afterwards.
    void commit();
    // Thread-safe after commit().
    void intersect(const RayPacket& rays, RayHits& hits) const;

private:
    struct Device;
    std::unique_ptr<Device> device_;
    std::uint32_t meshes_ = 0;
    bool committed_ = false;
    int packet_width_ = 4;
};

}  // namespace qs
