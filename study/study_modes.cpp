#include "study/study_modes.h"

namespace qs::study {

std::vector<Mode> all_modes(const Shaders& s, bool raycast) {
    std::vector<Mode> m = {
        {"fine", "derivatives", s.shader},
        {"coarse-lower", "derivatives", s.shader, Backend::Rasterizer, Derivatives::CoarseLower},
        {"coarse-upper", "derivatives", s.shader, Backend::Rasterizer, Derivatives::CoarseUpper},
        {"dual2", "derivatives", s.shader, Backend::Rasterizer, Derivatives::Analytic},
    };
    if (raycast) {
        m.push_back({"raycast-quads", "derivatives", s.shader, Backend::RayCaster, Derivatives::Fine});
        m.push_back({"ray-differentials", "derivatives", s.shader, Backend::RayCaster, Derivatives::Analytic});
    }
    m.push_back({"double", "precision", s.shader, Backend::Rasterizer, Derivatives::Fine, Precision::Double});
    if (!s.alternative.empty()) m.push_back({s.alternative_mode, "anti-aliasing", s.alternative});
    const std::string& plain = s.unfiltered.empty() ? s.shader : s.unfiltered;
    if (!s.unfiltered.empty()) m.push_back({"step", "anti-aliasing", plain});
    for (int k : {2, 4, 8}) {
        Mode ss{"ss" + std::to_string(k) + "x" + std::to_string(k), "anti-aliasing", plain};
        ss.supersample = k;
        m.push_back(ss);
    }
    return m;
}

std::string mode_names(const Shaders& shaders, bool raycast) {
    std::string names;
    for (const Mode& m : all_modes(shaders, raycast)) names += (names.empty() ? "" : ", ") + m.name;
    return names;
}

}  // namespace qs::study
