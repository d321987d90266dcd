#pragma once
// The ray caster: the second way to produce fragments, from the same draw calls, through the same
// programs, into the same framebuffer, in the same tile loop (core/). Primary rays go from the
// near plane to the far plane through pixel centres, cast 16 at a time (one 4x4 block, four
// quads) with Embree.
//
// Quad derivatives: a 2x2 quad runs once for every primitive its covered pixels hit, as the
// rasterizer runs it once per triangle covering it. In each run all four rays are intersected with
// that primitive's plane and its attributes are interpolated (or, for lanes that missed it,
// extrapolated) with the barycentric weights of the intersection point: helper lanes exactly as
// a GPU makes them, so dFdx/dFdy are the GPU's. Ray differentials (Derivatives::Analytic):
// every pixel alone, with the derivatives of its ray (Igehy 1999) carried to the surface and
// into the attributes, fed to Dual2 shaders.
//
// The BVH is built once, from the vertex stage's gl_Position taken back to world space with the
// camera's inverse view-projection; each frame reruns the vertex stage for the varyings (and
// rebuilds only if a vertex moved). A block that no triangle's screen footprint reaches is the
// clear colour without a ray cast (screen_footprint.h). Output is bit-identical for any thread
// count.

#include <memory>
#include <span>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "core/draw_call.h"
#include "core/framebuffer.h"
#include "core/render_stats.h"
#include "core/shading_settings.h"
#include "core/tile_grid.h"

namespace qs {

class RayCaster {
public:
    // `clip_from_world`: the camera's view-projection, the same for every draw (each draw's own
    // model-view-projection is in its uniforms). Throws RayCastError (embree_scene.h) when Embree
    // fails, std::invalid_argument for an index out of range or a draw without a program.
    RayCaster(std::span<const DrawCall> draws, const glm::mat4& clip_from_world);
    ~RayCaster();
    RayCaster(const RayCaster&) = delete;
    RayCaster& operator=(const RayCaster&) = delete;

    // Renders `draws` (the construction's meshes in the same order; uniforms may change, e.g.
    // time) into a width x height framebuffer cleared to `clear`, or only the rows of `band`
    // (core/tile_grid.h). Writes colour only: visibility is the closest hit, no depth buffer.
    // Throws UnsupportedRequest for a draw with noperspective varyings, user clip planes or
    // blending, which are the rasterizer's.
    void render_into(Framebuffer& fb, int width, int height, glm::vec4 clear, std::span<const DrawCall> draws,
                     const ShadingSettings& settings, RenderStats* stats = nullptr, RowBand band = {});

    double build_seconds() const;  // time spent building BVHs, in total

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace qs
