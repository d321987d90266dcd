#include "apps/command_line.h"

#include <cmath>

#include "render/memory_plan.h"
#include "scenes/output_file.h"

namespace qs::app {

namespace fs = std::filesystem;

fs::path resolved(const fs::path& p) {
    std::error_code ec;
    const fs::path folder = fs::weakly_canonical(p.parent_path().empty() ? fs::path(".") : p.parent_path(), ec);
    return ec ? p.lexically_normal() : folder / p.filename();
}

void check_output(const fs::path& output, const std::vector<fs::path>& inputs, const char* option, Streams streams) {
    try {
        output_place(output, streams);
    } catch (const OutputError& e) {
        throw UsageError(std::string(option) + " " + e.what());
    }
    for (const fs::path& in : inputs) {
        if (output.filename() == in.filename() && resolved(output) == in) {
            throw UsageError(std::string(option) + " " + output.string() + ": is an input of this command; it would be overwritten");
        }
    }
}

void check_output(const fs::path& output, const InputFiles& inputs, const char* option, Streams streams) {
    check_output(output, std::vector<fs::path>{}, option, streams);
    if (inputs.contains(output)) {
        throw UsageError(std::string(option) + " " + output.string() +
                         ": is an input of this command; it would be overwritten");
    }
}

const CLI::Validator kFinite(
    [](std::string& s) {
        double v = 0.0;
        return CLI::detail::lexical_cast(s, v) && std::isfinite(v) ? std::string() : "expected a finite number, got '" + s + "'";
    },
    "FINITE");

void add_plugin_option(CLI::App& cmd, std::vector<std::string>& plugins) {
    cmd.add_option("--plugin", plugins, "load a shader plugin (quadshade_add_shader_plugin) first; repeatable")
        ->option_text("LIB")->allow_extra_args(false);
}

std::uint64_t memory_limit(const std::string& option) {
    if (option.empty()) return available_memory();
    try {
        return parse_byte_size(option);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--memory-limit: ") + e.what());
    }
}

const char* precision_name(Precision p) { return p == Precision::Double ? "double" : "float"; }

const char* rule_name(Derivatives d) {
    switch (d) {
        case Derivatives::None: return "none";
        case Derivatives::Fine: return "fine";
        case Derivatives::CoarseLower: return "coarse-lower";
        case Derivatives::CoarseUpper: return "coarse-upper";
        case Derivatives::Analytic: return "analytic";
    }
    return "?";
}

}  // namespace qs::app
