#include "piglit/suite.h"

#include <algorithm>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace qs::piglit {

std::vector<std::filesystem::path> find_shader_tests(const std::vector<std::filesystem::path>& paths) {
    std::vector<std::filesystem::path> files;
    for (const std::filesystem::path& p : paths) {
        std::error_code ec;
        if (std::filesystem::is_directory(p, ec)) {
            const auto options = std::filesystem::directory_options::skip_permission_denied;
            for (auto it = std::filesystem::recursive_directory_iterator(p, options, ec);
                 !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
                if (it->is_regular_file(ec) && it->path().extension() == ".shader_test") files.push_back(it->path());
            }
            if (ec) throw std::runtime_error(p.string() + ": cannot read the folder: " + ec.message());
        } else if (std::filesystem::exists(p, ec)) {
            files.push_back(p);
        } else {
            throw std::runtime_error(p.string() + ": no such file or folder");
        }
    }
    std::sort(files.begin(), files.end());
    files.erase(std::unique(files.begin(), files.end()), files.end());
    return files;
}

std::vector<TestResult> run_shader_tests(const std::vector<std::filesystem::path>& files, const SuiteOptions& options,
                                         const std::function<void(const TestResult&)>& done) {
    std::vector<std::optional<TestResult>> results(files.size());
    std::mutex lock;
    std::size_t next = 0;  // the first result not handed over yet
    const int jobs = options.jobs > 0 ? options.jobs : int(std::max(1u, std::thread::hardware_concurrency()));
    tbb::task_arena arena(jobs);
    arena.execute([&] {
        tbb::parallel_for(std::size_t(0), files.size(), [&](std::size_t i) {
            TestResult r = run_shader_test(files[i], options.run);
            const std::lock_guard hold(lock);
            results[i] = std::move(r);
            for (; next < results.size() && results[next]; ++next) {
                if (done) done(*results[next]);
            }
        });
    });
    std::vector<TestResult> out;
    out.reserve(results.size());
    for (std::optional<TestResult>& r : results) out.push_back(std::move(*r));
    return out;
}

}  // namespace qs::piglit
