#include "render/textures.h"

#include <cstdint>

#include "scenes/texture_files.h"

namespace qs {

glsl::SamplerState sampler_state(const Sampler& s) {
    auto wrap = [](Wrap w) {
        switch (w) {
            case Wrap::Repeat: return glsl::Wrap::Repeat;
            case Wrap::MirroredRepeat: return glsl::Wrap::MirroredRepeat;
            case Wrap::ClampToEdge: break;
        }
        return glsl::Wrap::ClampToEdge;
    };
    auto linear = [](Filter f) {
        return f == Filter::Linear || f == Filter::LinearMipmapNearest || f == Filter::LinearMipmapLinear
                   ? glsl::Filter::Linear
                   : glsl::Filter::Nearest;
    };
    glsl::SamplerState r;
    r.wrap_s = wrap(s.wrap_s), r.wrap_t = wrap(s.wrap_t), r.wrap_r = wrap(s.wrap_r);
    r.mag = linear(s.mag_filter), r.min = linear(s.min_filter);
    r.mip = s.min_filter == Filter::NearestMipmapNearest || s.min_filter == Filter::LinearMipmapNearest ? glsl::MipFilter::Nearest
            : uses_mipmaps(s.min_filter)                                                                  ? glsl::MipFilter::Linear
                                                                                                          : glsl::MipFilter::None;
    return r;
}

std::unique_ptr<glsl::Texture> load_texture(const Scene& scene, const Texture& texture, std::uint64_t* loading_bytes) {
    const std::string where = scene.file.string() + ": " + texture.field + ": ";
    try {
        const Image8 image = read_texture_image(texture.image, loading_bytes);
        if (texture.dims == 2) {
            return std::make_unique<glsl::sampler2D>(image.width, image.height, image.rgba.data(), sampler_state(texture.sampler));
        }
        if (image.height % texture.depth != 0) {
            throw SceneError(where + "a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                             " image does not stack " + std::to_string(texture.depth) + " slices of equal height");
        }
        return std::make_unique<glsl::sampler3D>(image.width, image.height / texture.depth, texture.depth, image.rgba.data(),
                                                 sampler_state(texture.sampler));
    } catch (const ImageError& e) {
        throw SceneError(where + e.what());
    } catch (const std::invalid_argument& e) {
        throw SceneError(where + e.what());
    }
}

const glsl::Texture& white_texture(int dims) {
    static const std::uint8_t white[4] = {255, 255, 255, 255};
    static const glsl::sampler2D flat(1, 1, white, glsl::SamplerState{});
    static const glsl::sampler3D volume(1, 1, 1, white, glsl::SamplerState{});
    if (dims == 3) return volume;
    return flat;
}

}  // namespace qs
