#include "frontend/bounded_preprocess.h"

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <fstream>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include "frontend/glsl_error.h"

namespace qs::frontend {

namespace {

// The child's whole address space may grow by kMaxPreprocessMemory over what it inherits.
void limit_child_resources() {
    std::size_t pages = 0;
    std::ifstream("/proc/self/statm") >> pages;
    const rlim_t address_space = rlim_t(pages) * rlim_t(sysconf(_SC_PAGESIZE)) + kMaxPreprocessMemory;
    const rlimit memory{address_space, address_space};
    setrlimit(RLIMIT_AS, &memory);
    const rlimit cpu{rlim_t(kMaxPreprocessSeconds), rlim_t(kMaxPreprocessSeconds + 1)};
    setrlimit(RLIMIT_CPU, &cpu);
}

// Runs in the child: the preprocessed size, or UINT64_MAX when glslang ran out of memory. A
// preprocessing error is left to the parse that follows, which reports it with the rest.
std::uint64_t preprocessed_size(const std::string& file, const std::string& text, bool fragment) {
    try {
        return preprocess(file, text, fragment).text.size();
    } catch (...) {
        return UINT64_MAX;
    }
}

}  // namespace

void check_macro_expansion(const std::string& file, const std::string& text, bool fragment) {
    if (text.find("define") == std::string::npos) return;
    int fds[2];
    if (pipe(fds) != 0) return;  // no bound to be had: glslang's parse runs as it would
    const pid_t child = fork();
    if (child < 0) {
        close(fds[0]), close(fds[1]);
        return;
    }
    if (child == 0) {
        close(fds[0]);
        limit_child_resources();
        const std::uint64_t size = preprocessed_size(file, text, fragment);
        [[maybe_unused]] const ssize_t written = write(fds[1], &size, sizeof size);
        _exit(0);
    }
    close(fds[1]);
    // The child's CPU limit ends it; the wall-clock bound is for a child that cannot run at all.
    pollfd ready{fds[0], POLLIN, 0};
    std::uint64_t size = 0;
    const bool answered = poll(&ready, 1, 6 * kMaxPreprocessSeconds * 1000) == 1 && read(fds[0], &size, sizeof size) == sizeof size;
    close(fds[0]);
    if (!answered) kill(child, SIGKILL);
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    const std::string bounds = "(at most " + std::to_string(kMaxPreprocessedBytes >> 20) + " MiB of text, " +
                               std::to_string(kMaxPreprocessMemory >> 20) + " MiB of memory and " +
                               std::to_string(kMaxPreprocessSeconds) + " s to expand)";
    if (!answered || size == UINT64_MAX) {
        throw GlslError(file + ": error: its macros expand past what a shader may take here " + bounds);
    }
    if (size > kMaxPreprocessedBytes) {
        throw GlslError(file + ": error: its macros expand to " + std::to_string(size) + " bytes of text, past what a shader may take here " + bounds);
    }
}

Preprocessed preprocess(const std::string& file, const std::string& text, bool fragment) {
    glslang::TShader shader(fragment ? EShLangFragment : EShLangVertex);
    const char* strings = text.c_str();
    const int length = int(text.size());
    const char* name = file.c_str();
    shader.setStringsWithLengthsAndNames(&strings, &length, &name, 1);
    Preprocessed p;
    glslang::TShader::ForbidIncluder no_includes;
    const auto messages = EShMessages(EShMsgDefault | EShMsgEnhanced);
    p.ok = shader.preprocess(GetDefaultResources(), 110, ENoProfile, false, false, messages, &p.text, no_includes);
    if (!p.ok) p.log = std::string(shader.getInfoLog()) + shader.getInfoDebugLog();
    return p;
}

}  // namespace qs::frontend
