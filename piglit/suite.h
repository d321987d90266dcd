#pragma once
// Many shader_tests in one process, several at a time, as `piglit run` runs shader_runner on a
// test list: the files found, run in parallel, each result handed over in the files' order as
// soon as it and those before it are done.

#include <filesystem>
#include <functional>
#include <vector>

#include "piglit/run_test.h"
#include "piglit/test_result.h"

namespace qs::piglit {

// The .shader_test files a path names: the file itself, or every one under a folder (searched
// recursively), sorted, each once. Throws std::runtime_error for a path that does not exist.
std::vector<std::filesystem::path> find_shader_tests(const std::vector<std::filesystem::path>& paths);

struct SuiteOptions {
    RunOptions run;
    int jobs = 0;  // tests at once; 0: one per core
};

// Runs `files`; `done` is called once per file, in their order, from the calling thread's
// point of view serially (under a lock).
std::vector<TestResult> run_shader_tests(const std::vector<std::filesystem::path>& files, const SuiteOptions& options,
                                         const std::function<void(const TestResult&)>& done = {});

}  // namespace qs::piglit
