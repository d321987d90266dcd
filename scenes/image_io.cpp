// The one file that includes OpenImageIO.
#include "scenes/image_io.h"

#include <algorithm>
#include <memory>
#include <cmath>
#include <system_error>
#include <unistd.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

namespace qs {

namespace {

OIIO::ImageBuf to_buf(const Image& img) {
    OIIO::ImageSpec spec(img.width, img.height, 4, OIIO::TypeDesc::FLOAT);
    OIIO::ImageBuf buf(spec);
    buf.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, img.rgba.data());
    return buf;
}

}  // namespace

Image read_image(const std::filesystem::path& path) {
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) throw ImageError(path.string() + ": cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 ||
        std::int64_t(spec.width) * spec.height > (std::int64_t(1) << 28)) {
        throw ImageError(path.string() + ": unsupported image size " + std::to_string(spec.width) + "x" +
                         std::to_string(spec.height));
    }
    const int nc = spec.nchannels;
    std::vector<float> data(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(nc));
    if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, data.data())) {
        throw ImageError(path.string() + ": cannot decode image: " + in->geterror());
    }
    Image img{spec.width, spec.height, {}};
    img.rgba.resize(std::size_t(spec.width) * std::size_t(spec.height) * 4);
    for (std::size_t p = 0; p < std::size_t(spec.width) * std::size_t(spec.height); ++p) {
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
    std::string name = source.file.string();
    std::unique_ptr<OIIO::Filesystem::IOMemReader> memory;
    if (source.kind != ImageSource::Kind::File) {
        // OpenImageIO picks the format by the name's extension first, then tries every reader.
        const std::string& mime = source.mime_type;
        const char* ext = mime == "image/png" ? ".png" : mime == "image/jpeg" ? ".jpg" : "";
        name = std::string(source.kind == ImageSource::Kind::DataUri ? "data: URI image" : "bufferView image") + ext;
        memory = std::make_unique<OIIO::Filesystem::IOMemReader>(source.bytes.data(), source.bytes.size());
    }
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);  // PNG alpha stays as stored, as GL uploads it
    if (memory) {
        // OpenImageIO 2.4 reads from memory through this hint (its open()'s proxy argument alone
        // still looks for a file).
        void* proxy = memory.get();
        config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    }
    auto in = OIIO::ImageInput::open(name, &config, memory.get());
    if (!in) throw ImageError(name + ": cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.width > (1 << 15) || spec.height > (1 << 15) ||
        std::int64_t(spec.width) * spec.height > (std::int64_t(1) << 28)) {
        throw ImageError(name + ": unsupported image size " + std::to_string(spec.width) + "x" + std::to_string(spec.height));
    }
    const int nc = spec.nchannels;
    const std::size_t pixels = std::size_t(spec.width) * std::size_t(spec.height);
    std::vector<std::uint8_t> data(pixels * std::size_t(nc));
    if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::UINT8, data.data())) {
        throw ImageError(name + ": cannot decode image: " + in->geterror());
    }
    Image8 img{spec.width, spec.height, std::vector<std::uint8_t>(pixels * 4)};
    for (std::size_t p = 0; p < pixels; ++p) {
        const std::uint8_t* s = &data[p * std::size_t(nc)];
        std::uint8_t* d = &img.rgba[p * 4];
        d[0] = s[0];
        d[1] = nc >= 3 ? s[1] : s[0];
        d[2] = nc >= 3 ? s[2] : s[0];
        d[3] = nc >= 4 ? s[3] : (nc == 2 ? s[1] : 255);
    }
    return img;
}

bool is_float_format(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".exr" || ext == ".tif" || ext == ".tiff" || ext == ".hdr" || ext == ".pfm";
}

namespace {

// Writes interleaved pixels of `channels` channels to a temporary name beside `path`, then
// renames it into place: a failed write leaves no partial file.
void write_pixels(const std::filesystem::path& path, int width, int height, int channels, OIIO::TypeDesc format,
                  const void* pixels, const Metadata& metadata) {
    const std::filesystem::path folder = path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
    if (!std::filesystem::is_directory(folder)) {
        throw ImageError(path.string() + ": cannot write image: no folder " + folder.string());
    }
    // Same directory, so the final rename cannot cross file systems.
    std::filesystem::path tmp = path;
    tmp += ".tmp-" + std::to_string(::getpid()) + path.extension().string();
    auto out = OIIO::ImageOutput::create(path.string());
    if (!out) throw ImageError(path.string() + ": no image format for this file name: " + OIIO::geterror());
    OIIO::ImageSpec spec(width, height, channels, is_float_format(path) ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    for (const auto& [key, value] : metadata) spec.attribute(key, value);
    spec.attribute("Software", "quadshade");
    bool ok = out->open(tmp.string(), spec) && out->write_image(format, pixels) && out->close();
    if (!ok) {
        std::error_code ec;
        std::filesystem::remove(tmp, ec);
        throw ImageError(path.string() + ": cannot write image (" + out->geterror() + ")");
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::filesystem::remove(tmp, ec);
        throw ImageError(path.string() + ": cannot move the finished image into place: " + ec.message());
    }
}

}  // namespace

void write_image(const std::filesystem::path& path, const Image& image, const Metadata& metadata, bool alpha) {
    const int channels = alpha ? 4 : 3;
    const std::size_t npixels = std::size_t(image.width) * std::size_t(image.height);
    std::vector<float> floats(npixels * std::size_t(channels));
    for (std::size_t p = 0; p < npixels; ++p) {
        for (int c = 0; c < channels; ++c) floats[p * std::size_t(channels) + std::size_t(c)] = image.rgba[p * 4 + std::size_t(c)];
    }
    if (is_float_format(path)) {
        write_pixels(path, image.width, image.height, channels, OIIO::TypeDesc::FLOAT, floats.data(), metadata);
        return;
    }
    // GL's unorm8 conversion (clamp, scale, round to nearest), not OIIO's own.
    std::vector<std::uint8_t> bytes(floats.size());
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        float c = floats[i];
        c = std::isnan(c) ? 0.0f : std::min(std::max(c, 0.0f), 1.0f);
        bytes[i] = std::uint8_t(std::lrint(c * 255.0f));
    }
    write_pixels(path, image.width, image.height, channels, OIIO::TypeDesc::UINT8, bytes.data(), metadata);
}

void write_image(const std::filesystem::path& path, const Image8& image, const Metadata& metadata, bool alpha) {
    const int channels = alpha ? 4 : 3;
    const std::size_t npixels = std::size_t(image.width) * std::size_t(image.height);
    std::vector<std::uint8_t> bytes(npixels * std::size_t(channels));
    for (std::size_t p = 0; p < npixels; ++p) {
        for (int c = 0; c < channels; ++c) bytes[p * std::size_t(channels) + std::size_t(c)] = image.rgba[p * 4 + std::size_t(c)];
    }
    write_pixels(path, image.width, image.height, channels, OIIO::TypeDesc::UINT8, bytes.data(), metadata);
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
