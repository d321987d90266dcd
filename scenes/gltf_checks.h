#pragma once
// Checks on glTF data that tinygltf leaves to its user, kept apart from the loader (and free of
// tinygltf) so that each can be read, tested and fuzzed on its own: JSON nesting measured before
// parsing, the binary container's header, offsets and strides in arithmetic that cannot wrap,
// and transforms that can place something.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <glm/mat4x4.hpp>

namespace qs::gltf_checks {

// The deepest nesting of JSON objects and arrays in `json`, counting brackets outside strings,
// in one pass without recursion; stops at the first level deeper than `stop_above`.
int json_nesting_depth(std::string_view json, int stop_above);

// Whether `bytes` start with the binary glTF magic "glTF".
bool has_glb_magic(std::span<const unsigned char> bytes);

// The JSON chunk of a binary glTF, its header and chunk lengths checked against the bytes there
// are. Throws SceneError saying what is wrong (the caller names the file).
std::string_view glb_json_chunk(std::span<const unsigned char> glb);

// A URI's percent-escapes decoded the way tinygltf decodes buffer and image URIs before it opens
// them ("%20" a space; a '+' also a space), so that a URI is checked as the path it will be.
std::string percent_decoded(std::string_view uri);

// a + b and a * b, or nothing where they would not fit in 64 bits.
std::optional<std::uint64_t> checked_add(std::uint64_t a, std::uint64_t b);
std::optional<std::uint64_t> checked_mul(std::uint64_t a, std::uint64_t b);

// The end (one past the last byte) of `count` elements of `element` bytes, `stride` bytes apart,
// the first at `offset`: offset + (count - 1) stride + element; `offset` for no elements; nothing
// where the arithmetic would overflow.
std::optional<std::uint64_t> strided_end(std::uint64_t offset, std::uint64_t count, std::uint64_t stride,
                                         std::uint64_t element);

bool is_finite(const glm::mat4& m);
// The determinant in double (a float one underflows to 0 for small but usable scales).
double determinant(const glm::mat4& m);
// A transform that places things: finite, with a finite, non-zero determinant. An all-zero
// matrix or a scale of 0 flattens everything into nothing.
bool places_things(const glm::mat4& m);

}  // namespace qs::gltf_checks
