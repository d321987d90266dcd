// Fuzz target: a user's fragment shader, read by the GLSL front end (its preprocessing bounds,
// glslang, the lowering to the interpreter's code) and written as C++ by the translation writer.
// A GlslError naming the file is the expected way out of either; anything else (a crash, a
// sanitizer report, another exception, an error that does not say which file) is a bug.
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>

#include "frontend/compile.h"
#include "frontend/cpp_writer.h"
#include "frontend/glsl_error.h"
#include "fuzz/fuzz_check.h"

namespace {

bool names_the_file(const qs::frontend::GlslError& e) {
    const bool named = std::string_view(e.what()).find("fuzz.frag") != std::string_view::npos;
    if (!named) std::fprintf(stderr, "the message: %s\n", e.what());
    return named;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const qs::frontend::GlslSource fragment{"fuzz.frag", std::string(reinterpret_cast<const char*>(data), size)};
    try {
        const qs::frontend::CompiledProgram program = qs::frontend::compile_glsl(fragment, std::nullopt);
        FUZZ_CHECK(!program.program.fragment.code.empty());
    } catch (const qs::frontend::GlslError& e) {
        FUZZ_CHECK(names_the_file(e));
        return 0;
    }
    // What the interpreter runs, the writer writes or refuses with the line and why.
    try {
        const qs::frontend::Translation t = qs::frontend::translate_glsl(fragment, std::nullopt, "fuzz");
        FUZZ_CHECK(!t.header.empty());
    } catch (const qs::frontend::GlslError& e) {
        FUZZ_CHECK(names_the_file(e));
    }
    return 0;
}
