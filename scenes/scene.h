#pragma once
// The scene model: meshes in object space, objects placing them with a shader each, a camera,
// textures (where each image comes from, and how it is sampled), and the frame's settings.
// Loaded from glTF (gltf.h). Pure data: nothing here renders or decodes, and it depends on no
// renderer, so that the OSMesa reference can share it and nothing else.

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "scenes/uniforms.h"

namespace qs {

// Bad input: the message names the file and the field at fault.
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct Vertex {
    glm::vec3 position;  // object space: POSITION, the shaders' gl_Vertex.xyz
    glm::vec2 texcoord;  // TEXCOORD_0, the shaders' gl_MultiTexCoord0.st; (0, 0) is the image's top-left
};

struct Mesh {
    std::string name;
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;  // triangles
    // Whether the file gave texture coordinates (TEXCOORD_0). Without them every vertex's are
    // (0, 0), as GL's gl_MultiTexCoord0 reads without an array bound; an atlas bake refuses the
    // mesh, and quadshade render warns when a shader reads them.
    bool has_texcoords = true;
};

struct Camera {
    enum class Kind { Perspective, Orthographic } kind = Kind::Perspective;
    glm::mat4 view{1.0f};        // view_from_world
    float yfov = 0.0f;           // radians (perspective)
    float xmag = 1.0f, ymag = 1.0f;  // half extents (orthographic)
    float znear = 0.1f, zfar = 100.0f;

    // clip_from_view. The aspect ratio is the render's width / height, as the demo's window set
    // it; a glTF aspectRatio is ignored so that --size never distorts the image.
    glm::mat4 projection(float aspect) const;
};

// A glTF sampler, with glTF's (and GL's) enum values.
enum class Wrap : int { Repeat = 10497, MirroredRepeat = 33648, ClampToEdge = 33071 };
enum class Filter : int {
    Nearest = 9728,
    Linear = 9729,
    NearestMipmapNearest = 9984,  // minification only
    LinearMipmapNearest = 9985,
    NearestMipmapLinear = 9986,
    LinearMipmapLinear = 9987,
};
// Whether a minification filter reads mipmaps.
constexpr bool uses_mipmaps(Filter f) { return int(f) >= int(Filter::NearestMipmapNearest); }

// glTF leaves the filters to the client when a sampler omits them ("auto filtering"); these are
// the usual choice of glTF viewers (trilinear), and the wraps are glTF's defaults. wrap_r, for 3D
// textures, is no glTF field: the material's extras give it (gltf.h), REPEAT like the others.
struct Sampler {
    Filter mag_filter = Filter::Linear;
    Filter min_filter = Filter::LinearMipmapLinear;
    Wrap wrap_s = Wrap::Repeat, wrap_t = Wrap::Repeat, wrap_r = Wrap::Repeat;
    bool operator==(const Sampler&) const = default;
};

// Where a texture's image comes from: a file, or encoded bytes held in the scene (a data: URI,
// or a bufferView of a .glb). Decoding is the renderer's (and the reference's) business.
struct ImageSource {
    std::filesystem::path file;       // an external file; empty when embedded
    std::vector<std::uint8_t> bytes;  // the encoded image (PNG, JPEG, ...) when embedded
    std::string mime_type;            // as the file gives it, possibly empty
    enum class Kind { File, DataUri, BufferView } kind = Kind::File;
    bool operator==(const ImageSource&) const = default;
};

struct Texture {
    ImageSource image;
    Sampler sampler;
    // 2: a sampler2D. 3: a sampler3D of `depth` slices, stacked in the image from top to bottom:
    // slice z (r = (z + 0.5) / depth) is rows [z H, (z + 1) H) of an image of depth * H rows,
    // each slice's first row at t = 0, as a 2D texture's.
    int dims = 2;
    int depth = 1;
    // What names it, for messages: "materials[0].pbrMetallicRoughness.baseColorTexture (images[1])"
    // or "materials[0].extras.teximage".
    std::string field;
    bool operator==(const Texture&) const = default;
};

// A texture bound to a shader's sampler uniform by its GLSL name (the material's extras.textures).
struct SamplerBinding {
    std::string uniform;
    int texture = -1;  // index into Scene::textures
};

struct Object {
    std::string name;
    std::size_t mesh = 0;
    glm::mat4 world_from_object{1.0f};
    std::string shader;   // catalogue name; empty when the file names none
    // The texture bound to the shaders' `teximage`: the material's baseColorTexture, or the file
    // its extras.teximage names. Index into Scene::textures, -1 for none.
    int texture = -1;
    // The other samplers' textures, by uniform name (a name at most once, never "teximage").
    std::vector<SamplerBinding> samplers;
    std::string material; // for messages: which glTF material named the shader
    // Values for the shader's own uniforms: the material's extras.uniforms, by name.
    std::vector<UniformSetting> uniforms;
    // The material's doubleSided. When false (glTF's default, a primitive without a material
    // included) back faces are culled: a front face winds counter-clockwise seen from outside,
    // or clockwise when the node's world transform mirrors (glTF 3.7.4).
    bool double_sided = false;

    // The texture bound to sampler `uniform`, `teximage` included; -1 for none.
    int texture_for(std::string_view uniform) const;
    // Whether world_from_object mirrors (its determinant is negative), turning the front faces.
    bool mirrors() const;
};

struct Scene {
    std::filesystem::path file;
    std::vector<Mesh> meshes;
    std::vector<Object> objects;
    Camera camera;
    glm::vec4 clear_color{0.0f, 0.0f, 0.0f, 0.0f};
    float time = 0.0f;
    int width = 512, height = 512;            // default render size
    std::vector<Texture> textures;
    // Every file the scene was read from or names (itself, buffers, images, textures), resolved:
    // an output must be none of them.
    std::vector<std::filesystem::path> inputs;

    // MVP of an object for a render of the given aspect ratio (one compiled copy, so that the
    // renderer and the reference get the same bits).
    glm::mat4 model_view_projection(const Object& o, float aspect) const;
};

}  // namespace qs
