#pragma once
// Everything a shader translation needs: the number types and the GLSL vocabulary over them.
// Translations live in namespace qs::shaders and write `using namespace qs::glsl;`.

#include "glsl/builtins.h"
#include "glsl/mat.h"
#include "glsl/texture.h"
#include "glsl/vec.h"
#include "number/number.h"
