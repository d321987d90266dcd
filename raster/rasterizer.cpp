#include "raster/rasterizer.h"

#include <algorithm>
#include <array>
#include <bit>
#include <bitset>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "core/block_layout.h"
#include "core/block_rows.h"
#include "core/lane_batch.h"
#include "core/lanes16.h"
#include "core/prepared_draw.h"
#include "core/tile_frame.h"
#include "core/tile_writer.h"
#include "core/vertex_stage.h"
#include "raster/clipper.h"
#include "raster/depth_buffer.h"
#include "raster/fragment_inputs.h"
#include "raster/triangle_setup.h"

namespace qs {

namespace {

// Each lane's pixel offset in its block (block_layout.h) as 64-bit lanes, for the edge functions.
lanes16::Longs lane_offsets(const int (&d)[kBatchLanes]) {
    lanes16::Longs v;
    for (int i = 0; i < kBatchLanes; ++i) v[i] = d[i];
    return v;
}
const lanes16::Longs kLaneDx64 = lane_offsets(kLaneDx), kLaneDy64 = lane_offsets(kLaneDy);

// Whether no pixel centre of the tile at (x0, y0) lies inside t: the blocks' test in
// TileRenderer::block, once for the whole tile. A large triangle misses many of the tiles its
// bounding box touches (half of them for either triangle of a square).
bool misses_tile(const TriangleSetup& t, int x0, int y0) {
    for (const EdgeFunction& e : t.edges) {
        if (e.at(x0, y0) + e.most_offset(kTileSize) <= 0) return true;
    }
    return false;
}

// Renders the triangles of one tile, in submission order, straight into the tile's part of the
// framebuffer (no thread else writes there, so the result is the same for any thread count),
// through its TileWriter. Whole blocks' rows are streamed past the caches where they are final:
// the tile's last triangle writing a block no other wrote, and the clear colour of blocks none
// wrote (streaming more, or from a tile buffer, measures slower: docs/design.md, The renderer
// core).
// Blocks are cleared lazily: a block's first partial write clears it first, blocks never
// written are cleared by finish(), and a block covered at once is never cleared at all.
// Depth, when the frame needs it, stays tile-local in lane order, as the 24-bit values the
// reference's depth buffer holds (depth_buffer.h), and is stored once at the end.
class TileRenderer : public TileWriter {
public:
    // `clear`: the colour of what no triangle writes (none: the framebuffer keeps it);
    // `depth_test`: LESS test and depth write, for every draw of the frame or none; `fused`: fused
    // plane evaluation; `general`: every depth tested, even where it provably passes.
    TileRenderer(Framebuffer& fb, const std::vector<PreparedDraw>& draws, const std::optional<glm::vec4>& clear,
                 bool depth_test, bool fused, bool general)
        : TileWriter(fb, clear), draws_(draws), depth_test_(depth_test), fused_(fused), general_(general) {}

    // Starts the tile whose top-left pixel is (x0, y0); one renderer per thread renders its tiles
    // one after the other.
    void start(int x0, int y0) {
        x0_ = x0, y0_ = y0;
        touched_.reset();
        if (!fb_.depth.empty()) std::fill_n(depth_, kTilePixels, kDepthCleared);
    }

