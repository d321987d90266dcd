#include "render/textures.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>

#include "scenes/texture_files.h"
#include "shading/glsl/texture_cube.h"

namespace qs {

glsl::SamplerState sampler_state(const Texture& texture) {
    const Sampler& s = texture.sampler;
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
    if (texture.compare) {
        // scenes' CompareFunc holds GL's values, NEVER to ALWAYS in glsl::CompareFunc's order
        static_assert(int(CompareFunc::Always) - int(CompareFunc::Never) == int(glsl::CompareFunc::Always) &&
                      int(CompareFunc::LessEqual) - int(CompareFunc::Never) == int(glsl::CompareFunc::LessEqual));
        r.compare = glsl::CompareFunc(int(*texture.compare) - int(CompareFunc::Never));
    }
    return r;
}

namespace {

// A depth comparison texture's texels are float depths (its image's red channel).
glsl::TexelFormat texel_format(const Texture& texture) {
    return texture.compare ? glsl::TexelFormat::Depth32F : glsl::TexelFormat::Rgba8;
}

// A cube map's six faces, each read and checked against the first: square, of one size.
std::unique_ptr<glsl::Texture> load_cube(const Scene& scene, const Texture& texture, std::uint64_t* loading_bytes) {
    static const char* const kFaces[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
    std::array<Image8, 6> faces;
    std::uint64_t held = 0;  // the faces read so far, all kept until the cube map is made
    for (std::size_t f = 0; f < 6; ++f) {
        const std::string where = scene.file.string() + ": " + texture.field + "[" + std::to_string(f) + "] (face " + kFaces[f] + "): ";
        std::uint64_t loading = 0;
        try {
            faces[f] = read_texture_image(texture.faces.at(f), &loading);
        } catch (const ImageError& e) {
            throw SceneError(where + e.what());
        }
        if (loading_bytes) *loading_bytes = std::max(*loading_bytes, held + loading);
        held += faces[f].rgba.size();
        const Image8& image = faces[f];
        if (image.width != image.height) {
            throw SceneError(where + "a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                             " image: a cube map's faces are square");
        }
        if (image.width != faces[0].width) {
            throw SceneError(where + "a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                             " image where face +X is " + std::to_string(faces[0].width) + "x" +
                             std::to_string(faces[0].height) + ": a cube map's faces are of one size");
        }
    }
    std::array<const std::uint8_t*, 6> rgba;
    for (std::size_t f = 0; f < 6; ++f) rgba[f] = faces[f].rgba.data();
    try {
        return std::make_unique<glsl::samplerCube>(faces[0].width, rgba, sampler_state(texture), texel_format(texture));
    } catch (const std::invalid_argument& e) {
        throw SceneError(scene.file.string() + ": " + texture.field + ": " + e.what());
    }
}

}  // namespace

std::unique_ptr<glsl::Texture> load_texture(const Scene& scene, const Texture& texture, std::uint64_t* loading_bytes) {
    if (texture.dims == kCubeMap) return load_cube(scene, texture, loading_bytes);
    const std::string where = scene.file.string() + ": " + texture.field + ": ";
    try {
        const Image8 image = read_texture_image(texture.image, loading_bytes);
        if (texture.dims == 2) {
            return std::make_unique<glsl::sampler2D>(image.width, image.height, image.rgba.data(),
                                                     sampler_state(texture), texel_format(texture));
        }
        if (image.height % texture.depth != 0) {
            throw SceneError(where + "a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                             " image does not stack " + std::to_string(texture.depth) + " slices of equal height");
        }
        return std::make_unique<glsl::sampler3D>(image.width, image.height / texture.depth, texture.depth, image.rgba.data(),
                                                 sampler_state(texture));
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
    static const glsl::samplerCube cube(1, {white, white, white, white, white, white}, glsl::SamplerState{});
    if (dims == 3) return volume;
    if (dims == glsl::kCubeDims) return cube;
    return flat;
}

}  // namespace qs
