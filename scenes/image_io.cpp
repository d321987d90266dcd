// The one file that includes OpenImageIO.
#include "scenes/image_io.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <iterator>
#include <memory>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include "scenes/image_checks.h"
#include "scenes/limits.h"
#include "scenes/scene.h"
#include "scenes/scene_files.h"
#include "scenes/temporary_file.h"

namespace qs {

namespace {

OIIO::ImageBuf to_buf(const Image& img) {
    OIIO::ImageSpec spec(img.width, img.height, 4, OIIO::TypeDesc::FLOAT);
    OIIO::ImageBuf buf(spec);
    buf.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, img.rgba.data());
    return buf;
}

std::string lowercase_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

std::string size_text(std::int64_t width, std::int64_t height) { return std::to_string(width) + "x" + std::to_string(height); }

// OpenImageIO writes through this into the temporary file: every write goes straight to the
// file descriptor, and a short or failed one is recorded, so that commit() refuses a file that
// is missing bytes (a full disk) whatever the format's writer made of the failure.
class TemporaryFileProxy final : public OIIO::Filesystem::IOProxy {
public:
    explicit TemporaryFileProxy(TemporaryFile& file) : IOProxy(file.path().string(), Write), file_(file) {}
    const char* proxytype() const override { return "quadshade-temporary-file"; }
    size_t write(const void* buf, size_t size) override {
        const size_t n = pwrite(buf, size, m_pos);
        m_pos += std::int64_t(n);
        return n;
    }
    size_t pwrite(const void* buf, size_t size, int64_t offset) override {
        size_t done = 0;
        while (done < size) {
            const ssize_t n = ::pwrite(file_.fd(), static_cast<const char*>(buf) + done, size - done, offset + std::int64_t(done));
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                file_.note_write_error(n < 0 ? errno : ENOSPC);
                break;
            }
            done += size_t(n);
        }
        end_ = std::max(end_, offset + std::int64_t(done));
        return done;
    }
    size_t read(void* buf, size_t size) override {
        const size_t n = pread(buf, size, m_pos);
        m_pos += std::int64_t(n);
        return n;
    }
    size_t pread(void* buf, size_t size, int64_t offset) override {
        const ssize_t n = ::pread(file_.fd(), buf, size, offset);
        return n > 0 ? size_t(n) : 0;
    }
    size_t size() const override { return size_t(end_); }

private:
    TemporaryFile& file_;
    std::int64_t end_ = 0;
};

}  // namespace

std::uint64_t image_read_bytes(std::uint64_t width, std::uint64_t height) {
    // Up to four decoded float channels, then the RGBA copy.
    return width * height * (4 + 4) * sizeof(float);
}

Image read_image(const std::filesystem::path& path, const ImageReadLimits& limits) {
    std::vector<unsigned char> bytes;
    try {
        bytes = read_scene_file(path, limits.max_file_bytes, limits.follow_symlink);
    } catch (const SceneError& e) {
        throw ImageError(e.what());
    }
    return decode_image(bytes, path, limits);
}