    // Clears the blocks no triangle wrote and stores the depth.
    void finish() {
        if (clears() && !touched_.all()) {
            for (int block = 0; block < kTileBlocks; ++block) {
                if (!touched_[std::size_t(block)]) clear_block(block_x(block), block_y(block), RowStores::Streamed);
            }
        }
        if (fb_.depth.empty()) return;
        for (int block = 0; block < kTileBlocks; ++block) {
            const int x = block_x(block), y = block_y(block);
            const int n = std::min(kBlock, fb_.width - x);
            if (n <= 0) continue;
            // The block's sixteen divisions in one instruction, each lane's the scalar one's, then
            // its rows in pixel order in one shuffle: a block inside the image is stored a row at
            // a time, not lane by lane with a bounds test per pixel.
            const lanes16::Floats d = lanes16::load(&depth_[block * kBatchLanes]) / kDepthCleared;
            alignas(64) float rows[kBatchLanes];
            lanes16::store(rows, __builtin_shufflevector(d, d, kLaneAt[0][0], kLaneAt[0][1], kLaneAt[0][2], kLaneAt[0][3],
                                                         kLaneAt[1][0], kLaneAt[1][1], kLaneAt[1][2], kLaneAt[1][3],
                                                         kLaneAt[2][0], kLaneAt[2][1], kLaneAt[2][2], kLaneAt[2][3],
                                                         kLaneAt[3][0], kLaneAt[3][1], kLaneAt[3][2], kLaneAt[3][3]));
            const bool whole = n == kBlock && y >= 0 && y + kBlock <= fb_.height;
            for (int r = 0; r < kBlock; ++r) {
                if (y + r < 0 || y + r >= fb_.height) continue;
                float* depth = &fb_.depth[fb_.index(x, y + r)];
                if (whole) {
                    std::memcpy(depth, &rows[kBlock * r], kBlock * sizeof(float));
                } else {
                    for (int dx = 0; dx < n; ++dx) depth[dx] = rows[kBlock * r + dx];
                }
            }
        }
    }

    // Rasterizes triangle t inside the tile whose pixels are [x0, x1] x [y0, y1]; the tile's origin
    // lies on the quad grid. `last`: no later triangle of the tile reaches it.
    void render(const TriangleSetup& t, int x0, int y0, int x1, int y1, bool last) {
        const PreparedDraw& d = draws_[t.draw];
        draw_ = &d;
        last_ = last;
        // Built in place: assigned from a temporary, it was built on the stack in small stores
        // and copied with 64-byte loads, each waiting for those stores to reach the cache.
        static_assert(std::is_trivially_destructible_v<FragmentInputs>);
        std::construct_at(&inputs_, t, d, depth_test_, fb_.height);
        pending_.clear();
        in_[0].front_facing = in_[1].front_facing = t.front ? ~0u : 0u;
        if (!d.frag_coord && frag_coord_set_) {
            // A shader that reads gl_FragCoord without saying so reads NaN, not the last draw's.
            for (FragmentBatch& in : in_) {
                std::fill_n(&in.frag_coord[0][0], 4 * kBatchLanes, std::numeric_limits<float>::quiet_NaN());
            }
        }
        frag_coord_set_ = d.frag_coord || depth_test_;
        const int lo_x = std::max(x0, t.min_x), hi_x = std::min(x1, t.max_x);
        const int lo_y = std::max(y0, t.min_y), hi_y = std::min(y1, t.max_y);
        if (lo_x > hi_x || lo_y > hi_y) return;  // (and t reaches the tile: binning)
        // A triangle covering the whole tile is shaded a block pair at a time, without coverage
        // or depth tests, where every fragment passes: without a depth buffer, or as the tile's
        // first (its depths all still the cleared 1, which LESS passes for any depth below 1; a
        // backdrop drawn first, as Figure 1.1's ground plane).
        if (covers_tile(t, x0, y0) && (!depth_test_ || (!general_ && touched_.none() && !may_reach_depth_one(t)))) {
            if (fused_) {
                shade_tile<true>(x0, y0);
            } else {
                shade_tile<false>(x0, y0);
            }
            if (d.quads) count_quads(kTileBlocks * kBatchQuads);
            return;
        }
        // Each edge function at the blocks' top-left pixels, stepped block to block, and its
        // largest and smallest offset from there over the block's pixel centres.
        BlockEdges edges;
        for (int k = 0; k < 3; ++k) {
            const EdgeFunction& e = t.edges[std::size_t(k)];
            edges.most[k] = e.most_offset(kBlock);
            edges.least[k] = e.least_offset(kBlock);
            edges.lane[k] = e.dcdx * kLaneDx64 + e.dcdy * kLaneDy64;
        }
        const int bx0 = x0 + ((lo_x - x0) & ~(kBlock - 1));
        for (int by = y0 + ((lo_y - y0) & ~(kBlock - 1)); by <= hi_y; by += kBlock) {
            for (int k = 0; k < 3; ++k) edges.at[k] = t.edges[std::size_t(k)].at(bx0, by);
            for (int bx = bx0; bx <= hi_x; bx += kBlock) {
                block(bx, by, edges);
                for (int k = 0; k < 3; ++k) edges.at[k] += t.edges[std::size_t(k)].dcdx * kBlock;
            }
        }
        flush_blocks();
        flush(pending_);
    }

