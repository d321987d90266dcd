// What glTF materials bind beside the scene's shaders: the textures (baseColorTexture,
// extras.teximage and extras.textures: 2D, 3D, cube maps and depth comparison textures, each
// made once), KHR_texture_transform, and extras.uniforms.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <set>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

#include "scenes/gltf_checks.h"
#include "scenes/gltf_read.h"
#include "scenes/limits.h"
#include "scenes/scene_files.h"

namespace qs::gltf_read {

namespace checks = gltf_checks;

namespace {

// The file an image URI names: percent-decoded (RFC 3986, as glTF requires) and resolved by
// resolve_scene_uri (check_uris has already refused what it refuses, naming the field).
std::filesystem::path resolve_image_uri(const std::filesystem::path& scene_file, const std::string& uri,
                                        const ScenePathPolicy& policy, const std::string& field) {
    try {
        return resolve_scene_uri(scene_file, checks::percent_decoded(uri), policy);
    } catch (const SceneError& e) {
        fail(scene_file, field, e.what());
    }
}

double number_in(const tinygltf::Value& v, const std::filesystem::path& file, const std::string& field) {
    if (!v.IsNumber()) fail(file, field, "expected a number");
    const double d = v.GetNumberAsDouble();
    if (!std::isfinite(float(d))) fail(file, field, "not a finite float");
    return d;
}

}  // namespace

// A material's extras.uniforms: {"uScale": 4.0, "uTint": [1, 0.5, 0.2], ...}, each a number or
// an array of 2 to 16 numbers (matrices column by column).
std::vector<UniformSetting> read_uniforms(const tinygltf::Value& v, const std::filesystem::path& file, const std::string& field) {
    if (!v.IsObject()) fail(file, field, "expected an object of uniform names and values");
    std::vector<UniformSetting> out;
    for (const std::string& name : v.Keys()) {
        const std::string f = field + "." + name;
        if (!is_uniform_name(name)) fail(file, f, "'" + name + "' is not a GLSL uniform name");
        if (name == kResolutionUniform) fail(file, f, "uResolution is the frame's size, set by the renderer (scenes[].extras.size, --size)");
        UniformSetting s{name, {}, file.string() + ": " + f};
        const tinygltf::Value& x = v.Get(name);
        auto number = [&](const tinygltf::Value& n, const std::string& where) {
            if (!n.IsNumber()) fail(file, where, "expected a number");
            const double d = n.GetNumberAsDouble();
            if (!std::isfinite(d)) fail(file, where, "not a finite number");
            s.values.push_back(d);
        };
        if (x.IsArray()) {
            if (x.ArrayLen() < 1 || x.ArrayLen() > 16) fail(file, f, "expected 1 to 16 numbers");
            for (std::size_t i = 0; i < x.ArrayLen(); ++i) number(x.Get(int(i)), f + "[" + std::to_string(i) + "]");
        } else {
            number(x, f);
        }
        out.push_back(std::move(s));
    }
    return out;
}

// Material `mi`'s texture: extras.teximage if it names a file (with the baseColorTexture's
// sampler, if any), else pbrMetallicRoughness.baseColorTexture; -1 for neither.
int TextureReader::of_material(int mi) {
    const tinygltf::Material& mat = m_.materials[std::size_t(mi)];
    const std::string mf = "materials[" + std::to_string(mi) + "]";
    const tinygltf::TextureInfo& base = mat.pbrMetallicRoughness.baseColorTexture;
    const std::string base_field = mf + ".pbrMetallicRoughness.baseColorTexture";
    if (mat.extras.IsObject() && mat.extras.Has("teximage")) {
        const tinygltf::Value& v = mat.extras.Get("teximage");
        if (!v.IsString()) fail(file_, mf + ".extras.teximage", "expected a file name");
        Texture t;
        t.field = mf + ".extras.teximage";
        t.image = named_file(v.Get<std::string>(), t.field);
        if (base.index >= 0) t.sampler = sampler_of(texture_at(base.index, base_field), base_field);
        for (std::size_t i = 0; i < scene_.textures.size(); ++i) {  // the same file and sampler: one texture
            const Texture& o = scene_.textures[i];
            if (o.image.kind == ImageSource::Kind::File && o.image.file == t.image.file && o.sampler == t.sampler) return int(i);
        }
        return add(std::move(t));
    }
    if (base.index < 0) return -1;
    const auto [it, fresh] = gltf_textures_.try_emplace(base.index, -1);
    if (fresh) it->second = add(read_texture(base.index, base_field));
    return it->second;
}

// Material `mi`'s extras.textures (gltf.h): each uniform's texture. One named `teximage`
// replaces `teximage` (the material's baseColorTexture) as extras.teximage does, which it
// may not accompany.
void TextureReader::named_of_material(int mi, Object& o) {
    const tinygltf::Material& mat = m_.materials[std::size_t(mi)];
    if (!mat.extras.IsObject() || !mat.extras.Has("textures")) return;
    const std::string mf = "materials[" + std::to_string(mi) + "].extras";
    const tinygltf::Value& all = mat.extras.Get("textures");
    if (!all.IsObject()) fail(file_, mf + ".textures", "expected an object of sampler names");
    for (const std::string& name : all.Keys()) {
        const std::string field = mf + ".textures." + name;
        if (name.empty() || name.rfind("gl_", 0) == 0 ||
            !std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }) ||
            std::isdigit(static_cast<unsigned char>(name[0]))) {
            fail(file_, mf + ".textures", "'" + name + "' is not a GLSL identifier");
        }
        const int t = binding(all.Get(name), field);
        if (name == "teximage") {
            if (mat.extras.Has("teximage")) fail(file_, field, "teximage is bound twice (extras.teximage too)");
            if (scene_.textures[std::size_t(t)].dims != 2) fail(file_, field, "teximage is a sampler2D: no depth, no faces");
            o.texture = t;
        } else {
            o.samplers.push_back({name, t});
        }
    }
}

