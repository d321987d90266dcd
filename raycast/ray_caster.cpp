#include "raycast/ray_caster.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/vec3.hpp>

#include "core/block_layout.h"
#include "core/block_rows.h"
#include "core/lane_batch.h"
#include "core/float_environment.h"
#include "core/prepared_draw.h"
#include "core/tile_frame.h"
#include "core/tile_writer.h"
#include "core/vertex_stage.h"
#include "raycast/embree_scene.h"
#include "raycast/eye.h"
#include "raycast/primitive_groups.h"
#include "raycast/screen_footprint.h"

namespace qs {

namespace {

using Triangle = std::array<std::uint32_t, 3>;

// A triangle's plane as its fragments' intersections use it. A point P of the plane, rel = P - p0,
// has barycentric weights b1 = ((rel x e2) . n) / (n . n) and b2 = ((e1 x rel) . n) / (n . n)
// (signed sub-triangle areas over the whole, e1 and e2 the edges from vertex 0), that is
// rel . to_b1 and rel . to_b2 with the vectors below: a dot product each per ray, and no division
// (waiting on sixteen-lane double divisions would be a quarter of the fragment set-up's time).
struct TrianglePlane {
    glm::dvec3 p0;            // vertex 0
    glm::dvec3 n;             // e1 x e2
    glm::dvec3 to_b1, to_b2;  // (e2 x n) / (n . n), (n x e1) / (n . n)

    explicit TrianglePlane(const glm::dvec3& v0, const glm::dvec3& v1, const glm::dvec3& v2) : p0(v0) {
        const glm::dvec3 e1 = v1 - v0, e2 = v2 - v0;
        n = glm::cross(e1, e2);
        const double nn = glm::dot(n, n);
        to_b1 = glm::cross(e2, n) / nn, to_b2 = glm::cross(n, e1) / nn;
    }
};

// One draw's geometry in world space and this frame's vertex stage output.
struct Mesh {
    std::vector<glm::dvec3> world;      // per vertex
    std::vector<Triangle> triangles;    // Embree's primitive i is triangles[i]: the finite ones
    std::vector<TrianglePlane> planes;  // per primitive
    std::vector<std::uint8_t> front;    // per primitive: it winds counter-clockwise in GL's window
    std::vector<VertexOut> out;         // per vertex, this frame
    FaceCulling culling;                // the draw's, when the BVH was built
};

// det[x y w] of a triangle's clip coordinates: positive where what is seen of it winds
// counter-clockwise in GL's window, negative where clockwise, zero edge-on. Its sign is that of
// the window area wherever all three w are positive, and clipping keeps it (each clipped piece
// lies in the same plane through the eye, turning the same way), so a triangle crossing the near
// plane is judged as the rasterizer judges its clipped pieces.
double clip_winding(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c) {
    const glm::dvec3 p(a.x, a.y, a.w), q(b.x, b.y, b.w), r(c.x, c.y, c.w);
    return glm::dot(p, glm::cross(q, r));
}

// Embree works on rays and vertices whose coordinates stay within +-1.844e18 (FLT_LARGE in its
// sources); beyond, its assertions abort or its builder drops triangles silently.
constexpr double kEmbreeRange = 1.8e18;

bool within_embree_range(const glm::dvec3& v) {
    return std::abs(v.x) <= kEmbreeRange && std::abs(v.y) <= kEmbreeRange && std::abs(v.z) <= kEmbreeRange;
}

// The rays of a width x height image are within Embree's range: the near-plane points and the
// directions are projective images of the screen rectangle, largest at its corners.
void check_rays(const Eye& eye, int width, int height) {
    lanes16::Doubles x, y;  // the four corners, repeated
    for (int i = 0; i < kBatchLanes; ++i) x[i] = (i & 1) ? width : 0.0, y[i] = (i & 2) ? height : 0.0;
    const Eye::Rays r = eye.rays(x, y);
    for (int corner = 0; corner < 4; ++corner) {
        if (!within_embree_range(r.origin.at(corner)) || !within_embree_range(r.direction.at(corner))) {
            throw RayCastError("ray caster: the camera's rays reach coordinates beyond +-1.8e18 (the camera is too "
                               "far from the origin, or its view too wide), where Embree cannot trace them; the "
                               "rasterizer (--backend raster) can render this view");
        }
    }
}

// Fragments waiting to be shaded with one draw's program: their pixels and which write, and for
// each lane its place in its block, the primitive it is evaluated on and where its ray met it.
struct HitBatch {
    LaneBatch lanes;
    std::uint8_t lane[kBatchLanes];
    std::uint32_t primitive[kBatchLanes];
    float t[kBatchLanes];
};

// Casts and shades the tiles of one thread, one after the other (tile_loop.h).
class TileCaster : public TileWriter {
public:
    TileCaster(Framebuffer& fb, const EmbreeScene& bvh, const Eye& eye, const std::vector<PreparedDraw>& draws,
               const std::vector<Mesh>& meshes, const BlockCoverage& covered, glm::vec4 clear)
        : TileWriter(fb, clear), bvh_(bvh), eye_(eye), draws_(draws), meshes_(meshes), covered_(covered),
          pending_(draws.size()) {}