namespace {

// An image's bytes opened with the one reader `ext` names, after the container checks
// (image_checks.h), its header's size checked against `limits` before a pixel is decoded. `name`
// names it in messages; `memory` must outlive the reader.
std::unique_ptr<OIIO::ImageInput> open_image(std::span<const unsigned char> bytes, const std::string& name,
                                             const std::string& ext, const ImageReadLimits& limits,
                                             OIIO::Filesystem::IOMemReader& memory, OIIO::ImageSpec config = {}) {
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
    auto in = OIIO::ImageInput::create(ext.substr(1), false);
    // OpenImageIO 2.4 reads from memory through this hint (its open()'s proxy argument alone
    // still looks for a file).
    void* proxy = &memory;
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    OIIO::ImageSpec opened;
    if (!in || !in->set_ioproxy(&memory) || !in->open(name, opened, config)) {
        throw ImageError(name + ": cannot read image: " + (in ? in->geterror() : OIIO::geterror()));
    }
    const OIIO::ImageSpec& spec = in->spec();
    // The header's size, checked before a pixel is decoded: a small file can declare a huge image.
    if (spec.width <= 0 || spec.height <= 0 || spec.depth > 1 || spec.nchannels <= 0 || spec.nchannels > 64) {
        throw ImageError(name + ": unsupported image: " + size_text(spec.width, spec.height) + "x" +
                         std::to_string(spec.depth) + ", " + std::to_string(spec.nchannels) + " channels");
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

// The opened image decoded to 8-bit RGBA.
Image8 decode8(OIIO::ImageInput& in, const std::string& name) {
    const OIIO::ImageSpec& spec = in.spec();
    const int nc = std::min(spec.nchannels, 4);  // channels past RGBA are not needed
    const std::size_t pixels = std::size_t(spec.width) * std::size_t(spec.height);
    std::vector<std::uint8_t> data(pixels * std::size_t(nc));
    if (!in.read_image(0, 0, 0, nc, OIIO::TypeDesc::UINT8, data.data())) {
        throw ImageError(name + ": cannot decode image: " + in.geterror());
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
    OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
    const auto in = open_image(bytes, path.string(), lowercase_extension(path), limits, memory);
    const OIIO::ImageSpec& spec = in->spec();
    const std::uint64_t pixels = std::uint64_t(spec.width) * std::uint64_t(spec.height);
    const int nc = std::min(spec.nchannels, 4);  // channels past RGBA are not needed
    std::vector<float> data(std::size_t(pixels) * std::size_t(nc));
    if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, data.data())) {
        throw ImageError(path.string() + ": cannot decode image: " + in->geterror());
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

Image8 read_texture_image(const ImageSource& source) {
    ImageReadLimits limits;
    limits.max_side = limits::kTextureSide;
    limits.max_pixels = limits::kTextureTexels;
    std::vector<unsigned char> file_bytes;
    std::span<const unsigned char> bytes = source.bytes;
    std::string name = source.file.string(), ext = lowercase_extension(source.file);
    if (source.kind == ImageSource::Kind::File) {
        try {
            file_bytes = read_scene_file(source.file, limits::kResourceFileBytes);  // resolved already: no links
        } catch (const SceneError& e) {
            throw ImageError(e.what());
        }
        bytes = file_bytes;
    } else {
        // Embedded: the format its MIME type gives (glTF's two), else its signature.
        const std::string& mime = source.mime_type;
        const bool png = mime == "image/png" || (mime.empty() && bytes.size() >= 4 && bytes[0] == 0x89 && bytes[1] == 'P');
        const bool jpeg = mime == "image/jpeg" || (mime.empty() && bytes.size() >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8);
        name = source.kind == ImageSource::Kind::DataUri ? "data: URI image" : "bufferView image";
        ext = png ? ".png" : jpeg ? ".jpg" : "";
        if (ext.empty()) throw ImageError(name + ": not a PNG or JPEG image (MIME type '" + mime + "')");
    }
    OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);  // PNG alpha stays as stored, as GL uploads it
    const auto in = open_image(bytes, name, ext, limits, memory, config);
    return decode8(*in, name);
}

Image8 read_image8(const std::filesystem::path& path, const ImageReadLimits& limits) {
    std::vector<unsigned char> bytes;
    try {
        bytes = read_scene_file(path, limits.max_file_bytes, limits.follow_symlink);
    } catch (const SceneError& e) {
        throw ImageError(e.what());
    }
    OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
    const auto in = open_image(bytes, path.string(), lowercase_extension(path), limits, memory);
    return decode8(*in, path.string());
}

bool is_float_format(const std::filesystem::path& path) {
    const std::string ext = lowercase_extension(path);
    return ext == ".exr" || ext == ".tif" || ext == ".tiff" || ext == ".hdr" || ext == ".pfm";
}

struct ImageWriter::State {
    std::filesystem::path path;
    int width = 0, height = 0, channels = 0, next_row = 0;
    bool is_float = false;
    std::unique_ptr<TemporaryFile> file;
    std::unique_ptr<TemporaryFileProxy> proxy;
    std::unique_ptr<OIIO::ImageOutput> out;  // destroyed first: it writes through proxy
    std::vector<float> floats;
    std::vector<std::uint8_t> bytes;

    ~State() {
        if (out) out->close();
    }
};

ImageWriter::ImageWriter(const std::filesystem::path& path, int width, int height, bool alpha, const Metadata& metadata)
    : state_(std::make_unique<State>()) {
    State& s = *state_;
    s.path = path, s.width = width, s.height = height, s.channels = alpha ? 4 : 3;
    s.is_float = is_float_format(path);
    if (width <= 0 || height <= 0) throw ImageError(path.string() + ": cannot write an image of " + size_text(width, height));
    s.out = OIIO::ImageOutput::create(path.string());
    if (!s.out) throw ImageError(path.string() + ": no image format for this file name: " + OIIO::geterror());
    if (!s.out->supports("ioproxy")) {
        throw ImageError(path.string() + ": OpenImageIO cannot write this format through a checked file");
    }
    try {
        s.file = std::make_unique<TemporaryFile>(path);
    } catch (const std::runtime_error& e) {
        throw ImageError(std::string("cannot write image: ") + e.what());
    }
    s.proxy = std::make_unique<TemporaryFileProxy>(*s.file);
    OIIO::ImageSpec spec(width, height, s.channels, s.is_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    for (const auto& [key, value] : metadata) spec.attribute(key, value);
    spec.attribute("Software", "quadshade");
    if (!s.out->set_ioproxy(s.proxy.get()) || !s.out->open(s.file->path().string(), spec)) {
        throw ImageError(path.string() + ": cannot write image (" + s.out->geterror() + ")");
    }
}

ImageWriter::~ImageWriter() = default;

std::uint64_t ImageWriter::conversion_bytes(const std::filesystem::path& path, int width, int rows, bool alpha) {
    const std::uint64_t values = std::uint64_t(width) * std::uint64_t(rows) * (alpha ? 4u : 3u);
    return values * (sizeof(float) + (is_float_format(path) ? 0 : 1));
}

void ImageWriter::write_rows(int rows, const std::uint8_t* rgba) {
    State& s = *state_;
    if (rows <= 0 || s.next_row + rows > s.height) throw std::logic_error("ImageWriter: more rows than the image has");
    const std::size_t n = std::size_t(s.width) * std::size_t(rows);
    const std::size_t nc = std::size_t(s.channels);
    const void* pixels = nullptr;
    OIIO::TypeDesc format = OIIO::TypeDesc::UINT8;
    if (s.is_float) {
        s.floats.resize(n * nc);
        for (std::size_t p = 0; p < n; ++p) {
            for (std::size_t c = 0; c < nc; ++c) s.floats[p * nc + c] = float(rgba[p * 4 + c]) / 255.0f;
        }
        pixels = s.floats.data(), format = OIIO::TypeDesc::FLOAT;
    } else {
        s.bytes.resize(n * nc);
        for (std::size_t p = 0; p < n; ++p) {
            for (std::size_t c = 0; c < nc; ++c) s.bytes[p * nc + c] = rgba[p * 4 + c];
        }
        pixels = s.bytes.data();
    }
    if (!s.out->write_scanlines(s.next_row, s.next_row + rows, 0, format, pixels)) {
        throw ImageError(s.path.string() + ": cannot write image (" + s.out->geterror() + ")");
    }
    s.next_row += rows;
}

void ImageWriter::write_rows(int rows, const float* rgba) {
    State& s = *state_;
    if (rows <= 0 || s.next_row + rows > s.height) throw std::logic_error("ImageWriter: more rows than the image has");
    const std::size_t n = std::size_t(s.width) * std::size_t(rows);
    const std::size_t nc = std::size_t(s.channels);
    s.floats.resize(n * nc);
    for (std::size_t p = 0; p < n; ++p) {
        for (std::size_t c = 0; c < nc; ++c) s.floats[p * nc + c] = rgba[p * 4 + c];
    }
    const void* pixels = s.floats.data();
    OIIO::TypeDesc format = OIIO::TypeDesc::FLOAT;
    if (!s.is_float) {
        // GL's unorm8 conversion (clamp, scale, round to nearest), not OIIO's own.
        s.bytes.resize(s.floats.size());
        for (std::size_t i = 0; i < s.bytes.size(); ++i) {
            float c = s.floats[i];
            c = std::isnan(c) ? 0.0f : std::min(std::max(c, 0.0f), 1.0f);
            s.bytes[i] = std::uint8_t(std::lrint(c * 255.0f));
        }
        pixels = s.bytes.data();
        format = OIIO::TypeDesc::UINT8;
    }
    if (!s.out->write_scanlines(s.next_row, s.next_row + rows, 0, format, pixels)) {
        throw ImageError(s.path.string() + ": cannot write image (" + s.out->geterror() + ")");
    }
    s.next_row += rows;
}

void ImageWriter::commit() {
    State& s = *state_;
    if (s.next_row != s.height) throw std::logic_error("ImageWriter: commit before every row was written");
    const bool closed = s.out->close();
    s.out.reset();
    if (!closed) throw ImageError(s.path.string() + ": cannot write image (" + OIIO::geterror() + ")");
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
    const std::uint64_t row_bytes = std::max<std::uint64_t>(1, ImageWriter::conversion_bytes(path, width, 1, alpha));
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
    OIIO::ImageBuf A = to_buf(a), B = to_buf(b);
    OIIO::ROI rgb = A.roi();
    rgb.chbegin = 0, rgb.chend = 3;
    OIIO::ImageBufAlgo::CompareResults r = OIIO::ImageBufAlgo::compare(A, B, fail_threshold, warn_threshold, rgb);
    // r.error is also set whenever a pixel fails (OIIO 2.4), so it is not an error here.
    Comparison c;
    c.mean_error = r.meanerror, c.rms_error = r.rms_error, c.psnr = r.PSNR, c.max_error = r.maxerror;
    c.max_x = r.maxx, c.max_y = r.maxy, c.max_channel = r.maxc;
    c.pixels_over_fail = r.nfail, c.pixels_over_warn = r.nwarn;
    return c;
}

Image difference_heat_map(const Image& a, const Image& b, float full_scale) {
    OIIO::ImageBuf diff = OIIO::ImageBufAlgo::absdiff(to_buf(a), to_buf(b));
    std::vector<float> d(std::size_t(a.width) * std::size_t(a.height) * 4);
    diff.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, d.data());
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
    OIIO::ImageBuf buf(OIIO::ImageSpec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT), image.rgba.data());
    const float white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    if (!OIIO::ImageBufAlgo::render_text(buf, x, y, text, size, "DejaVuSans", OIIO::cspan<float>(white, 4))) {
        throw ImageError("cannot draw text: " + buf.geterror() + " (the gallery's labels need the DejaVu Sans font: "
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
