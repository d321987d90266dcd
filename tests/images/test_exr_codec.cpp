// OpenEXR through the OpenEXR library (images/exr_codec.h) against OpenImageIO, which read and
// wrote quadshade's OpenEXR files before and still reads its other formats: half, float and
// unsigned channels under any names, scanline and tiled files, every compression, a data window
// apart from the display window and multi-part files decode to the same channels and the same
// bits, float and 8-bit; written files hold the pixels, channels and attributes OpenImageIO's
// writer gives; a damaged file is refused with a message.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfMultiPartOutputFile.h>
#include <ImfOutputPart.h>
#include <ImfPartType.h>
#include <ImfStdIO.h>
#include <ImfTiledOutputPart.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "images/exr_codec.h"
#include "images/image_io.h"
#include "images/image_library.h"
#include "tests/images/codec_test_files.h"

namespace qs {

namespace {

using test::Bytes;
using test::MemorySink;

struct ExrChannel {
    std::string name;
    Imf::PixelType type = Imf::HALF;
};

// An OpenEXR file of one kind, made by OpenEXR.
struct ExrKind {
    std::string name;
    std::vector<ExrChannel> channels;
    Imf::Compression compression = Imf::ZIP_COMPRESSION;
    int width = 61, height = 37;
    Imath::V2i origin{0, 0};                     // the data window's; the display window is at 0, 0
    int tiles = 0;                               // > 0: tiled, tiles of this side
    Imf::LevelMode levels = Imf::ONE_LEVEL;      // of a tiled file
    int parts = 1;                               // the second part holds other pixels
};

std::vector<ExrChannel> named(std::initializer_list<const char*> names, Imf::PixelType type) {
    std::vector<ExrChannel> channels;
    for (const char* n : names) channels.push_back({n, type});
    return channels;
}

// A sample of channel c at (x, y) of a level and part: negative, beyond 1, on and about the
// halves between 8-bit levels, and a few NaNs and infinities.
float sample(int x, int y, int c, int level) {
    if (x == 3 && y == 2) return std::numeric_limits<float>::quiet_NaN();
    const float infinity = std::numeric_limits<float>::infinity();
    if (x == 4 && y == 2) return c % 2 ? -infinity : infinity;
    static const float kFractions[] = {0.0f, 0.5f, 0.49999997f, 0.50000006f, 0.25f, 0.75f};
    const int k = (x * 97 + y * 753 + c * 71 + level * 13) % 300 - 20;
    return (float(k) + kFractions[(x + 2 * y + c) % 6]) / 255.0f;
}

std::uint32_t unsigned_sample(int x, int y, int c, int level) {
    return std::uint32_t(x * 97 + y * 753 + c * 71 + level * 13) * 2654435761u;
}

// The pixels of one level of one part, a channel's samples one after another, in its own type.
struct Samples {
    std::vector<std::vector<unsigned char>> channels;
    Imf::FrameBuffer frame(const ExrKind& k, const Imath::Box2i& window) {
        Imf::FrameBuffer f;
        for (std::size_t c = 0; c < k.channels.size(); ++c) {
            const Imf::PixelType type = k.channels[c].type;
            const std::size_t bytes = type == Imf::HALF ? 2 : 4;
            f.insert(k.channels[c].name, Imf::Slice::Make(type, channels[c].data(), window, bytes));
        }
        return f;
    }
};

Samples make_samples(const ExrKind& k, int width, int height, int level) {
    Samples s;
    for (std::size_t c = 0; c < k.channels.size(); ++c) {
        std::vector<unsigned char> data;
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                unsigned char v[4];
                if (k.channels[c].type == Imf::HALF) {
                    const half h(sample(x, y, int(c), level));
                    const std::uint16_t bits = h.bits();
                    std::memcpy(v, &bits, 2);
                    data.insert(data.end(), v, v + 2);
                } else if (k.channels[c].type == Imf::FLOAT) {
                    const float f = sample(x, y, int(c), level);
                    std::memcpy(v, &f, 4);
                    data.insert(data.end(), v, v + 4);
                } else {
                    const std::uint32_t u = unsigned_sample(x, y, int(c), level);
                    std::memcpy(v, &u, 4);
                    data.insert(data.end(), v, v + 4);
                }
            }
        }
        s.channels.push_back(std::move(data));
    }
    return s;
}