    // Casts, shades and writes the tile whose top-left pixel is (x0, y0).
    void tile(int x0, int y0) {
        for (int by = y0; by < std::min(y0 + kTileSize, fb_.height); by += kBlock) {
            for (int bx = x0; bx < std::min(x0 + kTileSize, fb_.width); bx += kBlock) block(bx, by);
        }
        finish();
        cast_past_discards();
    }

private:
    // Pixel centres in GL window coordinates.
    struct WindowPoints {
        lanes16::Doubles x, y;
    };
    // A block's pixel centres and the rays through them.
    struct BlockRays {
        WindowPoints w;
        Eye::Rays r;
    };
    // A block whose every lane hit draw `draw`, as one batch in lane order, with its rays.
    struct WholeBlock {
        std::uint32_t draw;
        int bx, by;
        HitBatch batch;
        BlockRays cast;
    };

    // Casts, shades and writes the 4x4 block whose top-left pixel is (bx, by) in framebuffer
    // coordinates; pixels outside the framebuffer only ever serve as helpers. Only the lanes in
    // `lanes` are cast, from tnear[i] on when given.
    void block(int bx, int by, std::uint32_t lanes = 0xFFFFu, const float* tnear = nullptr) {
        RayPacket rays;
        rays.active = lanes & lanes_inside(bx, by, fb_.width, fb_.height);
        // No triangle's footprint reaches the block (the sky: a quarter of Figure 1.1's blocks).
        if (!covered_.covered(bx, by)) return clear_lanes(bx, by, rays.active);
        // The block lies well inside the only triangle seen there (most of Figure 1.1's ground):
        // every ray hits it, and a ray cast again past it, after a discard, meets nothing.
        const TriangleId* only = covered_.only(bx, by);
        if (only && tnear) return clear_lanes(bx, by, rays.active);
        // Every lane's ray; Embree reads the active ones. They are computed where the block would
        // wait, should it be whole.
        WholeBlock& whole = pairs_.next();
        BlockRays& cast = whole.cast;
        cast.w = centres(bx + lanes16::load(kLaneDx), by + lanes16::load(kLaneDy));
        cast.r = eye_.rays(cast.w.x, cast.w.y);
        RayHits hits;
        if (only) {
            // Set a register at a time: they are read as registers next, and a load of sixteen
            // lanes stored one by one waits for them to reach the cache.
            lanes16::Ints bit;
            for (int i = 0; i < kBatchLanes; ++i) bit[i] = 1 << i;
            const lanes16::Ints active = (bit & int(rays.active)) != 0, none = lanes16::Ints{} + int(kNoHit);
            const lanes16::Ints geometry = active ? lanes16::Ints{} + int(only->geometry) : none;
            const lanes16::Ints primitive = active ? lanes16::Ints{} + int(only->primitive) : none;
            std::memcpy(hits.geometry, &geometry, sizeof geometry), std::memcpy(hits.primitive, &primitive, sizeof primitive);
            lanes16::store(hits.t, lanes16::broadcast(1.0f));  // not read: it serves to cast again after a discard
        } else {
            if (tnear) std::copy_n(tnear, kBatchLanes, rays.tnear);
            lanes16::store(rays.origin, cast.r.origin), lanes16::store(rays.direction, cast.r.direction);
            bvh_.intersect(rays, hits);
        }
        const lanes16::Ints geometry = std::bit_cast<lanes16::Ints>(hits.geometry);
        const std::uint32_t missed = rays.active & lanes16::equal(geometry, lanes16::Ints{} + int(kNoHit));
        clear_lanes(bx, by, missed);
        if (missed == rays.active) return;
        if (rays.active == kAllLanes && whole_block(geometry, hits)) {
            whole.draw = hits.geometry[0], whole.bx = bx, whole.by = by;
            HitBatch& b = whole.batch;
            for (int i = 0; i < kBatchLanes; ++i) {
                b.lanes.x[i] = bx + kLaneDx[i], b.lanes.y[i] = by + kLaneDy[i];
                b.lane[i] = std::uint8_t(i), b.primitive[i] = hits.primitive[i], b.t[i] = hits.t[i];
            }
            b.lanes.count = kBatchLanes, b.lanes.write = kAllLanes;
            if (draws_[whole.draw].quads) count_quads(kBatchQuads);
            whole_block_cast();
            return;
        }
        for (int q = 0; q < kBatchQuads; ++q) {
            // Each primitive hit in the quad runs it once; done[] marks lanes already served.
            bool done[4] = {};
            for (int l = 0; l < 4; ++l) {
                const int lane = 4 * q + l;
                if (done[l] || hits.geometry[lane] == kNoHit) continue;
                const std::uint32_t g = hits.geometry[lane], p = hits.primitive[lane];
                std::uint32_t owned = 0;
                for (int k = l; k < 4; ++k) {
                    if (hits.geometry[4 * q + k] == g && hits.primitive[4 * q + k] == p) owned |= 1u << k, done[k] = true;
                }
                const PreparedDraw& d = draws_[g];
                for (int k = 0; k < 4; ++k) {
                    const int at = 4 * q + k;
                    if (d.quads || (owned >> k & 1)) append(g, at, bx + kLaneDx[at], by + kLaneDy[at], p, hits.t[at], owned >> k & 1);
                }
                count_quads(d.quads);
            }
        }
    }

