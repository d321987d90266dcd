#pragma once
// What a tile's worker does with fragments once a backend has produced them, the same for both
// backends: shades them, a 4x4 block or a gathered batch at a time or whole blocks in pairs
// (BlockPairs), and
// writes the frame: whole blocks as four rows (block_rows.h), streamed past the caches where
// nothing writes them again (cache_lines.h), single lanes (blended where the draw blends), the
// clear colour, the undefined-case mask where the frame holds one, and the counts of the frame's
// RenderStats. A backend's tile worker derives from it and keeps only what is its own: which
// fragments a block produces and their inputs (edge functions and depth, or rays and hits).

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <optional>

#include <glm/vec4.hpp>

#include "core/block_layout.h"
#include "core/block_rows.h"
#include "core/framebuffer.h"
#include "core/lanes16.h"
#include "core/prepared_draw.h"
#include "shading/program.h"

namespace qs {

// Whole blocks shaded two at a time (TileWriter::shade_pair): a block waits for the next one
// that may share its shader call. `Block` is what a backend keeps of a block until then, built in
// place at next().
template <class Block>
class BlockPairs {
public:
    Block& next() { return blocks_[waiting_ ? 1 - first_ : first_]; }

    // The block at next() is ready. With one waiting, the two go to pair(first, second) where
    // together(first, second), else the first to alone(first) and the second waits in its place;
    // with none waiting, it waits.
    template <class Together, class Pair, class Alone>
    [[gnu::always_inline]] void add(const Together& together, const Pair& pair, const Alone& alone) {
        if (!waiting_) {
            waiting_ = true;
            return;
        }
        const Block &first = blocks_[first_], &second = blocks_[1 - first_];
        if (!together(first, second)) {
            alone(first);
            first_ = 1 - first_;
            return;
        }
        waiting_ = false;
        pair(first, second);
    }
    // Hands the waiting block, if any, to alone(block).
    template <class Alone>
    void flush(const Alone& alone) {
        if (!waiting_) return;
        waiting_ = false;
        alone(blocks_[first_]);
    }

private:
    Block blocks_[2];
    int first_ = 0;
    bool waiting_ = false;
};

class TileWriter {
public:
    // What a worker did, summed over its tiles (RenderStats::add_work).
    struct Counts {
        std::uint64_t quads = 0, lanes = 0, written = 0;
    };

    // Writes into `fb`; `clear`: the colour of what no fragment writes (none: the framebuffer
    // keeps it).
    TileWriter(Framebuffer& fb, const std::optional<glm::vec4>& clear) : fb_(fb), clears_(clear.has_value()) {
        for (int i = 0; i < kBatchLanes; ++i) clear_row_[i] = clear ? (*clear)[i % 4] : 0.0f;
    }

    const Counts& counts() const { return counts_; }
    bool clears() const { return clears_; }

protected:
    // Shades in_[0] into out_[0] with draw d; `lanes`: how many lanes are fragments.
    void shade(const PreparedDraw& d, int lanes = kBatchLanes) {
        d.call->program->shade(d.mode, in_[0], d.call->uniforms, out_[0]);
        counts_.lanes += std::uint64_t(lanes);
    }
    // Shades two whole blocks, in_[0] and in_[1], into out_[0] and out_[1] with one call
    // (Program::shade_pair): twice the independent work per instruction chain (docs/design.md, The
    // renderer core).
    [[gnu::always_inline]] void shade_pair(const PreparedDraw& d) {
        d.call->program->shade_pair(d.mode, in_[0], in_[1], d.call->uniforms, out_[0], out_[1]);
        counts_.lanes += 2 * kBatchLanes;
    }
    void count_quads(std::uint64_t quads) { counts_.quads += quads; }

    // Writes every lane of out_[h] to the block whose top-left pixel is (bx, by), which lies inside
    // the image: four rows at once, and the lanes' undefined cases where the draw checks them.
    [[gnu::always_inline]] void write_whole(const PreparedDraw& d, int h, int bx, int by, RowStores stores) {
        store_block(fb_, bx, by, out_[h], d.mode.check_undefined, stores);
        counts_.written += kBatchLanes;
    }
    // Writes lane i of out_[h] to pixel (x, y): its colour (blended where the draw blends) and its
    // undefined cases where the draw checks them.
    void write_lane(const PreparedDraw& d, int h, int i, int x, int y) {
        float* p = fb_.pixel(x, y);
        const ColorBatch& out = out_[h];
        if (d.call->blend) {
            const float a = out.rgba[3][i];
            for (int c = 0; c < 4; ++c) p[c] = out.rgba[c][i] * a + p[c] * (1.0f - a);
        } else {
            for (int c = 0; c < 4; ++c) p[c] = out.rgba[c][i];
        }
        if (d.mode.check_undefined) *undefined_at(x, y) = out.undefined[i];
        ++counts_.written;
    }

    // Writes the clear colour into the pixels of the block whose top-left pixel is (x, y) that lie
    // inside the image, if the frame clears.
    void clear_block(int x, int y, RowStores stores) {
        if (!clears_) return;
        const int n = std::min(kBlock, fb_.width - x);
        const bool whole = n == kBlock && y >= 0 && y + kBlock <= fb_.height;
        if (whole) fill_block_rows(fb_, x, y, clear_row_, stores);
        for (int r = 0; r < kBlock; ++r) {
            if (n <= 0 || y + r < 0 || y + r >= fb_.height) continue;
            if (!whole) std::memcpy(fb_.pixel(x, y + r), &clear_row_, 4 * std::size_t(n) * sizeof(float));
            if (!fb_.undefined.empty()) std::fill_n(undefined_at(x, y + r), n, std::uint8_t(0));
        }
    }
    // Writes the clear colour into the lanes `lanes` (inside the image) of the block at (bx, by),
    // if the frame clears: all of them streamed, as nothing writes them again.
    void clear_lanes(int bx, int by, std::uint32_t lanes) {
        if (lanes == kAllLanes) return clear_block(bx, by, RowStores::Streamed);
        if (!clears_) return;
        for (std::uint32_t m = lanes; m != 0; m &= m - 1) {
            const int i = std::countr_zero(m);
            std::memcpy(fb_.pixel(bx + kLaneDx[i], by + kLaneDy[i]), &clear_row_, 4 * sizeof(float));
            if (!fb_.undefined.empty()) *undefined_at(bx + kLaneDx[i], by + kLaneDy[i]) = 0;
        }
    }

    std::uint8_t* undefined_at(int x, int y) { return &fb_.undefined[fb_.index(x, y)]; }

    Framebuffer& fb_;
    // Two batches: a gathered batch or a lone block uses the first, pairs of whole blocks both.
    FragmentBatch in_[2];
    ColorBatch out_[2];

private:
    lanes16::Floats clear_row_;  // four pixels of the clear colour
    bool clears_;
    Counts counts_;
};

}  // namespace qs
