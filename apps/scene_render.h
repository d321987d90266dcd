#pragma once
// From a loaded scene to a framebuffer: resolves each object's shader in the catalogue, loads the
// textures the drawn shaders sample (and no others), and builds the draw calls. Shared by the
// command line, the reference comparisons and the benchmarks.

#include <optional>
#include <string>

#include "rasterizer.h"
#include "scene.h"

namespace qs {

struct FrameRequest {
    int width = 0, height = 0;           // 0: the scene's size
    std::optional<float> time;           // default: the scene's time
    std::string shader_override;         // draw every object with this shader
    RasterOptions raster;
};

// Throws SceneError for an unknown or missing shader (naming the scene file and material) or a
// texture that cannot be read.
Framebuffer render_frame(Scene& scene, const FrameRequest& request, RasterStats* stats = nullptr);
// The same into `fb`, reusing its memory from frame to frame.
void render_frame_into(Framebuffer& fb, Scene& scene, const FrameRequest& request, RasterStats* stats = nullptr);

// The texture an object's program samples, loaded on first use. Throws SceneError naming the
// material when extras.teximage is missing or unreadable.
const glsl::sampler2D& texture_for(Scene& scene, const Object& object, const Program& program);

// The shader each object is drawn with under `shader_override`, checked against the catalogue.
const Program& program_for(const Scene& scene, const Object& object, const std::string& shader_override);

}  // namespace qs
