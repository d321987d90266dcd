#include "scenes/image_checks.h"

#include <cstdint>
#include <cstring>

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

// OpenEXR: magic, version, then one header (or, multi-part, headers ended by an empty one) of
// attributes: a name, a type name (both NUL-terminated), a 4-byte size and the value.
std::string exr_problem(std::span<const unsigned char> b) {
    if (b.size() < 8 || big_endian_u32(b.data()) != 0x762F3101u) return "not an OpenEXR file (no OpenEXR magic)";
    const bool multipart = b[5] & 0x10;  // version flags, bit 12
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
            if (!text(type) || at + 4 > b.size()) return "";
            const std::int32_t size = std::int32_t(std::uint32_t(b[at]) | std::uint32_t(b[at + 1]) << 8 |
                                                   std::uint32_t(b[at + 2]) << 16 | std::uint32_t(b[at + 3]) << 24);
            at += 4;
            if (size < 0 || std::uint64_t(size) > b.size() - at) {
                return "OpenEXR attribute '" + name + "' claims " + std::to_string(size) + " bytes, the file has " +
                       std::to_string(b.size() - at) + " after it";
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
