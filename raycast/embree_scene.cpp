// The one file that includes Embree: EmbreeScene over an Embree device, built into the module
// libquadshade-embree.so (modules/module_loader.h), whose one exported symbol is
// quadshade_embree_scene.
#include "raycast/embree_scene.h"

#include <cmath>
#include <cstring>
#include <mutex>
#include <string>

#include <embree3/rtcore.h>

namespace qs {

namespace {

const char* error_name(RTCError code) {
    switch (code) {
        case RTC_ERROR_NONE: return "no error";
        case RTC_ERROR_UNKNOWN: return "unknown error";
        case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
        case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
        case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
        case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
        case RTC_ERROR_CANCELLED: return "cancelled";
    }
    return "error";
}

// The device and its scene. Embree reports errors through a C callback, which must not throw:
// it records the first message and the next check() throws it.
struct Device {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::mutex mutex;
    std::string error;

    static void on_error(void* user, RTCError code, const char* message) {
        auto* self = static_cast<Device*>(user);
        const std::lock_guard lock(self->mutex);
        if (self->error.empty()) self->error = std::string(error_name(code)) + ": " + (message ? message : "");
    }

    void check(const char* what) {
        const std::lock_guard lock(mutex);
        if (!error.empty()) throw RayCastError(std::string("Embree ") + what + ": " + error);
    }

    ~Device() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

class EmbreeDeviceScene final : public EmbreeScene {
public:
    explicit EmbreeDeviceScene(int packet_width);
    std::uint32_t add_mesh(std::span<const glm::vec3> positions,
                           std::span<const std::array<std::uint32_t, 3>> triangles) override;
    void commit() override;
    void intersect(const RayPacket& rays, RayHits& hits) const override;

private:
    Device device_;
    std::uint32_t meshes_ = 0;
    bool committed_ = false;
    int packet_width_ = 4;
};

EmbreeDeviceScene::EmbreeDeviceScene(int packet_width) {
    if (packet_width != 0 && packet_width != 4 && packet_width != 8 && packet_width != 16) {
        throw std::invalid_argument("EmbreeScene: packets of " + std::to_string(packet_width) + " rays (4, 8 or 16)");
    }
    device_.device = rtcNewDevice(nullptr);
    if (!device_.device) {
        throw RayCastError(std::string("Embree: cannot create a device: ") + error_name(rtcGetDeviceError(nullptr)));
    }
    rtcSetDeviceErrorFunction(device_.device, &Device::on_error, &device_);
    // By default the widest packet this CPU traces natively: a wider one is split behind the
    // call, at about twice the cost (docs/design.md, Ray caster).
    auto native = [&](RTCDeviceProperty p) { return rtcGetDeviceProperty(device_.device, p) != 0; };
    packet_width_ = packet_width != 0                                    ? packet_width
                    : native(RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED) ? 16
                    : native(RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED)  ? 8
                                                                         : 4;
    device_.scene = rtcNewScene(device_.device);
    // Robust: no shortcuts that trade accuracy for speed, so that rays through shared edges and
    // vertices never fall between two triangles.
    rtcSetSceneFlags(device_.scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(device_.scene, RTC_BUILD_QUALITY_HIGH);
    device_.check("scene creation");
}

std::uint32_t EmbreeDeviceScene::add_mesh(std::span<const glm::vec3> positions,
                                          std::span<const std::array<std::uint32_t, 3>> triangles) {
    if (committed_) throw std::logic_error("EmbreeScene::add_mesh after commit");
    RTCGeometry g = rtcNewGeometry(device_.device, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Embree may read 16 bytes at the last vertex: one float3 of padding.
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), positions.size() + 1));
    auto* t = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                  3 * sizeof(std::uint32_t), triangles.size()));
    if (v && t) {
        for (std::size_t i = 0; i < positions.size(); ++i) {
            v[3 * i] = positions[i].x, v[3 * i + 1] = positions[i].y, v[3 * i + 2] = positions[i].z;
        }
        if (!triangles.empty()) std::memcpy(t, triangles.data(), triangles.size_bytes());
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(device_.scene, g, meshes_);
    }
    rtcReleaseGeometry(g);
    device_.check("mesh");
    return meshes_++;
}

