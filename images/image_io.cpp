// Image files: every decision about them is here; libpng's calls are in png_codec.cpp, OpenEXR's
// in exr_codec.cpp and OpenImageIO's in openimageio_library.cpp, all behind image_library.h.
#include "images/image_io.h"

#include <strings.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <iterator>
#include <memory>
#include <thread>

#include "files/read_file.h"
#include "files/temporary_file.h"
#include "images/exr_codec.h"
#include "images/image_checks.h"
#include "images/image_library.h"
#include "images/png_codec.h"
#include "modules/module_loader.h"

namespace qs {

namespace image_library {

const Library& library() {
    static const Library* const library = [] {
        try {
            using Entry = const Library* (*)();
            return reinterpret_cast<Entry>(load_module({"openimageio", "OpenImageIO", "to read and write images",
                                                        "quadshade_image_library"}))();
        } catch (const ModuleError& e) {
            throw ImageError(e.what());
        }
    }();
    return *library;
}

}  // namespace image_library

namespace {

std::string size_text(std::int64_t width, std::int64_t height) { return std::to_string(width) + "x" + std::to_string(height); }

// The encoder's bytes go straight into the temporary file's descriptor, and a short or failed
// write is recorded, so that commit() refuses a file that is missing bytes (a full disk) whatever
// the format's writer made of the failure.
class TemporaryFileSink final : public image_library::ByteSink {
public:
    explicit TemporaryFileSink(TemporaryFile& file) : file_(file) {}
    std::size_t write_at(const void* buf, std::size_t size, std::int64_t offset) override {
        std::size_t done = 0;
        while (done < size) {
            const ssize_t n = ::pwrite(file_.fd(), static_cast<const char*>(buf) + done, size - done, offset + std::int64_t(done));
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                if (!error_) error_ = n < 0 ? errno : ENOSPC;
                file_.note_write_error(error_);
                break;
            }
            done += std::size_t(n);
        }
        end_ = std::max(end_, offset + std::int64_t(done));
        return done;
    }
    std::size_t read_at(void* buf, std::size_t size, std::int64_t offset) override {
        const ssize_t n = ::pread(file_.fd(), buf, size, offset);
        return n > 0 ? std::size_t(n) : 0;
    }
    std::int64_t size() const override { return end_; }
    // Why the first write that failed did (errno), or 0.
    int error() const { return error_; }

private:
    TemporaryFile& file_;
    std::int64_t end_ = 0;
    int error_ = 0;
};

}  // namespace

void load_image_library() { image_library::library(); }

std::string lowercase_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

bool has_own_codec(const std::string& ext) { return ext == ".png" || ext == ".exr"; }

bool needs_image_library(const std::filesystem::path& file) { return !has_own_codec(lowercase_extension(file)); }

std::uint64_t image_read_bytes(std::uint64_t width, std::uint64_t height) {
    // Up to four decoded float channels, then the RGBA copy.
    return width * height * (4 + 4) * sizeof(float);
}

Image read_image(const std::filesystem::path& path, const ImageReadLimits& limits) {
    std::vector<unsigned char> bytes;
    try {
        bytes = read_regular_file(path, limits.max_file_bytes, limits.follow_symlink);
    } catch (const FileError& e) {
        throw ImageError(e.what());
    }
    return decode_image(bytes, path, limits);
}

