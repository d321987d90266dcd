// The one file that includes stb_image.
#include "reference/texture_image.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_FAILURE_USERMSG
#include <stb_image.h>

namespace qs {

DecodedImage decode_texture_image(const ImageSource& source) {
    std::string name = source.file.string();
    std::vector<std::uint8_t> file_bytes;
    const std::vector<std::uint8_t>* bytes = &source.bytes;
    if (source.kind == ImageSource::Kind::File) {
        std::ifstream in(source.file, std::ios::binary);
        if (!in) throw std::runtime_error(name + ": cannot read image file");
        file_bytes.assign(std::istreambuf_iterator<char>(in), {});
        bytes = &file_bytes;
    } else {
        name = source.kind == ImageSource::Kind::DataUri ? "data: URI image" : "bufferView image";
    }
    if (bytes->empty() || bytes->size() > std::size_t(1) << 30) throw std::runtime_error(name + ": empty or oversized image");
    const auto* data = bytes->data();
    const int size = int(bytes->size());
    DecodedImage d;
    int channels = 0;
    d.sixteen_bits = stbi_is_16_bit_from_memory(data, size) != 0;
    void* pixels = d.sixteen_bits ? static_cast<void*>(stbi_load_16_from_memory(data, size, &d.width, &d.height, &channels, 4))
                                  : static_cast<void*>(stbi_load_from_memory(data, size, &d.width, &d.height, &channels, 4));
    if (!pixels) throw std::runtime_error(name + ": cannot decode image: " + stbi_failure_reason());
    const std::unique_ptr<void, void (*)(void*)> owner(pixels, stbi_image_free);
    if (d.width < 1 || d.height < 1 || d.width > (1 << 15) || d.height > (1 << 15)) {
        throw std::runtime_error(name + ": unsupported image size " + std::to_string(d.width) + "x" + std::to_string(d.height));
    }
    d.bytes.resize(std::size_t(d.width) * std::size_t(d.height) * 4 * (d.sixteen_bits ? 2 : 1));
    std::memcpy(d.bytes.data(), pixels, d.bytes.size());
    return d;
}

}  // namespace qs
