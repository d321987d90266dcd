// PNG through libpng (images/png_codec.h) against OpenImageIO, which read and wrote quadshade's
// PNGs before and still reads its other formats: every kind of PNG libpng makes decodes to the
// same channels and the same bits, float and 8-bit, alpha associated or as stored; written files
// hold the pixels and text OpenImageIO's writer gives; a damaged file is refused with a message.
#include <png.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "images/image_io.h"
#include "images/image_library.h"
#include "images/png_codec.h"
#include "tests/images/codec_test_files.h"
#include "tests/test_paths.h"

namespace qs {

namespace {

using test::Bytes;
using test::MemorySink;

// A PNG of one kind, made by libpng, its samples from a generator of (x, y, channel).
struct PngKind {
    std::string name;
    int colour_type = PNG_COLOR_TYPE_RGB, bits = 8, width = 61, height = 37;
    bool interlaced = false, transparency = false;  // transparency: a tRNS chunk
    double gamma = 0.0;                             // > 0: a gAMA chunk
    bool srgb = false;                              // an sRGB chunk
    // Every value (one channel: across the image; two: every pair of 256 levels, x and y), else
    // values mixed from x, y and the channel.
    bool every_value = false;
};

void append(png_structp png, png_bytep data, std::size_t size) {
    auto* out = static_cast<Bytes*>(png_get_io_ptr(png));
    out->insert(out->end(), data, data + size);
}

unsigned mixed(int x, int y, int c, unsigned max) {
    return (unsigned(x) * 97u + unsigned(y) * 753u + unsigned(c) * 71u) % (max + 1);
}

unsigned sample(const PngKind& k, int x, int y, int c, int channels, unsigned max) {
    if (!k.every_value) return mixed(x, y, c, max);
    if (channels == 1) return (unsigned(y) * unsigned(k.width) + unsigned(x)) & max;
    return unsigned(c == 0 ? x : y) * (max / 255);
}

Bytes make_png(const PngKind& k) {
    Bytes out;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    REQUIRE((png && info));
    // No setjmp: a libpng error here (none is expected) aborts the test rather than jumping
    // across the rows' destructors.
    png_set_write_fn(png, &out, append, nullptr);
    png_set_IHDR(png, info, png_uint_32(k.width), png_uint_32(k.height), k.bits, k.colour_type,
                 k.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    const unsigned max = (1u << k.bits) - 1;
    int channels = 1;
    if (k.colour_type == PNG_COLOR_TYPE_PALETTE) {
        std::vector<png_color> palette(std::size_t(max) + 1);
        std::vector<png_byte> alpha(palette.size());
        for (std::size_t i = 0; i < palette.size(); ++i) {
            palette[i] = {png_byte(i * 37), png_byte(255 - i * 11), png_byte(i * i)};
            alpha[i] = png_byte(i * 53 + 7);
        }
        png_set_PLTE(png, info, palette.data(), int(palette.size()));
        if (k.transparency) png_set_tRNS(png, info, alpha.data(), int(alpha.size()), nullptr);
    } else {
        channels = k.colour_type == PNG_COLOR_TYPE_GRAY         ? 1
                   : k.colour_type == PNG_COLOR_TYPE_GRAY_ALPHA ? 2
                   : k.colour_type == PNG_COLOR_TYPE_RGB        ? 3
                                                                : 4;
        if (k.transparency) {
            png_color_16 colour{};
            colour.gray = png_uint_16(mixed(1, 0, 0, max));
            colour.red = png_uint_16(mixed(1, 0, 0, max)), colour.green = png_uint_16(mixed(1, 0, 1, max));
            colour.blue = png_uint_16(mixed(1, 0, 2, max));
            png_set_tRNS(png, info, nullptr, 0, &colour);
        }
    }
    if (k.gamma > 0.0) png_set_gAMA(png, info, k.gamma);
    if (k.srgb) png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    // Rows packed as PNG stores them: big-endian 16-bit samples, 1-4 bit samples packed high bit first.
    const std::size_t row_bytes = (std::size_t(k.width) * std::size_t(channels) * std::size_t(k.bits) + 7) / 8;
    std::vector<Bytes> rows(std::size_t(k.height), Bytes(row_bytes));
    std::vector<png_bytep> pointers;
    for (int y = 0; y < k.height; ++y) {
        Bytes& row = rows[std::size_t(y)];
        for (int x = 0; x < k.width; ++x) {
            for (int c = 0; c < channels; ++c) {
                const unsigned v = sample(k, x, y, c, channels, max);
                const std::size_t i = std::size_t(x) * std::size_t(channels) + std::size_t(c);
                if (k.bits == 16)
                    row[2 * i] = png_byte(v >> 8), row[2 * i + 1] = png_byte(v);
                else if (k.bits == 8)
                    row[i] = png_byte(v);
                else
                    row[i * std::size_t(k.bits) / 8] |= png_byte(v << (8 - k.bits - int(i * std::size_t(k.bits) % 8)));
            }
        }
        pointers.push_back(row.data());
    }
    png_write_image(png, pointers.data());
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return out;
}

struct OiioPng : test::OiioReader {
    OiioPng(const Bytes& bytes, bool unassociated_alpha) : OiioReader(bytes, "png", unassociated_alpha) {}
};

template <class T>
void check_same_pixels(const Bytes& bytes, bool unassociated_alpha, int channels) {
    std::string error;
    const auto ours = image_library::open_png(bytes, unassociated_alpha, error);
    REQUIRE(ours);
    test::check_same_as_oiio<T>(*ours, bytes, "png", unassociated_alpha, channels);
}


}  // namespace

TEST_CASE("libpng decodes every kind of PNG to OpenImageIO's channels and bits", "[images][png]") {
    std::vector<PngKind> kinds;
    for (int bits : {1, 2, 4, 8, 16})
        kinds.push_back({"gray " + std::to_string(bits) + "-bit", PNG_COLOR_TYPE_GRAY, bits});
    for (int bits : {1, 2, 4, 8})
        kinds.push_back({"palette " + std::to_string(bits) + "-bit", PNG_COLOR_TYPE_PALETTE, bits});
    for (int bits : {8, 16}) {
        const std::string b = bits == 8 ? " 8-bit" : " 16-bit";
        kinds.push_back({"gray+alpha" + b, PNG_COLOR_TYPE_GRAY_ALPHA, bits});
        kinds.push_back({"RGB" + b, PNG_COLOR_TYPE_RGB, bits});
        kinds.push_back({"RGBA" + b, PNG_COLOR_TYPE_RGBA, bits});
        kinds.push_back({"RGB with tRNS" + b, PNG_COLOR_TYPE_RGB, bits, 61, 37, false, true});
        kinds.push_back({"gray with tRNS" + b, PNG_COLOR_TYPE_GRAY, bits, 61, 37, false, true});
        kinds.push_back({"RGBA, interlaced" + b, PNG_COLOR_TYPE_RGBA, bits, 61, 37, true});
        // Alpha associated through the file's gamma, and (an sRGB chunk) not.
        kinds.push_back({"gray+alpha, gAMA 1/2.2" + b, PNG_COLOR_TYPE_GRAY_ALPHA, bits, 256, 256, false, false, 1 / 2.2,
                         false, true});
        kinds.push_back({"RGBA, gAMA 1/1.8, interlaced" + b, PNG_COLOR_TYPE_RGBA, bits, 61, 37, true, false, 1 / 1.8});
        kinds.push_back({"RGBA, sRGB" + b, PNG_COLOR_TYPE_RGBA, bits, 61, 37, false, false, 0.0, true});
    }
    kinds.push_back({"palette with tRNS 8-bit", PNG_COLOR_TYPE_PALETTE, 8, 61, 37, false, true});
    kinds.push_back({"palette with tRNS 2-bit, interlaced", PNG_COLOR_TYPE_PALETTE, 2, 61, 37, true, true});
    kinds.push_back({"gray 4-bit, interlaced", PNG_COLOR_TYPE_GRAY, 4, 61, 37, true});
    kinds.push_back({"every 16-bit gray value", PNG_COLOR_TYPE_GRAY, 16, 256, 256, false, false, 0.0, false, true});
    kinds.push_back(
        {"every 8-bit gray and alpha pair", PNG_COLOR_TYPE_GRAY_ALPHA, 8, 256, 256, false, false, 0.0, false, true});
    kinds.push_back({"one pixel", PNG_COLOR_TYPE_RGBA, 8, 1, 1});
    for (const PngKind& k : kinds) {
        const Bytes bytes = make_png(k);
        for (bool unassociated : {false, true}) {
            INFO(k.name << (unassociated ? ", alpha as stored" : ", alpha associated"));
            check_same_pixels<float>(bytes, unassociated, 0);
            check_same_pixels<std::uint8_t>(bytes, unassociated, 0);
            check_same_pixels<float>(bytes, unassociated, 1);  // the first channels only
        }
    }
}

TEST_CASE("libpng writes the pixels and text OpenImageIO's PNG writer does", "[images][png]") {
    for (int channels : {3, 4}) {
        INFO(channels << " channels");
        const Metadata attributes{{"quadshade:scene", "a.gltf"}, {"Software", "quadshade"}};
        image_library::EncoderSpec spec{67, 23, channels, false, attributes};
        std::vector<std::uint8_t> pixels(std::size_t(spec.width * spec.height * channels));
        for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = std::uint8_t(i * 7 % 256 < 16 ? 0 : i * 13 % 256);
        const Bytes ours = test::encode(*image_library::create_png(), "test.png", spec, pixels);
        std::string error;
        const auto oiio_encoder = image_library::library().create("test.png", error);
        REQUIRE(oiio_encoder);
        const Bytes theirs = test::encode(*oiio_encoder, "test.png", spec, pixels);
        OiioPng a(ours, true), b(theirs, true);
        CHECK(a.in->spec().nchannels == channels);
        std::vector<std::uint8_t> pa(pixels.size()), pb(pixels.size());
        REQUIRE(a.in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, pa.data()));
        REQUIRE(b.in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, pb.data()));
        CHECK(pa == pb);
        if (channels == 3) CHECK(pa == pixels);
        for (const char* key : {"quadshade:scene", "Software"}) {
            CHECK(a.in->spec().get_string_attribute(key) == b.in->spec().get_string_attribute(key));
        }
        CHECK(a.in->spec().get_string_attribute("Software") == "quadshade");
    }
}

