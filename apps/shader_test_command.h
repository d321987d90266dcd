#pragma once
// quadshade shader-test: piglit's .shader_test files run with quadshade as the GL driver
// (piglit/): its options and the command.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "piglit/suite.h"

namespace qs::app {

struct ShaderTestArgs {
    std::vector<std::string> paths;
    piglit::SuiteOptions suite;
    std::string junit;
    bool quiet = false;  // only the tests that did not pass or skip, and the summary
};

void add_shader_test_options(CLI::App& cmd, ShaderTestArgs& a);
// Exit 0 when no test failed or crashed, 3 otherwise.
int cmd_shader_test(const ShaderTestArgs& a);

}  // namespace qs::app
