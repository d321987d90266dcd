#include "render/textures.h"

#include "scenes/image_io.h"

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
    r.wrap_s = wrap(s.wrap_s), r.wrap_t = wrap(s.wrap_t);
    r.mag = linear(s.mag_filter), r.min = linear(s.min_filter);
    r.mip = s.min_filter == Filter::NearestMipmapNearest || s.min_filter == Filter::LinearMipmapNearest ? glsl::MipFilter::Nearest
            : uses_mipmaps(s.min_filter)                                                                  ? glsl::MipFilter::Linear
                                                                                                          : glsl::MipFilter::None;
    return r;
}

glsl::sampler2D load_texture(const Scene& scene, const Texture& texture) {
    try {
        const Image8 image = read_texture_image(texture.image);
        return glsl::sampler2D(image.width, image.height, image.rgba.data(), sampler_state(texture.sampler));
    } catch (const ImageError& e) {
        throw SceneError(scene.file.string() + ": " + texture.field + ": " + e.what());
    }
}

}  // namespace qs
