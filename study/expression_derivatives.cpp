#include "study/expression_derivatives.h"

#include <map>
#include <memory>
#include <stdexcept>

#include "frontend/compile.h"
#include "interpreter/glsl_program.h"
#include "shading/catalogue.h"
#include "shading/glsl_export.h"

namespace qs::study {

std::vector<DerivativeMap> expression_maps(const std::string& shader, const std::vector<std::string>& expressions,
                                           const std::string& option) {
    if (expressions.empty()) return {};
    const Program* program = find_program(shader);
    if (!program) throw std::runtime_error("unknown shader '" + shader + "'");
    const std::string file = shader + (shader.ends_with(".frag") ? "" : ".frag");
    const frontend::GlslSource fragment{file, glsl_source(*program, false)};
    const frontend::GlslSource vertex{shader + ".vert", glsl_source(*program, true)};
    // The expressions' components, by program name: each compiled once per process.
    static std::map<std::string, int> components;
    std::vector<DerivativeMap> maps;
    for (std::size_t i = 0; i < expressions.size(); ++i) {
        const std::string& e = expressions[i];
        const std::string name = shader + " d(" + e + ")", stem = "d-expression-" + std::to_string(i + 1);
        auto compile = [&](int component, const std::string& program_name) {
            frontend::CompileOptions options;
            options.derivative_probe = frontend::DerivativeProbe{e, component, option};
            frontend::CompiledProgram compiled;
            try {
                compiled = frontend::compile_glsl(fragment, vertex, options);
            } catch (const frontend::GlslError& error) {
                const std::string what = error.what();
                // About the expression (it names the option): the user's to mend; else the shader's.
                if (what.find(option) != std::string::npos) throw std::invalid_argument(what);
                throw std::runtime_error(shader + ": its GLSL cannot be evaluated with " + option + ": " + what);
            }
            const int n = compiled.probe_components;
            add_compiled_program(std::make_unique<interpreter::GlslProgram>(program_name, std::move(compiled)),
                                 "derivative maps", vertex.text, fragment.text);
            return n;
        };
        if (!components.count(name)) {
            // The first component tells how many there are; a vector's maps are named by component.
            const std::string first = name + ".x";
            const int n = compile(0, first);
            for (int c = 1; c < n; ++c) compile(c, name + "." + "xyzw"[c]);
            components[name] = n;
        }
        const int n = components[name];
        for (int c = 0; c < n; ++c) {
            const std::string suffix = n == 1 ? "" : std::string(".") + "xyzw"[c];
            maps.push_back({n == 1 ? e : "(" + e + ")" + suffix, stem + suffix, name + "." + "xyzw"[c]});
        }
    }
    return maps;
}

}  // namespace qs::study