// An image file a material names (extras.teximage, extras.textures): a file name, not a URI,
// so not percent-decoded; resolved as every file a scene names (the file need not exist: a
// texture is read only when a shader samples it).
ImageSource TextureReader::named_file(const std::string& name, const std::string& field) {
    ImageSource image;
    try {
        image.file = resolve_scene_uri(file_, name, policy_);
    } catch (const SceneError& e) {
        fail(file_, field, e.what());
    }
    scene_.inputs.push_back(image.file);
    return image;
}

// One binding of extras.textures: a glTF texture index, an image file, or an object of them
// with a sampler, a depth and wrapR.
int TextureReader::binding(const tinygltf::Value& v, const std::string& field) {
    if (v.IsInt() || v.IsNumber()) return texture_index(v, field, Sampler{}, false, 2, 1);
    if (v.IsString()) return file_texture(v.Get<std::string>(), field, Sampler{}, 2, 1);
    if (!v.IsObject()) fail(file_, field, "expected a textures[] index, an image file name or an object");
    for (const std::string& key : v.Keys()) {
        if (key != "texture" && key != "image" && key != "faces" && key != "sampler" && key != "depth" &&
            key != "wrapR" && key != "compare") {
            fail(file_, field + "." + key, "unknown key (texture, image, faces, sampler, depth, wrapR, compare)");
        }
    }
    if (int(v.Has("texture")) + int(v.Has("image")) + int(v.Has("faces")) != 1) {
        fail(file_, field, "needs exactly one of texture (an index), image (a file) and faces (a cube map's six files)");
    }
    if (v.Has("faces") && v.Has("depth")) fail(file_, field + ".depth", "a cube map (faces) has no depth");
    int dims = v.Has("faces") ? kCubeMap : 2, depth = 1;
    if (v.Has("depth")) {
        const tinygltf::Value& d = v.Get("depth");
        if (!d.IsInt() || d.Get<int>() < 1 || d.Get<int>() > 2048) fail(file_, field + ".depth", "expected a slice count in 1..2048");
        dims = 3, depth = d.Get<int>();
    }
    Sampler sampler;
    const bool own_sampler = v.Has("sampler");
    if (own_sampler) {
        const tinygltf::Value& si = v.Get("sampler");
        if (!si.IsInt()) fail(file_, field + ".sampler", "expected a samplers[] index");
        sampler = sampler_at(si.Get<int>(), field + ".sampler");
    }
    if (v.Has("wrapR")) {
        if (dims != 3) fail(file_, field + ".wrapR", "only a 3D texture (with a depth) has an r axis");
        const tinygltf::Value& w = v.Get("wrapR");
        sampler.wrap_r = wrap_of(w.IsInt() ? w.Get<int>() : -1, field + ".wrapR");
    }
    std::optional<CompareFunc> compare;
    if (v.Has("compare")) {
        const tinygltf::Value& c = v.Get("compare");
        if (c.IsString()) compare = compare_func_named(c.Get<std::string>());
        if (!compare) {
            fail(file_, field + ".compare",
                 "expected a compare function: NEVER, LESS, EQUAL, LEQUAL, GREATER, NOTEQUAL, GEQUAL or ALWAYS");
        }
        if (dims == 3) fail(file_, field + ".compare", "a depth comparison texture is 2D or a cube map (no depth)");
    }
    if (v.Has("image") && !v.Get("image").IsString()) fail(file_, field + ".image", "expected a file name");
    return v.Has("faces")   ? cube_texture(v.Get("faces"), field + ".faces", sampler, compare)
           : v.Has("image") ? file_texture(v.Get("image").Get<std::string>(), field + ".image", sampler, dims, depth,
                                           compare)
                            : texture_index(v.Get("texture"), field + ".texture", sampler, own_sampler, dims, depth,
                                            compare);
}

