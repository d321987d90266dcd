#pragma once
// Numbers in a shader_test as piglit reads them (tests/shaders/parser_utils.c and
// tests/util/piglit-util.h), so that a value means what it means to piglit's shader_runner:
// floats through strtod rounded to float, or their bits in hex ("0x3f800000" is 1.0); ints
// through strtoll in any base, kept to 32 bits; uints through strtoul ("-1" is 0xffffffff).

#include <cstdint>
#include <vector>

namespace qs::piglit {

// One number at s (after blanks); *end is where it stopped (s when there was none).
float parse_float(const char* s, char** end);
std::int32_t parse_integer(const char* s, char** end);  // strtol_hex: "0x" bits, else any base
float parse_half(const char* s, char** end);  // a float rounded to half precision
// f rounded to the nearest IEEE half-precision value (ties to even), overflowing to infinity.
float round_to_half(float f);

// Up to n numbers from the start of s, as many as there are; `rest` where reading stopped.
std::vector<float> parse_floats(const char* s, std::size_t n, const char** rest = nullptr);
std::vector<std::int32_t> parse_ints(const char* s, std::size_t n, const char** rest = nullptr);
std::vector<std::uint32_t> parse_uints(const char* s, std::size_t n, const char** rest = nullptr);

}  // namespace qs::piglit
