#pragma once
// glslang's preprocessor expands macros without a bound: forty lines of `#define A1 (A0+A0)` ask
// for 2^40 tokens and take the machine's memory before any message. A shader that defines macros
// is therefore preprocessed once in a child process under a limit of memory and CPU time, and
// refused by name when its expansion does not fit, before the parse that keeps its AST. Both
// preprocess with `preprocess` below.

#include <string>

namespace qs::frontend {

// The most text a shader's macros may expand to, and the time and memory its preprocessing may take.
inline constexpr std::size_t kMaxPreprocessedBytes = 16u << 20;
inline constexpr int kMaxPreprocessSeconds = 3;
inline constexpr std::size_t kMaxPreprocessMemory = std::size_t(512) << 20;

// Throws GlslError naming `file` when `text` (a stage's source as glslang will parse it) expands
// past the bounds above; returns at once for a text without `#define`.
void check_macro_expansion(const std::string& file, const std::string& text, bool fragment);

// glslang's preprocessor alone on a stage's `text`: comments gone, macros expanded, lines kept.
// `ok` is false when it fails, and `log` says why in glslang's words.
struct Preprocessed {
    bool ok = false;
    std::string text, log;
};
Preprocessed preprocess(const std::string& file, const std::string& text, bool fragment);

}  // namespace qs::frontend