int TextureReader::texture_index(const tinygltf::Value& v, const std::string& field, const Sampler& sampler,
                                 bool own_sampler, int dims, int depth, std::optional<CompareFunc> compare) {
    if (!v.IsInt()) fail(file_, field, "expected a textures[] index");
    Texture t = read_texture(v.Get<int>(), field);
    const Wrap wrap_r = sampler.wrap_r;
    if (own_sampler) t.sampler = sampler;
    t.sampler.wrap_r = wrap_r;
    t.dims = dims, t.depth = depth, t.compare = compare;
    return add_once(std::move(t));
}

int TextureReader::file_texture(const std::string& uri, const std::string& field, const Sampler& sampler, int dims,
                                int depth, std::optional<CompareFunc> compare) {
    Texture t;
    t.field = field;
    t.image = named_file(uri, field);
    t.sampler = sampler;
    t.dims = dims, t.depth = depth, t.compare = compare;
    return add_once(std::move(t));
}

// A cube map from six image files in GL's face order (+X, -X, +Y, -Y, +Z, -Z); their sizes
// are checked when the images are read.
int TextureReader::cube_texture(const tinygltf::Value& v, const std::string& field, const Sampler& sampler,
                                std::optional<CompareFunc> compare) {
    if (!v.IsArray() || v.ArrayLen() != 6) {
        fail(file_, field, "expected an array of six image files, the faces +X, -X, +Y, -Y, +Z, -Z");
    }
    Texture t;
    t.field = field;
    for (int i = 0; i < 6; ++i) {
        const std::string face_field = field + "[" + std::to_string(i) + "]";
        if (!v.Get(i).IsString()) fail(file_, face_field, "expected an image file name");
        t.faces.push_back(named_file(v.Get(i).Get<std::string>(), face_field));
    }
    t.sampler = sampler;
    t.dims = kCubeMap, t.compare = compare;
    return add_once(std::move(t));
}

// The same image, sampler and shape: one texture (its first field names it).
int TextureReader::add_once(Texture t) {
    for (std::size_t i = 0; i < scene_.textures.size(); ++i) {
        Texture o = scene_.textures[i];
        o.field = t.field;
        if (o == t) return int(i);
    }
    return add(std::move(t));
}

const tinygltf::Texture& TextureReader::texture_at(int index, const std::string& field) const {
    if (std::size_t(index) >= m_.textures.size()) fail(file_, field + ".index", "texture index out of range");
    return m_.textures[std::size_t(index)];
}

Texture TextureReader::read_texture(int index, const std::string& field) const {
    const tinygltf::Texture& gt = texture_at(index, field);
    const std::string tf = "textures[" + std::to_string(index) + "]";
    if (gt.source < 0 || std::size_t(gt.source) >= m_.images.size()) {
        fail(file_, tf + ".source", gt.source < 0 ? "no image (only PNG/JPEG sources are supported)" : "image index out of range");
    }
    const tinygltf::Image& image = m_.images[std::size_t(gt.source)];
    Texture t;
    t.field = field + " (" + tf + ", images[" + std::to_string(gt.source) + "])";
    t.sampler = sampler_of(gt, field);
    t.image.mime_type = image.mimeType;
    if (image.bufferView >= 0) {
        t.image.kind = ImageSource::Kind::BufferView;
        const std::string vf = "images[" + std::to_string(gt.source) + "].bufferView";
        if (std::size_t(image.bufferView) >= m_.bufferViews.size()) fail(file_, vf, "index out of range");
        const tinygltf::BufferView& v = m_.bufferViews[std::size_t(image.bufferView)];
        if (v.buffer < 0 || std::size_t(v.buffer) >= m_.buffers.size()) fail(file_, vf, "buffer view has no buffer");
        const std::vector<unsigned char>& b = m_.buffers[std::size_t(v.buffer)].data;
        if (v.byteOffset > b.size() || v.byteLength > b.size() - v.byteOffset) {
            fail(file_, vf, "reaches past the end of its buffer");
        }
        t.image.bytes.assign(b.begin() + std::ptrdiff_t(v.byteOffset), b.begin() + std::ptrdiff_t(v.byteOffset + v.byteLength));
    } else if (image.uri.empty()) {
        t.image.kind = ImageSource::Kind::DataUri;
        t.image.bytes.assign(image.image.begin(), image.image.end());
        if (t.image.bytes.empty()) fail(file_, "images[" + std::to_string(gt.source) + "].uri", "empty data: URI");
    } else {
        t.image.file = resolve_image_uri(file_, image.uri, policy_, "images[" + std::to_string(gt.source) + "].uri");
    }
    return t;
}

