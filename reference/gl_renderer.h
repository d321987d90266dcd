#pragma once
// Renders a scene as any OpenGL application would, from the glTF alone: each object's shader is
// the GLSL pair NAME.vert / NAME.frag in a folder (`quadshade shaders --export-glsl DIR` writes
// it), its uniforms are bound by name (`time`, `dims`, the scene's transforms and vertex inputs of
// scenes/shader_inputs.h, and each sampler the program declares to the texture the object's
// material binds to that name: teximage, extras.textures; any other vertex input is refused, and
// so is a matrix uniform nothing sets), its textures
// are decoded here (texture_image.h) and uploaded in glTF's orientation (the image's first row at
// t = 0; a 3D texture's slices are the image's bands of rows, glTexImage3D's own order) with the
// sampler's wraps and filters, and glGenerateMipmap when the minification filter reads mipmaps.
// A material that names no shader is drawn with the default material's GLSL
// (kDefaultMaterialShader), a sampler its material binds no texture to reads a 1x1 white texture,
// and the uniforms the scene gives (scenes/object_uniforms.h) are set by name where a program has
// them, the material's extras.uniforms and --uniform over them. The objects are posed at the
// frame's time (Scene::pose) and drawn in Scene::draw_order, each with gl_Vertex, gl_Normal,
// gl_Color, gl_MultiTexCoord0 and gl_MultiTexCoord1 from the scene's vertices, and the
// projection matrix the scene model's clip_from_object (gl_ModelViewProjectionMatrix = P * I).
// Fixed-function state: depth test LESS against a buffer cleared to 1, back faces culled unless
// the material is doubleSided (front faces clockwise where the node mirrors; no culling in an
// atlas bake); blending (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, depth writes off) for the default
// material's alphaMode BLEND, none otherwise. Shared with the renderer: the scene model and the
// GLSL text, nothing else.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "images/image_io.h"
#include "reference/gl_context.h"
#include "scenes/scene.h"
#include "scenes/shader_inputs.h"

namespace qs {

struct GlFrameRequest {
    int width = 0, height = 0;
    std::optional<double> time;  // the scene's own by default
    std::string shader_override;  // draw every object with this shader's GLSL
    // --uniform values, replacing the materials' of the same name for every program that has
    // that uniform; one no program has is refused (UniformOptionError).
    std::vector<UniformSetting> uniforms;
    // Draw each triangle at its TEXCOORD_0 (an atlas bake, as quadshade bake draws it): every
    // vertex shader's own main() runs, then gl_Position is replaced by the texcoord mapped to
    // [-1, 1] (atlas_vertex_source).
    bool atlas = false;
};

// A vertex shader's GLSL made to draw into a texture atlas: its main() renamed and called by a
// main() that then sets gl_Position = vec4(gl_MultiTexCoord0.st * 2.0 - 1.0, 0.0, 1.0), so its
// varyings are its own and texcoord (s, t) lands at window (s W, t H).
std::string atlas_vertex_source(const std::string& source);

// The programs of one context, each linked once from a folder of exported GLSL (NAME.vert,
// NAME.frag) and deleted with it: renderers drawing into the same context share them.
class GlPrograms {
public:
    explicit GlPrograms(std::filesystem::path glsl_dir) : glsl_dir_(std::move(glsl_dir)) {}
    ~GlPrograms();
    GlPrograms(const GlPrograms&) = delete;
    GlPrograms& operator=(const GlPrograms&) = delete;
    // Throws std::runtime_error with the compiler's log when the GLSL fails, or naming a
    // uniform the reference does not bind.
    unsigned program(const std::string& shader, bool atlas = false);
    const std::filesystem::path& glsl_dir() const { return glsl_dir_; }

private:
    std::filesystem::path glsl_dir_;
    struct Linked {
        std::string shader;
        bool atlas;
        unsigned id;
    };
    std::vector<Linked> linked_;
};

// Renders a scene's frames into the current context: GLSL compiled and textures uploaded once,
// at construction. Throws std::runtime_error with the compiler's log when GLSL fails, naming the
// file and field of a texture that cannot be read, and naming a uniform it cannot bind.
class GlSceneRenderer {
public:
    GlSceneRenderer(const Scene& scene, const GlFrameRequest& request, GlContext& context,
                    const std::filesystem::path& glsl_dir);
    // With the context's programs, linked by an earlier renderer or kept for a later one.
    GlSceneRenderer(const Scene& scene, const GlFrameRequest& request, GlContext& context, GlPrograms& programs);
    ~GlSceneRenderer();
    GlSceneRenderer(const GlSceneRenderer&) = delete;
    GlSceneRenderer& operator=(const GlSceneRenderer&) = delete;

