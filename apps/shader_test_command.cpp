#include "apps/shader_test_command.h"

#include <chrono>
#include <cstdio>

#include "apps/command_line.h"
#include "piglit/report.h"

namespace qs::app {

void add_shader_test_options(CLI::App& cmd, ShaderTestArgs& a) {
    cmd.add_option("paths", a.paths, "shader_test files, or folders to search for them")->required()->option_text("FILE|DIR...");
    add_choice<Derivatives>(cmd, "--derivatives", a.suite.run.derivatives,
                            {{"fine", Derivatives::Fine},
                             {"coarse-lower", Derivatives::CoarseLower},
                             {"coarse-upper", Derivatives::CoarseUpper},
                             {"analytic", Derivatives::Analytic}},
                            "RULE", "dFdx/dFdy: fine (llvmpipe, default), coarse-lower (softpipe), coarse-upper, analytic");
    add_choice<Backend>(cmd, "--backend", a.suite.run.backend, {{"raster", Backend::Rasterizer}, {"raycast", Backend::RayCaster}},
                        "B", "raster (default) or raycast");
    cmd.add_option("--jobs", a.suite.jobs, "tests run at once (default: one per core)")->check(CLI::Range(1, 1024))->option_text("N");
    cmd.add_option("--junit", a.junit, "write a JUnit XML report")->option_text("FILE");
    cmd.add_flag("--quiet", a.quiet, "print only the tests that fail, warn or crash, and the summary");
}

int cmd_shader_test(const ShaderTestArgs& a) {
    std::vector<std::filesystem::path> paths(a.paths.begin(), a.paths.end());
    if (!a.junit.empty()) check_output(a.junit, paths, "--junit");
    const std::vector<std::filesystem::path> files = piglit::find_shader_tests(paths);
    if (files.empty()) throw UsageError("shader-test: no .shader_test file in " + a.paths.front());
    const auto start = std::chrono::steady_clock::now();
    const std::vector<piglit::TestResult> results = piglit::run_shader_tests(files, a.suite, [&](const piglit::TestResult& r) {
        if (a.quiet && (r.status == piglit::Status::Pass || r.status == piglit::Status::Skip)) return;
        piglit::print_result(stdout, r);
        std::fflush(stdout);
    });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    piglit::print_summary(stdout, results, seconds);
    if (!a.junit.empty()) piglit::write_junit(a.junit, results);
    for (const piglit::TestResult& r : results) {
        if (r.status == piglit::Status::Fail || r.status == piglit::Status::Crash) return kExitDifferent;
    }
    return 0;
}

}  // namespace qs::app