    // Whether the tile at (x0, y0) lies inside the image and every pixel centre of it inside t.
    bool covers_tile(const TriangleSetup& t, int x0, int y0) const {
        if (x0 < 0 || y0 < 0 || x0 + kTileSize > fb_.width || y0 + kTileSize > fb_.height) return false;
        for (const EdgeFunction& e : t.edges) {
            if (e.at(x0, y0) + e.least_offset(kTileSize) <= 0) return false;
        }
        return true;
    }

private:
    // A whole block waiting to be shaded with the next (shade_block): its top-left pixel packed in
    // one word, stored and loaded whole. Stored as two ints and loaded as one 8-byte pair, it
    // would be a load the store buffer cannot forward, waiting for every older store to reach the
    // cache, the previous pair's framebuffer rows among them (docs/design.md, The renderer core).
    struct WaitingBlock {
        std::uint64_t at;
        std::uint32_t mask;  // the lanes that write

        static std::uint64_t pack(int bx, int by) {
            return std::uint64_t(std::uint32_t(bx)) | std::uint64_t(std::uint32_t(by)) << 32;
        }
        int bx() const { return int(std::uint32_t(at)); }
        int by() const { return int(std::uint32_t(at >> 32)); }
    };

    struct BlockEdges {
        std::int64_t at[3];     // edge k at the block's top-left pixel centre
        std::int64_t most[3];   // the largest offset from there over the block's pixel centres
        std::int64_t least[3];  // the smallest
        lanes16::Longs lane[3];  // the offset from there of each lane's pixel centre
    };

    // Coverage, early depth and shading of the 4x4 block whose top-left pixel is (bx, by).
    void block(int bx, int by, const BlockEdges& e) {
        // The edge functions are linear: the block is outside an edge when its largest value
        // there is not inside, fully inside when its smallest is.
        bool inside_all = true;
        for (int k = 0; k < 3; ++k) {
            if (e.at[k] + e.most[k] <= 0) return;
            inside_all &= e.at[k] + e.least[k] > 0;
        }
        // Else each lane's E = at + offset, the same integers as EdgeFunction::inside.
        std::uint32_t mask = kAllLanes;
        if (!inside_all) {
            mask = lanes16::sum_positive(e.at[0], e.lane[0]) & lanes16::sum_positive(e.at[1], e.lane[1]) &
                   lanes16::sum_positive(e.at[2], e.lane[2]);
        }
        mask &= lanes_inside(bx, by, fb_.width, fb_.height);
        if (mask != 0 && depth_test_) mask = depth_mask(bx, by, mask);
        if (mask == 0) return;
        if (draw_->quads) {
            // A quad runs when any of its lanes writes; its other lanes are helpers. Blocks whose
            // four quads all run are shaded as they are, the others' running quads are gathered.
            const std::uint32_t running = running_quads(mask);
            count_quads(std::uint64_t(std::popcount(running) / 4));
            if (running == kAllLanes) {
                shade_block(bx, by, mask);
                return;
            }
            append_lanes(bx, by, running, mask);
        } else if (mask == kAllLanes) {
            shade_block(bx, by, mask);
        } else {
            append_lanes(bx, by, mask, mask);  // per pixel: the covered pixels of partial blocks, no helpers
        }
    }