Bytes make_exr(const ExrKind& k) {
    std::vector<Imf::Header> headers;
    for (int p = 0; p < k.parts; ++p) {
        Imf::Header h(Imath::Box2i({0, 0}, {k.width + 7, k.height + 5}),
                      Imath::Box2i(k.origin, k.origin + Imath::V2i(k.width - 1, k.height - 1)));
        h.compression() = k.compression;
        for (const ExrChannel& c : k.channels) h.channels().insert(c.name, Imf::Channel(c.type));
        if (k.tiles > 0) h.setTileDescription(Imf::TileDescription(unsigned(k.tiles), unsigned(k.tiles), k.levels));
        h.setType(k.tiles > 0 ? Imf::TILEDIMAGE : Imf::SCANLINEIMAGE);
        if (k.parts > 1) h.setName("part " + std::to_string(p));
        headers.push_back(h);
    }
    Imf::StdOSStream out;
    {
        Imf::MultiPartOutputFile file(out, headers.data(), k.parts);
        for (int p = 0; p < k.parts; ++p) {
            if (k.tiles == 0) {
                Imf::OutputPart part(file, p);
                Samples s = make_samples(k, k.width, k.height, 5 * p);
                part.setFrameBuffer(s.frame(k, headers[std::size_t(p)].dataWindow()));
                part.writePixels(k.height);
                continue;
            }
            Imf::TiledOutputPart part(file, p);
            for (int ly = 0; ly < part.numYLevels(); ++ly) {
                for (int lx = 0; lx < part.numXLevels(); ++lx) {
                    if (k.levels != Imf::RIPMAP_LEVELS && lx != ly) continue;
                    const Imath::Box2i window = part.dataWindowForLevel(lx, ly);
                    Samples s = make_samples(k, window.max.x - window.min.x + 1, window.max.y - window.min.y + 1,
                                             lx + 3 * ly + 5 * p);
                    part.setFrameBuffer(s.frame(k, window));
                    part.writeTiles(0, part.numXTiles(lx) - 1, 0, part.numYTiles(ly) - 1, lx, ly);
                }
            }
        }
    }
    const std::string bytes = out.str();
    return Bytes(bytes.begin(), bytes.end());
}

// OpenImageIO's reader on OpenEXR bytes (a texture's with its alpha as stored changes nothing for
// OpenEXR).
struct OiioExr : test::OiioReader {
    explicit OiioExr(const Bytes& bytes, bool unassociated_alpha = false)
        : OiioReader(bytes, "exr", unassociated_alpha) {}
};

template <class T>
void check_same_pixels(const Bytes& bytes, int channels, bool unassociated_alpha = false) {
    std::string error;
    const auto ours = image_library::open_exr(bytes, "test.exr", error);
    INFO(error);
    REQUIRE(ours);
    test::check_same_as_oiio<T>(*ours, bytes, "exr", unassociated_alpha, channels);
}


}  // namespace

