#pragma once
// Runs a program in a child process with an argument vector and an explicit environment (no
// shell, nothing inherited that is not passed), and collects what it writes. The throughput
// bench runs llvmpipe this way, once per vector width: Mesa reads LP_NATIVE_VECTOR_WIDTH once
// per process.

#include <cstdint>
#include <string>
#include <vector>

namespace qs::bench {

struct ChildOutput {
    int exit_code = -1;     // the child's exit status, or -1 when a signal ended it
    int signal = 0;         // the signal that ended it, 0 when it exited
    std::string out, err;   // everything it wrote to stdout and stderr
    double wall_seconds = 0.0;         // from before it was started until it was reaped
    double cpu_seconds = 0.0;          // its user and system time, on every core
    std::uint64_t peak_rss_bytes = 0;  // its peak resident memory (getrusage's ru_maxrss)
    bool ok() const { return exit_code == 0; }
    // "exit status 3", "killed by signal 6 (Aborted)".
    std::string status() const;
};

// Runs argv[0] (a path; PATH is not searched) with `argv` and exactly the environment `env`
// ("NAME=value" strings) and waits for it. Throws std::runtime_error when it cannot be started.
ChildOutput run_child(const std::vector<std::string>& argv, const std::vector<std::string>& env);

// This process's environment without the NAMEs that `set` gives, then `set` ("NAME=value" each).
std::vector<std::string> environment_with(const std::vector<std::string>& set);

// The path of the running executable (/proc/self/exe), for re-executing it.
std::string self_executable();

}  // namespace qs::bench