    // Whether every lane of a block cast whole hit one draw (`geometry` is hits.geometry), so
    // that the block is shaded as it is, as one batch: with quads, each quad must lie on one
    // triangle (else it runs once per triangle, each time with its other lanes as helpers on that
    // triangle's plane).
    bool whole_block(const lanes16::Ints& geometry, const RayHits& hits) const {
        const std::uint32_t g = hits.geometry[0];
        if (g == kNoHit || lanes16::equal(geometry, lanes16::Ints{} + int(g)) != kAllLanes) return false;
        if (!draws_[g].quads) return true;
        const lanes16::Ints primitive = std::bit_cast<lanes16::Ints>(hits.primitive);
        const lanes16::Ints first = __builtin_shufflevector(primitive, primitive, 0, 0, 0, 0, 4, 4, 4, 4, 8, 8, 8, 8, 12,
                                                            12, 12, 12);  // each quad's first lane
        return lanes16::equal(primitive, first) == kAllLanes;
    }

    // A whole block was cast into pairs_.next(). Whole blocks are shaded two at a time, as the
    // rasterizer shades them: the first waits for the next of the same draw, or for finish().
    void whole_block_cast() {
        pairs_.add([](const WholeBlock& first, const WholeBlock& second) { return first.draw == second.draw; },
                   [&](const WholeBlock& first, const WholeBlock& second) {
                       const PreparedDraw& d = draws_[first.draw];
                       set_up(d, meshes_[first.draw], first.batch, &first.cast, in_[0]);
                       set_up(d, meshes_[second.draw], second.batch, &second.cast, in_[1]);
                       shade_pair(d);
                       write_whole(first, 0);
                       write_whole(second, 1);
                   },
                   [&](const WholeBlock& w) { shade_whole(w); });
    }

    // Shades and writes whole block w alone.
    void shade_whole(const WholeBlock& w) {
        shade(w.draw, w.batch, &w.cast);
        write_whole(w, 0);
    }

    // Writes out_[h], shaded for whole block w: four rows at once (it lies inside the image:
    // every lane was cast), streamed, as every whole block (a ray caster writes each pixel once a
    // frame).
    void write_whole(const WholeBlock& w, int h) {
        if (out_[h].discarded != 0) return write(w.draw, w.batch, h);
        TileWriter::write_whole(draws_[w.draw], h, w.bx, w.by, RowStores::Streamed);
    }

