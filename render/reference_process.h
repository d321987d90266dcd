#pragma once
// quadshade-reference (reference/), run as a separate process beside the quadshade executable:
// the OSMesa reference shares nothing with the renderer but the scene file and the GLSL text.

#include <filesystem>
#include <string>
#include <vector>

namespace qs {

// The folder of the running executable. Throws std::runtime_error when it cannot be found.
std::filesystem::path executable_folder();

// quadshade-reference beside the running executable. Throws std::runtime_error naming `command`
// (the subcommand that needs it) when it is missing: a build without OSMesa.
std::filesystem::path reference_executable(const std::string& command);

// Runs `argv` (argv[0] a path) with its stdout and stderr going to `log`; returns its exit status
// (or 128 + the signal). Throws std::runtime_error when it cannot be started.
int run_process(const std::vector<std::string>& argv, const std::filesystem::path& log);

// A log's text, trailing newlines and spaces removed (for messages).
std::string read_text(const std::filesystem::path& file);

}  // namespace qs
