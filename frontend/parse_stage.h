#pragma once
// One stage's GLSL parsed by glslang, as the lowering and the C++ writer read it. Internal to
// frontend/, like every file that includes glslang.

#include <memory>
#include <string>
#include <vector>

#include <glslang/Public/ShaderLang.h>

#include "frontend/compile.h"

namespace qs::frontend {

struct ParsedStage {
    std::vector<std::string> strings, names;  // what glslang parsed (kept alive with the shader)
    std::unique_ptr<glslang::TShader> shader;
    int version = 110;
};

// Parses `source` as `stage`, glslang's warnings appended to `warnings`; with `probe`, a fragment
// stage with the probe's expression as main's last statement (derivative_probe.h). Throws
// GlslError with glslang's messages for GLSL that does not compile.
ParsedStage parse(const GlslSource& source, EShLanguage stage, std::vector<std::string>& warnings,
                  const DerivativeProbe* probe = nullptr);

}  // namespace qs::frontend
