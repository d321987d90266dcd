#pragma once
// The ways a study renders a shader, each measured for time and error:
//   derivatives    fine, coarse-lower, coarse-upper (2x2 quads under each rule), dual2 (analytic
//                  partials), and with the ray caster raycast-quads and ray-differentials
//   precision      double (fine quads in double)
//   anti-aliasing  the shader's alternative filter (a variant it names), step (its unfiltered
//                  variant) and ss2x2, ss4x4, ss8x8: the unfiltered variant, or the shader itself,
//                  rendered at k x k samples per pixel and box-filtered

#include <string>
#include <vector>

#include "render/scene_render.h"

namespace qs::study {

// The shader a study measures, and the variants of it that it may name.
struct Shaders {
    std::string shader;
    std::string unfiltered;        // empty: none (the truth and the supersampled modes use `shader`)
    std::string alternative;       // empty: none
    std::string alternative_mode;  // its mode's name
};

struct Mode {
    std::string name, group;
    std::string shader;  // which variant
    Backend backend = Backend::Rasterizer;
    Derivatives rule = Derivatives::Fine;
    Precision precision = Precision::Float;
    int supersample = 1;
};

// Every mode for `shaders`, the ray caster's only when `raycast`.
std::vector<Mode> all_modes(const Shaders& shaders, bool raycast);

// The names of the modes all_modes gives (for a usage message).
std::string mode_names(const Shaders& shaders, bool raycast);

}  // namespace qs::study
