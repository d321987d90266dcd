#pragma once
// What the PNG and OpenEXR codec tests share: image files as bytes in memory, and an encoder run
// into them the way ImageWriter drives one.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "scenes/image_library.h"

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

}  // namespace qs::test
