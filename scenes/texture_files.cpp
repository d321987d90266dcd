#include "scenes/texture_files.h"

#include <algorithm>
#include <span>
#include <string>
#include <vector>

#include "scenes/limits.h"
#include "scenes/scene_files.h"

namespace qs {

// A render's largest side is one the image files take.
static_assert(limits::kImageSide <= kMaxImageSide);

namespace {

// The format of a texture's image, as an extension: a file's own, embedded bytes' by their MIME
// type (glTF's two), else by their signature; empty when neither PNG nor JPEG.
std::string texture_extension(const ImageSource& source) {
    if (source.kind == ImageSource::Kind::File) return lowercase_extension(source.file);
    const std::string& mime = source.mime_type;
    const std::vector<std::uint8_t>& bytes = source.bytes;
    const bool png =
        mime == "image/png" || (mime.empty() && bytes.size() >= 4 && bytes[0] == 0x89 && bytes[1] == 'P');
    const bool jpeg =
        mime == "image/jpeg" || (mime.empty() && bytes.size() >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8);
    return png ? ".png" : jpeg ? ".jpg" : "";
}

}  // namespace

bool needs_image_library(const Scene& scene) {
    const auto needs = [](const ImageSource& image) {
        const std::string ext = texture_extension(image);
        return !ext.empty() && !has_own_codec(ext);
    };
    return std::any_of(scene.textures.begin(), scene.textures.end(), [&](const Texture& t) {
        return needs(t.image) || std::any_of(t.faces.begin(), t.faces.end(), needs);
    });
}

Image8 read_texture_image(const ImageSource& source, std::uint64_t* decoding_bytes) {
    ImageReadLimits limits;
    limits.max_side = limits::kTextureSide;
    limits.max_pixels = limits::kTextureTexels;
    std::vector<unsigned char> file_bytes;
    std::span<const unsigned char> bytes = source.bytes;
    std::string name = source.file.string(), ext = texture_extension(source);
    if (source.kind == ImageSource::Kind::File) {
        try {
            file_bytes = read_scene_file(source.file, limits::kResourceFileBytes);  // resolved already: no links
        } catch (const SceneError& e) {
            throw ImageError(e.what());
        }
        bytes = file_bytes;
    } else {
        name = source.kind == ImageSource::Kind::DataUri ? "data: URI image" : "bufferView image";
        if (ext.empty()) throw ImageError(name + ": not a PNG or JPEG image (MIME type '" + source.mime_type + "')");
    }
    // PNG alpha stays as stored (unassociated), as GL uploads it.
    Image8 img = decode_image8(bytes, name, ext, limits, /*unassociated_alpha=*/true, decoding_bytes);
    if (decoding_bytes) *decoding_bytes += file_bytes.size() + img.rgba.size();
    return img;
}

}  // namespace qs
