#include "modules/module_loader.h"

#include <dlfcn.h>

#include <filesystem>
#include <string>

namespace qs {

namespace {

// lib/quadshade beside the running executable's bin/ (QUADSHADE_MODULE_DIR_FROM_BIN: the
// installation's relative path, which the build tree repeats).
std::filesystem::path module_folder() {
    std::error_code ec;
    const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) throw ModuleError("cannot find the running executable (/proc/self/exe): " + ec.message());
    return (executable.parent_path() / QUADSHADE_MODULE_DIR_FROM_BIN).lexically_normal();
}

}  // namespace

void* load_module(const Module& module) {
    const std::string file = (module_folder() / ("libquadshade-" + std::string(module.name) + ".so")).string();
    const std::string what = std::string(module.library) + " (needed " + module.purpose + ")";
    // RTLD_LOCAL: the wrapped library's symbols stay out of the program's and its plugins' way.
    // RTLD_LAZY: the wrapped library's own dependencies bind their functions at the first call,
    // as they do in a program that links them (binding all of OpenImageIO's at once took 5% more
    // CPU time); the module itself is linked to bind every symbol now (quadshade_add_module), so
    // that one missing from its library is reported here.
    void* handle = ::dlopen(file.c_str(), RTLD_LAZY | RTLD_LOCAL);
    if (!handle) {
        const char* why = ::dlerror();
        throw ModuleError("cannot load " + what + ": " + (why ? why : file + ": unknown error"));
    }
    void* entry = ::dlsym(handle, module.entry);
    if (!entry) throw ModuleError("cannot load " + what + ": " + file + " has no " + module.entry);
    return entry;
}

}  // namespace qs