namespace {

// An image's bytes opened with the one reader `ext` names, after the container checks
// (image_checks.h), its header's size checked against `limits` before a pixel is decoded. `name`
// names it in messages; `bytes` must outlive the decoder.
std::unique_ptr<image_library::Decoder> open_image(std::span<const unsigned char> bytes, const std::string& name,
                                                   const std::string& ext, const ImageReadLimits& limits,
                                                   bool unassociated_alpha = false) {
    // Only the reader the extension names, and only formats a texture or a render may be: never
    // OpenImageIO's tour of every reader it has (DICOM, camera raw, video...) on unknown bytes.
    // Not BMP, whose reader allocates what a 200-byte file's run lengths claim (fuzzing found
    // 0.8 GB), nor TGA or PNM, which quadshade has no use for.
    static const char* const kReadable[] = {".png", ".jpg", ".jpeg", ".exr", ".tif", ".tiff", ".hdr"};
    if (std::find(std::begin(kReadable), std::end(kReadable), ext) == std::end(kReadable)) {
        throw ImageError(name + ": unsupported image format '" + ext + "' (quadshade reads PNG, JPEG, OpenEXR, TIFF and HDR)");
    }
    if (const std::string problem = image_container_problem(bytes, ext); !problem.empty()) {
        throw ImageError(name + ": cannot read image: " + problem);
    }
    std::string error;
    // OpenEXR's alpha is associated whatever `unassociated_alpha` asks, as OpenImageIO reads it.
    auto in = ext == ".png"   ? image_library::open_png(bytes, unassociated_alpha, error)
              : ext == ".exr" ? image_library::open_exr(bytes, name, error)
                              : image_library::library().open(bytes, name, ext.substr(1), unassociated_alpha, error);
    if (!in) throw ImageError(name + ": cannot read image: " + error);
    const image_library::ImageShape spec = in->shape();
    // The header's size, checked before a pixel is decoded: a small file can declare a huge image.
    if (spec.width <= 0 || spec.height <= 0 || spec.depth > 1 || spec.channels <= 0 || spec.channels > 64) {
        throw ImageError(name + ": unsupported image: " + size_text(spec.width, spec.height) + "x" +
                         std::to_string(spec.depth) + ", " + std::to_string(spec.channels) + " channels");
    }
    const std::uint64_t pixels = std::uint64_t(spec.width) * std::uint64_t(spec.height);
    if (spec.width > limits.max_side || spec.height > limits.max_side || pixels > limits.max_pixels) {
        throw ImageError(name + ": image is " + size_text(spec.width, spec.height) + " (" + std::to_string(pixels) +
                         " pixels): more than the " + std::to_string(limits.max_side) + " per side and " +
                         std::to_string(limits.max_pixels) + " pixels read here (it would take " +
                         byte_size_text(image_read_bytes(std::uint64_t(spec.width), std::uint64_t(spec.height))) + ")");
    }
    if ((limits.width && spec.width != limits.width) || (limits.height && spec.height != limits.height)) {
        throw ImageError(name + ": image is " + size_text(spec.width, spec.height) + ", not the " +
                         size_text(limits.width, limits.height) + " it is compared with");
    }
    return in;
}

// The opened image decoded to 8-bit RGBA. `decoding_bytes`, when given, receives the most the
// decoding held beside the image it returns: the samples as stored (when not 8-bit) and as 8-bit.
Image8 decode8(image_library::Decoder& in, const std::string& name, std::uint64_t* decoding_bytes = nullptr) {
    const image_library::ImageShape spec = in.shape();
    const int nc = std::min(spec.channels, 4);  // channels past RGBA are not needed
    const std::size_t pixels = std::size_t(spec.width) * std::size_t(spec.height);
    std::vector<std::uint8_t> data(pixels * std::size_t(nc));
    if (!in.read(nc, data.data())) {
        throw ImageError(name + ": cannot decode image: " + in.error());
    }
    if (decoding_bytes) {
        const std::uint64_t stored =
            spec.channel_bytes == 1 ? 0 : pixels * std::uint64_t(spec.channels * spec.channel_bytes);
        *decoding_bytes = stored + (nc == 4 ? 0 : data.size());
    }
    if (nc == 4) return Image8{spec.width, spec.height, std::move(data)};
    Image8 img{spec.width, spec.height, std::vector<std::uint8_t>(pixels * 4)};
    for (std::size_t p = 0; p < pixels; ++p) {
        const std::uint8_t* s = &data[p * std::size_t(nc)];
        std::uint8_t* d = &img.rgba[p * 4];
        d[0] = s[0];
        d[1] = nc >= 3 ? s[1] : s[0];
        d[2] = nc >= 3 ? s[2] : s[0];
        d[3] = nc == 2 ? s[1] : 255;
    }
    return img;
}

}  // namespace

