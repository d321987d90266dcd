#pragma once
// Which of a shader's instantiations (program_of.h) shades a draw: decided here, once, for both
// renderers, from what the shader needs and what was asked. A request no instantiation honours
// is refused before anything renders, never quietly shaded another way.

#include <cstdint>
#include <stdexcept>

#include "shading/program.h"

namespace qs {

struct ShadeRequest {
    Derivatives derivatives = Derivatives::Fine;  // the rule for shaders that take derivatives
    Precision precision = Precision::Float;
    bool check_undefined = false;  // Checked numbers (number/checked.h)
    bool general_path = false;     // quads with helper lanes even for shaders that take no derivatives
};

// A request that no instantiation can honour; the message names the options.
struct UnsupportedRequest : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
};

// Throws UnsupportedRequest for: double precision with a coarse rule (quads in double are
// instantiated for the fine rule only: they serve the error study, against llvmpipe's rule);
// undefined-case checking with analytic derivatives or double precision (Checked wraps float
// pixels and quads).
void check_supported(const ShadeRequest& request);

struct DrawShading {
    ShadeMode mode;
    bool quads;  // 2x2 quads with helper lanes; false: independent pixels or Dual2
};

// The shading of one draw: per pixel when neither the shader nor its texture's level of detail
// takes derivatives (unless the general path is asked for), else quads under the requested rule,
// or Dual2 for analytic derivatives. Checks the request first.
DrawShading choose_shading(const Needs& needs, bool texture_lod, const ShadeRequest& request);

// A set of ShadeModes: the instantiations a build of a shader holds (ProgramOf honours a
// shader's `compiled_modes`; a plugin compiled for one run holds only what the run shades).
struct ShadeModes {
    std::uint32_t bits = ~0u;  // every mode
    static constexpr int bit(ShadeMode m) {
        return int(m.derivatives) * 4 + int(m.precision) * 2 + int(m.check_undefined);
    }
    constexpr bool has(ShadeMode m) const { return (bits >> bit(m) & 1u) != 0; }
    constexpr bool covers(ShadeModes other) const { return (other.bits & ~bits) == 0; }
};

// The modes `request` shades a shader of `needs` in, on every draw (with a texture's level of
// detail or without). Checks the request first.
ShadeModes modes_for(const Needs& needs, const ShadeRequest& request);

}  // namespace qs
