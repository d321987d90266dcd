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
    bool compile_glsl = false;      // --compile
    std::vector<std::string> plugins;
    bool no_reference = false, no_derivative_maps = false;
    std::vector<std::string> frames;  // --frames: N or A:B each
    std::string memory_limit;         // --memory-limit; empty: what the system has available
    std::string study_file;         // --study FILE: one study per line
    const CLI::App* app = nullptr;  // what parsed these (which options were given)
};

// The options of `quadshade study`; those of a study file's line when `line` (no -o, no --study).
void add_study_options(CLI::App& cmd, StudyArgs& a, bool line = false);
int cmd_study(StudyArgs& a);

}  // namespace qs::app
