// quadshade-bench-png-encoding FILE.png...: what zlib's level and libpng's row filter cost a PNG
// as quadshade writes one (8-bit, not interlaced): each file decoded, then encoded in memory at
// level 6 over unfiltered rows (OpenImageIO's settings) and at level 1 over rows filtered by the
// row above (images/png_codec.cpp's), the best of 5 runs of each; prints a Markdown table of the
// time and the size.

#include <png.h>
#include <zlib.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iterator>
#include <vector>

namespace {

struct Settings {
    const char* name;
    int level, filters;
    int strategy;  // -1: libpng's choice (Z_FILTERED over filtered rows)
};

void append(png_structp png, png_bytep data, std::size_t size) {
    auto* out = static_cast<std::vector<unsigned char>*>(png_get_io_ptr(png));
    out->insert(out->end(), data, data + size);
}

// libpng's own error handling (abort) throughout: a benchmark of valid files.
struct Decoded {
    png_uint_32 width = 0, height = 0;
    int colour_type = 0;
    std::vector<std::vector<unsigned char>> rows;
};

bool decode(const char* file, Decoded& d) {
    std::FILE* in = std::fopen(file, "rb");
    if (!in) return false;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, in);
    png_read_png(png, info, PNG_TRANSFORM_EXPAND | PNG_TRANSFORM_STRIP_16, nullptr);
    d.width = png_get_image_width(png, info), d.height = png_get_image_height(png, info);
    d.colour_type = png_get_color_type(png, info);
    png_bytepp rows = png_get_rows(png, info);
    const std::size_t bytes = png_get_rowbytes(png, info);
    for (png_uint_32 y = 0; y < d.height; ++y) d.rows.emplace_back(rows[y], rows[y] + bytes);
    png_destroy_read_struct(&png, &info, nullptr);
    std::fclose(in);
    return true;
}

std::vector<unsigned char> encode(const Decoded& d, const Settings& s) {
    std::vector<unsigned char> out;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_set_write_fn(png, &out, append, nullptr);
    png_set_compression_level(png, s.level);
    if (s.strategy >= 0) png_set_compression_strategy(png, s.strategy);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, s.filters);
    png_set_IHDR(png, info, d.width, d.height, 8, d.colour_type, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (const auto& row : d.rows) png_write_row(png, row.data());
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    const Settings settings[] = {{"level 6, unfiltered", 6, PNG_NO_FILTERS, Z_DEFAULT_STRATEGY},
                                 {"level 1, Up", Z_BEST_SPEED, PNG_FILTER_UP, -1}};
    std::printf("| image | pixels |");
    for (const Settings& s : settings) std::printf(" %s: ms · kB |", s.name);
    std::printf("\n|---|---:|");
    for (std::size_t i = 0; i < std::size(settings); ++i) std::printf("---:|");
    std::printf("\n");
    for (int i = 1; i < argc; ++i) {
        Decoded d;
        if (!decode(argv[i], d)) {
            std::fprintf(stderr, "%s: cannot open\n", argv[i]);
            return 1;
        }
        std::printf("| %s | %ux%u |", argv[i], d.width, d.height);
        for (const Settings& s : settings) {
            double best = 1e30;
            std::size_t size = 0;
            for (int run = 0; run < 5; ++run) {
                const auto start = std::chrono::steady_clock::now();
                size = encode(d, s).size();
                best = std::min(
                    best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
            }
            std::printf(" %.1f · %.1f |", best, double(size) / 1000.0);
        }
        std::printf("\n");
    }
    return 0;
}
