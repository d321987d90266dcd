#pragma once
// One shader_test run as piglit's shader_runner runs it on a GL driver, with quadshade as the
// driver: the shaders through the GLSL front end and the interpreter, the draws through the
// rasterizer (or the ray caster) into a 250x250 (or SIZE) RGBA8 framebuffer object, read back as
// 8-bit values by the probes. The GL state a script changes (clear colour, matrices, current
// colour, shade model, two-sided colour, tolerance, uniforms) is kept here; what quadshade does
// not do is a named skip, decided before anything is drawn.

#include <filesystem>

#include "piglit/test_result.h"
#include "render/scene_render.h"
#include "shading/shade_mode.h"

namespace qs::piglit {

struct RunOptions {
    Derivatives derivatives = Derivatives::Fine;  // quad rule, or Analytic (Dual2)
    Backend backend = Backend::Rasterizer;
};

// Never throws for a test's content: a malformed file fails, an exception from the renderer is
// a crash (its message kept), as a crashing shader_runner would be.
TestResult run_shader_test(const std::filesystem::path& file, const RunOptions& options);

}  // namespace qs::piglit