TEST_CASE("OpenEXR decodes every kind of OpenEXR file to OpenImageIO's channels and bits", "[images][exr]") {
    std::vector<ExrKind> kinds;
    kinds.push_back({"RGBA half", named({"R", "G", "B", "A"}, Imf::HALF)});
    kinds.push_back({"RGB float", named({"R", "G", "B"}, Imf::FLOAT)});
    kinds.push_back({"RGBA float", named({"R", "G", "B", "A"}, Imf::FLOAT)});
    kinds.push_back({"Y half", named({"Y"}, Imf::HALF)});
    kinds.push_back({"YA float", named({"Y", "A"}, Imf::FLOAT)});
    kinds.push_back({"layers and other names",
                     {{"Z", Imf::FLOAT}, {"diffuse.R", Imf::HALF}, {"diffuse.green", Imf::HALF}, {"alpha", Imf::HALF},
                      {"b", Imf::FLOAT}, {"G", Imf::HALF}, {"red", Imf::FLOAT}, {"custom", Imf::HALF},
                      {"a.x", Imf::FLOAT}, {"RA", Imf::HALF}}});
    kinds.push_back({"no known names", named({"u", "v", "w"}, Imf::HALF)});
    kinds.push_back({"unsigned and half", {{"id", Imf::UINT}, {"R", Imf::HALF}, {"G", Imf::UINT}}});
    const std::pair<Imf::Compression, const char*> compressions[] = {
        {Imf::NO_COMPRESSION, "none"}, {Imf::RLE_COMPRESSION, "RLE"},     {Imf::ZIPS_COMPRESSION, "ZIPS"},
        {Imf::PIZ_COMPRESSION, "PIZ"}, {Imf::PXR24_COMPRESSION, "PXR24"}, {Imf::B44_COMPRESSION, "B44"},
        {Imf::B44A_COMPRESSION, "B44A"}, {Imf::DWAA_COMPRESSION, "DWAA"}, {Imf::DWAB_COMPRESSION, "DWAB"}};
    for (const auto& [c, name] : compressions) {
        kinds.push_back({std::string("RGBA half, ") + name, named({"R", "G", "B", "A"}, Imf::HALF), c});
        kinds.push_back({std::string("RGB float, ") + name, named({"R", "G", "B"}, Imf::FLOAT), c});
    }
    kinds.push_back({"data window apart from the display window", named({"R", "G", "B", "A"}, Imf::HALF),
                     Imf::ZIP_COMPRESSION, 45, 29, {-5, 3}});
    kinds.push_back({"tiled", named({"R", "G", "B", "A"}, Imf::HALF), Imf::ZIP_COMPRESSION, 61, 37, {2, -1}, 16});
    kinds.push_back({"tiled, mipmapped", named({"R", "G", "B"}, Imf::FLOAT), Imf::PIZ_COMPRESSION, 61, 37, {0, 0}, 8,
                     Imf::MIPMAP_LEVELS});
    kinds.push_back({"tiled, ripmapped", named({"Y"}, Imf::HALF), Imf::NO_COMPRESSION, 33, 20, {0, 0}, 8,
                     Imf::RIPMAP_LEVELS});
    kinds.push_back({"two parts", named({"R", "G", "B", "A"}, Imf::HALF), Imf::ZIP_COMPRESSION, 61, 37, {0, 0}, 0,
                     Imf::ONE_LEVEL, 2});
    kinds.push_back({"two tiled parts", named({"R", "G", "B"}, Imf::FLOAT), Imf::RLE_COMPRESSION, 61, 37, {1, 1}, 16,
                     Imf::ONE_LEVEL, 2});
    kinds.push_back({"one pixel", named({"R", "G", "B", "A"}, Imf::HALF), Imf::ZIP_COMPRESSION, 1, 1});
    for (const ExrKind& k : kinds) {
        INFO(k.name);
        const Bytes bytes = make_exr(k);
        check_same_pixels<float>(bytes, 0);
        check_same_pixels<std::uint8_t>(bytes, 0);
        check_same_pixels<float>(bytes, 1);  // the first channels only
        check_same_pixels<std::uint8_t>(bytes, std::min(4, int(k.channels.size())));
        check_same_pixels<std::uint8_t>(bytes, std::min(4, int(k.channels.size())), /*unassociated_alpha=*/true);
    }
}

