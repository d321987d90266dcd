#pragma once
// A fragment shader's text with a user's expression placed where main ends (DerivativeProbe,
// compile_options.h), for glslang to parse as main's last statement. Internal to frontend/.
//
// The expression is the user's text, so it goes in only as one expression: printable characters,
// no ';', '{', '}' (a statement or a block of its own), no '#' or '\' (a directive, a line
// continuation), no comment, and parentheses that close where they open. Put between "(" and
// ");", glslang then reads it inside a parenthesised expression, which only an expression can
// fill: anything else is a syntax error, reported as glslang words it.

#include <string>
#include <vector>

#include "frontend/compile_options.h"

namespace qs::frontend {

// Where the probe's text goes among the strings glslang parses: the shader up to main's closing
// brace, the probe's statement, then the rest. Nodes at loc.string == kProbeString are the probe's.
inline constexpr int kProbeString = 1;

struct ProbedSource {
    std::vector<std::string> strings;  // the three strings, in order
    std::vector<std::string> names;    // for messages: the file, the option, the file
};

// `preprocessed` (the fragment shader as glslang's preprocessor writes it: no comments, macros
// expanded, its lines kept) split at main's closing brace around the probe's statement. Throws
// GlslError naming the option for an expression that could be more than an expression, naming
// `file` for a shader whose main has no body.
ProbedSource probed_source(const std::string& file, const std::string& preprocessed, const DerivativeProbe& probe);

// glslang's messages about the probe's string ("OPTION:1:COL: error: ...") worded as the option
// and the expression ("OPTION "EXPRESSION": error: ..."); other lines as they are.
std::string probe_messages(const std::string& messages, const DerivativeProbe& probe);

}  // namespace qs::frontend
