#pragma once
// GLSL source with every float literal written as the float Mesa reads it. Mesa's compiler reads
// a float literal with strtof and folds constant expressions in float; glslang keeps float
// constants as doubles and folds them in double, so `3.0 * G4` (G4 a const float) would round
// from the exact decimal rather than from G4's float. Given each literal's float value exactly
// (17 significant digits: strtod reads back the same double, which is the float), glslang's
// constants are Mesa's, and one folded operation on them rounds as Mesa's does (a double holds
// a float +, -, * or / exactly enough that rounding it to float rounds once). A chain of folded
// operations keeps its intermediate values in double and may still differ by an ulp.

#include <string>

namespace qs::frontend {

// `text` with its float literals rewritten so; comments, integers (hexadecimal too) and double
// literals (`lf`) as they are. Lines and their count are kept.
std::string float_literals_as_float(const std::string& text);

}  // namespace qs::frontend
