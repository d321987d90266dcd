#include "core/tile_grid.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace qs {

void check_image_size(int width, int height) {
    if (width <= 0 || height <= 0 || width > kMaxDimension || height > kMaxDimension) {
        throw std::invalid_argument("image size " + std::to_string(width) + "x" + std::to_string(height) +
                                    " is outside 1.." + std::to_string(kMaxDimension));
    }
}

int quad_row_offset(int height, QuadPairing pairing) {
    // Top-down pairing: framebuffer rows (2k, 2k+1), offset 0. Bottom-up: GL rows (2k, 2k+1) are
    // framebuffer rows (H-2-2k, H-1-2k), so at an odd height the grid starts at row -1.
    return (pairing == QuadPairing::BottomUp && (height & 1)) ? -1 : 0;
}

std::vector<RowBand> image_bands(int height, QuadPairing pairing, int max_rows) {
    const int row0 = quad_row_offset(height, pairing);
    const int tile_rows = std::max(1, max_rows / kTileSize);
    std::vector<RowBand> bands;
    for (int begin = 0; begin < height;) {
        // The first band starts at row 0 inside the tile that begins at row0 (-1 or 0).
        const int end = std::min(height, row0 + ((begin - row0) / kTileSize + tile_rows) * kTileSize);
        bands.push_back({begin, end});
        begin = end;
    }
    return bands;
}

RowBand checked_band(RowBand band, int height, QuadPairing pairing) {
    if (band.begin == 0 && band.end == 0) return {0, height};
    const int row0 = quad_row_offset(height, pairing);
    auto on_grid = [&](int row, int edge) { return row == edge || (row - row0) % kTileSize == 0; };
    if (band.begin < 0 || band.end > height || band.begin >= band.end || !on_grid(band.begin, 0) ||
        !on_grid(band.end, height)) {
        throw std::invalid_argument("row band " + std::to_string(band.begin) + ".." + std::to_string(band.end) +
                                    " does not lie on the tile grid of an image " + std::to_string(height) + " rows high");
    }
    return band;
}

TileGrid::TileGrid(int width, int height, QuadPairing pairing, RowBand band)
    : columns((width + kTileSize - 1) / kTileSize), row0(quad_row_offset(height, pairing)) {
    first_row = (band.begin - row0) / kTileSize;
    rows = (band.end - row0 + kTileSize - 1) / kTileSize - first_row;
}

}  // namespace qs