    // Shades the tile at (x0, y0), which lies inside the triangle and the image, block pair by
    // block pair: no coverage to test, no early depth (the caller checks that every fragment
    // passes), the depths written where the frame has a depth buffer. The loop is the same
    // work as shade_block's, with the per-draw choices inside interpolate made once per tile
    // rather than per block (about a tenth of the simplex square), and for inputs that are
    // only a few smooth varyings (FragmentInputs::ColumnVaryings) none made per block at all.
    template <bool Fused>
    void shade_tile(int x0, int y0) {
        const FragmentInputs inputs = inputs_;  // fragment_inputs.h: why a copy
        if (inputs.only_smooth_varyings()) {
            switch (inputs.count()) {
                case 1: return shade_tile_varyings<Fused, 1>(inputs, x0, y0);
                case 2: return shade_tile_varyings<Fused, 2>(inputs, x0, y0);
                case 3: return shade_tile_varyings<Fused, 3>(inputs, x0, y0);
                case 4: return shade_tile_varyings<Fused, 4>(inputs, x0, y0);
                default: break;
            }
        }
        shade_tile_with(x0, y0, [&](FragmentBatch& batch, int column, const lanes16::Floats& y) {
            inputs.fill<Fused>(batch, lanes_x(x0 + kBlock * column), y);
        });
    }
    template <bool Fused, int Count>
    void shade_tile_varyings(const FragmentInputs& inputs, int x0, int y0) {
        const FragmentInputs::ColumnVaryings<Fused, Count, kTileColumns> columns(
            inputs, [&](int column) { return lanes_x(x0 + kBlock * column); });
        shade_tile_with(x0, y0, [&](FragmentBatch& batch, int column, const lanes16::Floats& y) {
            columns.fill(batch, column, y);
        });
    }
    // The tile's loop; fill(batch, column, y) writes the inputs of the block in that column of
    // blocks whose lanes' y is y.
    template <class Fill>
    [[gnu::always_inline]] void shade_tile_with(int x0, int y0, const Fill& fill) {
        static_assert(kTileColumns % 2 == 0);
        const PreparedDraw& draw = *draw_;
        for (int by = y0; by < y0 + kTileSize; by += kBlock) {
            const lanes16::Floats y = lanes_y(by);
            for (int column = 0; column < kTileColumns; column += 2) {
                const int bx = x0 + kBlock * column;
                fill(in_[0], column, y);
                fill(in_[1], column + 1, y);
                shade_pair(draw);
                tile_block(0, bx, by);
                tile_block(1, bx + kBlock, by);
            }
        }
    }
    // Writes batch h of a whole tile, the block at (bx, by): whole, or its lanes that did not
    // discard. Inlined into the tile's loop whatever GCC's budget says (a call per block is slower:
    // docs/design.md, Rasterizer).
    [[gnu::always_inline]] void tile_block(int h, int bx, int by) {
        if (out_[h].discarded == 0) return write_whole(h, bx, by);
        for (int i = 0; i < kBatchLanes; ++i) {
            if (!(out_[h].discarded >> i & 1)) write_lane(h, i, bx + kLaneDx[i], by + kLaneDy[i]);
        }
    }
    // Writes every lane of batch h, the block at (bx, by): its colour, and its depth where the
    // frame has a depth buffer.
    [[gnu::always_inline]] void write_whole(int h, int bx, int by) {
        if (draw_->call->blend) [[unlikely]] {  // each pixel read back and blended
            for (int i = 0; i < kBatchLanes; ++i) write_lane(h, i, bx + kLaneDx[i], by + kLaneDy[i]);
            return;
        }
        const int block = block_base(bx, by) / kBatchLanes;
        const bool final = last_ && !touched_[std::size_t(block)];
        TileWriter::write_whole(*draw_, h, bx, by, final ? RowStores::Streamed : RowStores::Cached);
        touched_[std::size_t(block)] = true;
        if (depth_test_) lanes16::store(&depth_[block * kBatchLanes], depth24(lanes16::load(in_[h].frag_coord[2])));
    }

    // The framebuffer x and y of the lanes of the block whose top-left pixel is (bx, by).
    static lanes16::Floats lanes_x(int bx) { return lanes16::to_float(bx + lanes16::load(kLaneDx)); }
    static lanes16::Floats lanes_y(int by) { return lanes16::to_float(by + lanes16::load(kLaneDy)); }