void EmbreeDeviceScene::commit() {
    rtcCommitScene(device_.scene);
    device_.check("BVH build");
    committed_ = true;
}

// Embree's ray packets of K rays, and the call that traces one.
template <int K>
struct Packet;
template <>
struct Packet<4> {
    using RayHit = RTCRayHit4;
    static void intersect(const int* valid, RTCScene scene, RTCIntersectContext* context, RayHit* r) {
        rtcIntersect4(valid, scene, context, r);
    }
};
template <>
struct Packet<8> {
    using RayHit = RTCRayHit8;
    static void intersect(const int* valid, RTCScene scene, RTCIntersectContext* context, RayHit* r) {
        rtcIntersect8(valid, scene, context, r);
    }
};
template <>
struct Packet<16> {
    using RayHit = RTCRayHit16;
    static void intersect(const int* valid, RTCScene scene, RTCIntersectContext* context, RayHit* r) {
        rtcIntersect16(valid, scene, context, r);
    }
};

// The batch's rays as kBatchLanes / K packets of K.
template <int K>
void trace(RTCScene scene, const RayPacket& rays, RayHits& hits) {
    for (int first = 0; first < kBatchLanes; first += K) {
        alignas(64) typename Packet<K>::RayHit r;
        alignas(64) int valid[K];
        for (int j = 0; j < K; ++j) {
            const int i = first + j;
            const bool active = rays.active >> i & 1;
            valid[j] = active ? -1 : 0;
            // An inactive lane still gets a well-formed, empty ray: Embree's packets narrower
            // than K check every lane (`ray.valid()`, an assertion that aborts), whatever the
            // valid mask says, and the caller leaves these lanes unset.
            r.ray.org_x[j] = active ? rays.origin[0][i] : 0.0f, r.ray.org_y[j] = active ? rays.origin[1][i] : 0.0f;
            r.ray.org_z[j] = active ? rays.origin[2][i] : 0.0f;
            r.ray.dir_x[j] = active ? rays.direction[0][i] : 0.0f, r.ray.dir_y[j] = active ? rays.direction[1][i] : 0.0f;
            r.ray.dir_z[j] = active ? rays.direction[2][i] : 1.0f;
            r.ray.tnear[j] = active ? rays.tnear[i] : 0.0f, r.ray.tfar[j] = active ? 1.0f : -INFINITY;
            r.ray.time[j] = 0.0f;
            r.ray.mask[j] = 0xFFFFFFFFu, r.ray.id[j] = unsigned(j), r.ray.flags[j] = 0;
            r.hit.geomID[j] = RTC_INVALID_GEOMETRY_ID, r.hit.primID[j] = RTC_INVALID_GEOMETRY_ID;
            r.hit.instID[0][j] = RTC_INVALID_GEOMETRY_ID;
        }
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // neighbouring primary rays
        Packet<K>::intersect(valid, scene, &context, &r);
        // Inactive lanes are misses whatever Embree left in them: a packet wider than the
        // ISA's is traced in narrower pieces, which return inactive lanes unset.
        for (int j = 0; j < K; ++j) {
            const int i = first + j;
            const bool hit = (rays.active >> i & 1) && r.hit.geomID[j] != RTC_INVALID_GEOMETRY_ID;
            hits.geometry[i] = hit ? r.hit.geomID[j] : kNoHit;
            hits.primitive[i] = hit ? r.hit.primID[j] : kNoHit;
            hits.t[i] = hit ? r.ray.tfar[j] : 1.0f;
        }
    }
}

void EmbreeDeviceScene::intersect(const RayPacket& rays, RayHits& hits) const {
    static_assert(kBatchLanes % 16 == 0);
    switch (packet_width_) {
        case 16: return trace<16>(device_.scene, rays, hits);
        case 8: return trace<8>(device_.scene, rays, hits);
        default: return trace<4>(device_.scene, rays, hits);
    }
}

}  // namespace

}  // namespace qs

extern "C" __attribute__((visibility("default"))) qs::EmbreeScene* quadshade_embree_scene(int packet_width) {
    return new qs::EmbreeDeviceScene(packet_width);
}
