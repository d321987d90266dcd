#pragma once
// Users' shaders from outside this repository: a plugin is a shared library built with the
// installed package's quadshade_add_shader_plugin (cmake/quadshadeConfig.cmake.in) whose
// QUADSHADE_SHADERS lines add its shaders to the catalogue when it is loaded. Its GLSL files sit
// beside it.

#include <filesystem>
#include <string>
#include <vector>

namespace qs {

// Loads the plugin and adds its shaders to the catalogue; returns what the caller should warn
// about (a plugin compiled without optimisation: its shaders render several times slower).
// Throws std::runtime_error naming the file when it cannot be found or loaded, adds no shader,
// names a shader that is already in the catalogue or was built against other quadshade headers.
// The library stays loaded for the process's life (the catalogue points into it).
std::vector<std::string> load_plugin(const std::filesystem::path& plugin);

}  // namespace qs
