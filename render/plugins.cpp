#include "render/plugins.h"

#include <dlfcn.h>

#include <set>
#include <stdexcept>
#include <string>

#include "shading/catalogue.h"

namespace qs {

std::vector<std::string> load_plugin(const std::filesystem::path& plugin) {
    std::error_code ec;
    const std::filesystem::path path = std::filesystem::canonical(plugin, ec);
    if (ec) throw std::runtime_error(plugin.string() + ": cannot open the plugin: " + ec.message());
    if (!std::filesystem::is_regular_file(path, ec)) {
        throw std::runtime_error(plugin.string() + ": the plugin is not a file");
    }
    static std::set<std::filesystem::path> loaded;  // a second --plugin of the same file adds nothing
    if (!loaded.insert(path).second) return {};
    registration::begin_plugin(path);
    // RTLD_LOCAL: two plugins' own symbols never meet; RTLD_NOW: a missing symbol is reported
    // here, not in the middle of a frame.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    registration::PluginResult result = registration::end_plugin();
    if (!handle) {
        const char* why = dlerror();
        throw std::runtime_error(plugin.string() + ": cannot load the plugin: " + (why ? why : "unknown error"));
    }
    if (!result.problems.empty()) {
        std::string message = plugin.string() + ": ";
        for (std::size_t i = 0; i < result.problems.size(); ++i) message += (i ? "; " : "") + result.problems[i];
        throw std::runtime_error(message);
    }
    if (result.added == 0) {
        throw std::runtime_error(plugin.string() +
                                 ": the plugin registers no shader (QUADSHADE_SHADERS in its sources, built with "
                                 "quadshade_add_shader_plugin)");
    }
    if (result.unoptimised) {
        return {plugin.string() + ": compiled without optimisation, its shaders render several times slower (its "
                "pixels are the same): configure it with -DCMAKE_BUILD_TYPE=Release, or with none"};
    }
    return {};
}

}  // namespace qs