TEST_CASE("OpenEXR writes the pixels, channels and attributes OpenImageIO's OpenEXR writer does", "[images][exr]") {
    for (int channels : {1, 2, 3, 4}) {
        INFO(channels << " channels");
        const Metadata attributes{{"quadshade:scene", "a.gltf"}, {"Software", "quadshade"}};
        image_library::EncoderSpec spec{67, 23, channels, true, attributes};
        std::vector<float> pixels(std::size_t(spec.width * spec.height * channels));
        for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = float(i % 301) / 255.0f - 0.1f;
        pixels[5] = std::numeric_limits<float>::quiet_NaN();
        const Bytes ours = test::encode(*image_library::create_exr(), "test.exr", spec, pixels);
        std::string error;
        const auto oiio_encoder = image_library::library().create("test.exr", error);
        REQUIRE(oiio_encoder);
        const Bytes theirs = test::encode(*oiio_encoder, "test.exr", spec, pixels);
        OiioExr a(ours), b(theirs);
        CHECK(a.in->spec().nchannels == channels);
        CHECK(a.in->spec().channelnames == b.in->spec().channelnames);
        CHECK(a.in->spec().format == OIIO::TypeDesc::FLOAT);
        CHECK(a.in->spec().format == b.in->spec().format);
        std::vector<float> pa(pixels.size()), pb(pixels.size());
        REQUIRE(a.in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pa.data()));
        REQUIRE(b.in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pb.data()));
        CHECK(std::memcmp(pa.data(), pb.data(), pa.size() * sizeof(float)) == 0);
        CHECK(std::memcmp(pa.data(), pixels.data(), pa.size() * sizeof(float)) == 0);
        for (const char* key : {"quadshade:scene", "Software", "compression"}) {
            CHECK(a.in->spec().get_string_attribute(key) == b.in->spec().get_string_attribute(key));
        }
        CHECK(a.in->spec().get_string_attribute("Software") == "quadshade");
        CHECK(a.in->spec().get_string_attribute("compression") == "zip");
    }
}

TEST_CASE("a damaged OpenEXR file is refused with a message naming it, and a failed write is reported",
          "[images][exr][hostile]") {
    const Bytes whole = make_exr({"RGB", named({"R", "G", "B"}, Imf::HALF), Imf::ZIP_COMPRESSION, 19, 11});
    // Every truncation, and every byte of the file flipped: refused or decoded, never a crash
    // (OpenEXR's exceptions stop at the codec), and a refusal names the file.
    std::size_t refused = 0;
    const auto decode = [&](const Bytes& bytes) {
        try {
            const Image img = decode_image(bytes, "damaged.exr");
            CHECK(img.rgba.size() == std::size_t(img.width) * std::size_t(img.height) * 4);
        } catch (const ImageError& e) {
            ++refused;
            CHECK_THAT(e.what(), Catch::StartsWith("damaged.exr: "));
        }
    };
    for (std::size_t size = 0; size < whole.size(); ++size)
        decode(Bytes(whole.begin(), whole.begin() + std::ptrdiff_t(size)));
    CHECK(refused == whole.size());
    for (std::size_t i = 0; i < whole.size(); ++i) {
        Bytes flipped = whole;
        flipped[i] ^= 0x5A;
        decode(flipped);
    }
    std::string error;
    CHECK_FALSE(image_library::open_exr(Bytes(whole.begin(), whole.begin() + 40), "cut.exr", error));
    CHECK_THAT(error, Catch::StartsWith("OpenEXR: "));

    // A sink that takes 100 bytes only: the encoder stops with an error.
    image_library::EncoderSpec spec{64, 64, 3, true, {}};
    std::vector<float> pixels(64 * 64 * 3);
    for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = float(i * 31 % 251) / 250.0f;
    MemorySink sink;
    sink.limit = 100;
    const auto encoder = image_library::create_exr();
    bool written = encoder->open("full.exr", sink, spec);
    for (int y = 0; written && y < 64; ++y)
        written = encoder->write_rows(y, y + 1, true, pixels.data() + std::size_t(y) * 64 * 3);
    written = written && encoder->close();
    CHECK_FALSE(written);
    CHECK_THAT(encoder->error(), Catch::Contains("write"));
}

}  // namespace qs
