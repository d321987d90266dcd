#pragma once
// The 2x2-quad rasterizer: draw calls in, a framebuffer out, as a GL driver would produce it.
//
// Pipeline per frame: vertex stage (per vertex, in parallel) -> clipping (clipper.h) -> triangle
// setup -> binning into 64x64 tiles (core/tile_grid.h) -> tiles in parallel (core/tile_frame.h),
// each tile's triangles in submission order -> quads (or single pixels for derivative-free
// shaders) batched kBatchLanes lanes at a time -> early depth test (unless no two triangles overlap: depth_buffer.h) -> shading -> colour
// and depth writes for covered lanes only.
// The output is bit-identical for any thread count.

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec4.hpp>

#include "core/draw_call.h"
#include "core/framebuffer.h"
#include "core/render_stats.h"
#include "core/shading_settings.h"
#include "core/tile_grid.h"
#include "raster/depth_buffer.h"
#include "raster/edge_function.h"
#include "raster/plane_equation.h"
#include "raster/triangle_setup.h"
#include "shading/batches.h"

namespace qs {

// The rasterizer's own settings, beside the shading ones both backends share.
struct RasterSettings {
    FillRule fill_rule = FillRule::LeftBottom;
    // Evaluate attribute planes with fused multiply-adds (llvmpipe on FMA hosts) or separately
    // rounded ones (softpipe). See plane_equation.h.
    bool fused_interpolation = fused_interpolation_default();
    // The vertices' viewport transform as one fused multiply-add: Mesa's draw module (both
    // drivers' vertex stage) compiles it with llvm.fmuladd, fused on FMA hosts. See clipper.h.
    bool fused_viewport = fused_interpolation_default();
    // Shade derivative-free shaders in quads with helper lanes too (the general path), interpolate
    // gl_FragCoord for every shader, and keep a depth buffer even when it provably changes
    // nothing (depth_buffer.h), testing every fragment against it (a tile's first triangle too).
    // For measuring what specialisation saves, and for checking that it changes nothing.
    bool force_general_path = false;
    bool operator==(const RasterSettings&) const = default;
};

struct RasterOptions : ShadingSettings, RasterSettings {};

// A frame's set-up triangles and tile bins, kept by a caller that renders many frames
// (SceneRenderer) so that each reuses the memory of the last: allocated afresh, their pages are
// faulted in every frame, serially, before the tiles run in parallel (a tenth of a one-thread
// Figure 1.1 frame).
struct RasterMemory {
    std::vector<TriangleSetup> triangles;
    DepthBufferDecision depth;  // the last frame's, for a frame with the same triangles
    std::vector<std::vector<std::uint32_t>> bins;  // per tile
};

// Renders draws into a width x height framebuffer cleared to `clear`, with GL's depth test
// (LESS, a depth buffer cleared to 1) left out where it provably changes nothing (depth_buffer.h).
// Throws std::invalid_argument for absurd sizes or a draw without a program, UnsupportedRequest
// (shade_choice.h) for options no shader instantiation honours.
Framebuffer rasterize(int width, int height, glm::vec4 clear, std::span<const DrawCall> draws,
                      const RasterOptions& options, RenderStats* stats = nullptr);
// The same into `fb`, reusing its memory (animation loops, benchmarks): every pixel is written;
// with a band (image_bands, core/tile_grid.h), only its rows; with `memory`, the working memory
// of the last frame that was given it.
void rasterize_into(Framebuffer& fb, int width, int height, glm::vec4 clear, std::span<const DrawCall> draws,
                    const RasterOptions& options, RenderStats* stats = nullptr, RowBand band = {},
                    RasterMemory* memory = nullptr);
// Renders draws over what `fb` holds (a whole image, as rasterize_into leaves it or as its caller
// filled it), as GL draws into a framebuffer it does not clear, with GL's depth test disabled:
// every fragment that is not discarded writes its colour, in submission order. Throws
// std::invalid_argument for a framebuffer that does not hold a whole image, as rasterize_into
// does for bad draws.
void rasterize_over(Framebuffer& fb, std::span<const DrawCall> draws, const RasterOptions& options,
                    RenderStats* stats = nullptr);

}  // namespace qs