Image decode_image(std::span<const unsigned char> bytes, const std::filesystem::path& path, const ImageReadLimits& limits) {
    const auto in = open_image(bytes, path.string(), lowercase_extension(path), limits);
    const image_library::ImageShape spec = in->shape();
    const std::uint64_t pixels = std::uint64_t(spec.width) * std::uint64_t(spec.height);
    const int nc = std::min(spec.channels, 4);  // channels past RGBA are not needed
    std::vector<float> data(std::size_t(pixels) * std::size_t(nc));
    if (!in->read(nc, data.data())) {
        throw ImageError(path.string() + ": cannot decode image: " + in->error());
    }
    Image img{spec.width, spec.height, {}};
    img.rgba.resize(std::size_t(pixels) * 4);
    for (std::size_t p = 0; p < std::size_t(pixels); ++p) {
        const float* s = &data[p * std::size_t(nc)];
        float* d = &img.rgba[p * 4];
        d[0] = s[0];
        d[1] = nc >= 3 ? s[1] : s[0];
        d[2] = nc >= 3 ? s[2] : s[0];
        d[3] = nc == 4 ? s[3] : (nc == 2 ? s[1] : 1.0f);
    }
    return img;
}

Image8 decode_image8(std::span<const unsigned char> bytes, const std::string& name, const std::string& ext,
                     const ImageReadLimits& limits, bool unassociated_alpha, std::uint64_t* decoding_bytes) {
    const auto in = open_image(bytes, name, ext, limits, unassociated_alpha);
    return decode8(*in, name, decoding_bytes);
}

Image8 read_image8(const std::filesystem::path& path, const ImageReadLimits& limits) {
    std::vector<unsigned char> bytes;
    try {
        bytes = read_regular_file(path, limits.max_file_bytes, limits.follow_symlink);
    } catch (const FileError& e) {
        throw ImageError(e.what());
    }
    const auto in = open_image(bytes, path.string(), lowercase_extension(path), limits);
    return decode8(*in, path.string());
}

bool is_float_format(const std::filesystem::path& path) {
    const std::string ext = lowercase_extension(path);
    return ext == ".exr" || ext == ".tif" || ext == ".tiff" || ext == ".hdr" || ext == ".pfm";
}

namespace {

// The attributes a file is written with: the caller's and the program's name, each once. A later
// one of the same name (in any case) replaces the earlier in its place, and one without a name is
// dropped, as OpenImageIO keeps its attributes; every encoder then writes them in order.
Metadata file_attributes(const Metadata& metadata) {
    Metadata all = metadata, out;
    all.emplace_back("Software", "quadshade");
    for (const auto& attribute : all) {
        if (attribute.first.empty()) continue;
        const auto same = std::find_if(out.begin(), out.end(), [&](const auto& kept) {
            return ::strcasecmp(kept.first.c_str(), attribute.first.c_str()) == 0;
        });
        if (same != out.end())
            *same = attribute;
        else
            out.push_back(attribute);
    }
    return out;
}

}  // namespace

struct ImageWriter::State {
    std::filesystem::path path;
    int width = 0, height = 0, channels = 0, next_row = 0;
    bool is_float = false;
    std::unique_ptr<TemporaryFile> file;
    std::unique_ptr<TemporaryFileSink> sink;
    std::unique_ptr<image_library::Encoder> out;  // destroyed first: it writes into sink
    std::vector<float> floats;
    std::vector<std::uint8_t> bytes;
    // Why the encoder failed: the file's own error when a write to it did (a full disk, a file
    // size limit), else the encoder's message.
    std::string write_failure() const { return sink && sink->error() ? std::strerror(sink->error()) : out->error(); }
};

ImageWriter::ImageWriter(const std::filesystem::path& path, int width, int height, bool alpha, const Metadata& metadata)
    : state_(std::make_unique<State>()) {
    State& s = *state_;
    s.path = path, s.width = width, s.height = height, s.channels = alpha ? 4 : 3;
    s.is_float = is_float_format(path);
    if (width <= 0 || height <= 0) throw ImageError(path.string() + ": cannot write an image of " + size_text(width, height));
    std::string error;
    const std::string ext = lowercase_extension(path);
    s.out = ext == ".png"   ? image_library::create_png()
            : ext == ".exr" ? image_library::create_exr()
                            : image_library::library().create(path.string(), error);
    if (!s.out) throw ImageError(path.string() + ": " + error);
    try {
        s.file = std::make_unique<TemporaryFile>(path);
    } catch (const std::runtime_error& e) {
        throw ImageError(std::string("cannot write image: ") + e.what());
    }
    s.sink = std::make_unique<TemporaryFileSink>(*s.file);
    const image_library::EncoderSpec spec{width, height, s.channels, s.is_float, file_attributes(metadata)};
    if (!s.out->open(s.file->path().string(), *s.sink, spec)) {
        throw ImageError(path.string() + ": cannot write image (" + s.write_failure() + ")");
    }
}

