#pragma once
// Listing 1.3's 2D simplex noise, and the listing's typo as printed: a family of its own, compiled without
// the other shader groups' scheduling (shading/CMakeLists.txt says why). Translated from
// simplex2d.frag beside this header and shading/noise/simplex2d.glsl.

#include <span>

#include "shading/glsl.h"
#include "shading/noise/simplex2d.h"
#include "shading/program.h"
#include "shading/program_of.h"
#include "shading/shaders/aastep_shaders.h"
#include "shading/shaders/collections.h"
#include "shading/shaders/vertex_stages.h"

namespace qs::shaders {
using namespace qs::glsl;

// The typo makes the noise jump across simplex edges (tests/shading); Mesa's reassociated dot
// products put one pixel of the grazing plane on the jump's other side (measured: 1 pixel, 83/255).
inline constexpr CheckBound kListingTypoCheckBounds[] = {
    {"grazing-plane", "fine", 3, 3, 0,
     "the typo's jumps along simplex edges, where Mesa's reassociated dot products move a pixel across (measured 1)"}};

template <noise::Simplex2dCorner corner>
struct Simplex2d {
    static constexpr bool typo = corner == noise::Simplex2dCorner::ListingTypo;
    static constexpr ShaderInfo info{
        .name = typo ? "simplex2d_listing_typo" : "simplex2d",
        .description =
            typo ? "Listing 1.3 with its printed C.xxxx typo (breaks along simplex edges)" : "Listing 1.3: 2D simplex noise",
        .glsl_fragment = {"noise/simplex2d.glsl", "shaders/simplex2d.frag"},
        .glsl_defines = typo ? "#define SIMPLEX2D_LISTING_TYPO\n" : "",
        .wide_batches = true,
        .check_bounds = typo ? std::span<const CheckBound>(kListingTypoCheckBounds) : std::span<const CheckBound>(),
    };
    using VertexStage = PlaneSt10;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return grey(0.5f + 0.5f * noise::snoise<F, corner>(in.st));
    }
};

QUADSHADE_SHADERS_IN(kGustavson, Simplex2d<noise::Simplex2dCorner::Correct>, Simplex2d<noise::Simplex2dCorner::ListingTypo>)

}  // namespace qs::shaders
