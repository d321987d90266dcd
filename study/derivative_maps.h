#pragma once
// Derivative maps: dFdx and dFdy of values a shader computes under each quad rule, against the
// analytic partials Dual2 carries, over the pixels the scene covers. The values are the shader's
// inputs (the varyings its vertex stage writes, input_derivatives.h) or expressions a user names
// (expression_derivatives.h); each is drawn by a Program whose colour is (dFdx, dFdy, the value, 1).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace qs::study {

// One value to map: its name in the tables, the stem of its images and the Program that draws it.
struct DerivativeMap {
    std::string label, stem, program;
};

// The maps of every input of `shader`: flat varyings have no derivatives to map. The programs are
// added to the catalogue once per process.
std::vector<DerivativeMap> input_maps(const std::string& shader);

struct DerivativeRow {
    std::string input, rule;
    double rms_dx = 0, max_dx = 0, rms_dy = 0, max_dy = 0;  // |rule - analytic|, per pixel
    double scale = 0;  // the analytic |(dx, dy)|'s RMS: what the errors are relative to
    std::size_t covered = 0;
    std::string map_image, heat_image, analytic_image;  // relative to the study's folder
};

// Each map drawn on `scene` (at its size, at `time` or the scene's): DIR/STEM-analytic.png (dx in
// red, dy in green, each 0.5 + 0.5 d / its largest |d|) and, per rule, DIR/STEM-RULE.png and its
// heat map against the analytic one (full scale a quarter of the largest analytic |d|). `relative`
// is DIR relative to the study's folder. A pixel is covered where the map's program wrote a colour.
std::vector<DerivativeRow> derivative_maps(const Scene& scene, const std::vector<DerivativeMap>& maps,
                                           std::optional<double> time, int threads, const std::filesystem::path& dir,
                                           const std::string& relative);

}  // namespace qs::study
