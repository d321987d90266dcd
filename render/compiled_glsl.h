#pragma once
// A user's GLSL run compiled: the front end's C++ translation (frontend/cpp_writer.h) built into a
// plugin with the compiler and flags quadshade was built with, cached, and loaded.
//
// The cache is $XDG_CACHE_HOME/quadshade/plugins (else ~/.cache/quadshade/plugins): one folder per
// plugin, named by a hash of everything that decides it (the translation and its GLSL, quadshade's
// version and shading headers, the compiler and its flags). A plugin is compiled in a fresh
// private folder and renamed into place whole, so two runs at once never see half of one: the
// second to finish keeps the first's. A cache that cannot be used (unwritable, full, a plugin that
// does not load, a compiler that fails) gives the interpreter instead, with one warning.

#include <optional>
#include <string>

#include "frontend/compile.h"
#include "shading/program.h"
#include "shading/shade_choice.h"

namespace qs {

enum class GlslWay {
    Interpret,  // the interpreter only
    Cached,     // the compiled translation where the cache has it, else the interpreter
    Compile,    // the compiled translation, compiled now where the cache lacks it (--compile)
};

// The compiled translation of the pair, registered in the catalogue as `name` made a shader's
// name ("marble.frag (2)" as "marble_frag_2"), or nullptr where
// the cache lacks it (way Cached), the writer does not translate the shader, or the cache is
// unusable (with a warning on stderr, once per process). Says on stderr when it compiles and how
// long it took. The plugin shades in `modes` (ProgramOf's compiled_modes): a cached one that
// shades in them and more serves too; one is compiled for `modes` only, which for one render's
// modes takes a few times less than for all of them.
const Program* compiled_glsl_program(const frontend::GlslSource& fragment, const std::optional<frontend::GlslSource>& vertex,
                                     const std::string& name, GlslWay way, ShadeModes modes = {});

// The cache's folder: $XDG_CACHE_HOME/quadshade/plugins, else $HOME/.cache/quadshade/plugins.
std::optional<std::string> plugin_cache_dir();

}  // namespace qs
