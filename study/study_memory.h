#pragma once
// A study's memory, planned before it runs, as render, bake and check plan theirs
// (render/memory_plan.h). A study runs one step at a time on each view, each freeing what it
// made: the float, double and checked frames (stability.h), the derivative maps, the truth (a
// band of its supersampled rows at a time, summed into a double image), then each mode's frame
// (k x k samples per pixel for the supersampled ones) and llvmpipe's image of it, read back from
// quadshade-reference, whose own process renders it meanwhile. Throughout, it holds the scene and
// one renderer's (its meshes, draw calls, textures, the ray caster's BVH), and on each view its
// truth and llvmpipe's images. The plan is the largest step with what is held beside it.

#include <cstdint>
#include <string>
#include <vector>

#include "scenes/scene.h"
#include "study/study.h"

namespace qs::study {

// What llvmpipe's process holds rendering an image (quadshade-reference's peak resident memory,
// 216 MiB at 512x512 to 689 MiB at 3072x3072: about 210 MiB and 56 bytes a pixel; docs/results.md,
// "A study's memory"), rounded up.
inline constexpr std::uint64_t kReferenceBaseBytes = std::uint64_t(256) << 20;
inline constexpr std::uint64_t kReferenceBytesPerPixel = 64;

struct MemoryPlan {
    std::uint64_t peak = 0;  // at the largest step: this process's, and llvmpipe's beside it
    std::string largest;     // that step, in words
};

// The plan of `request` on `scene` (as drawn: its objects kept, at the study's size) with `modes`.
// Builds the renderers it measures (a rasterizer's for each variant of the shader, and a ray
// caster's for its modes); renders nothing.
MemoryPlan plan_memory(const Request& request, Scene& scene, const std::vector<Mode>& modes);

// Throws MemoryError naming the step, what it needs and `limit`, when the plan needs more.
void check_memory(const MemoryPlan& plan, std::uint64_t limit);

}  // namespace qs::study
