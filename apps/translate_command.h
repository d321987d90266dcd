#pragma once
// `quadshade translate FRAG [--vert VERT] -o DIR`: a user's GLSL written as a C++ translation
// (frontend/cpp_writer.h) with a CMake project that builds it as a plugin.

#include <string>

#include <CLI/CLI.hpp>

namespace qs::app {

struct TranslateArgs {
    std::string fragment, vertex, output, name;
};

void add_translate_options(CLI::App& cmd, TranslateArgs& a);
int cmd_translate(const TranslateArgs& a);

}  // namespace qs::app
