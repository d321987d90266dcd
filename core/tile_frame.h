#pragma once
// A frame rendered in tiles: the bookkeeping both backends share, so that a backend holds only
// how it produces a block's fragments. TileFrame checks the image size and the band, prepares the
// draws for shading (prepared_draw.h), limits the threads and flushes denormals for as long as
// the frame lives, and render_tiles holds the framebuffer and runs the tiles of the frame's grid
// (tile_loop.h) with one worker per thread, each a TileWriter (tile_writer.h) whose counts it
// collects. Between the two a backend makes what its tiles read (triangles and bins, or a BVH).
//
// The frame's geometry (the vertex stage, and what each backend derives from it: clipping and
// triangle setup, or world positions and the BVH) is computed with denormals flushed, as Mesa's
// draw module runs it and as the tiles shade (float_environment.h).

#include <memory>
#include <span>
#include <vector>

#include "core/draw_call.h"
#include "core/float_environment.h"
#include "core/framebuffer.h"
#include "core/parallel.h"
#include "core/prepared_draw.h"
#include "core/render_stats.h"
#include "core/shading_settings.h"
#include "core/tile_grid.h"
#include "core/tile_loop.h"

namespace qs {

class TileFrame {
public:
    // A width x height frame, or the rows of `band` (checked_band; {}: the whole image), of
    // `draws` shaded under `settings`; `general_path`: quads with helper lanes for every shader
    // (ShadeRequest). Throws std::invalid_argument for an absurd size or band, or a draw without
    // a program, UnsupportedRequest for settings no instantiation honours.
    TileFrame(int width, int height, RowBand band, std::span<const DrawCall> draws, const ShadingSettings& settings,
              bool general_path = false)
        : width_(checked_size(width, height)), height_(height), band_(checked_band(band, height, settings.pairing)),
          draws_(prepare_draws(draws,
                               {settings.derivatives, settings.precision, settings.check_undefined, general_path})),
          check_undefined_(settings.check_undefined), limit_(settings.threads),
          grid_(width, height, settings.pairing, band_) {}
    TileFrame(const TileFrame&) = delete;
    TileFrame& operator=(const TileFrame&) = delete;

    int width() const { return width_; }
    int height() const { return height_; }
    const std::vector<PreparedDraw>& draws() const { return draws_; }
    const TileGrid& grid() const { return grid_; }
    RenderStats& stats() { return stats_; }

    // Makes `fb` hold the band (with a depth buffer where `depth`), runs tile(worker, i) for every
    // tile i of the grid, `make()` giving each thread its worker (a std::unique_ptr to a class
    // derived from TileWriter), and adds the workers' counts to the stats, which go to `out`.
    // Every pixel of the band is written by its tile: the framebuffer's memory is reused as it is.
    template <class Worker, class Make, class Tile>
    void render_tiles(Framebuffer& fb, bool depth, const Make& make, const Tile& tile, RenderStats* out) {
        fb.hold(width_, height_, band_, depth, check_undefined_);
        stats_.depth_buffer = depth;
        for (const std::unique_ptr<Worker>& worker : for_each_tile<Worker>(grid_, make, tile)) {
            stats_.add_work(worker->counts().quads, worker->counts().lanes, worker->counts().written);
        }
        if (out) *out = stats_;
    }

private:
    static int checked_size(int width, int height) {
        check_image_size(width, height);
        return width;
    }

    int width_, height_;
    RowBand band_;
    std::vector<PreparedDraw> draws_;
    bool check_undefined_;
    ThreadLimit limit_;
    FlushDenormals flush_;
    TileGrid grid_;
    RenderStats stats_;
};

}  // namespace qs
