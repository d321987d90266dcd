#pragma once
// quadshade study: its options and the command (study/study.h does the work).

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "study/study.h"

namespace qs::app {

struct StudyArgs {
    study::Request request;
    std::string scene, output;
    std::string glsl, vertex_glsl;  // --glsl FRAG, --vert VERT
    std::vector<std::string> plugins;
    bool no_reference = false, no_derivative_maps = false;
};

void add_study_options(CLI::App& cmd, StudyArgs& a);
int cmd_study(StudyArgs& a);

}  // namespace qs::app
