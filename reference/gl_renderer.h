#pragma once
// Renders a scene through OpenGL with the original GLSL of each object's shader (the files
// listed in its ShaderInfo, under shading/), with the same meshes, matrices, uniforms and
// textures quadshade uses. Fixed-function state as the chapter's demo: depth test LESS against
// a depth buffer cleared to 1 for every object, no culling, no blending.

#include <filesystem>
#include <optional>
#include <string>

#include "reference/gl_context.h"
#include "scenes/image_io.h"
#include "scenes/scene.h"

namespace qs {

struct GlFrameRequest {
    int width = 0, height = 0;
    std::optional<float> time;
    std::string shader_override;
};

// The GLSL text of one stage: the #version line of ShaderInfo::glsl_version, the shader's
// defines, then its files in order.
std::string glsl_source(const ShaderInfo& info, bool vertex_stage, const std::filesystem::path& shading_dir);

// Renders a scene's frames into the current context: GLSL compiled and textures uploaded once,
// at construction. Throws std::runtime_error with the compiler's log when GLSL fails.
class GlSceneRenderer {
public:
    GlSceneRenderer(Scene& scene, const GlFrameRequest& request, GlContext& context,
                    const std::filesystem::path& shading_dir);
    ~GlSceneRenderer();
    GlSceneRenderer(const GlSceneRenderer&) = delete;
    GlSceneRenderer& operator=(const GlSceneRenderer&) = delete;

    // Draws the frame and waits for it (glFinish), without reading it back.
    void draw();
    // draw(), then the colour buffer.
    Image render();

private:
    Scene& scene_;
    GlFrameRequest request_;
    GlContext& context_;
    std::vector<const ShaderInfo*> infos_;      // per object
    std::vector<unsigned> programs_;            // per object
    std::vector<unsigned> textures_;            // per object, 0 for none
    std::vector<const glsl::sampler2D*> texels_;  // per object, nullptr for none
};

// One frame: GlSceneRenderer(...).render().
Image render_gl(Scene& scene, const GlFrameRequest& request, GlContext& context,
                const std::filesystem::path& shading_dir);

}  // namespace qs
