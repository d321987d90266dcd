#include "piglit/numbers.h"

#include <bit>
#include <cstdlib>
#include <cstring>

namespace qs::piglit {

namespace {

const char* skip_blanks(const char* s) {
    while (*s == ' ' || *s == '\t') ++s;
    return s;
}

}  // namespace

float parse_float(const char* s, char** end) {
    s = skip_blanks(s);
    if (std::strncmp(s, "0x", 2) == 0) return std::bit_cast<float>(std::uint32_t(std::strtoul(s, end, 16)));
    return float(std::strtod(s, end));
}

std::int32_t parse_integer(const char* s, char** end) {
    s = skip_blanks(s);
    if (std::strncmp(s, "0x", 2) == 0) return std::int32_t(std::uint32_t(std::strtoul(s, end, 16)));
    return std::int32_t(std::strtol(s, end, 0));
}

std::optional<float> parse_half(const char* s, char** end) {
    const float f = parse_float(s, end);
    return float(static_cast<_Float16>(f));
}

std::vector<float> parse_floats(const char* s, std::size_t n, const char** rest) {
    std::vector<float> out;
    const char* at = s;
    while (out.size() < n) {
        char* end = nullptr;
        const float v = parse_float(at, &end);
        if (end == at || end == skip_blanks(at)) break;
        out.push_back(v);
        at = end;
    }
    if (rest) *rest = at;
    return out;
}

std::vector<std::int32_t> parse_ints(const char* s, std::size_t n, const char** rest) {
    std::vector<std::int32_t> out;
    const char* at = s;
    while (out.size() < n) {
        char* end = nullptr;
        const long long v = std::strtoll(at, &end, 0);
        if (end == at) break;
        out.push_back(std::int32_t(std::uint32_t(std::uint64_t(v))));
        at = end;
    }
    if (rest) *rest = at;
    return out;
}

std::vector<std::uint32_t> parse_uints(const char* s, std::size_t n, const char** rest) {
    std::vector<std::uint32_t> out;
    const char* at = s;
    while (out.size() < n) {
        char* end = nullptr;
        const unsigned long v = std::strtoul(at, &end, 0);
        if (end == at) break;
        out.push_back(std::uint32_t(v));
        at = end;
    }
    if (rest) *rest = at;
    return out;
}

}  // namespace qs::piglit
