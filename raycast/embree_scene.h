#pragma once
// Embree 3 behind one small interface: a static scene of triangle meshes and packets of
// kBatchLanes rays. embree_scene.cpp is the only file that includes Embree; every rtc* call is
// there, and the device's errors come back as RayCastError. It is built into a module of its own
// (modules/module_loader.h), loaded by the first EmbreeScene::create: a rasterized frame never
// loads Embree.

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>

#include <glm/vec3.hpp>

#include "shading/batches.h"

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
    // Loads the Embree module on the first call (RayCastError naming Embree when it cannot).
    // packet_width: rays per Embree call, 4, 8 or 16; 0 for the widest the CPU traces natively
    // (a wider packet is split into pieces of that width behind the call, at twice the cost).
    static std::unique_ptr<EmbreeScene> create(int packet_width = 0);
    // Loads the Embree module now, as the first create() would.
    static void load_library();
    virtual ~EmbreeScene() = default;

    // Adds a mesh; its geometry id is the number of meshes added before it. Triangles index
    // `positions`; both are copied.
    virtual std::uint32_t add_mesh(std::span<const glm::vec3> positions,
                                   std::span<const std::array<std::uint32_t, 3>> triangles) = 0;
    // Builds the BVH; no meshes may be added afterwards.
    virtual void commit() = 0;
    // Thread-safe after commit().
    virtual void intersect(const RayPacket& rays, RayHits& hits) const = 0;
};

}  // namespace qs
