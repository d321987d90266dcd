#pragma once
// The scene model: meshes in object space, objects placing them with a shader each, a camera,
// textures (where each image comes from, and how it is sampled), and the frame's settings.
// Loaded from glTF (gltf.h). Pure data: nothing here renders or decodes, and it depends on no
// renderer, so that the OSMesa reference can share it and nothing else.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "scenes/uniforms.h"

namespace qs {

// The catalogue shader that draws a material naming no shader of its own (and a primitive without
// a material): glTF's base colour, lit (shading/shaders/gltf_material.h).
inline constexpr std::string_view kDefaultMaterialShader = "gltf_material";

// Bad input: the message names the file and the field at fault.
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct Vertex {
    glm::vec3 position;  // object space: POSITION, the shaders' gl_Vertex.xyz
    glm::vec2 texcoord;  // TEXCOORD_0, the shaders' gl_MultiTexCoord0.st; (0, 0) is the image's top-left
    glm::vec3 normal{0.0f};  // NORMAL, gl_Normal; (0, 0, 0) where the mesh has none
    glm::vec4 color{1.0f};   // COLOR_0, gl_Color; (1, 1, 1, 1) where none, alpha 1 for a vec3 colour
    // gl_MultiTexCoord1.st: TEXCOORD_1, or TEXCOORD_n (n >= 2) where the primitive's material reads
    // its base colour texture from set n (Material::texcoord); (0, 0) where the mesh has none.
    glm::vec2 texcoord1{0.0f};
};

struct Mesh {
    std::string name;
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;  // triangles (strips and fans are unrolled into them)
    // Whether the file gave texture coordinates (TEXCOORD_0). Without them every vertex's are
    // (0, 0), as GL's gl_MultiTexCoord0 reads without an array bound; an atlas bake refuses the
    // mesh, and quadshade render warns when a shader reads them.
    bool has_texcoords = true;
    bool has_normals = false;    // NORMAL
    bool has_texcoord1 = false;  // the set Vertex::texcoord1 holds
    // The glTF primitive it was read from, for messages: "meshes[3].primitives[1]" (empty for a
    // mesh made in code).
    std::string source{};
    // Its bounds in object space (positions), for ordering blended objects back to front.
    glm::vec3 lower{0.0f}, upper{0.0f};
};

struct Camera {
    enum class Kind { Perspective, Orthographic } kind = Kind::Perspective;
    glm::dmat4 view{1.0};           // view_from_world
    double yfov = 0.0;              // radians (perspective)
    double xmag = 1.0, ymag = 1.0;  // half extents (orthographic)
    double znear = 0.1, zfar = 100.0;
    // The width / height of the camera's view (glTF's perspective aspectRatio; xmag / ymag for an
    // orthographic camera); 0 where the file gives none.
    double aspect_ratio = 0.0;
    std::string name{};  // for messages and --camera: the camera node's name, else "cameras[i]"
    // An orthographic camera whose view box is stretched to the image whatever its aspect (the
    // scene's extras.stretch): a full-window plane's, as the chapter's demo draws its plane.
    bool stretch = false;

    // clip_from_view for a render of the given width / height. The camera's view always shows
    // whole, undistorted: a perspective camera keeps yfov and an orthographic one ymag, and where
    // the camera gives its own aspect ratio and the image is narrower than it, the height grows
    // instead so that the camera's width still shows (the view is widened along one axis, never
    // stretched). A perspective camera without aspectRatio follows the image's width. Only a
    // `stretch` orthographic camera maps xmag and ymag to the image's edges.
    glm::dmat4 projection(double aspect) const;
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

// A depth comparison texture's function (GL_TEXTURE_COMPARE_FUNC, with GL's enum values): a
// lookup passes where `reference FUNC depth` holds.
enum class CompareFunc : int {
    Never = 0x0200,
    Less = 0x0201,
    Equal = 0x0202,
    LessEqual = 0x0203,
    Greater = 0x0204,
    NotEqual = 0x0205,
    GreaterEqual = 0x0206,
    Always = 0x0207,
};
// The name a scene file gives it, GL's without the GL_ prefix ("LEQUAL"); the function of a name,
// or none.
std::string_view compare_func_name(CompareFunc f);
std::optional<CompareFunc> compare_func_named(std::string_view name);

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

// Texture::dims of a cube map.
inline constexpr int kCubeMap = 6;

struct Texture {
    ImageSource image;
    Sampler sampler;
    // 2: a sampler2D. 3: a sampler3D of `depth` slices, stacked in the image from top to bottom:
    // slice z (r = (z + 0.5) / depth) is rows [z H, (z + 1) H) of an image of depth * H rows,
    // each slice's first row at t = 0, as a 2D texture's. 6 (kCubeMap): a samplerCube of the six
    // images `faces` (`image` unused), in GL's order +X, -X, +Y, -Y, +Z, -Z, square and of one
    // size, each face's first row at t = 0.
    int dims = 2;
    int depth = 1;
    std::vector<ImageSource> faces;
    // Set for a depth comparison texture, read by a sampler2DShadow (or a samplerCubeShadow, of a
    // cube map): the image's red channel is the depth (red / 255), compared with this function;
    // its mipmaps, where its sampler reads them, are float depths (GL_DEPTH_COMPONENT32F's).
    std::optional<CompareFunc> compare;
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

// How glTF's alphaMode composes a material's colour: OPAQUE ignores alpha, MASK discards
// fragments whose alpha is below alphaCutoff, BLEND blends over what is drawn before it (GL's
// SRC_ALPHA, ONE_MINUS_SRC_ALPHA, without depth writes), after every other object.
enum class AlphaMode { Opaque, Mask, Blend };

// The parts of a glTF metallic-roughness material the default material draws.
struct Material {
    glm::dvec4 base_color_factor{1.0};  // pbrMetallicRoughness.baseColorFactor
    // The TEXCOORD_n set the base colour texture reads (its texCoord, or KHR_texture_transform's):
    // 0 is gl_MultiTexCoord0, any other gl_MultiTexCoord1 (Vertex::texcoord1).
    int texcoord = 0;
    // KHR_texture_transform of the base colour texture: uv' = (M (u, v, 1)).xy, glTF's
    // translation * rotation * scale.
    glm::dmat3 texture_transform{1.0};
    AlphaMode alpha_mode = AlphaMode::Opaque;
    double alpha_cutoff = 0.5;
    bool unlit = false;  // KHR_materials_unlit
};

struct Object {
    std::string name;
    std::size_t mesh = 0;
    // Where the loaded scene has it (its nodes' own transforms, no animation applied): Scene::pose
    // gives it at a time. Composed in double.
    glm::dmat4 world_from_object{1.0};
    std::string shader;  // catalogue name; empty when the file names none (the default material)
    // A user's GLSL that draws it instead (the material's extras.glsl), files the scene names,
    // resolved as its textures are; empty for none. The vertex shader may be left out.
    std::filesystem::path glsl_fragment, glsl_vertex;
    // The texture bound to the shaders' `teximage`: the material's baseColorTexture, or the file
    // its extras.teximage names. Index into Scene::textures, -1 for none.
    int texture = -1;
    // The other samplers' textures, by uniform name (a name at most once, never "teximage").
    std::vector<SamplerBinding> samplers;
    // For messages: the glTF material that draws it ("'Red' (materials[2])"), or for a primitive
    // without one "no material (meshes[3].primitives[1])".
    std::string material;
    Material look{};  // glTF's base colour, alpha mode and unlit flag, for the default material
    // Values for the shader's own uniforms: the material's extras.uniforms, by name.
    std::vector<UniformSetting> uniforms;
    // The material's doubleSided. When false (glTF's default, a primitive without a material
    // included) back faces are culled: a front face winds counter-clockwise seen from outside,
    // or clockwise when the node's world transform mirrors (glTF 3.7.4).
    bool double_sided = false;
    // The glTF node that places it (-1 for an object made in code) and, for an instance of
    // EXT_mesh_gpu_instancing, the instance's transform under it: world = node's world * instance.
    int node = -1;
    glm::dmat4 instance{1.0};

