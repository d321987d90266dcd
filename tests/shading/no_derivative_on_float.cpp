// Must fail to compile: plain float has no neighbouring fragments (see tests/CMakeLists.txt).
#include "shading/glsl.h"

float slope(float v) { return qs::dFdx(v); }
