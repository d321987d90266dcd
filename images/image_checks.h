#pragma once
// Checks on image files' containers before a decoder sees them. Decoders trust the lengths a file
// declares and allocate them before reading: a PNG chunk or an OpenEXR header attribute that
// claims gigabytes costs gigabytes (found by fuzzing: 0.8 GB for a 277-byte PNG, 1.9 GB for a
// 974-byte EXR). A declared length can never exceed the bytes the file has, so that is checked
// here, the whole file being in memory.

#include <span>
#include <string>
#include <string_view>

namespace qs {

// What is wrong with the container of a file of format `extension` (".png", ".exr"; other
// formats pass), or an empty string when its declared lengths fit in it.
std::string image_container_problem(std::span<const unsigned char> bytes, std::string_view extension);

}  // namespace qs
