#include "generators/texture_scenes.h"

#include <cmath>
#include <fstream>
#include <iterator>

#include <glm/gtc/matrix_transform.hpp>

#include "images/image_io.h"
#include "scenes/gltf.h"
#include "scenes/scene.h"

namespace qs {

namespace {

// A w x h test image: every texel differs from its neighbours in every channel (a hashed red, a
// green ramp across, a blue checker of 3-texel cells) so that a wrong texel, weight or level
// shows, and alpha between 0.6 and 1 so that a decoder premultiplying it shows too. Rows are
// distinct, so orientation shows.
Image test_image(int w, int h) {
    Image img{w, h, std::vector<float>(std::size_t(w) * std::size_t(h) * 4)};
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const unsigned hash = (unsigned(x) * 73856093u) ^ (unsigned(y) * 19349663u);
            float* p = &img.rgba[(std::size_t(y) * std::size_t(w) + std::size_t(x)) * 4];
            p[0] = float((hash >> 7) % 256u) / 255.0f;
            p[1] = (float(x) + 0.5f) / float(w) * 0.8f + (float(y) + 0.5f) / float(h) * 0.2f;
            p[2] = ((x / 3 + y / 3) % 2) ? 0.9f : 0.15f;
            p[3] = 0.6f + 0.4f * float((x * 7 + y * 3) % 11) / 10.0f;
        }
    }
    return img;
}

std::vector<std::uint8_t> read_bytes(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

// The Table 1.1 square, (-1, -1, 0)..(1, 1, 0), with st from `lo` (lower left) to `hi`.
Mesh square(glm::vec2 lo, glm::vec2 hi) {
    Mesh m;
    m.name = "square";
    m.vertices = {{{-1, -1, 0}, {lo.x, lo.y}}, {{1, -1, 0}, {hi.x, lo.y}}, {{1, 1, 0}, {hi.x, hi.y}}, {{-1, 1, 0}, {lo.x, hi.y}}};
    m.indices = {0, 1, 2, 0, 2, 3};
    return m;
}

Scene base_scene(int width, int height, Mesh mesh, const Texture& texture) {
    Scene s;
    s.meshes = {std::move(mesh)};
    s.width = width, s.height = height;
    s.clear_color = {0.0f, 0.0f, 0.0f, 0.0f};  // alpha 0 where nothing is drawn: alpha is coverage
    s.textures = {texture};
    Object o;
    o.name = "plane", o.shader = "single_texture", o.texture = 0;
    s.objects = {o};
    return s;
}

// The square filling the window, orthographic: texels magnified or minified by st's range alone.
Scene flat_scene(int width, int height, glm::vec2 lo, glm::vec2 hi, const Texture& texture) {
    Scene s = base_scene(width, height, square(lo, hi), texture);
    s.camera.kind = Camera::Kind::Orthographic;
    s.camera.xmag = s.camera.ymag = 1.0f;
    s.camera.stretch = true;
    s.camera.znear = 0.5f, s.camera.zfar = 1.5f;
    s.camera.view = glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, -1.0f});
    return s;
}

// The square stretched into a 2 x 40 ground plane receding to the horizon, seen from 0.5 above
// its near edge: texels magnified at the bottom of the image, minified by hundreds at the top,
// and every level of detail between.
Scene receding_scene(int width, int height, const Texture& texture) {
    Scene s = base_scene(width, height, square({0.0f, 0.0f}, {2.0f, 20.0f}), texture);
    s.objects[0].world_from_object = glm::scale(glm::translate(glm::mat4(1.0f), {0.0f, 19.0f, 0.0f}), {1.0f, 20.0f, 1.0f});
    s.camera.yfov = glm::radians(50.0f);
    s.camera.znear = 0.1f, s.camera.zfar = 100.0f;
    s.camera.view = glm::lookAt(glm::vec3(0.0f, -1.5f, 0.5f), glm::vec3(0.0f, 6.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f));
    return s;
}

Texture file_texture(const std::filesystem::path& dir, int w, int h, Sampler sampler) {
    const std::string name = "texture-" + std::to_string(w) + "x" + std::to_string(h) + ".png";  // in images/
    const std::filesystem::path file = dir / "images" / name;
    if (!std::filesystem::exists(file)) write_image(file, test_image(w, h), {}, true);
    Texture t;
    t.image.file = file;
    t.sampler = sampler;
    return t;
}

Sampler sampler(Filter mag, Filter min, Wrap s, Wrap t) { return {mag, min, s, t}; }

const char* filter_name(Filter f) {
    switch (f) {
        case Filter::Nearest: return "nearest";
        case Filter::Linear: return "linear";
        case Filter::NearestMipmapNearest: return "nearest-mipmap-nearest";
        case Filter::LinearMipmapNearest: return "linear-mipmap-nearest";
        case Filter::NearestMipmapLinear: return "nearest-mipmap-linear";
        case Filter::LinearMipmapLinear: return "linear-mipmap-linear";
    }
    return "?";
}

}  // namespace

