#include "images/image_checks.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace qs {

namespace {

std::uint32_t big_endian_u32(const unsigned char* p) {
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | std::uint32_t(p[3]);
}

// PNG: the signature, then chunks of a 4-byte length, a 4-byte type, the data and a CRC.
std::string png_problem(std::span<const unsigned char> b) {
    static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    if (b.size() < 8 || std::memcmp(b.data(), kSignature, 8) != 0) return "not a PNG file (no PNG signature)";
    std::size_t at = 8;
    while (at + 12 <= b.size()) {
        const std::uint64_t length = big_endian_u32(&b[at]);
        const std::string type(reinterpret_cast<const char*>(&b[at + 4]), 4);
        if (length > b.size() - at - 12) {
            return "PNG chunk '" + type + "' claims " + std::to_string(length) + " bytes, the file has " +
                   std::to_string(b.size() - at - 12) + " after it";
        }
        if (type == "IEND") return "";
        at += 12 + std::size_t(length);
    }
    return "";  // a truncated file: the decoder reports it
}

std::uint32_t little_endian_u32(const unsigned char* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}

// The bytes OpenEXR's reader takes for a value of `type` when the file says `size`; -1: as many
// as `size` says. Its reader reads each known type by its layout, not by the size the file gives
// (a channel list up to its empty name, a preview by its width and height), so where the two
// disagree it goes on reading the next attribute from the wrong place, and a string length read
// from there is allocated before a byte is checked (2.2 GB and 14 s for a 745-byte file, found by
// the image fuzzer).
std::int64_t exr_value_bytes(std::string_view type, std::span<const unsigned char> value) {
    struct Fixed {
        std::string_view type;
        int bytes;
    };
    static const Fixed kFixed[] = {{"box2i", 16},      {"box2f", 16},    {"chromaticities", 32}, {"compression", 1},
                                   {"deepImageState", 1}, {"double", 8}, {"envmap", 1},          {"float", 4},
                                   {"int", 4},         {"keycode", 28},  {"lineOrder", 1},       {"m33f", 36},
                                   {"m33d", 72},       {"m44f", 64},     {"m44d", 128},          {"rational", 8},
                                   {"tiledesc", 9},    {"timecode", 8},  {"v2i", 8},             {"v2f", 8},
                                   {"v2d", 16},        {"v3i", 12},      {"v3f", 12},            {"v3d", 24}};
    for (const Fixed& f : kFixed) {
        if (type == f.type) return f.bytes;
    }
    if (type == "chlist") {  // names, each followed by 16 bytes, up to an empty name
        std::size_t at = 0;
        while (at < value.size() && value[at] != 0) {
            const void* end = std::memchr(&value[at], 0, value.size() - at);
            if (!end) return -2;  // runs past its size
            at = std::size_t(static_cast<const unsigned char*>(end) - value.data()) + 1 + 16;
        }
        return std::int64_t(at) + 1;
    }
    if (type == "preview") {  // width, height, then 4 bytes a pixel
        if (value.size() < 8) return 8;
        // Two 32-bit sizes: their product fits 64 bits, four times it may not (the image fuzzer
        // finds such input).
        const std::uint64_t texels = std::uint64_t(little_endian_u32(&value[0])) * little_endian_u32(&value[4]);
        if (texels > (value.size() - 8) / 4) return -2;  // more than its size holds
        return 8 + 4 * std::int64_t(texels);
    }
    return -1;  // string, stringvector, floatvector and unknown types: read by their size
}

// OpenEXR: magic, version, then one header (or, multi-part, headers ended by an empty one) of
// attributes: a name, a type name (both NUL-terminated), a 4-byte size and the value. Refused:
// a size past the end of the file, a size other than the one the reader will take, and names
// longer than the reader reads (it would go on from the wrong place as well).
std::string exr_problem(std::span<const unsigned char> b) {
    if (b.size() < 8 || big_endian_u32(b.data()) != 0x762F3101u) return "not an OpenEXR file (no OpenEXR magic)";
    const bool long_names = b[5] & 0x04;  // version flags, bit 10
    const bool multipart = b[5] & 0x10;   // bit 12
    const std::size_t max_name = long_names ? 255 : 31, max_type = 255;
    std::size_t at = 8;
    auto text = [&](std::string& out) {
        const void* end = std::memchr(&b[at], 0, b.size() - at);
        if (!end) return false;
        out.assign(reinterpret_cast<const char*>(&b[at]), static_cast<const unsigned char*>(end) - &b[at]);
        at += out.size() + 1;
        return true;
    };
    for (int header = 0;; ++header) {
        std::string name, type;
        for (;;) {
            if (at >= b.size() || !text(name)) return "";  // truncated: the decoder reports it
            if (name.empty()) break;                         // end of this header
            if (name.size() > max_name) {
                return "OpenEXR attribute name '" + name.substr(0, 40) + "...' is longer than " + std::to_string(max_name) +
                       " characters";
            }
            if (!text(type) || at + 4 > b.size()) return "";
            if (type.size() > max_type) return "OpenEXR attribute '" + name + "' has a type name longer than 255 characters";
            const std::int32_t size = std::int32_t(little_endian_u32(&b[at]));
            at += 4;
            if (size < 0 || std::uint64_t(size) > b.size() - at) {
                return "OpenEXR attribute '" + name + "' claims " + std::to_string(size) + " bytes, the file has " +
                       std::to_string(b.size() - at) + " after it";
            }
            const std::int64_t takes = exr_value_bytes(type, b.subspan(at, std::size_t(size)));
            if (takes != -1 && takes != size) {
                return "OpenEXR attribute '" + name + "' of type " + type + " has " + std::to_string(size) +
                       " bytes, not the layout of its type";
            }
            at += std::size_t(size);
        }
        // A multi-part file's header list ends with an empty header (one more NUL).
        if (!multipart || (at < b.size() && b[at] == 0)) return "";
    }
}

}  // namespace

std::string image_container_problem(std::span<const unsigned char> bytes, std::string_view extension) {
    if (extension == ".png") return png_problem(bytes);
    if (extension == ".exr") return exr_problem(bytes);
    return "";
}

}  // namespace qs
