#include "rasterizer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "clipper.h"
#include "fixed_point.h"
#include "triangle_setup.h"

namespace qs {

namespace {

inline constexpr int kMaxDimension = 1 << 15;  // larger images exceed the guard band's intent

// A draw's vertex stage output and the mode its fragments are shaded in.
struct PreparedDraw {
    const DrawCall* call;
    ShadeMode mode;
    bool quads;       // shade 2x2 quads with helper lanes
    bool depth_test;  // LESS test and depth write
    int varyings;
};

// Fragments waiting to be shaded: kBatchLanes pixel positions (framebuffer coordinates) and
// which lanes write. In quad mode lanes 4q..4q+3 form quad q in the layout of number/lanes.h.
struct Batch {
    int x[kBatchLanes], y[kBatchLanes];
    bool write[kBatchLanes];
    int count = 0;
};

class TileRenderer {
public:
    TileRenderer(Framebuffer& fb, const std::vector<PreparedDraw>& draws, int quad_row0)
        : fb_(fb), draws_(draws), quad_row0_(quad_row0) {}

    void render(const TriangleSetup& t, int x0, int y0, int x1, int y1) {
        const PreparedDraw& d = draws_[t.draw];
        tri_ = &t;
        draw_ = &d;
        batch_.count = 0;
        const int bx0 = std::max(x0, t.min_x), bx1 = std::min(x1, t.max_x);
        const int by0 = std::max(y0, t.min_y), by1 = std::min(y1, t.max_y);
        if (bx0 > bx1 || by0 > by1) return;
        if (d.quads) {
            // Quads aligned to even x and to the pairing's row grid.
            const int qx0 = bx0 & ~1;
            const int qy0 = quad_row0_ + (((by0 - quad_row0_) >> 1) << 1);
            for (int qy = qy0; qy <= by1; qy += 2) {
                for (int qx = qx0; qx <= bx1; qx += 2) add_quad(qx, qy);
            }
        } else {
            for (int y = by0; y <= by1; ++y) {
                for (int x = bx0; x <= bx1; ++x) {
                    if (covered(x, y) && depth_passes(x, y)) add_pixel(x, y);
                }
            }
        }
        flush();
    }

private:
    bool covered(int x, int y) const {
        if (x < 0 || y < 0 || x >= fb_.width || y >= fb_.height) return false;  // scissor
        const auto& e = tri_->edges;
        return e[0].inside(x, y) && e[1].inside(x, y) && e[2].inside(x, y);
    }

    bool depth_passes(int x, int y) const {
        if (!draw_->depth_test) return true;
        const float z = tri_->z.at(float(x), float(y));
        return z < fb_.depth[std::size_t(y) * std::size_t(fb_.width) + std::size_t(x)];
    }

    void add_pixel(int x, int y) {
        const int i = batch_.count++;
        batch_.x[i] = x, batch_.y[i] = y, batch_.write[i] = true;
        if (batch_.count == kBatchLanes) flush();
    }

    // Quad at framebuffer (qx, qy) = its top-left pixel. Lanes in GL order: 0,1 the lower row
    // (framebuffer row qy+1), 2,3 the upper row (qy).
    void add_quad(int qx, int qy) {
        const int lx[4] = {qx, qx + 1, qx, qx + 1};
        const int ly[4] = {qy + 1, qy + 1, qy, qy};
        bool write[4];
        bool any = false;
        for (int l = 0; l < 4; ++l) {
            write[l] = covered(lx[l], ly[l]) && depth_passes(lx[l], ly[l]);
            any |= write[l];
        }
        if (!any) return;  // no lane would write: the quad does not run
        const int base = batch_.count;
        for (int l = 0; l < 4; ++l) {
            batch_.x[base + l] = lx[l], batch_.y[base + l] = ly[l], batch_.write[base + l] = write[l];
        }
        batch_.count += 4;
        ++quads_;
        if (batch_.count == kBatchLanes) flush();
    }