    // Shades the whole block whose top-left pixel is (bx, by); `mask`: the lanes that write.
    // Blocks are shaded two at a time (Program::shade_pair): the first waits for the second, or
    // for flush_blocks() at the end of the triangle. The two are different pixels of one triangle,
    // so the order they are written in does not matter.
    void shade_block(int bx, int by, std::uint32_t mask) {
        pairs_.next() = {WaitingBlock::pack(bx, by), mask};
        pairs_.add([](const WaitingBlock&, const WaitingBlock&) { return true; },
                   [&](const WaitingBlock& first, const WaitingBlock& second) {
                       interpolate_block(in_[0], first.bx(), first.by());
                       interpolate_block(in_[1], second.bx(), second.by());
                       shade_pair(*draw_);
                       write_block(0, first.bx(), first.by(), first.mask);
                       write_block(1, second.bx(), second.by(), second.mask);
                   },
                   [&](const WaitingBlock& b) { shade_alone(b); });
    }

    // Shades the block left waiting, if any.
    void flush_blocks() {
        pairs_.flush([&](const WaitingBlock& b) { shade_alone(b); });
    }
    void shade_alone(const WaitingBlock& b) {
        interpolate_block(in_[0], b.bx(), b.by());
        shade(*draw_);
        write_block(0, b.bx(), b.by(), b.mask);
    }

    void interpolate_block(FragmentBatch& in, int bx, int by) { interpolate(in, lanes_x(bx), lanes_y(by)); }

    // Writes the shaded batch h, the block whose top-left pixel is (bx, by); `mask`: the lanes
    // that write.
    void write_block(int h, int bx, int by, std::uint32_t mask) {
        const ColorBatch& out = out_[h];
        mask &= ~out.discarded;  // GLSL discard: no colour, no depth
        if (mask != kAllLanes) {
            for (int i = 0; i < kBatchLanes; ++i) {
                if (mask >> i & 1) write_lane(h, i, bx + kLaneDx[i], by + kLaneDy[i]);
            }
            return;
        }
        write_whole(h, bx, by);
    }

    // Adds `lanes` of the block at (bx, by) to the gathered batch, in lane order, those in `write`
    // writing, in as few steps as the batch's room allows. Whole quads stay whole and aligned
    // in the batch: it holds a multiple of four lanes when quads are appended.
    void append_lanes(int bx, int by, std::uint32_t lanes, std::uint32_t write) {
        using namespace lanes16;
        const Ints x = bx + load(kLaneDx), y = by + load(kLaneDy);
        while (lanes != 0) {
            const std::uint32_t taken = lowest_bits(lanes, kBatchLanes - pending_.count);
            store(pending_.x, append(load(pending_.x), pending_.count, taken, x));
            store(pending_.y, append(load(pending_.y), pending_.count, taken, y));
            pending_.write |= compress_bits(write, taken) << pending_.count;
            pending_.count += std::popcount(taken);
            lanes &= ~taken;
            if (pending_.count == kBatchLanes) {
                flush(pending_);
                pending_.clear();
            }
        }
    }

    // The lanes of the block at (bx, by) that pass the depth test (LESS). The tile's depth is in
    // lane order: the block's sixteen values lie together.
    std::uint32_t depth_mask(int bx, int by, std::uint32_t mask) const {
        const lanes16::Floats x = lanes_x(bx), y = lanes_y(by);
        const lanes16::Floats z = fused_ ? inputs_.depth<true>(x, y) : inputs_.depth<false>(x, y);
        return mask & lanes16::less(depth24(z), lanes16::load(&depth_[block_base(bx, by)]));
    }

    // The shader inputs of the lanes at pixels (x, y) (framebuffer coordinates, y down) from the
    // current triangle.
    void interpolate(FragmentBatch& in, const lanes16::Floats& x, const lanes16::Floats& y) const {
        if (fused_) {
            inputs_.fill<true>(in, x, y);
        } else {
            inputs_.fill<false>(in, x, y);
        }
    }