// The texture's sampler, glTF's defaults where it gives none, its values checked.
Sampler TextureReader::sampler_of(const tinygltf::Texture& gt, const std::string& field) const {
    if (gt.sampler < 0) return Sampler{};
    return sampler_at(gt.sampler, field + " sampler");
}

Wrap TextureReader::wrap_of(int v, const std::string& field) const {
    if (v != int(Wrap::Repeat) && v != int(Wrap::MirroredRepeat) && v != int(Wrap::ClampToEdge)) {
        fail(file_, field, "unknown wrap mode " + std::to_string(v) + " (10497, 33648 or 33071)");
    }
    return Wrap(v);
}

// samplers[index], `field` naming where the index came from.
Sampler TextureReader::sampler_at(int index, const std::string& field) const {
    Sampler s;
    const std::string sf = "samplers[" + std::to_string(index) + "]";
    if (index < 0 || std::size_t(index) >= m_.samplers.size()) fail(file_, field, sf + " is out of range");
    const tinygltf::Sampler& g = m_.samplers[std::size_t(index)];
    s.wrap_s = wrap_of(g.wrapS, sf + ".wrapS");
    s.wrap_t = wrap_of(g.wrapT, sf + ".wrapT");
    if (g.magFilter != -1) {
        if (g.magFilter != int(Filter::Nearest) && g.magFilter != int(Filter::Linear)) {
            fail(file_, sf + ".magFilter", "unknown filter " + std::to_string(g.magFilter) + " (9728 or 9729)");
        }
        s.mag_filter = Filter(g.magFilter);
    }
    if (g.minFilter != -1) {
        if (g.minFilter != int(Filter::Nearest) && g.minFilter != int(Filter::Linear) &&
            (g.minFilter < int(Filter::NearestMipmapNearest) || g.minFilter > int(Filter::LinearMipmapLinear))) {
            fail(file_, sf + ".minFilter", "unknown filter " + std::to_string(g.minFilter) + " (9728, 9729 or 9984-9987)");
        }
        s.min_filter = Filter(g.minFilter);
    }
    return s;
}

int TextureReader::add(Texture t) {
    scene_.textures.push_back(std::move(t));
    return int(scene_.textures.size() - 1);
}

// KHR_texture_transform on a textureInfo: glTF's translation * rotation * scale, and the texCoord
// it may override.
void read_texture_transform(const tinygltf::Value& t, const std::filesystem::path& file, const std::string& field,
                            Material& look) {
    if (!t.IsObject()) fail(file, field, "expected an object");
    glm::dvec2 offset(0.0), scale(1.0);
    double rotation = 0.0;
    auto pair = [&](const char* key, glm::dvec2& out) {
        if (!t.Has(key)) return;
        const tinygltf::Value& a = t.Get(key);
        if (!a.IsArray() || a.ArrayLen() != 2) fail(file, field + "." + key, "expected 2 numbers");
        for (int i = 0; i < 2; ++i) out[i] = number_in(a.Get(i), file, field + "." + key);
    };
    pair("offset", offset);
    pair("scale", scale);
    if (t.Has("rotation")) rotation = number_in(t.Get("rotation"), file, field + ".rotation");
    if (t.Has("texCoord")) {
        const tinygltf::Value& c = t.Get("texCoord");
        if (!c.IsInt() || c.Get<int>() < 0) fail(file, field + ".texCoord", "expected a TEXCOORD_n set, n >= 0");
        look.texcoord = c.Get<int>();
    }
    // Column by column. The rotation turns the image clockwise as the extension describes it
    // (u' = c u + s v, v' = -s u + c v), as viewers and Khronos's TextureTransformTest take it: the
    // GLSL listing in the extension's text writes its transpose.
    const glm::dmat3 translation(1.0, 0.0, 0.0, 0.0, 1.0, 0.0, offset.x, offset.y, 1.0);
    const double c = std::cos(rotation), s = std::sin(rotation);
    const glm::dmat3 rotate(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0);
    const glm::dmat3 scaling(scale.x, 0.0, 0.0, 0.0, scale.y, 0.0, 0.0, 0.0, 1.0);
    look.texture_transform = translation * rotate * scaling;
}

}  // namespace qs::gltf_read
