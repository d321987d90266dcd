#include "shading/shade_choice.h"

namespace qs {

void check_supported(const ShadeRequest& r) {
    const bool coarse = r.derivatives == Derivatives::CoarseLower || r.derivatives == Derivatives::CoarseUpper;
    if (r.precision == Precision::Double && coarse) {
        throw UnsupportedRequest("double precision is shaded with the fine derivative rule, per pixel or analytically; "
                                 "not with a coarse rule");
    }
    if (r.check_undefined && r.derivatives == Derivatives::Analytic) {
        throw UnsupportedRequest("checking for undefined GLSL cases needs quad or per-pixel derivatives, not analytic");
    }
    if (r.check_undefined && r.precision == Precision::Double) {
        throw UnsupportedRequest("checking for undefined GLSL cases shades in float, not double");
    }
}

DrawShading choose_shading(const Needs& needs, bool texture_lod, const ShadeRequest& r) {
    check_supported(r);
    DrawShading s{{r.derivatives, r.precision, r.check_undefined}, true};
    // Derivatives: the shader's own, or its texture's level of detail.
    const bool derivatives = needs.derivatives || texture_lod;
    if (!derivatives && !r.general_path) {
        s.mode.derivatives = Derivatives::None;  // per pixel, no helper lanes
        s.quads = false;
    } else if (s.mode.derivatives == Derivatives::None) {  // no rule asked: llvmpipe's where one is needed
        s.mode.derivatives = derivatives ? Derivatives::Fine : Derivatives::None;
        s.quads = derivatives;
    } else if (s.mode.derivatives == Derivatives::Analytic) {
        s.quads = false;  // Dual2 carries the derivatives: no neighbours needed
    }
    return s;
}

ShadeModes modes_for(const Needs& needs, const ShadeRequest& request) {
    ShadeModes m{0};
    for (const bool texture_lod : {false, true}) {
        m.bits |= 1u << ShadeModes::bit(choose_shading(needs, texture_lod, request).mode);
    }
    return m;
}

}  // namespace qs