ImageWriter::~ImageWriter() = default;

std::uint64_t ImageWriter::conversion_bytes(const std::filesystem::path& path, int width, int rows, bool alpha) {
    const std::uint64_t channels = alpha ? 4u : 3u, values = std::uint64_t(width) * std::uint64_t(rows) * channels;
    std::uint64_t encoder = 0;
    const std::string ext = lowercase_extension(path);
    if (ext == ".png") {
        // libpng's row and the row above (for the Up filter), and the encoder's copy of the row
        // it divides by alpha; zlib's state, 256 KiB whatever the size, is in the writer's own
        // state (kRenderOverheadBytes).
        encoder = 3 * (std::uint64_t(width) * channels + 1);
    } else if (ext == ".exr") {
        // OpenEXR keeps two line buffers per thread of its pool (at most one thread per core,
        // exr_codec.cpp), each of 16 rows of the file's pixels, and its ZIP compressor two more of
        // that size for each: 8192x64 float RGB took 13.3 MiB more than as TIFF on a thread per core.
        const std::uint64_t buffers = 2 * std::max(1u, std::thread::hardware_concurrency());
        encoder = buffers * 3 * 16 * std::uint64_t(width) * channels * sizeof(float);
    }
    return values * (is_float_format(path) ? sizeof(float) : 1) + encoder;
}

void ImageWriter::write_rows(int rows, const std::uint8_t* rgba) {
    State& s = *state_;
    if (rows <= 0 || s.next_row + rows > s.height) throw std::logic_error("ImageWriter: more rows than the image has");
    const std::size_t n = std::size_t(s.width) * std::size_t(rows);
    const std::size_t nc = std::size_t(s.channels);
    const void* pixels = nullptr;
    if (s.is_float) {
        s.floats.resize(n * nc);
        for (std::size_t p = 0; p < n; ++p) {
            for (std::size_t c = 0; c < nc; ++c) s.floats[p * nc + c] = float(rgba[p * 4 + c]) / 255.0f;
        }
        pixels = s.floats.data();
    } else {
        s.bytes.resize(n * nc);
        for (std::size_t p = 0; p < n; ++p) {
            for (std::size_t c = 0; c < nc; ++c) s.bytes[p * nc + c] = rgba[p * 4 + c];
        }
        pixels = s.bytes.data();
    }
    if (!s.out->write_rows(s.next_row, s.next_row + rows, s.is_float, pixels)) {
        throw ImageError(s.path.string() + ": cannot write image (" + s.write_failure() + ")");
    }
    s.next_row += rows;
}

void ImageWriter::write_rows(int rows, const float* rgba) {
    State& s = *state_;
    if (rows <= 0 || s.next_row + rows > s.height) throw std::logic_error("ImageWriter: more rows than the image has");
    const std::size_t n = std::size_t(s.width) * std::size_t(rows);
    const std::size_t nc = std::size_t(s.channels);
    const void* pixels = nullptr;
    if (s.is_float) {
        s.floats.resize(n * nc);
        for (std::size_t p = 0; p < n; ++p) {
            for (std::size_t c = 0; c < nc; ++c) s.floats[p * nc + c] = rgba[p * 4 + c];
        }
        pixels = s.floats.data();
    } else {
        // GL's unorm8 conversion (clamp, scale, round to nearest), not OIIO's own.
        s.bytes.resize(n * nc);
        for (std::size_t p = 0; p < n; ++p) {
            for (std::size_t c = 0; c < nc; ++c) {
                float v = rgba[p * 4 + c];
                v = std::isnan(v) ? 0.0f : std::min(std::max(v, 0.0f), 1.0f);
                s.bytes[p * nc + c] = std::uint8_t(std::rint(v * 255.0f));  // as lrint, but inlined (it sets no errno)
            }
        }
        pixels = s.bytes.data();
    }
    if (!s.out->write_rows(s.next_row, s.next_row + rows, s.is_float, pixels)) {
        throw ImageError(s.path.string() + ": cannot write image (" + s.write_failure() + ")");
    }
    s.next_row += rows;
}

