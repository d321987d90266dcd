#include "piglit/numbers.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

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

float round_to_half(float f) {
    // Written out rather than through _Float16, which clang before 15 does not have on x86.
    if (!std::isfinite(f)) return f;
    const float a = std::fabs(f);
    if (a >= 65520.0f) return std::copysign(std::numeric_limits<float>::infinity(), f);  // past 65504's half step
    // A half's step near a: 2^(E-10) for a in [2^E, 2^(E+1)), normal halves' E from -14; subnormals share
    // 2^-24. Scaling by a power of two is exact, and nearbyint rounds to even as the conversion does.
    int e = 0;
    std::frexp(a, &e);
    const float step = std::ldexp(1.0f, std::max(e - 1, -14) - 10);
    return std::copysign(std::nearbyint(a / step) * step, f);
}

float parse_half(const char* s, char** end) { return round_to_half(parse_float(s, end)); }

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