    // Interpolates, shades and writes the gathered batch.
    void flush(LaneBatch& b) {
        using namespace lanes16;
        if (b.count == 0) return;
        // Unused lanes take lane 0's position (they write nothing), padded in registers: the
        // batch's arrays were stored whole (append_lanes), and whole loads of them are forwarded.
        static constexpr Ints kLane{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
        const Ints used = kLane < b.count;
        const Ints x = load(b.x), y = load(b.y);
        interpolate(in_[0], to_float(used ? x : Ints{} + x[0]), to_float(used ? y : Ints{} + y[0]));
        shade(*draw_, b.count);
        const std::uint32_t write = b.write & ~out_[0].discarded;  // GLSL discard: no colour, no depth
        for (int i = 0; i < b.count; ++i) {
            if (write >> i & 1) write_lane(0, i, b.x[i], b.y[i]);
        }
    }

    // Writes lane i of batch h (and its depth) to pixel (x, y), clearing its block first if
    // nothing wrote it yet.
    void write_lane(int h, int i, int x, int y) {
        const int t = tile_index(x, y);
        const int block = t / kBatchLanes;
        if (!touched_[std::size_t(block)]) {
            clear_block(block_x(block), block_y(block), RowStores::Cached);
            touched_[std::size_t(block)] = true;
        }
        TileWriter::write_lane(*draw_, h, i, x, y);
        if (depth_test_ && !draw_->call->blend) depth_[t] = depth24(in_[h].frag_coord[2][i]);
    }

    // Framebuffer position of a tile block's top-left pixel.
    int block_x(int block) const { return x0_ + (block % (kTileSize / kBlock)) * kBlock; }
    int block_y(int block) const { return y0_ + (block / (kTileSize / kBlock)) * kBlock; }

    // Index in the tile of lane 0 of the block holding pixel (x, y).
    int block_base(int x, int y) const {
        const unsigned tx = unsigned(x - x0_), ty = unsigned(y - y0_);  // inside the tile: >= 0
        return int(((ty / kBlock) * (kTileSize / kBlock) + tx / kBlock) * kBatchLanes);
    }
    // Index of pixel (x, y) in the tile: its block's 16 lanes, then its lane in that block.
    int tile_index(int x, int y) const {
        return block_base(x, y) + kLaneAt[unsigned(y - y0_) % kBlock][unsigned(x - x0_) % kBlock];
    }

    static constexpr int kTilePixels = kTileSize * kTileSize;
    static constexpr int kTileBlocks = kTilePixels / kBatchLanes;
    static constexpr int kTileColumns = kTileSize / kBlock;  // columns of blocks
    const std::vector<PreparedDraw>& draws_;
    bool depth_test_, fused_, general_;
    bool last_ = false;  // render()'s
    int x0_ = 0, y0_ = 0;
    std::bitset<kTileBlocks> touched_;  // blocks holding their final pixels or the clear colour
    alignas(64) float depth_[kTilePixels];  // 24-bit depths (depth24), exact in float
    const PreparedDraw* draw_ = nullptr;
    FragmentInputs inputs_;  // the current triangle's
    LaneBatch pending_;
    bool frag_coord_set_ = true;  // in_[].frag_coord may hold numbers (it starts uninitialised)
    BlockPairs<WaitingBlock> pairs_;
};

}  // namespace

Framebuffer rasterize(int width, int height, glm::vec4 clear, std::span<const DrawCall> draws,
                      const RasterOptions& options, RenderStats* stats) {
    Framebuffer fb;
    rasterize_into(fb, width, height, clear, draws, options, stats);
    return fb;
}

namespace {

// rasterize_into's and rasterize_over's frame: cleared to `clear` (none: drawn over what `fb`
// holds), depth tested where `depth_test` and it matters.
void rasterize_frame(Framebuffer& fb, int width, int height, const std::optional<glm::vec4>& clear, bool depth_test,
                     std::span<const DrawCall> draws, const RasterOptions& options, RenderStats* stats_out, RowBand band,
                     RasterMemory* memory) {
    TileFrame frame(width, height, band, draws, options, options.force_general_path);
    const std::vector<PreparedDraw>& prepared = frame.draws();
    RenderStats& stats = frame.stats();
    // Vertex stage, clipping and setup, per draw, triangles kept in submission order.
    const Viewport viewport(width, height);
    RasterMemory own;
    RasterMemory& kept = memory ? *memory : own;
    std::vector<TriangleSetup>& triangles = kept.triangles;
    triangles.clear();
    for (std::size_t di = 0; di < prepared.size(); ++di) {
        const DrawCall& call = *prepared[di].call;
        const std::vector<VertexOut> outs = run_vertex_stage(call);
        std::vector<ClipVertex> verts(outs.size());
        for (std::size_t i = 0; i < outs.size(); ++i) {
            verts[i] = {outs[i].clip, viewport.window(outs[i].clip, options.fused_viewport), outs[i].varyings,
                        outs[i].clip_distances};
        }
        std::vector<std::array<ClipVertex, 3>> clipped;
        for (std::size_t i = 0; i + 2 < call.indices.size(); i += 3) {
            ++stats.triangles_in;
            const std::uint32_t a = call.indices[i], b = call.indices[i + 1], c = call.indices[i + 2];
            clipped.clear();
            clip_triangle(verts[a], verts[b], verts[c], prepared[di].varyings, viewport, clipped,
                          {call.clip_distances, prepared[di].noperspective});
            for (const auto& tri : clipped) {
                if (auto t = setup_triangle(tri, prepared[di].varyings, width, height, options.fill_rule,
                                            prepared[di].flat, verts[c], call.culling, prepared[di].noperspective)) {
                    t->draw = int(di);
                    triangles.push_back(*t);
                }
            }
        }
    }
    stats.triangles_setup = triangles.size();
    // Depth is tested for every draw or none: GL tests it always, and leaving it out is only
    // allowed where it provably changes nothing (depth_buffer.h).
    const bool depth = depth_test && (options.force_general_path || kept.depth.matters(triangles, width, height));

    // Binning: bins[i] holds the triangles that may touch tile i of the band, in submission order:
    // those whose bounding box reaches the tile, less those its edges keep out of it (a tile's
    // last triangle streams its rows, TileRenderer).
    const TileGrid& grid = frame.grid();
    std::vector<std::vector<std::uint32_t>>& bins = kept.bins;
    bins.resize(std::size_t(grid.count()));
    for (std::vector<std::uint32_t>& bin : bins) bin.clear();
    for (std::uint32_t i = 0; i < triangles.size(); ++i) {
        const TriangleSetup& t = triangles[i];
        const int tx0 = t.min_x / kTileSize, tx1 = t.max_x / kTileSize;
        const int ty0 = std::max(grid.row_of(t.min_y), 0), ty1 = std::min(grid.row_of(t.max_y), grid.rows - 1);
        for (int ty = ty0; ty <= ty1; ++ty) {
            for (int tx = tx0; tx <= tx1; ++tx) {
                const int b = ty * grid.columns + tx;
                if (!misses_tile(t, grid.x0(b), grid.y0(b))) bins[std::size_t(b)].push_back(i);
            }
        }
    }

    frame.render_tiles<TileRenderer>(
        fb, depth,
        [&] {
            return std::make_unique<TileRenderer>(fb, prepared, clear, depth, options.fused_interpolation,
                                                  options.force_general_path);
        },
        [&](TileRenderer& tile, int b) {
            const int x0 = grid.x0(b), y0 = grid.y0(b);
            tile.start(x0, y0);
            const std::vector<std::uint32_t>& bin = bins[std::size_t(b)];
            for (std::size_t k = 0; k < bin.size(); ++k) {
                tile.render(triangles[bin[k]], x0, y0, x0 + kTileSize - 1, y0 + kTileSize - 1, k + 1 == bin.size());
            }
            tile.finish();
        },
        stats_out);
}

}  // namespace

void rasterize_into(Framebuffer& fb, int width, int height, glm::vec4 clear, std::span<const DrawCall> draws,
                    const RasterOptions& options, RenderStats* stats, RowBand band, RasterMemory* memory) {
    rasterize_frame(fb, width, height, clear, true, draws, options, stats, band, memory);
}

void rasterize_over(Framebuffer& fb, std::span<const DrawCall> draws, const RasterOptions& options, RenderStats* stats) {
    if (fb.first_row != 0 || fb.rows != fb.height || fb.rgba.size() != std::size_t(fb.width) * std::size_t(fb.height) * 4) {
        throw std::invalid_argument("drawing over a framebuffer that does not hold a whole image");
    }
    rasterize_frame(fb, fb.width, fb.height, std::nullopt, false, draws, options, stats, {}, nullptr);
}

}  // namespace qs
