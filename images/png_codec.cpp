// PNG through libpng (png_codec.h). libpng reports an error by calling on_error, which longjmps
// back to the setjmp of the function that made the call: those functions (read_header, read_row,
// read_interlaced, write_header, write_row, write_end) hold only trivially destructible locals, and
// what libpng's callbacks reach is plain data (PngStream), so that no jump passes a destructor.
#include "images/png_codec.h"

#include <png.h>
#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <type_traits>
#include <vector>

namespace qs::image_library {

namespace {

// What libpng's callbacks reach: the reader's bytes or the writer's sink, and the last error.
struct PngStream {
    png_structp png = nullptr;
    png_infop info = nullptr;
    char error[256] = "";
    const unsigned char* bytes = nullptr;  // reading: the file
    std::size_t size = 0, at = 0;
    ByteSink* sink = nullptr;  // writing
    std::int64_t written = 0;
};
static_assert(std::is_trivially_destructible_v<PngStream>);

PngStream& stream_of(png_structp png, bool io) {
    return *static_cast<PngStream*>(io ? png_get_io_ptr(png) : png_get_error_ptr(png));
}

void on_error(png_structp png, png_const_charp message) {
    PngStream& s = stream_of(png, false);
    std::snprintf(s.error, sizeof s.error, "%s", message);
    png_longjmp(png, 1);
}

// Warnings (a damaged ancillary chunk skipped, a text key shortened) are not failures, as for
// OpenImageIO, and libpng would print them.
void on_warning(png_structp, png_const_charp) {}

void read_bytes(png_structp png, png_bytep out, std::size_t size) {
    PngStream& s = stream_of(png, true);
    if (size > s.size - s.at) png_error(png, "the file ends before its image does (truncated)");
    std::memcpy(out, s.bytes + s.at, size);
    s.at += size;
}

void write_bytes(png_structp png, png_bytep data, std::size_t size) {
    PngStream& s = stream_of(png, true);
    const std::size_t done = s.sink->write_at(data, size, s.written);  // the sink records a failure too
    s.written += std::int64_t(done);
    if (done != size) png_error(png, "a write to the file failed");
}

void flush_bytes(png_structp) {}  // every write is positioned and goes straight to the file

// The calls libpng may fail, each behind its setjmp.

bool read_header(PngStream& s) {
    if (setjmp(png_jmpbuf(s.png))) return false;
    png_read_info(s.png, s.info);
    // Palette to RGB, gray below 8 bits to 8, a tRNS chunk to an alpha channel: as OpenImageIO
    // reads PNG. No gamma or colour conversion.
    png_set_expand(s.png);
    if constexpr (std::endian::native == std::endian::little) png_set_swap(s.png);
    png_set_interlace_handling(s.png);
    png_read_update_info(s.png, s.info);
    return true;
}

bool read_row(PngStream& s, png_bytep row) {
    if (setjmp(png_jmpbuf(s.png))) return false;
    png_read_row(s.png, row, nullptr);
    return true;
}

bool read_interlaced(PngStream& s, png_bytepp rows) {
    if (setjmp(png_jmpbuf(s.png))) return false;
    png_read_image(s.png, rows);
    return true;
}

bool write_header(PngStream& s, png_uint_32 width, png_uint_32 height, int color_type, png_textp text, int texts) {
    if (setjmp(png_jmpbuf(s.png))) return false;
    // zlib's fastest level over rows filtered by the row above: a fourth to a sixth of the time of
    // level 6 over unfiltered rows (OpenImageIO's settings), for files a quarter larger on shaded
    // renders (docs/results.md, "The cost of one call").
    png_set_compression_level(s.png, Z_BEST_SPEED);
    png_set_filter(s.png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
    png_set_IHDR(s.png, s.info, width, height, 8, color_type, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (texts > 0) png_set_text(s.png, s.info, text, texts);
    png_write_info(s.png, s.info);
    return true;
}

bool write_row(PngStream& s, png_bytep row) {
    if (setjmp(png_jmpbuf(s.png))) return false;
    png_write_row(s.png, row);
    return true;
}

bool write_end(PngStream& s) {
    if (setjmp(png_jmpbuf(s.png))) return false;
    png_write_end(s.png, s.info);
    return true;
}

std::string libpng_error(const PngStream& s) {
    return std::string("libpng: ") + (s.error[0] ? s.error : "unknown error");
}

template <class T>
T load(const unsigned char* p) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

template <class T>
void store(unsigned char* p, T v) {
    std::memcpy(p, &v, sizeof v);
}

// Colours multiplied by alpha in a row of `channels` samples of T (alpha last), as OpenImageIO
// associates a PNG's alpha: in integers, or where the file gives a gamma through it
// (D * (alpha / max)^gamma, truncated).
template <class T>
void associate_alpha(unsigned char* row, std::size_t width, int channels, float gamma) {
    constexpr unsigned max = std::numeric_limits<T>::max();
    const std::size_t stride = std::size_t(channels) * sizeof(T);
    const int a = channels - 1;
    if (gamma == 1.0f) {
        for (std::size_t x = 0; x < width; ++x) {
            unsigned char* p = row + x * stride;
            const unsigned alpha = load<T>(p + std::size_t(a) * sizeof(T));
            for (int c = 0; c < a; ++c)
                store<T>(p + std::size_t(c) * sizeof(T), T(load<T>(p + std::size_t(c) * sizeof(T)) * alpha / max));
        }
        return;
    }
    const float inv_max = float(1.0 / max);
    for (std::size_t x = 0; x < width; ++x) {
        unsigned char* p = row + x * stride;
        const float factor =
            float(std::pow(double(float(load<T>(p + std::size_t(a) * sizeof(T))) * inv_max), double(gamma)));
        for (int c = 0; c < a; ++c) {
            store<T>(p + std::size_t(c) * sizeof(T), T(float(load<T>(p + std::size_t(c) * sizeof(T))) * factor));
        }
    }
}

// A sample as stored (8 or 16 bits) as OpenImageIO converts it: to float by its scale's
// reciprocal, from 16 to 8 bits through that float, rounded.
template <class T>
T convert(unsigned v, int bytes) {
    if constexpr (std::is_same_v<T, float>) {
        return bytes == 1 ? float(v) * (1.0f / 255.0f) : float(v) * (1.0f / 65535.0f);
    } else {
        return bytes == 1 ? T(v) : T(std::roundf(float(v) * (1.0f / 65535.0f) * 255.0f));
    }
}

class PngDecoder final : public Decoder {
public:
    PngDecoder(std::span<const unsigned char> bytes, bool unassociated_alpha)
        : bytes_(bytes), unassociated_alpha_(unassociated_alpha) {}
    ~PngDecoder() override { close(); }
    PngDecoder(const PngDecoder&) = delete;
    PngDecoder& operator=(const PngDecoder&) = delete;

    // (Re)starts libpng's reader on the bytes and reads the header; false, error() saying why, on failure.
    bool start() {
        close();
        stream_ = PngStream{};
        stream_.bytes = bytes_.data(), stream_.size = bytes_.size();
        stream_.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &stream_, on_error, on_warning);
        if (stream_.png) stream_.info = png_create_info_struct(stream_.png);
        if (!stream_.info) return fail("libpng: cannot make a reader (out of memory)");
        png_set_read_fn(stream_.png, &stream_, read_bytes);
        if (!read_header(stream_)) return fail(libpng_error(stream_));
        png_uint_32 width = 0, height = 0;
        int bits = 0, colour = 0, interlace = 0;
        png_get_IHDR(stream_.png, stream_.info, &width, &height, &bits, &colour, &interlace, nullptr, nullptr);
        // libpng refuses sides over a million (its default limit), so they fit an int.
        shape_ = {int(width), int(height), 1, int(png_get_channels(stream_.png, stream_.info)), bits == 16 ? 2 : 1};
        interlaced_ = interlace != PNG_INTERLACE_NONE;
        // OpenImageIO's gamma for association: the gAMA chunk's, unless an sRGB chunk is there,
        // rounded to hundredths.
        int intent = 0;
        double file_gamma = 0.0;
        gamma_ = 1.0f;
        if (!png_get_sRGB(stream_.png, stream_.info, &intent) && png_get_gAMA(stream_.png, stream_.info, &file_gamma) &&
            file_gamma > 0.0) {
            gamma_ = std::roundf(float(100.0 * double(float(1.0 / file_gamma)))) / 100.0f;
        }
        read_ = false;
        return true;
    }
    ImageShape shape() const override { return shape_; }
    bool read(int channels, float* out) override { return read_pixels(channels, out); }
    bool read(int channels, std::uint8_t* out) override { return read_pixels(channels, out); }
    std::string error() override { return error_; }

private:
    bool fail(std::string message) {
        error_ = std::move(message);
        return false;
    }
    void close() {
        if (stream_.png) png_destroy_read_struct(&stream_.png, stream_.info ? &stream_.info : nullptr, nullptr);
        stream_.png = nullptr, stream_.info = nullptr;
    }

    // Rows decoded one at a time into a row of the file's samples (an interlaced file: the whole
    // image), alpha associated there, then converted into `out`; an 8-bit file read whole as
    // 8-bit is decoded straight into `out`.
    template <class T>
    bool read_pixels(int channels, T* out) {
        if (channels < 1 || channels > shape_.channels)
            return fail("cannot read " + std::to_string(channels) + " channels");
        if (read_ && !start()) return false;  // the reader reads once: a second read starts again
        read_ = true;
        const std::size_t width = std::size_t(shape_.width), height = std::size_t(shape_.height);
        const std::size_t row_bytes = png_get_rowbytes(stream_.png, stream_.info);
        const int bytes = shape_.channel_bytes;
        const bool direct = std::is_same_v<T, std::uint8_t> && bytes == 1 && channels == shape_.channels;
        const bool associate = !unassociated_alpha_ && (shape_.channels == 2 || shape_.channels == 4);
        std::vector<unsigned char> samples(direct ? 0 : interlaced_ ? row_bytes * height : row_bytes);
        const auto row_of = [&](std::size_t y) {
            return direct ? reinterpret_cast<unsigned char*>(out) + y * row_bytes
                          : samples.data() + (interlaced_ ? y * row_bytes : 0);
        };
        if (interlaced_) {
            std::vector<png_bytep> rows(height);
            for (std::size_t y = 0; y < height; ++y) rows[y] = row_of(y);
            if (!read_interlaced(stream_, rows.data())) return fail(libpng_error(stream_));
        }
        const std::size_t stored = std::size_t(shape_.channels);
        for (std::size_t y = 0; y < height; ++y) {
            unsigned char* row = row_of(y);
            if (!interlaced_ && !read_row(stream_, row)) return fail(libpng_error(stream_));
            if (associate) {
                if (bytes == 1)
                    associate_alpha<std::uint8_t>(row, width, shape_.channels, gamma_);
                else
                    associate_alpha<std::uint16_t>(row, width, shape_.channels, gamma_);
            }
            if (direct) continue;
            T* o = out + y * width * std::size_t(channels);
            for (std::size_t x = 0; x < width; ++x) {
                for (std::size_t c = 0; c < std::size_t(channels); ++c) {
                    const std::size_t i = x * stored + c;
                    const unsigned v = bytes == 1 ? row[i] : load<std::uint16_t>(row + 2 * i);
                    o[x * std::size_t(channels) + c] = convert<T>(v, bytes);
                }
            }
        }
        return true;
    }

    std::span<const unsigned char> bytes_;
    bool unassociated_alpha_;
    PngStream stream_;
    ImageShape shape_;
    bool interlaced_ = false, read_ = false;
    float gamma_ = 1.0f;
    std::string error_;
};

class PngEncoder final : public Encoder {
public:
    PngEncoder() = default;
    ~PngEncoder() override { close_stream(); }
    PngEncoder(const PngEncoder&) = delete;
    PngEncoder& operator=(const PngEncoder&) = delete;

    bool open(const std::string&, ByteSink& sink, const EncoderSpec& spec) override {
        static const int kColourTypes[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                           PNG_COLOR_TYPE_RGB_ALPHA};
        if (spec.floats) return fail("PNG is written with 8-bit samples only");
        if (spec.channels < 1 || spec.channels > 4)
            return fail("PNG holds 1 to 4 channels, not " + std::to_string(spec.channels));
        if (spec.width <= 0 || spec.height <= 0) return fail("PNG cannot hold an image of no pixels");
        width_ = std::size_t(spec.width), height_ = spec.height, channels_ = spec.channels;
        text_ = spec.attributes;  // each a tEXt chunk, in order
        std::vector<png_text> chunks(text_.size());
        for (std::size_t i = 0; i < text_.size(); ++i) {
            chunks[i] = png_text{};
            chunks[i].compression = PNG_TEXT_COMPRESSION_NONE;
            chunks[i].key = const_cast<char*>(text_[i].first.c_str());  // libpng copies them
            chunks[i].text = const_cast<char*>(text_[i].second.c_str());
        }
        stream_.sink = &sink;
        stream_.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &stream_, on_error, on_warning);
        if (stream_.png) stream_.info = png_create_info_struct(stream_.png);
        if (!stream_.info) return fail("libpng: cannot make a writer (out of memory)");
        png_set_write_fn(stream_.png, &stream_, write_bytes, flush_bytes);
        if (!write_header(stream_, png_uint_32(spec.width), png_uint_32(spec.height), kColourTypes[channels_ - 1],
                          chunks.data(), int(chunks.size()))) {
            return fail(libpng_error(stream_));
        }
        row_.resize(width_ * std::size_t(channels_));
        return true;
    }

    bool write_rows(int first, int end, bool floats, const void* pixels) override {
        if (!stream_.png) return fail("the PNG writer is not open");
        if (floats) return fail("PNG is written with 8-bit samples only");
        if (first != next_row_ || end < first || end > height_) return fail("rows written out of order");
        const auto* in = static_cast<const std::uint8_t*>(pixels);
        const bool alpha = channels_ == 2 || channels_ == 4;
        for (int y = first; y < end; ++y, in += row_.size()) {
            std::copy_n(in, row_.size(), row_.data());
            // OpenImageIO takes the rows given a PNG with alpha as premultiplied and divides
            // colour by alpha (where alpha is not 0); so does this writer, for the same pixels.
            if (alpha) {
                const std::size_t a = std::size_t(channels_ - 1);
                for (std::size_t x = 0; x < width_; ++x) {
                    std::uint8_t* p = &row_[x * std::size_t(channels_)];
                    if (p[a] == 0) continue;
                    for (std::size_t c = 0; c < a; ++c)
                        p[c] = std::uint8_t(std::min(255u, unsigned(p[c]) * 255u / p[a]));
                }
            }
            if (!write_row(stream_, row_.data())) return fail(libpng_error(stream_));
            ++next_row_;
        }
        return true;
    }

    bool close() override {
        if (!stream_.png) return fail("the PNG writer is not open");
        if (next_row_ != height_) {
            close_stream();
            return fail("closed after " + std::to_string(next_row_) + " of " + std::to_string(height_) + " rows");
        }
        const bool ended = write_end(stream_);
        const std::string error = ended ? "" : libpng_error(stream_);
        close_stream();
        return ended || fail(error);
    }

    std::string error() override { return error_; }

private:
    bool fail(std::string message) {
        error_ = std::move(message);
        return false;
    }
    void close_stream() {
        if (stream_.png) png_destroy_write_struct(&stream_.png, stream_.info ? &stream_.info : nullptr);
        stream_.png = nullptr, stream_.info = nullptr;
    }

    PngStream stream_;
    std::vector<std::pair<std::string, std::string>> text_;
    std::vector<std::uint8_t> row_;
    std::size_t width_ = 0;
    int height_ = 0, channels_ = 0, next_row_ = 0;
    std::string error_;
};

}  // namespace

std::unique_ptr<Decoder> open_png(std::span<const unsigned char> bytes, bool unassociated_alpha, std::string& error) {
    auto decoder = std::make_unique<PngDecoder>(bytes, unassociated_alpha);
    if (!decoder->start()) {
        error = decoder->error();
        return nullptr;
    }
    return decoder;
}

std::unique_ptr<Encoder> create_png() { return std::make_unique<PngEncoder>(); }

}  // namespace qs::image_library
