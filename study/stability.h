#pragma once
// Numerical stability of a shader on a view: its float image against its double one (where the
// float image departs, and by how much), and the pixels whose colour depends on a GLSL case with
// an undefined result (render/undefined_mask.h: NaN produced, division by zero, a built-in
// outside its domain).

#include <filesystem>
#include <optional>
#include <string>

#include "render/undefined_mask.h"
#include "scenes/scene.h"

namespace qs::study {

struct Stability {
    double rms = 0, max = 0;  // float against double over RGB in [0, 1]
    std::size_t over_1 = 0;   // pixels more than 1/255 apart
    bool checked = false;     // the undefined cases were checked
    UndefinedCounts undefined;
    std::string note;                                               // why they were not
    std::string float_image, double_image, heat_image, mask_image;  // relative to the study's folder
};

// Renders `shader` on `scene` (at its size, at `time` or the scene's) with the fine rule in float and in double,
// and in float with the undefined cases checked; writes DIR/float.png, double.png,
// float-vs-double.png (heat map, full scale 8/255) and undefined.png. `relative` is DIR relative
// to the study's folder.
Stability stability(const Scene& scene, const std::string& shader, std::optional<double> time, int threads,
                    const std::filesystem::path& dir, const std::string& relative);

// Adds `offset` to the coordinates the shaders read: TEXCOORD_0 (x, y) and the object-space
// positions, each object's transform moved back by it so that the geometry stays where it was
// (to float precision): a pattern evaluated far from its origin.
void offset_coordinates(Scene& scene, const glm::dvec3& offset);

}  // namespace qs::study
