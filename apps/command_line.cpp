#include "apps/command_line.h"

#include <cmath>
#include <cstdio>

#include "files/output_file.h"
#include "images/image_io.h"
#include "interpreter/glsl_program.h"
#include "render/glsl_shaders.h"
#include "render/memory_plan.h"
#include "scenes/texture_files.h"

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

void add_glsl_options(CLI::App& cmd, std::string& fragment, std::string& vertex, bool& compile) {
    cmd.add_option("--glsl", fragment,
                   "draw every object with this GLSL fragment shader, run as written\n"
                   "(docs/glsl.md); its vertex shader is --vert's, or one written for it")
        ->option_text("FRAG");
    cmd.add_option("--vert", vertex, "the GLSL vertex shader for --glsl")->option_text("VERT");
    cmd.add_flag("--compile", compile, kCompileHelp);
}

const Program* use_glsl_options(const std::string& fragment, const std::string& vertex, bool compile, std::string& shader,
                                const std::vector<ShadeRequest>& shading) {
    if (fragment.empty()) {
        if (!vertex.empty()) throw UsageError("--vert: give the fragment shader with --glsl");
        return nullptr;
    }
    if (!shader.empty()) throw UsageError("--glsl and --shader: give one shader to draw with");
    const GlslShader s = load_glsl_shader(fragment, vertex.empty() ? std::nullopt : std::optional<fs::path>(vertex),
                                          glsl_way(compile), shading);
    for (const std::string& w : s.warnings) std::fprintf(stderr, "quadshade: %s\n", w.c_str());
    shader = std::string(s.program->info().name);
    return s.program;
}

void warn_after_render(const Program* program) {
    const auto* glsl = dynamic_cast<const interpreter::GlslProgram*>(program);
    if (!glsl) return;
    const std::string name(program->info().name);
    if (glsl->reached_loop_limit()) {
        std::fprintf(stderr, "quadshade: warning: %s: a loop ran 65535 iterations and was left there, as llvmpipe leaves it\n",
                     name.c_str());
    }
    if (glsl->compiled_blocks_failed()) {
        std::fprintf(stderr, "quadshade: warning: %s: LLVM did not compile its float arithmetic; the interpreter ran it\n",
                     name.c_str());
    }
}

std::uint64_t memory_limit(const std::string& option) {
    if (option.empty()) return available_memory();
    try {
        return parse_byte_size(option);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--memory-limit: ") + e.what());
    }
}

std::uint64_t load_image_library_for(const Scene& scene) {
    if (!needs_image_library(scene)) return 0;
    const std::uint64_t before = resident_bytes();
    load_image_library();
    const std::uint64_t after = resident_bytes();
    return after > before ? after - before : 0;
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
