#include "render/glsl_shaders.h"

#include <map>
#include <memory>
#include <mutex>

#include "frontend/compile.h"
#include "interpreter/glsl_program.h"
#include "shading/catalogue.h"
#include "shading/glsl_export.h"

namespace qs {

GlslShader load_glsl_shader(const std::filesystem::path& fragment, const std::optional<std::filesystem::path>& vertex,
                            GlslWay way, const std::vector<ShadeRequest>& shading) {
    static std::mutex mutex;
    static std::map<std::pair<std::string, std::string>, GlslShader> loaded;
    const std::lock_guard lock(mutex);
    std::error_code ec;
    const auto canonical = [&](const std::filesystem::path& p) {
        const std::filesystem::path c = std::filesystem::weakly_canonical(p, ec);
        return ec ? p.string() : c.string();
    };
    const auto key = std::make_pair(canonical(fragment), vertex ? canonical(*vertex) : std::string());
    if (auto it = loaded.find(key); it != loaded.end()) return it->second;

    const frontend::GlslSource f = frontend::read_glsl_file(fragment);
    std::optional<frontend::GlslSource> v;
    if (vertex) v = frontend::read_glsl_file(*vertex);
    frontend::CompiledProgram compiled = frontend::compile_glsl(f, v);
    std::string name = fragment.filename().string();
    for (int n = 2; find_program(name); ++n) name = fragment.filename().string() + " (" + std::to_string(n) + ")";
    std::vector<std::string> warnings = compiled.warnings;
    ShadeModes modes;
    if (!shading.empty()) modes.bits = 0;
    for (const ShadeRequest& r : shading) {
        try {
            modes.bits |= modes_for(Needs{.derivatives = compiled.program.fragment.derivatives}, r).bits;
        } catch (const UnsupportedRequest&) {
            // refused by the render itself, with its own message
        }
    }
    if (modes.bits == 0) modes = ShadeModes{};
    if (const Program* p = compiled_glsl_program(f, v, name, way, modes)) {
        GlslShader shader{p, std::move(warnings)};
        loaded.emplace(key, shader);
        return shader;
    }
    std::string vertex_text = compiled.vertex.text;
    auto program = std::make_unique<interpreter::GlslProgram>(name, std::move(compiled));
    const Program& p = add_compiled_program(std::move(program), kGlslCollection, std::move(vertex_text), f.text);
    GlslShader shader{&p, std::move(warnings)};
    loaded.emplace(key, shader);
    return shader;
}

std::string interpreted_twin(const std::string& name) {
    const std::string twin = name + ".interpreted";
    if (find_program(twin)) return twin;
    const Program* translation = find_program(name);
    if (!translation) throw std::invalid_argument("no shader '" + name + "' in the catalogue");
    const std::string vertex = glsl_source(*translation, true), fragment = glsl_source(*translation, false);
    frontend::CompiledProgram compiled = frontend::compile_glsl({name + ".frag", fragment}, frontend::GlslSource{name + ".vert", vertex});
    auto program = std::make_unique<interpreter::GlslProgram>(twin, std::move(compiled));
    program->adopt_check_bounds(translation->info().check_bounds);
    add_compiled_program(std::move(program), kGlslCollection, vertex, fragment);
    return twin;
}

}  // namespace qs
