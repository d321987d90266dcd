#pragma once
// Image files, PNG through libpng and the other formats through OpenImageIO (both behind
// image_library.h; OpenImageIO loaded on first use): reading
// textures and images to compare (regular files only, their size checked on the header before
// anything is decoded), writing renders safely (a temporary file, every write checked, renamed
// into place: see temporary_file.h), in one piece or row band by row band, and comparing images.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>


namespace qs {

class ImageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// An RGBA float image, rows top-down.
struct Image {
    int width = 0, height = 0;
    std::vector<float> rgba;
};

using Metadata = std::vector<std::pair<std::string, std::string>>;

// The largest side of an image quadshade reads or writes (its renders' largest: the rasterizer's
// fixed-point guard band).
inline constexpr int kMaxImageSide = 1 << 15;

// What read_image accepts, checked on the file's header before any pixel is decoded.
struct ImageReadLimits {
    int max_side = kMaxImageSide;
    std::uint64_t max_pixels = std::uint64_t(1) << 28;
    std::uint64_t max_file_bytes = std::uint64_t(1) << 31;
    bool follow_symlink = true;  // false for files a scene names (their links are resolved already)
    // When not 0: the size the image must have (an image compared with a render), checked on the
    // header, so that a small file declaring a huge image costs nothing to refuse.
    int width = 0, height = 0;
};

// Loads OpenImageIO (a module of its own: image_library.h), as the first image read or written
// in a format other than PNG does, and the first comparison, heat map or text drawn. Throws
// ImageError naming it when it cannot be loaded. A command that will need it calls it first, so
// that its frame times and memory measurements do not count the library's own start-up.
void load_image_library();

// Whether reading or writing `file` (its extension names the format) needs OpenImageIO: every
// format but PNG and OpenEXR, which libpng and OpenEXR (linked into quadshade) decode and encode.
bool needs_image_library(const std::filesystem::path& file);

// Reads PNG, JPEG, OpenEXR, TIFF and HDR files, the format named by the extension;
// grey/RGB are expanded to RGBA (alpha 1). Only regular files are opened (never a FIFO or
// device); the image is decoded from memory.
Image read_image(const std::filesystem::path& path, const ImageReadLimits& limits = {});
// The same from a file's bytes already in memory; `name`'s extension picks the format, and
// `name` names the image in messages.
Image decode_image(std::span<const unsigned char> bytes, const std::filesystem::path& name,
                   const ImageReadLimits& limits = {});

// An RGBA image of 8-bit unorm channels, rows top-down: what a GL_RGBA8 texture holds.
struct Image8 {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;
};

// A file read as read_image reads one, decoded to 8 bits per channel (exactly the values of an
// 8-bit file; deeper channels rounded), grey and RGB expanded to RGBA (alpha 255): a quarter of
// read_image's memory, for comparisons made in 8-bit steps.
Image8 read_image8(const std::filesystem::path& path, const ImageReadLimits& limits = {});

// Encoded bytes in the format `ext` names (".png", ".jpg", ...; lower case) decoded to 8 bits per
// channel as read_image8 decodes a file, `name` naming them in messages. With
// `unassociated_alpha`, alpha stays as stored (never premultiplied), as GL uploads a texture.
// `decoding_bytes`, when given, receives the most the decoding held beside its result: the
// samples as stored (when not 8-bit) and as 8-bit.
Image8 decode_image8(std::span<const unsigned char> bytes, const std::string& name, const std::string& ext,
                     const ImageReadLimits& limits, bool unassociated_alpha = false,
                     std::uint64_t* decoding_bytes = nullptr);

// A file name's extension in lower case (".png"): what names its format.
std::string lowercase_extension(const std::filesystem::path& path);

// Whether quadshade reads and writes the format (an extension such as ".png", lower case) itself,
// through libpng or OpenEXR, without OpenImageIO.
bool has_own_codec(const std::string& ext);

// Bytes an image of width x height takes as read_image's result at its peak (decoded channels
// and the RGBA copy), for checking memory before reading.
std::uint64_t image_read_bytes(std::uint64_t width, std::uint64_t height);

// Writes an image row band by row band: RGB, or RGBA with `alpha`, as 8-bit unorm for formats
// without float (PNG, ...), float for EXR/TIFF/HDR. `metadata` becomes string attributes (PNG
// text chunks, EXR headers). Nothing appears at `path` until commit() has checked every write;
// a writer destroyed without commit() leaves the previous file, if any, untouched.
class ImageWriter {
public:
    // Throws ImageError naming `path` (a folder, no folder to write into, an unknown format).
    ImageWriter(const std::filesystem::path& path, int width, int height, bool alpha, const Metadata& metadata = {});
    ~ImageWriter();
    ImageWriter(const ImageWriter&) = delete;
    ImageWriter& operator=(const ImageWriter&) = delete;

    // The next `rows` rows, top-down, RGBA float (4 per pixel, width per row).
    void write_rows(int rows, const float* rgba);
    // The same from 8-bit RGBA (values v / 255).
    void write_rows(int rows, const std::uint8_t* rgba);
    void commit();

    // Bytes write_rows needs beside its input for `rows` rows (the conversion to the file's
    // channels and type), and the encoder's own buffers.
    static std::uint64_t conversion_bytes(const std::filesystem::path& path, int width, int rows, bool alpha);
    // The most write_image converts at once.
    static constexpr std::uint64_t kChunkBytes = std::uint64_t(16) << 20;

private:
    struct State;
    std::unique_ptr<State> state_;
};

// Whole images, converted for the file a few rows at a time (ImageWriter::kChunkBytes at most).
void write_image(const std::filesystem::path& path, const Image& image, const Metadata& metadata = {},
                 bool alpha = false);

// Writes 8-bit RGB, or RGBA with `alpha`, as they are (for formats without float).
void write_image(const std::filesystem::path& path, const Image8& image, const Metadata& metadata = {},
                 bool alpha = false);

// Whether a file name's format stores float.
bool is_float_format(const std::filesystem::path& path);

// What OpenImageIO's ImageBufAlgo::compare reports, over RGB (alpha ignored), in [0, 1] units.
struct Comparison {
    double mean_error = 0.0, rms_error = 0.0, psnr = 0.0, max_error = 0.0;
    int max_x = 0, max_y = 0, max_channel = 0;
    std::uint64_t pixels_over_fail = 0;  // pixels with some channel over the fail threshold
    std::uint64_t pixels_over_warn = 0;
};
Comparison compare_images(const Image& a, const Image& b, float fail_threshold, float warn_threshold);

// |a - b| per pixel (max over RGB) as a heat map, and a side-by-side strip a | b | heat map.
Image difference_heat_map(const Image& a, const Image& b, float full_scale);
Image side_by_side(const std::vector<const Image*>& images);

// Draws `text` into `image` in white, its baseline's left end at pixel (x, y) (y down), `size`
// pixels high, in the DejaVu Sans font (Debian's fonts-dejavu-core). Throws ImageError when no
// such font is installed. The text is drawn as given: nothing in it is a format.
void draw_text(Image& image, int x, int y, std::string_view text, int size);

}  // namespace qs
