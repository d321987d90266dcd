#include "scenes/gltf_checks.h"

#include <cmath>
#include <cstring>

#include "scenes/scene.h"

namespace qs::gltf_checks {

int json_nesting_depth(std::string_view json, int stop_above) {
    int depth = 0, deepest = 0;
    bool in_string = false, escaped = false;
    for (const char c : json) {
        if (in_string) {
            if (escaped) {
                escaped = false;
            } else if (c == '\\') {
                escaped = true;
            } else if (c == '"') {
                in_string = false;
            }
            continue;
        }
        if (c == '"') {
            in_string = true;
        } else if (c == '{' || c == '[') {
            if (++depth > deepest) {
                deepest = depth;
                if (deepest > stop_above) return deepest;
            }
        } else if ((c == '}' || c == ']') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

bool has_glb_magic(std::span<const unsigned char> bytes) {
    return bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
}

namespace {
std::uint32_t little_endian_u32(const unsigned char* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}
}  // namespace

std::string_view glb_json_chunk(std::span<const unsigned char> glb) {
    // Header: magic, version, total length; then chunk 0: length, type "JSON", data.
    constexpr std::size_t kHeader = 12, kChunkHeader = 8;
    if (!has_glb_magic(glb)) throw SceneError("binary glTF: no 'glTF' magic");
    if (glb.size() < kHeader + kChunkHeader) throw SceneError("binary glTF: shorter than its header");
    const std::uint32_t version = little_endian_u32(&glb[4]);
    if (version != 2) throw SceneError("binary glTF: version " + std::to_string(version) + ", not 2");
    const std::uint64_t length = little_endian_u32(&glb[8]);
    if (length > glb.size()) {
        throw SceneError("binary glTF: header says " + std::to_string(length) + " bytes, the file has " +
                         std::to_string(glb.size()));
    }
    const std::uint64_t json_length = little_endian_u32(&glb[12]);
    if (little_endian_u32(&glb[16]) != 0x4E4F534Au) throw SceneError("binary glTF: the first chunk is not JSON");
    if (kHeader + kChunkHeader + json_length > length) {  // 64-bit: cannot wrap
        throw SceneError("binary glTF: the JSON chunk (" + std::to_string(json_length) +
                         " bytes) reaches past the file's length");
    }
    return {reinterpret_cast<const char*>(glb.data() + kHeader + kChunkHeader), std::size_t(json_length)};
}

std::string percent_decoded(std::string_view uri) {
    auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return -1;
    };
    std::string out;
    out.reserve(uri.size());
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
            out += char(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
            i += 2;
        } else {
            out += uri[i] == '+' ? ' ' : uri[i];
        }
    }
    return out;
}

std::optional<std::uint64_t> checked_add(std::uint64_t a, std::uint64_t b) {
    std::uint64_t r;
    if (__builtin_add_overflow(a, b, &r)) return std::nullopt;
    return r;
}

std::optional<std::uint64_t> checked_mul(std::uint64_t a, std::uint64_t b) {
    std::uint64_t r;
    if (__builtin_mul_overflow(a, b, &r)) return std::nullopt;
    return r;
}

std::optional<std::uint64_t> strided_end(std::uint64_t offset, std::uint64_t count, std::uint64_t stride,
                                         std::uint64_t element) {
    if (count == 0) return offset;
    const auto span = checked_mul(count - 1, stride);
    if (!span) return std::nullopt;
    const auto last = checked_add(offset, *span);
    if (!last) return std::nullopt;
    return checked_add(*last, element);
}

bool is_finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) return false;
        }
    }
    return true;
}

double determinant(const glm::mat4& m) {
    // Laplace expansion over 2x2 minors of the first two columns and the last two.
    auto a = [&](int c, int r) { return double(m[c][r]); };
    double det = 0.0;
    const int pairs[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    const double signs[6] = {1, -1, 1, 1, -1, 1};
    for (int i = 0; i < 6; ++i) {
        const int r0 = pairs[i][0], r1 = pairs[i][1];
        const int s0 = pairs[5 - i][0], s1 = pairs[5 - i][1];  // the complementary rows
        const double low = a(0, r0) * a(1, r1) - a(0, r1) * a(1, r0);
        const double high = a(2, s0) * a(3, s1) - a(2, s1) * a(3, s0);
        det += signs[i] * low * high;
    }
    return det;
}

bool places_things(const glm::mat4& m) {
    if (!is_finite(m)) return false;
    const double det = determinant(m);
    return std::isfinite(det) && det != 0.0;
}

}  // namespace qs::gltf_checks
