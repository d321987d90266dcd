#pragma once
// Modules: shared libraries of quadshade's own, each the one wrapper of an outside library that
// only some commands need (OpenImageIO: images/openimageio_library.cpp; Embree:
// raycast/embree_scene.cpp). The executables do not link those libraries: a module is loaded the
// first time a call needs it, so that `quadshade --help` or a listing never pays for OpenImageIO's
// dozens of dependencies, nor a rasterized frame for Embree (docs/results.md, "The cost of one
// call"). Modules sit in lib/quadshade beside the executable's bin/, in the build tree as in an
// installation, and reach the program only through the entry point they export.

#include <stdexcept>

namespace qs {

class ModuleError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct Module {
    const char* name;     // libquadshade-NAME.so
    const char* library;  // what it wraps, for messages: "OpenImageIO"
    const char* purpose;  // what it is needed for, for messages: "to read and write images"
    const char* entry;    // the extern "C" function it exports
};

// The module's entry point, the module loaded on the first call for it (it then stays loaded).
// Throws ModuleError naming the library, the module file and the loader's reason when the module
// or one of the libraries it links cannot be loaded.
void* load_module(const Module& module);

}  // namespace qs