void write_texture_scenes(const std::filesystem::path& root) {
    const std::filesystem::path dir = root / "conformance";
    std::filesystem::create_directories(dir / "images");
    auto save = [&](const Scene& s, const std::string& name) { save_scene(s, dir / ("texture-" + name)); };
    constexpr Wrap kRepeat = Wrap::Repeat, kMirror = Wrap::MirroredRepeat, kClamp = Wrap::ClampToEdge;
    constexpr Filter kLinear = Filter::Linear, kNearest = Filter::Nearest;
    const Sampler bilinear_repeat = sampler(kLinear, kLinear, kRepeat, kRepeat);

    // Wraps, st far outside [0, 1], on odd (non-power-of-two) and power-of-two images, odd and
    // even image sizes, orthographic:
    // REPEAT on a 13x7 image, st in [-2.6, 3.4] x [-1.7, 2.3], bilinear, 61x45;
    save(flat_scene(61, 45, {-2.6f, -1.7f}, {3.4f, 2.3f}, file_texture(dir, 13, 7, bilinear_repeat)), "wrap-repeat-npot.gltf");
    // REPEAT on a 16x8 image over 80 periods (minified, no mipmaps), 64x48;
    save(flat_scene(64, 48, {-37.3f, -21.9f}, {45.1f, 30.3f}, file_texture(dir, 16, 8, bilinear_repeat)),
         "wrap-repeat-pot.gltf");
    // MIRRORED_REPEAT (llvmpipe's float path), bilinear, 61x45;
    save(flat_scene(61, 45, {-2.6f, -1.7f}, {3.4f, 2.3f}, file_texture(dir, 13, 7, sampler(kLinear, kLinear, kMirror, kMirror))),
         "wrap-mirrored.gltf");
    // CLAMP_TO_EDGE, nearest, st in [-0.6, 1.7] x [-0.45, 1.35], 64x48;
    save(flat_scene(64, 48, {-0.6f, -0.45f}, {1.7f, 1.35f}, file_texture(dir, 13, 7, sampler(kNearest, kNearest, kClamp, kClamp))),
         "wrap-clamp.gltf");
    // MIRRORED_REPEAT along s, REPEAT along t, 61x45.
    save(flat_scene(61, 45, {-2.6f, -1.7f}, {3.4f, 2.3f}, file_texture(dir, 16, 8, sampler(kLinear, kLinear, kMirror, kRepeat))),
         "wrap-mixed.gltf");

    // Every filter under magnification and minification on the receding plane (64x32 image, 64x48):
    // each minification filter with LINEAR magnification;
    for (Filter min : {Filter::Nearest, Filter::Linear, Filter::NearestMipmapNearest, Filter::LinearMipmapNearest,
                       Filter::NearestMipmapLinear, Filter::LinearMipmapLinear}) {
        save(receding_scene(64, 48, file_texture(dir, 64, 32, sampler(kLinear, min, kRepeat, kRepeat))),
             std::string("min-") + filter_name(min) + ".gltf");
    }
    // NEAREST magnification under trilinear minification, 61x45;
    save(receding_scene(61, 45, file_texture(dir, 64, 32, sampler(kNearest, Filter::LinearMipmapLinear, kRepeat, kRepeat))),
         "mag-nearest.gltf");
    // mipmaps of a 37x19 image (levels 18x9, 9x4, ...: odd sizes), CLAMP_TO_EDGE along s, 61x45;
    save(receding_scene(61, 45, file_texture(dir, 37, 19, sampler(kLinear, Filter::LinearMipmapLinear, kClamp, kRepeat))),
         "npot-mipmaps.gltf");
    // MIRRORED_REPEAT with mipmaps and different min and mag filters (llvmpipe's float path,
    // which decides per two quads whether to filter linearly).
    save(receding_scene(64, 48, file_texture(dir, 64, 32, sampler(kLinear, Filter::NearestMipmapLinear, kMirror, kMirror))),
         "mirrored-mipmaps.gltf");

    // Where the image comes from: a PNG file, the same bytes as a data: URI and in a .glb's
    // bufferView (16x16, trilinear, REPEAT).
    const Texture from_file = file_texture(dir, 16, 16, sampler(kLinear, Filter::LinearMipmapLinear, kRepeat, kRepeat));
    Texture embedded = from_file;
    embedded.image.bytes = read_bytes(from_file.image.file);
    embedded.image.file.clear();
    embedded.image.mime_type = "image/png";
    save(receding_scene(64, 48, from_file), "source-file.gltf");
    embedded.image.kind = ImageSource::Kind::DataUri;
    save(receding_scene(64, 48, embedded), "source-data-uri.gltf");
    embedded.image.kind = ImageSource::Kind::BufferView;
    save(receding_scene(64, 48, embedded), "source-buffer-view.glb");
}

}  // namespace qs