TEST_CASE("an image file holds each attribute once, a later one of the same name in any case replacing the earlier",
          "[images][png]") {
    const std::filesystem::path file = test::temp_dir("png-attributes") / "a.png";
    const Image image{2, 1, std::vector<float>(8, 0.5f)};
    write_image(file, image,
                {{"software", "x"}, {"quadshade:scene", "a.gltf"}, {"", "nameless"}, {"QUADSHADE:Scene", "b"}});
    std::ifstream in(file, std::ios::binary);
    const Bytes bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const OiioPng png(bytes, true);
    std::vector<std::string> names;
    for (const OIIO::ParamValue& p : png.in->spec().extra_attribs) names.push_back(p.name().string());
    CHECK(std::count(names.begin(), names.end(), "Software") == 1);
    CHECK(std::count(names.begin(), names.end(), "software") == 0);
    CHECK(png.in->spec().get_string_attribute("Software") == "quadshade");  // the program's name, last
    CHECK(png.in->spec().get_string_attribute("quadshade:scene") == "b");
    CHECK(std::count(names.begin(), names.end(), "") == 0);
}

TEST_CASE("a damaged PNG is refused with a message naming it, and a failed write is reported",
          "[images][png][hostile]") {
    const Bytes whole = make_png({"RGB", PNG_COLOR_TYPE_RGB, 8, 19, 11});
    // Every truncation, and every byte of the file flipped: refused or decoded, never a crash
    // (libpng's errors jump out of its reader), and a refusal names the file.
    std::size_t refused = 0;
    const auto decode = [&](const Bytes& bytes) {
        try {
            const Image img = decode_image(bytes, "damaged.png");
            CHECK(img.rgba.size() == std::size_t(img.width) * std::size_t(img.height) * 4);
        } catch (const ImageError& e) {
            ++refused;
            CHECK_THAT(e.what(), Catch::StartsWith("damaged.png: "));
        }
    };
    for (std::size_t size = 0; size < whole.size(); ++size)
        decode(Bytes(whole.begin(), whole.begin() + std::ptrdiff_t(size)));
    CHECK(refused >= whole.size() - 12);  // all but a file cut in its IEND chunk
    for (std::size_t i = 0; i < whole.size(); ++i) {
        Bytes flipped = whole;
        flipped[i] ^= 0x5A;
        decode(flipped);
    }
    std::string error;
    CHECK_FALSE(image_library::open_png(Bytes(whole.begin(), whole.begin() + 40), false, error));
    CHECK_THAT(error, Catch::Contains("libpng") && Catch::Contains("truncated"));

    // A sink that takes 100 bytes only: the encoder stops with an error.
    image_library::EncoderSpec spec{64, 64, 3, false, {}};
    std::vector<std::uint8_t> pixels(64 * 64 * 3);
    for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = std::uint8_t(i * 31 % 251);
    MemorySink sink;
    sink.limit = 100;
    const auto encoder = image_library::create_png();
    bool written = encoder->open("full.png", sink, spec);
    for (int y = 0; written && y < 64; ++y)
        written = encoder->write_rows(y, y + 1, false, pixels.data() + std::size_t(y) * 64 * 3);
    written = written && encoder->close();
    CHECK_FALSE(written);
    CHECK_THAT(encoder->error(), Catch::Contains("write"));
}

}  // namespace qs
