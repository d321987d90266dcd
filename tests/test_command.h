#pragma once
// Runs a command line of the project's executables through the shell, as a user types it.

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace qs::test {

// The command's exit code (-1 when a signal ended it); its stderr goes to err_file when one is
// given (and into *err when asked), to /dev/null otherwise.
inline int run(const std::string& cmd, std::string* err = nullptr, const std::filesystem::path& err_file = {}) {
    const int status = std::system((cmd + " 2> " + (err_file.empty() ? std::string("/dev/null") : err_file.string())).c_str());
    if (err && !err_file.empty()) {
        std::ifstream in(err_file);
        err->assign(std::istreambuf_iterator<char>(in), {});
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace qs::test
