#pragma once
// Everything a shader translation needs: the number types and the GLSL vocabulary over them.
// Translations live in namespace qs::shaders and write `using namespace qs::glsl;`.

#include "shading/glsl/builtins.h"
#include "shading/glsl/control.h"
#include "shading/glsl/mat.h"
#include "shading/glsl/table.h"
#include "shading/glsl/texture.h"
#include "shading/glsl/uniform.h"
#include "shading/glsl/vec.h"
#include "shading/number/number.h"