    // Shades what waits: the gathered batches and a whole block.
    void finish() {
        for (std::size_t g = 0; g < pending_.size(); ++g) flush(g);
        pairs_.flush([&](const WholeBlock& w) { shade_whole(w); });
    }

    // GLSL discard leaves the pixel to whatever lies behind: the rays of discarded fragments
    // are cast again from just past their hit, block by block, until they meet a fragment that
    // is kept or nothing (the clear colour), as depth testing would have it.
    void cast_past_discards() {
        while (!discarded_.empty()) {
            std::vector<Discarded> now;
            now.swap(discarded_);
            std::sort(now.begin(), now.end(), [](const Discarded& a, const Discarded& b) {
                return std::tie(a.by, a.bx) < std::tie(b.by, b.bx);
            });
            for (std::size_t i = 0; i < now.size();) {
                float tnear[kBatchLanes] = {};
                std::uint32_t lanes = 0;
                std::size_t j = i;
                for (; j < now.size() && now[j].bx == now[i].bx && now[j].by == now[i].by; ++j) {
                    lanes |= 1u << now[j].lane;
                    tnear[now[j].lane] = std::nextafter(now[j].t, 2.0f);
                }
                block(now[i].bx, now[i].by, lanes, tnear);
                i = j;
            }
            finish();
        }
    }

    // Quads are appended four lanes at a time and batches hold whole quads, so they stay aligned.
    void append(std::uint32_t g, int lane, int x, int y, std::uint32_t primitive, float t, bool write) {
        HitBatch& b = pending_[g];
        const int i = b.lanes.count;
        b.primitive[i] = primitive, b.lane[i] = std::uint8_t(lane), b.t[i] = t;
        if (b.lanes.add(x, y, write)) flush(g);
    }

    // The centres of pixels (x, y) in framebuffer coordinates (y down), in GL window coordinates.
    WindowPoints centres(const lanes16::Ints& x, const lanes16::Ints& y) const {
        return {lanes16::to_double(x) + 0.5, fb_.height - (lanes16::to_double(y) + 0.5)};
    }

