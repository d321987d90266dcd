#pragma once
// What the quadshade subcommands share: exit codes, the usage error, the checks every output
// gets, and the option helpers built on CLI11.

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "files/output_file.h"
#include "render/compiled_glsl.h"
#include "scenes/scene.h"
#include "shading/program.h"

namespace qs::app {

// 0 is success; 3: `compare` found differences over its thresholds, a `check` case missed its
// bar, or a `test` case failed.
inline constexpr int kExitInput = 1, kExitUsage = 2, kExitDifferent = 3;

// Bad usage (exit 2): an option combination or value the command cannot honour.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The file system entry `p` names: its folder resolved (symlinks and all), its own name kept. An
// output replaces that entry (written beside it, renamed over it), never what a link there points to.
std::filesystem::path resolved(const std::filesystem::path& p);

// Refuses (UsageError) an output that cannot be written where it is named (a folder, a device,
// a stream unless `streams` allows one: files/output_file.h) or is one of `inputs` (the scene's
// own files, a suite's...). Cheap for a million frames: only an output named like an input has
// its folder resolved.
void check_output(const std::filesystem::path& output, const std::vector<std::filesystem::path>& inputs,
                  const char* option, Streams streams = Streams::Refused);
void check_output(const std::filesystem::path& output, const InputFiles& inputs, const char* option,
                  Streams streams = Streams::Refused);

// A CLI11 check that a number is finite (CLI11 reads "nan", "inf" and 1e400 as numbers).
extern const CLI::Validator kFinite;

// An option whose value is one of `choices`, with the old command line's messages.
template <class T>
CLI::Option* add_choice(CLI::App& app, const std::string& name, T& target, std::vector<std::pair<std::string, T>> choices,
                        const std::string& text, const std::string& help) {
    return app
        .add_option_function<std::string>(
            name,
            [&target, choices, name](const std::string& v) {
                std::string names;
                for (const auto& [n, value] : choices) {
                    if (n == v) {
                        target = value;
                        return;
                    }
                    names += (names.empty() ? "" : " | ") + n;
                }
                throw CLI::ValidationError(name, "expected " + names + ", got '" + v + "'");
            },
            help)
        ->option_text(text);
}

// --plugin, repeatable: shared libraries whose shaders join the catalogue (render/plugins.h),
// loaded in order once the command line has parsed.
void add_plugin_option(CLI::App& cmd, std::vector<std::string>& plugins);

// --glsl FRAG and --vert VERT: a user's GLSL drawn on every object (render/glsl_shaders.h).
// --compile: run it as its compiled C++ translation (render/compiled_glsl.h).
void add_glsl_options(CLI::App& cmd, std::string& fragment, std::string& vertex, bool& compile);
// What --compile says, for every command that takes GLSL files.
inline constexpr const char* kCompileHelp =
    "run the GLSL as its C++ translation, compiled now where the plugin cache lacks it\n"
    "(once cached it is used without --compile; docs/glsl.md)";
// The way GLSL files run: the cached translation where there is one, compiled first with --compile.
inline GlslWay glsl_way(bool compile) { return compile ? GlslWay::Compile : GlslWay::Cached; }
// Compiles the shaders --glsl and --vert name, if any, and names their program in `shader`
// (refusing --shader beside --glsl); returns it, or nullptr. Prints glslang's warnings. The
// compiled translation, where it is used, shades what `shading` asks (all ways without it).
const Program* use_glsl_options(const std::string& fragment, const std::string& vertex, bool compile, std::string& shader,
                                const std::vector<ShadeRequest>& shading = {});
// The warnings, once each, that `program` (a GLSL program, or nullptr) left a loop at llvmpipe's
// limit, or ran interpreted where LLVM did not compile its float arithmetic.
void warn_after_render(const Program* program);

// --memory-limit's bytes; empty: what the system has available.
std::uint64_t memory_limit(const std::string& option);

// Loads OpenImageIO when one of `scene`'s textures needs it (images/image_io.h), for a command
// that measures its memory from before it loaded the scene: returns the resident memory the
// loading added, which is the program's, not the command's.
std::uint64_t load_image_library_for(const Scene& scene);

// The names the options give these, for messages and image metadata.
const char* precision_name(Precision p);
const char* rule_name(Derivatives d);

}  // namespace qs::app
