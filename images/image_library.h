#pragma once
// What image_io.cpp asks of the image libraries: decoding an image from its bytes, encoding rows
// into bytes that quadshade writes (and checks) itself, and the comparison, heat map and text
// drawing of `quadshade compare` and `gallery`. image_io.cpp keeps every decision (which formats,
// which library, which sizes, the RGBA layout, GL's unorm conversion, where the bytes go). PNG's
// Decoder and Encoder are libpng's (png_codec.h), OpenEXR's the OpenEXR library's (exr_codec.h),
// both linked; the other formats and the rest are
// OpenImageIO's: openimageio_library.cpp only calls it, in a module of its own
// (modules/module_loader.h) loaded by the first call of image_library::library(). Nothing here
// throws across the module's edge: failures come back as messages.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "images/image_io.h"

namespace qs::image_library {

// An image's header: its size and channels.
struct ImageShape {
    int width = 0, height = 0, depth = 0, channels = 0;
    int channel_bytes = 0;  // of one sample as stored: 1 (8-bit), 2 (16-bit, half), 4 (float)
};

// An image opened from bytes in memory (which must outlive it), its header read, no pixel decoded.
class Decoder {
public:
    virtual ~Decoder() = default;
    virtual ImageShape shape() const = 0;
    // The first `channels` channels of every pixel, rows in the file's order, into `out`
    // (width x height x channels values); false when the pixels cannot be decoded (error() says why).
    virtual bool read(int channels, float* out) = 0;
    virtual bool read(int channels, std::uint8_t* out) = 0;
    virtual std::string error() = 0;
};

// Where an Encoder's bytes go, positioned: a file quadshade has opened and checks every write to.
class ByteSink {
public:
    virtual std::size_t write_at(const void* data, std::size_t size, std::int64_t offset) = 0;
    virtual std::size_t read_at(void* data, std::size_t size, std::int64_t offset) = 0;  // what was written
    virtual std::int64_t size() const = 0;  // the end of what was written

protected:
    ~ByteSink() = default;
};

// What an image file starts with: its size, channels, sample type and string attributes.
struct EncoderSpec {
    int width = 0, height = 0, channels = 0;
    bool floats = false;  // float samples, else 8-bit
    Metadata attributes;
};

// An image encoded into a ByteSink, rows top-down.
class Encoder {
public:
    virtual ~Encoder() = default;
    // Starts the file `file_name` in `sink` (which must outlive the encoder); false on failure.
    virtual bool open(const std::string& file_name, ByteSink& sink, const EncoderSpec& spec) = 0;
    // Rows [first, end) of the spec's channels, float or 8-bit, packed; false on failure.
    virtual bool write_rows(int first, int end, bool floats, const void* pixels) = 0;
    // Writes what the format keeps until the end; false on failure.
    virtual bool close() = 0;
    virtual std::string error() = 0;  // why the last call failed
};

class Library {
public:
    // The reader of `format` ("png", "exr", ...; never a tour of every reader) on `bytes`, whose
    // header it reads; `unassociated_alpha`: colours come back as stored, not premultiplied.
    // nullptr, with `error` set, when it cannot be opened. `name` names the image for the library.
    virtual std::unique_ptr<Decoder> open(std::span<const unsigned char> bytes, const std::string& name,
                                          const std::string& format, bool unassociated_alpha,
                                          std::string& error) const = 0;
    // An encoder of the format `file_name`'s extension names; nullptr, with `error` set (what
    // follows "FILE: " in a message), when that format has no writer or none that writes into a
    // ByteSink.
    virtual std::unique_ptr<Encoder> create(const std::string& file_name, std::string& error) const = 0;
    // OpenImageIO's ImageBufAlgo::compare over the RGB channels of two width x height RGBA float images.
    virtual Comparison compare(int width, int height, const float* a, const float* b, float fail_threshold,
                                  float warn_threshold) const = 0;
    // |a - b| per channel, RGBA floats, into `out`.
    virtual void absolute_difference(int width, int height, const float* a, const float* b, float* out) const = 0;
    // Draws `text` in white into the RGBA float image; false, with `error` set, on failure.
    virtual bool draw_text(int width, int height, float* rgba, int x, int y, std::string_view text, int size,
                           const std::string& font, std::string& error) const = 0;

protected:
    ~Library() = default;
};

// OpenImageIO, its module loaded on the first call. Throws ImageError (image_io.h) naming
// OpenImageIO and the module when it cannot be loaded.
const Library& library();

}  // namespace qs::image_library