    void flush() {
        if (batch_.count == 0) return;
        const TriangleSetup& t = *tri_;
        const PreparedDraw& d = *draw_;
        // Unused lanes repeat lane 0 (a valid position) and write nothing.
        for (int i = batch_.count; i < kBatchLanes; ++i) {
            batch_.x[i] = batch_.x[0], batch_.y[i] = batch_.y[0], batch_.write[i] = false;
        }
        const float height = float(fb_.height);
        float fx[kBatchLanes], fy[kBatchLanes], inv_w[kBatchLanes], rcp_inv_w[kBatchLanes];
        for (int i = 0; i < kBatchLanes; ++i) {
            fx[i] = float(batch_.x[i]);
            fy[i] = float(batch_.y[i]);
            inv_w[i] = t.inv_w.at(fx[i], fy[i]);
            rcp_inv_w[i] = 1.0f / inv_w[i];
            in_.frag_coord[0][i] = fx[i] + 0.5f;
            in_.frag_coord[1][i] = height - (fy[i] + 0.5f);  // GL window y points up
            in_.frag_coord[2][i] = t.z.at(fx[i], fy[i]);
            in_.frag_coord[3][i] = inv_w[i];
        }
        for (int v = 0; v < d.varyings; ++v) {
            const PlaneEquation& p = t.varyings[v];
            for (int i = 0; i < kBatchLanes; ++i) in_.varying[v][i] = p.at(fx[i], fy[i]) * rcp_inv_w[i];
        }
        if (d.mode.derivatives == Derivatives::Analytic) {
            // value = A / W with A, W linear: d(value)/dx = (dA/dx - value dW/dx) / W.
            // Framebuffer y points down, GL's up: d/dy_GL = -d/dy_framebuffer.
            for (int v = 0; v < d.varyings; ++v) {
                const PlaneEquation& p = t.varyings[v];
                for (int i = 0; i < kBatchLanes; ++i) {
                    const float value = in_.varying[v][i];
                    in_.varying_dx[v][i] = (p.dadx - value * t.inv_w.dadx) * rcp_inv_w[i];
                    in_.varying_dy[v][i] = -(p.dady - value * t.inv_w.dady) * rcp_inv_w[i];
                }
            }
            in_.z_dx = t.z.dadx, in_.z_dy = -t.z.dady;
            in_.inv_w_dx = t.inv_w.dadx, in_.inv_w_dy = -t.inv_w.dady;
        }
        d.call->program->shade(d.mode, in_, d.call->uniforms, out_);
        lanes_ += std::uint64_t(batch_.count);
        for (int i = 0; i < batch_.count; ++i) {
            if (!batch_.write[i]) continue;
            float* px = fb_.pixel(batch_.x[i], batch_.y[i]);
            for (int c = 0; c < 4; ++c) px[c] = out_.rgba[c][i];
            if (d.depth_test) {
                fb_.depth[std::size_t(batch_.y[i]) * std::size_t(fb_.width) + std::size_t(batch_.x[i])] =
                    in_.frag_coord[2][i];
            }
            ++written_;
        }
        batch_.count = 0;
    }

public:
    std::uint64_t quads() const { return quads_; }
    std::uint64_t lanes() const { return lanes_; }
    std::uint64_t written() const { return written_; }

private:
    Framebuffer& fb_;
    const std::vector<PreparedDraw>& draws_;
    int quad_row0_;
    std::uint64_t quads_ = 0, lanes_ = 0, written_ = 0;
    const TriangleSetup* tri_ = nullptr;
    const PreparedDraw* draw_ = nullptr;
    Batch batch_;
    FragmentBatch in_;
    ColorBatch out_;
};

}  // namespace

int quad_row_offset(int height, QuadPairing pairing) {
    // Top-down pairing: framebuffer rows (2k, 2k+1), offset 0. Bottom-up: GL rows (2k, 2k+1) are
    // framebuffer rows (H-2-2k, H-1-2k), so at an odd height the grid starts at row -1.
    return (pairing == QuadPairing::BottomUp && (height & 1)) ? -1 : 0;
}

Framebuffer rasterize(int width, int height, glm::vec4 clear, std::span<const DrawCall> draws,
                      const RasterOptions& options, RasterStats* stats_out) {
    if (width <= 0 || height <= 0 || width > kMaxDimension || height > kMaxDimension) {
        throw std::invalid_argument("image size " + std::to_string(width) + "x" + std::to_string(height) +
                                    " is outside 1.." + std::to_string(kMaxDimension));
    }
    std::vector<PreparedDraw> prepared;
    bool any_depth = options.force_general_path;
    for (const DrawCall& call : draws) {
        if (!call.program) throw std::invalid_argument("draw call without a program");
        const Needs& needs = call.program->info().needs;
        PreparedDraw d{&call, {options.derivatives, options.precision}, true, needs.depth, needs.varyings};
        if (!needs.derivatives && !options.force_general_path) {
            d.mode.derivatives = Derivatives::None;  // per pixel, no helper lanes
            d.quads = false;
        } else if (d.mode.derivatives == Derivatives::None) {
            d.mode.derivatives = needs.derivatives ? Derivatives::Fine : Derivatives::None;
            d.quads = needs.derivatives;
        } else if (d.mode.derivatives == Derivatives::Analytic) {
            d.quads = false;  // Dual2 carries derivatives: no neighbours needed
        }
        if (options.force_general_path) d.depth_test = true;
        any_depth |= d.depth_test;
        prepared.push_back(d);
    }

    std::unique_ptr<tbb::global_control> limit;
    if (options.threads > 0) {
        limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      std::size_t(options.threads));
    }

