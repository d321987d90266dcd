#pragma once
// quadshade bake (a shader into a mesh's UV atlas, with its height and normal maps) and
// quadshade bake-volume (a shader on an N^3 grid into a 3D texture): their options and commands.

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "render/normal_bake.h"
#include "shading/shade_mode.h"

namespace qs::app {

struct VolumeArgs {
    std::string shader, output, scene;
    std::string glsl, vertex_glsl;  // --glsl FRAG, --vert VERT
    bool compile_glsl = false;      // --compile
    int size = 32;
    std::optional<double> time;
    std::vector<std::string> uniforms, plugins;
    Derivatives derivatives = Derivatives::Fine;
    int threads = 0;
    bool allow_outside = false;
};

void add_volume_options(CLI::App& cmd, VolumeArgs& a);
int cmd_bake_volume(VolumeArgs a);

struct BakeArgs {
    std::string mesh, shader, output;
    std::string glsl, vertex_glsl;  // --glsl FRAG, --vert VERT
    bool compile_glsl = false;      // --compile
    int size = 1024;
    std::vector<std::string> maps{"color"};
    int skirt = 0;
    std::optional<double> time;
    std::vector<std::string> uniforms, plugins;
    Derivatives derivatives = Derivatives::Fine;
    int threads = 0;
    bool allow_outside = false;
    // The normal map (--maps normal): how, and the finite differences' step.
    CLI::Option* normals_option = nullptr;
    NormalMethod normals = NormalMethod::Analytic;
    CLI::Option* precision_option = nullptr;
    Precision normal_precision = Precision::Float;
    std::optional<double> normal_step;
    std::string memory_limit;  // empty: what the system has available
};

void add_bake_options(CLI::App& cmd, BakeArgs& a);
int cmd_bake(BakeArgs a);

}  // namespace qs::app