    // The fragments of batch `b`, into `in`: each lane's ray meets its triangle's plane at P; the
    // attributes there are the vertices' weighted by P's barycentric coordinates, which is
    // perspective-correct interpolation (a GPU's a/w over 1/w is the same point seen from the
    // screen). For a helper lane P lies outside the triangle and the weights extrapolate.
    // `cast`: the batch is a whole block, in lane order, and these are its rays.
    void set_up(const PreparedDraw& d, const Mesh& m, const HitBatch& b, const BlockRays* cast, FragmentBatch& in) {
        using namespace lanes16;
        const LaneBatch& at = b.lanes;
        // Unused lanes repeat lane 0 (and write nothing). Padded in a register and stored whole:
        // PrimitiveGroups loads all sixteen at once, which waits for sixteen separate stores to
        // reach the cache (a load spanning several stores is not forwarded).
        const Ints hit = std::bit_cast<Ints>(b.primitive);
        Ints lane;
        for (int i = 0; i < kBatchLanes; ++i) lane[i] = i;
        const Ints padded = lane < at.count ? hit : Ints{} + hit[0];
        alignas(64) std::uint32_t primitive[kBatchLanes];
        std::memcpy(primitive, &padded, sizeof primitive);
        const PrimitiveGroups groups(primitive);
        in.front_facing = 0;
        for (int i = 0; i < kBatchLanes; ++i) in.front_facing |= std::uint32_t(m.front[primitive[i]]) << i;
        auto plane = [&](const glm::dvec3 TrianglePlane::*v) {
            auto component = [&](int c) {
                return groups.spread_doubles([&](int g) { return (m.planes[groups.primitive[g]].*v)[c]; });
            };
            return Doubles3{component(0), component(1), component(2)};
        };
        // The ray parameter first, so that its division runs while the attributes are spread below.
        const Doubles3 p0 = plane(&TrianglePlane::p0), n = plane(&TrianglePlane::n);
        Eye::Rays own;
        const WindowPoints w = cast ? cast->w : centres(load(at.x), load(at.y));
        const Eye::Rays& r = cast ? cast->r : (own = eye_.rays(w.x, w.y));
        const Doubles per_dn = 1.0 / dot(r.direction, n);
        const Doubles t = dot(p0 - r.origin, n) * per_dn;
        const Doubles3 to_b1 = plane(&TrianglePlane::to_b1), to_b2 = plane(&TrianglePlane::to_b2);
        // The vertices' attributes, per varying and lane.
        alignas(64) float a[3][kMaxVaryings][kBatchLanes];
        for (int c = 0; c < 3; ++c) {
            for (int v = 0; v < d.varyings; ++v) {
                store(a[c][v], groups.spread_floats([&](int g) {
                    return m.out[m.triangles[groups.primitive[g]][std::size_t(c)]].varyings[std::size_t(v)];
                }));
            }
        }
        const Doubles3 rel = r.origin + t * r.direction - p0;
        // Barycentric weights of vertices 1 and 2 (TrianglePlane).
        const Doubles b1 = dot(rel, to_b1), b2 = dot(rel, to_b2);
        const Doubles b0 = 1.0 - b1 - b2;
        // gl_FragCoord where the shader reads it (its depth and 1/w cost a projection and two
        // divisions); elsewhere NaN, as the rasterizer leaves it.
        const Floats nan = broadcast(std::numeric_limits<float>::quiet_NaN());
        Doubles4 clip{};
        if (d.frag_coord) {
            clip = transform(eye_.clip_from_world, p0 + rel, 1.0);
            store(in.frag_coord[0], to_float(w.x));
            store(in.frag_coord[1], to_float(w.y));
            store(in.frag_coord[2], to_float(0.5 * clip.z / clip.w + 0.5));
            store(in.frag_coord[3], to_float(1.0 / clip.w));
        } else {
            for (float(&c)[kBatchLanes] : in.frag_coord) store(c, nan);
        }
        for (int v = 0; v < d.varyings; ++v) {
            const Floats a0 = load(a[0][v]), a1 = load(a[1][v]), a2 = load(a[2][v]);
            const bool flat = d.flat >> v & 1;  // the provoking vertex's: the last
            store(in.varying[v], flat ? a2 : to_float(b0 * to_double(a0) + b1 * to_double(a1) + b2 * to_double(a2)));
        }
        if (d.mode.derivatives != Derivatives::Analytic) return;
        // Igehy's transfer: the hit moves along the surface as the ray moves with the pixel,
        // dP = dO + t dD + dt D with dt = -((dO + t dD) . n) / (D . n); the weights' derivatives
        // follow from dP as the weights from P, and everything else by the chain rule.
        const Eye::Differentials rd = eye_.differentials(r);
        auto carry = [&](const Doubles3& dorigin, const Doubles3& ddirection, float (&dvarying)[kMaxVaryings][kBatchLanes],
                         float (&dfrag)[2][kBatchLanes]) {
            const Doubles3 moved = dorigin + t * ddirection;
            const Doubles3 dp = moved - (dot(moved, n) * per_dn) * r.direction;
            const Doubles db1 = dot(dp, to_b1), db2 = dot(dp, to_b2);
            if (d.frag_coord) {
                const Doubles4 dclip = transform(eye_.clip_from_world, dp, 0.0);
                store(dfrag[0], to_float(0.5 * (dclip.z * clip.w - clip.z * dclip.w) / (clip.w * clip.w)));
                store(dfrag[1], to_float(-dclip.w / (clip.w * clip.w)));
            } else {
                store(dfrag[0], nan), store(dfrag[1], nan);
            }
            for (int v = 0; v < d.varyings; ++v) {
                const Floats a0 = load(a[0][v]), a1 = load(a[1][v]), a2 = load(a[2][v]);
                const bool flat = d.flat >> v & 1;
                store(dvarying[v], flat ? Floats{} : to_float(db1 * to_double(a1 - a0) + db2 * to_double(a2 - a0)));
            }
        };
        carry(rd.origin_dx, rd.direction_dx, in.varying_dx, in.frag_coord_dx);
        carry(rd.origin_dy, rd.direction_dy, in.varying_dy, in.frag_coord_dy);
    }

    void flush(std::size_t g) {
        HitBatch& b = pending_[g];
        if (b.lanes.count == 0) return;
        b.lanes.pad();
        shade(g, b, nullptr);
        write(g, b, 0);
        b.lanes.clear();
    }