    RasterStats stats;
    // Vertex stage, clipping and setup, per draw, triangles kept in submission order.
    const float guard_x = fixed::kGuardBand / (float(width) * 0.5f) - 1.0f;
    const float guard_y = fixed::kGuardBand / (float(height) * 0.5f) - 1.0f;
    std::vector<TriangleSetup> triangles;
    for (std::size_t di = 0; di < prepared.size(); ++di) {
        const DrawCall& call = *prepared[di].call;
        std::vector<ClipVertex> verts(call.vertices.size());
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, verts.size(), 256), [&](const auto& r) {
            for (std::size_t i = r.begin(); i != r.end(); ++i) {
                VertexOut out;
                call.program->vertex(call.vertices[i], call.uniforms, out);
                verts[i] = {out.clip, out.varyings};
            }
        });
        std::vector<std::array<ClipVertex, 3>> clipped;
        for (std::size_t i = 0; i + 2 < call.indices.size(); i += 3) {
            ++stats.triangles_in;
            const std::uint32_t a = call.indices[i], b = call.indices[i + 1], c = call.indices[i + 2];
            if (a >= verts.size() || b >= verts.size() || c >= verts.size()) {
                throw std::invalid_argument("triangle " + std::to_string(i / 3) + " indexes vertex " +
                                            std::to_string(std::max({a, b, c})) + " of " +
                                            std::to_string(verts.size()));
            }
            clipped.clear();
            clip_triangle(verts[a], verts[b], verts[c], prepared[di].varyings, guard_x, guard_y, clipped);
            for (const auto& tri : clipped) {
                if (auto t = setup_triangle(tri, prepared[di].varyings, width, height, options.fill_rule)) {
                    t->draw = int(di);
                    triangles.push_back(*t);
                }
            }
        }
    }
    stats.triangles_setup = triangles.size();

    // Binning: tile rows follow the quad grid so that no quad straddles two tiles.
    const int row0 = quad_row_offset(height, options.pairing);
    const int tiles_x = (width + kTileSize - 1) / kTileSize;
    const int tiles_y = (height - row0 + kTileSize - 1) / kTileSize;
    std::vector<std::vector<std::uint32_t>> bins(std::size_t(tiles_x) * std::size_t(tiles_y));
    for (std::uint32_t i = 0; i < triangles.size(); ++i) {
        const TriangleSetup& t = triangles[i];
        const int tx0 = t.min_x / kTileSize, tx1 = t.max_x / kTileSize;
        const int ty0 = (t.min_y - row0) / kTileSize, ty1 = (t.max_y - row0) / kTileSize;
        for (int ty = ty0; ty <= ty1; ++ty) {
            for (int tx = tx0; tx <= tx1; ++tx) bins[std::size_t(ty) * std::size_t(tiles_x) + std::size_t(tx)].push_back(i);
        }
    }

    Framebuffer fb(width, height, clear, any_depth);
    std::atomic<std::uint64_t> quads{0}, lanes{0}, written{0};
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, bins.size(), 1), [&](const auto& r) {
        for (std::size_t b = r.begin(); b != r.end(); ++b) {
            const int tx = int(b % std::size_t(tiles_x)), ty = int(b / std::size_t(tiles_x));
            const int x0 = tx * kTileSize, y0 = row0 + ty * kTileSize;
            TileRenderer tile(fb, prepared, row0);
            for (std::uint32_t i : bins[b]) tile.render(triangles[i], x0, y0, x0 + kTileSize - 1, y0 + kTileSize - 1);
            quads += tile.quads(), lanes += tile.lanes(), written += tile.written();
        }
    });
    stats.quads = quads, stats.lanes_shaded = lanes, stats.pixels_written = written;
    if (stats_out) *stats_out = stats;
    return fb;
}

}  // namespace qs
