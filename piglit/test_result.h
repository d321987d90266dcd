#pragma once
// What running one shader_test gives: piglit's result word, why (a skip's reason, a failure's
// message) and the probes that did not match.

#include <array>
#include <string>
#include <vector>

namespace qs::piglit {

// piglit's result words, in order of severity for a summary.
enum class Status { Pass, Warn, Fail, Crash, Skip };
const char* status_word(Status s);  // "pass", "warn", ...

// A probe whose pixels did not match: the first such pixel, with what was expected and seen
// (GL window coordinates, y up; values as 8-bit readback divided by 255).
struct ProbeMismatch {
    int line = 0;
    std::string command;
    int x = 0, y = 0;
    int components = 4;
    std::array<float, 4> expected{}, observed{};
    std::size_t pixels = 1;  // of the probe's pixels, how many did not match
    bool warn = false;       // probe warn: it warned, not failed
};

struct TestResult {
    std::string file;  // as given
    Status status = Status::Pass;
    // A skip's reason, short and without the test's own names ("extension GL_ARB_foo",
    // "command 'texture shadow2D'", "GLSL: gl_ClipVertex"), so that skips can be counted by it.
    std::string reason;
    std::string message;  // what happened, in full (compile errors, the failing line)
    std::vector<ProbeMismatch> probes;
    double seconds = 0.0;
};

}  // namespace qs::piglit
