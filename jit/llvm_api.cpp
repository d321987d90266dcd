#include "jit/llvm_api.h"

#include <dlfcn.h>

#include <mutex>
#include <string>

#include "jit/compiled_blocks.h"

namespace qs::jit {

namespace {

#define QS_STRING(x) #x
#define QS_NAME(x) QS_STRING(x)  // the name a macro such as LLVM_NATIVE_TARGET stands for

// The library by its soname (libllvm15's, the one Mesa's llvmpipe loads too), else where the
// build found it.
void* open_library() {
    void* library = dlopen(QUADSHADE_LLVM_SONAME, RTLD_NOW | RTLD_LOCAL);
    if (!library) library = dlopen(QUADSHADE_LLVM_PATH, RTLD_NOW | RTLD_LOCAL);
    return library;
}

}  // namespace

const LlvmApi& llvm() {
    static std::once_flag once;
    static LlvmApi api;
    static std::string error;
    std::call_once(once, [] {
        void* library = open_library();
        if (!library) {
            const char* why = dlerror();
            error = std::string("cannot load ") + QUADSHADE_LLVM_SONAME + (why ? std::string(": ") + why : std::string());
            return;
        }
        LlvmApi loaded;
#define QS_LLVM_LOAD(name)                                                                 \
    loaded.name = reinterpret_cast<decltype(&::name)>(dlsym(library, QS_NAME(name)));       \
    if (!loaded.name && error.empty()) error = std::string(QUADSHADE_LLVM_SONAME) + " has no " QS_NAME(name);
        QS_LLVM_FUNCTIONS(QS_LLVM_LOAD)
#undef QS_LLVM_LOAD
        if (!error.empty()) return;
        loaded.LLVM_NATIVE_TARGETINFO();
        loaded.LLVM_NATIVE_TARGET();
        loaded.LLVM_NATIVE_TARGETMC();
        loaded.LLVM_NATIVE_ASMPRINTER();
        api = loaded;
    });
    if (!error.empty()) throw JitError(error);
    return api;
}

}  // namespace qs::jit
