#pragma once
// The scene model: meshes in object space, objects placing them with a shader each, a camera,
// and the frame's settings. Loaded from glTF (gltf.h); nothing here renders.

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "shading/glsl/texture.h"
#include "shading/program.h"

namespace qs {

// Bad input: the message names the file and the field at fault.
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct Mesh {
    std::string name;
    std::vector<VertexIn> vertices;
    std::vector<std::uint32_t> indices;  // triangles
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

struct Object {
    std::string name;
    std::size_t mesh = 0;
    glm::mat4 world_from_object{1.0f};
    std::string shader;   // catalogue name; empty when the file names none
    int texture = -1;     // index into Scene::textures, -1 for none
    std::string material; // for messages: which glTF material named the shader
};

struct Texture {
    std::filesystem::path path;
    glsl::sampler2D texels;  // loaded only when a shader that samples it is drawn
    bool loaded = false;
    // Why `path` may not be read (resolve_scene_uri refused it: outside the scene's folder, a
    // URI scheme, ...); empty when it may. Reported when a shader that samples it is drawn.
    std::string refused;
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

    // MVP of an object for a render of the given aspect ratio.
    glm::mat4 model_view_projection(const Object& o, float aspect) const {
        return camera.projection(aspect) * camera.view * o.world_from_object;
    }
};

}  // namespace qs
