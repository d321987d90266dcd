#pragma once
// How both backends divide an image into work: 64x64 pixel tiles on the 2x2 quad grid, one
// thread's each, and bands of whole tile rows for images rendered a band at a time.

#include <vector>

namespace qs {

// Which rows form a quad. OSMesa's default buffer is stored top-down and pairs rows counting
// from the top, so at an odd height GL window row 0 pairs with a helper row below the image;
// an FBO pairs GL rows (2k, 2k+1) from the bottom.
enum class QuadPairing { TopDown, BottomUp };

inline constexpr int kTileSize = 64;

// The quad grid's first framebuffer row: 0, or -1 for bottom-up pairing at an odd height.
int quad_row_offset(int height, QuadPairing pairing);

// Rows [begin, end) of an image, top-down: a render of a band holds and renders those rows
// only, each pixel exactly as a render of the whole image gives it. {0, 0}: the whole image.
struct RowBand {
    int begin = 0, end = 0;
};

// An image's rows in bands of at most `max_rows` (at least one tile row), split on the tile
// grid: a tile, and so every quad, lies in one band, and a band renders exactly its part of the
// whole frame. The same split serves both backends.
std::vector<RowBand> image_bands(int height, QuadPairing pairing, int max_rows);
// `band` resolved ({0, 0}: the whole image) and checked to be one image_bands could give;
// throws std::invalid_argument otherwise.
RowBand checked_band(RowBand band, int height, QuadPairing pairing);

// Framebuffer sizes both renderers accept: 1..kMaxDimension on each side (clipped vertices lie
// in the viewport, so edge-function products stay below 2^52). Throws std::invalid_argument
// naming the size otherwise.
inline constexpr int kMaxDimension = 1 << 15;
void check_image_size(int width, int height);

// The tiles of one band (checked_band) of a width x height image: whole-frame tile rows from
// first_row on, counted from the quad grid's first row so that no quad straddles two tiles.
// Tile i is column i % columns of band row i / columns.
struct TileGrid {
    TileGrid(int width, int height, QuadPairing pairing, RowBand band);

    int columns = 0, rows = 0;  // tiles across, and tile rows in the band
    int row0 = 0;               // quad_row_offset: the top of tile row 0 of the frame
    int first_row = 0;          // the band's first tile row in the whole frame

    int count() const { return columns * rows; }
    // Framebuffer position of tile i's top-left pixel (y is -1 for a grid that starts above the image).
    int x0(int i) const { return (i % columns) * kTileSize; }
    int y0(int i) const { return row0 + (first_row + i / columns) * kTileSize; }
    // The band's tile row holding framebuffer row y (negative above the band, rows and more below).
    int row_of(int y) const { return (y - row0) / kTileSize - first_row; }
};

}  // namespace qs