    // The texture bound to sampler `uniform`, `teximage` included; -1 for none.
    int texture_for(std::string_view uniform) const;
    // Whether world_from_object mirrors (its determinant is negative), turning the front faces.
    bool mirrors() const;
};

// glTF's node graph, kept for animation: each node's parent and its local transform.
struct Node {
    std::string name;
    int parent = -1;          // an index into Scene::nodes, always lower than the node's own
    bool has_matrix = false;  // a matrix node (glTF forbids animating it)
    glm::dmat4 matrix{1.0};
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};  // w, x, y, z
    glm::dvec3 scale{1.0};

    glm::dmat4 local() const;  // matrix, or T * R * S
};

// One animation channel of glTF: a node's translation, rotation or scale as keyframes.
struct Channel {
    enum class Path { Translation, Rotation, Scale } path = Path::Translation;
    enum class Interpolation { Linear, Step, CubicSpline } interpolation = Interpolation::Linear;
    int node = 0;               // Scene::nodes
    std::vector<double> times;  // increasing
    // components() per value (3, or 4 for a rotation as x, y, z, w); CUBICSPLINE keeps three per
    // keyframe: in-tangent, value, out-tangent.
    std::vector<double> values;
    int components() const { return path == Path::Rotation ? 4 : 3; }
};

// Where everything is at one time: each object's world transform and the camera's view.
struct Pose {
    std::vector<glm::dmat4> world_from_object;  // per Scene::objects
    glm::dmat4 view{1.0};
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
    // Animation (gltf.h): the nodes, the camera's node (-1: none, or not animated) and the
    // channels that move them. Empty for a scene without animations.
    std::vector<Node> nodes;
    int camera_node = -1;
    std::vector<Channel> channels;
    // What the file asks that is drawn otherwise than it says (an extension used but not
    // implemented, primitives of points or lines skipped, ...), one line each, for the command
    // lines to warn.
    std::vector<std::string> warnings;

    // Whether any object or the camera moves with time.
    bool animated() const { return !channels.empty(); }
    // The objects' world transforms and the camera's view at `time` (seconds): each channel's
    // value there (before its first keyframe, the first; after its last, the last), the nodes
    // composed in double. Without animations, the loaded transforms.
    Pose pose(double time) const;
    // The rest pose: the loaded transforms.
    Pose rest() const;
    // gl_ModelViewProjectionMatrix of object `i` for a render of the given width / height:
    // projection * view * world composed in double and rounded to float once (one compiled copy,
    // so that the renderer and the reference get the same bits).
    glm::mat4 clip_from_object(const Pose& pose, std::size_t i, double aspect) const;
    // view * world of object `i`, in double.
    glm::dmat4 view_from_object(const Pose& pose, std::size_t i) const;
    // The order the objects are drawn in: every object whose material does not blend in scene
    // order, then the blending ones back to front (by the view depth of their bounding box's
    // centre, farthest first; ties in scene order), as GL applications draw transparency.
    std::vector<std::size_t> draw_order(const Pose& pose) const;
};

// Whether object `i` of `scene` mirrors under `pose` (its world transform's determinant is
// negative), which turns its front faces clockwise.
bool mirrors(const Pose& pose, std::size_t i);

}  // namespace qs