void ImageWriter::commit() {
    State& s = *state_;
    if (s.next_row != s.height) throw std::logic_error("ImageWriter: commit before every row was written");
    const bool closed = s.out->close();
    const std::string error = closed ? "" : s.write_failure();
    s.out.reset();
    if (!closed) throw ImageError(s.path.string() + ": cannot write image (" + error + ")");
    try {
        s.file->commit();
    } catch (const std::runtime_error& e) {
        throw ImageError(e.what());
    }
}

namespace {

// Writes `image` (RGBA rows of T) a few rows at a time, so that the conversion for the file
// stays small whatever the image's size.
template <class T>
void write_in_chunks(const std::filesystem::path& path, int width, int height, const std::vector<T>& rgba,
                     const Metadata& metadata, bool alpha) {
    ImageWriter writer(path, width, height, alpha, metadata);
    // What one more row adds (the encoder's own buffers are there whatever the chunk).
    const std::uint64_t row_bytes = std::max<std::uint64_t>(
        1, ImageWriter::conversion_bytes(path, width, 2, alpha) - ImageWriter::conversion_bytes(path, width, 1, alpha));
    const int chunk =
        int(std::clamp<std::uint64_t>(ImageWriter::kChunkBytes / row_bytes, 1, std::uint64_t(std::max(height, 1))));
    for (int y = 0; y < height; y += chunk) {
        writer.write_rows(std::min(chunk, height - y), rgba.data() + std::size_t(y) * std::size_t(width) * 4);
    }
    writer.commit();
}

}  // namespace

void write_image(const std::filesystem::path& path, const Image& image, const Metadata& metadata, bool alpha) {
    write_in_chunks(path, image.width, image.height, image.rgba, metadata, alpha);
}

void write_image(const std::filesystem::path& path, const Image8& image, const Metadata& metadata, bool alpha) {
    write_in_chunks(path, image.width, image.height, image.rgba, metadata, alpha);
}

Comparison compare_images(const Image& a, const Image& b, float fail_threshold, float warn_threshold) {
    if (a.width != b.width || a.height != b.height) {
        throw ImageError("cannot compare a " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                         " image with a " + std::to_string(b.width) + "x" + std::to_string(b.height) + " one");
    }
    return image_library::library().compare(a.width, a.height, a.rgba.data(), b.rgba.data(), fail_threshold, warn_threshold);
}

Image difference_heat_map(const Image& a, const Image& b, float full_scale) {
    std::vector<float> d(std::size_t(a.width) * std::size_t(a.height) * 4);
    image_library::library().absolute_difference(a.width, a.height, a.rgba.data(), b.rgba.data(), d.data());
    Image heat{a.width, a.height, std::vector<float>(d.size())};
    for (std::size_t p = 0; p < d.size(); p += 4) {
        const float m = std::max({d[p], d[p + 1], d[p + 2]});
        const float t = std::min(m / full_scale, 1.0f);
        // black -> red -> yellow -> white as the difference grows; exact zero stays black
        heat.rgba[p] = std::min(3.0f * t, 1.0f);
        heat.rgba[p + 1] = std::clamp(3.0f * t - 1.0f, 0.0f, 1.0f);
        heat.rgba[p + 2] = std::clamp(3.0f * t - 2.0f, 0.0f, 1.0f);
        heat.rgba[p + 3] = 1.0f;
    }
    return heat;
}

void draw_text(Image& image, int x, int y, std::string_view text, int size) {
    std::string error;
    if (!image_library::library().draw_text(image.width, image.height, image.rgba.data(), x, y, text, size, "DejaVuSans", error)) {
        throw ImageError("cannot draw text: " + error + " (the gallery's labels need the DejaVu Sans font: "
                         "Debian's fonts-dejavu-core)");
    }
}

Image side_by_side(const std::vector<const Image*>& images) {
    Image out;
    for (const Image* i : images) out.width += i->width, out.height = std::max(out.height, i->height);
    out.rgba.assign(std::size_t(out.width) * std::size_t(out.height) * 4, 0.0f);
    int x0 = 0;
    for (const Image* i : images) {
        for (int y = 0; y < i->height; ++y) {
            std::copy_n(&i->rgba[std::size_t(y) * std::size_t(i->width) * 4], std::size_t(i->width) * 4,
                        &out.rgba[(std::size_t(y) * std::size_t(out.width) + std::size_t(x0)) * 4]);
        }
        x0 += i->width;
    }
    return out;
}

}  // namespace qs
