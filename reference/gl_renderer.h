#pragma once
// Renders a scene through OpenGL with the original GLSL of each object's shader (the files
// listed in its ShaderInfo, under shading/), with the same meshes, matrices, uniforms and
// textures quadshade uses. Fixed-function state as the chapter's demo: depth test LESS when
// any object needs depth, no culling, no blending.

#include <filesystem>
#include <optional>
#include <string>

#include "gl_context.h"
#include "image_io.h"
#include "scene.h"

namespace qs {

struct GlFrameRequest {
    int width = 0, height = 0;
    std::optional<float> time;
    std::string shader_override;
};

// The GLSL text of one stage: "#version 120", the shader's defines, then its files in order.
std::string glsl_source(const ShaderInfo& info, bool vertex_stage, const std::filesystem::path& shading_dir);

// Renders into the current context (sized request.width x request.height). Throws
// std::runtime_error with the compiler's log when GLSL fails to compile or link.
Image render_gl(Scene& scene, const GlFrameRequest& request, GlContext& context,
                const std::filesystem::path& shading_dir);

}  // namespace qs
