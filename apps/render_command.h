#pragma once
// quadshade render: its options and the command (frames, bands of rows, the undefined-case mask).

#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "render/scene_render.h"
#include "scenes/gltf.h"

namespace qs::app {

struct RenderArgs {
    std::string scene, output, mask_output;
    FrameRequest request;
    std::pair<int, int> frames{-1, -1};  // -1: no animation
    float fps = 30.0f;
    bool alpha = false;
    SceneLoadOptions load;
    std::string memory_limit;  // empty: what the system has available
    std::vector<std::string> plugins;
    std::string glsl, vertex_glsl;  // --glsl FRAG, --vert VERT
    bool compile_glsl = false;      // --compile
    std::vector<std::string> uniforms;  // --uniform NAME=VALUE, read by parse_uniform_option
    std::vector<std::string> raster_only;  // the rasterizer's own options given (note_raster_only)
    bool animated() const { return frames.first >= 0; }
};

void add_render_options(CLI::App& cmd, RenderArgs& a);
// After parsing: notes which of the rasterizer's own options `cmd` was given (RenderArgs::raster_only).
void note_raster_only(const CLI::App& cmd, RenderArgs& a);
int cmd_render(RenderArgs& a);

}  // namespace qs::app
