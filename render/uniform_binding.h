#pragma once
// A shader's own uniforms given their values: each declared uniform (ShaderInfo::uniforms) takes
// the setting of its name (the material's, replaced by the command line's), or its GLSL
// initializer; uResolution takes the frame's size.

#include <cstdint>
#include <string>
#include <vector>

#include "scenes/uniforms.h"
#include "shading/program.h"

namespace qs {

// Uniforms::user for one object. `settings` from merge_uniforms. A setting whose name the shader
// does not declare, or whose numbers do not fit the declared type, throws: SceneError for a
// material's (its origin names the file and field), UniformOptionError for a command line's;
// `ignore_unknown_material` skips a material's unknown names (under --shader, a material's
// uniforms were written for another shader).
std::vector<std::uint32_t> bind_uniforms(const ShaderInfo& info, const std::vector<UniformSetting>& settings, int width,
                                         int height, bool ignore_unknown_material);

// Whether `info` declares a uniform of that name.
bool declares_uniform(const ShaderInfo& info, const std::string& name);

}  // namespace qs
