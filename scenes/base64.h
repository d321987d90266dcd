#pragma once
// RFC 4648 base64, for data: URIs (a glTF file's embedded images, a study report's images).

#include <cstdint>
#include <span>
#include <string>

namespace qs {

std::string base64(std::span<const std::uint8_t> bytes);

}  // namespace qs