    // Shades batch b of draw g into out_[0].
    void shade(std::size_t g, const HitBatch& b, const BlockRays* cast) {
        const PreparedDraw& d = draws_[g];
        set_up(d, meshes_[g], b, cast, in_[0]);
        TileWriter::shade(d, b.lanes.count);
    }

    // Writes the lanes of batch b of draw g, shaded into out_[h], lane by lane; the ones that
    // discarded wait to be cast again.
    void write(std::size_t g, const HitBatch& b, int h) {
        const PreparedDraw& d = draws_[g];
        const LaneBatch& at = b.lanes;
        for (int i = 0; i < at.count; ++i) {
            if (!(at.write >> i & 1)) continue;
            if (out_[h].discarded >> i & 1) {
                discarded_.push_back({at.x[i] - kLaneDx[b.lane[i]], at.y[i] - kLaneDy[b.lane[i]], b.lane[i], b.t[i]});
                continue;
            }
            write_lane(d, h, i, at.x[i], at.y[i]);
        }
    }

    const EmbreeScene& bvh_;
    const Eye& eye_;
    const std::vector<PreparedDraw>& draws_;
    const std::vector<Mesh>& meshes_;  // per draw
    const BlockCoverage& covered_;     // what each block's rays may hit
    std::vector<HitBatch> pending_;    // per draw
    BlockPairs<WholeBlock> pairs_;
    // Fragments that discarded: their block, lane and where their ray met the surface.
    struct Discarded {
        int bx, by, lane;
        float t;
    };
    std::vector<Discarded> discarded_;
};

// Runs every draw's vertex stage into meshes[i].out.
void run_vertex_stages(std::span<const DrawCall> draws, std::vector<Mesh>& meshes) {
    for (std::size_t i = 0; i < draws.size(); ++i) meshes[i].out = run_vertex_stage(draws[i]);
}

}  // namespace

struct RayCaster::Impl {
    Eye eye;
    std::vector<Mesh> meshes;
    std::unique_ptr<EmbreeScene> bvh;
    std::unique_ptr<ScreenFootprint> footprint;  // the BVH's triangles seen by the eye
    double build_seconds = 0.0;

    // World positions from this frame's gl_Position; true when they differ from the BVH's.
    bool update_positions() {
        bool moved = false;
        for (Mesh& m : meshes) {
            m.world.resize(m.out.size());
            for (std::size_t v = 0; v < m.out.size(); ++v) {
                const glm::dvec4 h = eye.world_from_clip * glm::dvec4(m.out[v].clip);
                const glm::dvec3 p = glm::dvec3(h) / h.w;
                moved |= std::memcmp(&p, &m.world[v], sizeof p) != 0;  // bitwise: NaN equals itself
                m.world[v] = p;
            }
        }
        return moved;
    }

