#pragma once
// Derivative maps: dFdx and dFdy of each of a shader's inputs (the varyings its vertex stage
// writes, input_derivatives.h) under each quad rule, against the analytic partials Dual2
// carries, over the pixels the scene covers.

#include <filesystem>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace qs::study {

struct DerivativeRow {
    std::string input, rule;
    double rms_dx = 0, max_dx = 0, rms_dy = 0, max_dy = 0;  // |rule - analytic|, per pixel
    double scale = 0;  // the analytic |(dx, dy)|'s RMS: what the errors are relative to
    std::size_t covered = 0;
    std::string map_image, heat_image, analytic_image;  // relative to the study's folder
};

// The maps of every input of `shader` on `scene` (at its size, with its time): for each input,
// DIR/d-INPUT-analytic.png (dx in red, dy in green, each 0.5 + 0.5 d / its largest |d|) and, per
// rule, DIR/d-INPUT-RULE.png and its heat map against the analytic one (full scale a quarter of
// the largest analytic |d|). `relative` is DIR relative to the study's folder. Flat varyings
// have no derivatives to map.
std::vector<DerivativeRow> derivative_maps(const Scene& scene, const std::string& shader, int threads,
                                           const std::filesystem::path& dir, const std::string& relative);

}  // namespace qs::study
