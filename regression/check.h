#pragma once
// `quadshade check`: does a shader's C++ translation render what its GLSL renders? Each case (a
// shader on a scene under a derivative rule) is rendered by quadshade in this process and from
// the exported GLSL alone by quadshade-reference, a separate process, through OSMesa: llvmpipe
// for the fine rule, softpipe for coarse-lower. The two images are compared in 8-bit steps after
// GL's unorm conversion, and each case is held to the project's bar unless its shader documents
// a departure (ShaderInfo::check_bounds).
//
// The bar against llvmpipe (fine): coverage identical, at most 0.1% of the covered pixels more
// than 1/255 off, none more than 2/255 off (tests/reference/test_conformance.cpp holds the
// catalogue to the same). Against softpipe (coarse-lower) the bar allows what softpipe does
// differently from every rasterizer that snaps to sub-pixels (design.md, "Not reproduced
// exactly"): see kCoarseLowerBar in check.cpp.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "images/image_io.h"

namespace qs {

enum class CheckRule { Fine, CoarseLower };

struct CheckRequest {
    // Empty: every shader of the catalogue, plugins' included, but the built-in probes (*_probe:
    // tests of their own, drawn for one window); a probe is checked when named.
    std::vector<std::string> shaders;
    // .gltf/.glb scenes, and folders standing for every scene in them, each checked with every
    // shader it can feed (it binds the textures the shader samples). Empty: the default set,
    // installed in share/quadshade/scenes beside the executable's bin/: the geometry conformance
    // scenes and the Table 1.1 plane with every shader, the texture conformance scenes
    // (texture-*) with the shaders that sample one.
    std::vector<std::filesystem::path> scenes;
    // Every case's size in pixels; 0: each scene's own.
    int width = 0, height = 0;
    std::vector<CheckRule> rules{CheckRule::Fine};
    // Where the exported GLSL, report.csv and a quadshade | OSMesa | heat map image of every case
    // that differs at all are written.
    std::filesystem::path output = "quadshade-check";
    int jobs = 0;  // cases at once (a reference process and a render each); 0: one per core
    // What the cases checked at once may use together (each reserves its render's and images'
    // memory first: render/memory_plan.h's MemoryBudget); 0: what the system has available.
    std::uint64_t memory_limit = 0;
};

// One case's differences. A pixel's difference is its largest RGB channel difference in 8-bit
// steps; it is covered where alpha > 1/2 (a coverage difference: alpha on either side of 1/2 and
// more than one step apart, so that a shader's own alpha near 1/2 is not taken for coverage).
struct CaseCounts {
    std::size_t pixels = 0, covered = 0;  // covered: by the reference
    std::size_t coverage = 0;             // covered by one image and not the other
    std::size_t over_1 = 0, over_2 = 0;   // pixels more than 1/255 (2/255) off
    int max_steps = 0, max_x = -1, max_y = -1;  // the largest difference and its first pixel (top row 0)
};
CaseCounts count_differences(const Image& ours, const Image& reference);

// Runs every case and prints a line for each and a summary (stdout). Before the cases, each
// shader is shaded once on its first case in its checked instantiation, which finds a Loop's
// body writing a variable the loop does not hold (shading/glsl/control.h): that fails the shader
// with a line naming the loop. Returns 0 when every case meets its bar, 3 when one does not. Throws on bad input (an unknown shader, a folder without
// scenes, quadshade-reference missing or failing: its message is in the exception).
int run_check(const CheckRequest& request);

// The scenes installed beside the executable (share/quadshade/scenes beside its bin/): those
// `check` runs on by default, the planes that bind the shaders' textures and the solid textures' scene.
std::filesystem::path installed_scenes_folder();

}  // namespace qs