    void build(std::span<const DrawCall> draws) {
        std::unique_ptr<EmbreeScene> scene = EmbreeScene::create();  // the first loads Embree: not the BVH's time
        const auto start = std::chrono::steady_clock::now();
        auto seen = std::make_unique<ScreenFootprint>(eye.clip_from_world, eye.world_from_clip);
        std::vector<glm::vec3> positions;
        for (std::size_t i = 0; i < meshes.size(); ++i) {
            Mesh& m = meshes[i];
            positions.assign(m.world.begin(), m.world.end());
            // Triangles with a vertex that is not finite are left out, as the rasterizer drops them.
            m.triangles.clear(), m.planes.clear(), m.front.clear();
            const auto& idx = draws[i].indices;
            for (std::size_t k = 0; k + 2 < idx.size(); k += 3) {
                const Triangle t{idx[k], idx[k + 1], idx[k + 2]};  // in range: run_vertex_stage checked
                auto finite = [&](std::uint32_t v) {
                    return std::isfinite(positions[v].x) && std::isfinite(positions[v].y) && std::isfinite(positions[v].z);
                };
                if (!finite(t[0]) || !finite(t[1]) || !finite(t[2])) continue;
                // Culled triangles are left out: the BVH holds what the eye sees from one side.
                const double turn = clip_winding(m.out[t[0]].clip, m.out[t[1]].clip, m.out[t[2]].clip);
                if (m.culling.cull_back) {
                    if (turn == 0.0 || !m.culling.keeps(turn > 0.0 ? Winding::CounterClockwise : Winding::Clockwise)) continue;
                }
                for (std::uint32_t v : t) {
                    if (!within_embree_range(m.world[v])) {
                        throw RayCastError("ray caster: vertex " + std::to_string(v) + " of draw " + std::to_string(i) +
                                           " lies beyond +-1.8e18, where Embree cannot trace it; the rasterizer "
                                           "(--backend raster) can draw it");
                    }
                }
                m.triangles.push_back(t);
                m.planes.emplace_back(m.world[t[0]], m.world[t[1]], m.world[t[2]]);
                m.front.push_back(turn > 0.0);
                seen->add(m.world[t[0]], m.world[t[1]], m.world[t[2]],
                          TriangleId{std::uint32_t(i), std::uint32_t(m.triangles.size() - 1)});
            }
            scene->add_mesh(positions, m.triangles);
        }
        scene->commit();
        bvh = std::move(scene), footprint = std::move(seen);
        build_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
};

RayCaster::RayCaster(std::span<const DrawCall> draws, const glm::mat4& clip_from_world) : impl_(std::make_unique<Impl>()) {
    impl_->eye.clip_from_world = glm::dmat4(clip_from_world);
    impl_->eye.world_from_clip = glm::inverse(impl_->eye.clip_from_world);
    impl_->meshes.resize(draws.size());
    for (std::size_t i = 0; i < draws.size(); ++i) impl_->meshes[i].culling = draws[i].culling;
    const FlushDenormals ftz;  // as every frame's geometry (TileFrame)
    run_vertex_stages(draws, impl_->meshes);
    impl_->update_positions();
    impl_->build(draws);
}

RayCaster::~RayCaster() = default;

double RayCaster::build_seconds() const { return impl_->build_seconds; }

void RayCaster::render_into(Framebuffer& fb, int width, int height, glm::vec4 clear, std::span<const DrawCall> draws,
                            const ShadingSettings& options, RenderStats* stats_out, RowBand band) {
    Impl& im = *impl_;
    TileFrame frame(width, height, band, draws, options);
    const std::vector<PreparedDraw>& prepared = frame.draws();
    // Rays meet the surface in 3D: nothing is interpolated in the window or clipped by a plane.
    // Each pixel is its nearest surface's: nothing is blended.
    for (const PreparedDraw& p : prepared) {
        if (p.noperspective || p.call->clip_distances || p.call->blend) {
            throw UnsupportedRequest("the ray caster has no noperspective varyings, user clip planes or blending: "
                                     "those are the rasterizer's");
        }
    }
    if (draws.size() != im.meshes.size()) throw std::invalid_argument("ray caster: the draws are not the ones its BVH holds");
    for (std::size_t i = 0; i < draws.size(); ++i) {
        if (draws[i].vertices.size() != im.meshes[i].out.size()) {
            throw std::invalid_argument("ray caster: draw " + std::to_string(i) + " has other vertices than its BVH");
        }
    }
    run_vertex_stages(draws, im.meshes);
    bool culling_changed = false;
    for (std::size_t i = 0; i < draws.size(); ++i) {
        culling_changed |= im.meshes[i].culling != draws[i].culling;
        im.meshes[i].culling = draws[i].culling;
    }
    if (im.update_positions() || culling_changed) im.build(draws);

    RenderStats& stats = frame.stats();
    for (std::size_t i = 0; i < draws.size(); ++i) {
        stats.triangles_in += draws[i].indices.size() / 3;
        stats.triangles_setup += im.meshes[i].triangles.size();
    }
    im.eye.ndc_per_x = 2.0 / width, im.eye.ndc_per_y = 2.0 / height;
    check_rays(im.eye, width, height);

    const TileGrid& grid = frame.grid();
    const BlockCoverage& covered = im.footprint->blocks(width, height, grid.y0(0), grid.y0(0) + grid.rows * kTileSize);
    frame.render_tiles<TileCaster>(
        fb, false,
        [&] { return std::make_unique<TileCaster>(fb, *im.bvh, im.eye, prepared, im.meshes, covered, clear); },
        [&](TileCaster& caster, int i) { caster.tile(grid.x0(i), grid.y0(i)); }, stats_out);
}

}  // namespace qs