    // Draws the frame and waits for it (glFinish), without reading it back.
    void draw();
    // draw(), then the colour buffer as floats, rows top-down.
    Image render();
    // The last frame drawn as GL converts it to 8-bit unorm (glReadPixels of GL_UNSIGNED_BYTE),
    // rows top-down.
    Image8 read_unorm8() const;

private:
    struct Texture {
        unsigned id = 0;
        unsigned target = 0;  // GL_TEXTURE_2D, GL_TEXTURE_3D or GL_TEXTURE_CUBE_MAP
        int width = 0, height = 0;
    };
    // A sampler uniform of an object's program and the texture unit it reads.
    struct Binding {
        int location = -1;
        int unit = 0;
        const Texture* texture = nullptr;
    };
    // A value for one of a program's own uniforms, as glUniform takes it.
    struct UniformValue {
        int location = -1;
        unsigned type = 0;  // GL_FLOAT_VEC3, GL_INT, GL_FLOAT_MAT2, ...
        std::vector<double> values;
    };
    // A scene transform a program reads by name (scenes/shader_inputs.h), and a vertex input.
    struct MatrixBinding {
        int location = -1;
        SceneMatrix matrix;
    };
    struct AttributeBinding {
        int location = -1;
        VertexAttribute attribute;
    };
    // Where a mesh keeps an attribute: its first component (the stride is Vertex's) and how many
    // there are. Throws naming the scene, mesh and shader for one the scene model does not carry.
    struct AttributeArray {
        const float* first;
        int components;
    };
    AttributeArray attribute_array(const Mesh& mesh, VertexAttribute attribute, const std::string& shader,
                                   const std::string& name) const;
    void prepare(GlPrograms& programs);
    void set_state(std::size_t i, const Pose& pose);
    void set_uniforms(std::size_t i, const Pose& pose, double time, double aspect);
    void draw_mesh(std::size_t i);
    std::vector<UniformValue> uniform_values(unsigned program, const std::string& shader,
                                             const std::vector<UniformSetting>& settings, const std::filesystem::path& glsl_dir) const;
    // `shadow`: for a sampler2DShadow, which reads a depth comparison texture (and only it does).
    const Texture& texture_of(const Object& o, const std::string& shader, const std::string& uniform, int dims, bool shadow);
    const Texture& white(int dims);
    const Texture& upload_cube(const qs::Texture& source, Texture& t);

    const Scene& scene_;
    GlFrameRequest request_;
    GlContext& context_;
    std::unique_ptr<GlPrograms> own_programs_;  // when constructed from a GLSL folder
    std::vector<unsigned> programs_;       // per object
    std::vector<std::vector<Binding>> bound_;  // per object, its program's samplers
    std::vector<std::vector<UniformValue>> uniforms_;  // per object
    std::vector<std::vector<MatrixBinding>> matrices_;       // per object
    std::vector<std::vector<AttributeBinding>> attributes_;  // per object
    std::vector<Texture> textures_;        // per scene texture, id 0 until uploaded
    Texture white_[3];                     // 2D, 3D and a cube map, id 0 until made
    std::vector<std::string> shaders_;     // per object, the shader it is drawn with
};

}  // namespace qs
