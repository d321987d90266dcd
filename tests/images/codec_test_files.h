#pragma once
// What the PNG and OpenEXR codec tests share: image files as bytes in memory, an encoder run into
// them the way ImageWriter drives one, and OpenImageIO's reading of them to hold a decoder to.

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "images/image_library.h"

namespace qs::test {

using Bytes = std::vector<unsigned char>;

// An in-memory file for an encoder.
class MemorySink final : public image_library::ByteSink {
public:
    std::size_t write_at(const void* data, std::size_t size, std::int64_t offset) override {
        const std::size_t room = std::size_t(offset) < limit ? std::min(size, limit - std::size_t(offset)) : 0;
        if (room == 0) return 0;
        if (bytes.size() < std::size_t(offset) + room) bytes.resize(std::size_t(offset) + room);
        std::memcpy(bytes.data() + offset, data, room);
        return room;
    }
    std::size_t read_at(void* data, std::size_t size, std::int64_t offset) override {
        const std::size_t n =
            std::size_t(offset) < bytes.size() ? std::min(size, bytes.size() - std::size_t(offset)) : 0;
        std::memcpy(data, bytes.data() + offset, n);
        return n;
    }
    std::int64_t size() const override { return std::int64_t(bytes.size()); }
    Bytes bytes;
    std::size_t limit = std::size_t(-1);  // writes past it fail, as on a full disk
};

// `pixels` (float or 8-bit samples, packed rows) encoded as the file `name`, a few rows at a
// time as ImageWriter writes them.
template <class Sample>
Bytes encode(image_library::Encoder& encoder, const std::string& name, const image_library::EncoderSpec& spec,
             const std::vector<Sample>& pixels) {
    MemorySink sink;
    REQUIRE(encoder.open(name, sink, spec));
    const std::size_t row = std::size_t(spec.width) * std::size_t(spec.channels);
    for (int y = 0; y < spec.height; y += 5) {
        const int end = std::min(y + 5, spec.height);
        REQUIRE(encoder.write_rows(y, end, std::is_same_v<Sample, float>, pixels.data() + std::size_t(y) * row));
    }
    REQUIRE(encoder.close());
    return sink.bytes;
}

// OpenImageIO's reader of `format` ("png", "exr") on bytes in memory, as openimageio_library.cpp
// opens one; `unassociated_alpha`: colours as stored, as for a texture.
struct OiioReader {
    OIIO::Filesystem::IOMemReader memory;
    std::unique_ptr<OIIO::ImageInput> in;
    OiioReader(const Bytes& bytes, const std::string& format, bool unassociated_alpha)
        : memory(bytes.data(), bytes.size()) {
        in = OIIO::ImageInput::create(format, false);
        REQUIRE(in);
        OIIO::ImageSpec config, spec;
        if (unassociated_alpha) config.attribute("oiio:UnassociatedAlpha", 1);
        void* proxy = &memory;
        config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
        REQUIRE(in->set_ioproxy(&memory));
        REQUIRE(in->open("test." + format, spec, config));
    }
};

// `ours`, a decoder of `bytes`, gives OpenImageIO's shape and, for the first `channels` channels
// (0: all), its samples bit for bit, as floats or 8-bit (T).
template <class T>
void check_same_as_oiio(image_library::Decoder& ours, const Bytes& bytes, const std::string& format,
                        bool unassociated_alpha, int channels) {
    OiioReader theirs(bytes, format, unassociated_alpha);
    const OIIO::ImageSpec& spec = theirs.in->spec();
    const image_library::ImageShape shape = ours.shape();
    CHECK(shape.width == spec.width);
    CHECK(shape.height == spec.height);
    CHECK(shape.channels == spec.nchannels);
    CHECK(shape.channel_bytes == int(spec.format.size()));
    if (channels == 0) channels = spec.nchannels;
    const std::size_t n = std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(channels);
    std::vector<T> a(n), b(n);
    REQUIRE(ours.read(channels, a.data()));
    REQUIRE(theirs.in->read_image(0, 0, 0, channels,
                                  std::is_same_v<T, float> ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8, b.data()));
    std::size_t differing = 0, first = n;
    for (std::size_t i = 0; i < n; ++i) {
        const bool differs = std::memcmp(&a[i], &b[i], sizeof(T)) != 0;
        if (differs && first == n) first = i;
        differing += differs;
    }
    INFO("first differing sample " << first << ": " << (first < n ? double(a[first]) : 0.0) << " vs "
                                   << (first < n ? double(b[first]) : 0.0));
    CHECK(differing == 0);
}

}  // namespace qs::test
