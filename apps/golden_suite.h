#pragma once
// `quadshade test`: golden-image suites. A suite file (JSON, docs/golden-suites.md) lists cases:
// a scene rendered with given settings and compared with an expected image under a tolerance as
// OpenImageIO's idiff states one (a pixel fails above `fail`, the case fails when more than
// `fail_percent` of its pixels do; likewise `warn`). Cases run in parallel; a shard (K/N) runs
// every N-th case; each run can write a report fragment, and fragments merge into one report.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "render/scene_render.h"

namespace qs {

// Differences in 8-bit steps of the largest RGB channel difference (images are 8-bit RGB PNG, as
// `quadshade render -o FILE.png` writes them).
struct Tolerance {
    double fail = 1.0, fail_percent = 0.0;  // a pixel fails above `fail` steps; at most fail_percent % may
    double warn = 0.0, warn_percent = 0.0;
    std::optional<double> hard_fail;        // any pixel above this fails the case
};

struct SuiteCase {
    std::string name;
    std::filesystem::path scene, expected;  // resolved against the suite's folder
    FrameRequest request;                   // size, time, shader, rule, backend, precision, uniforms
    Tolerance tolerance;
};

struct Suite {
    std::filesystem::path file;
    std::string name;
    std::vector<SuiteCase> cases;
};

// Reads a suite file; throws std::runtime_error naming the file and the field of anything wrong.
Suite load_suite(const std::filesystem::path& file);

enum class CaseStatus { Pass, Warn, Fail, Updated };
const char* status_name(CaseStatus s);  // PASS, WARN, FAIL, UPDATED

struct CaseResult {
    std::string name;
    std::size_t index = 0;  // the case's place in the suite
    CaseStatus status = CaseStatus::Fail;
    std::string message;  // what failed or warned, or the error
    long long pixels = 0, failing = 0, warning = 0;
    int max_steps = 0;
    double seconds = 0.0;
    std::filesystem::path expected, actual, diff;  // actual and diff: kept beside expected on failure
};

struct SuiteRun {
    std::string suite;  // the suite's name
    int shard = 1, shards = 1;  // shard 0: the merge of shards 1..shards
    std::size_t suite_cases = 0;  // in the whole suite, every shard
    std::vector<CaseResult> results;
};

struct SuiteRequest {
    std::filesystem::path suite;
    bool update = false;  // re-bless: write each case's image as its expected image
    int jobs = 0;         // cases rendered at once; 0: one per core
    int shard = 1, shards = 1;
};

// Runs the suite's cases of the shard, printing progress and a summary (stdout).
SuiteRun run_suite(const SuiteRequest& request);

// Report fragments (JSON) and their merge; the JUnit XML and HTML reports of a run.
void write_fragment(const SuiteRun& run, const std::filesystem::path& file);
// Throws std::runtime_error naming the file when fragments are unreadable, of other suites, or
// do not hold every shard 1..N exactly once.
SuiteRun merge_fragments(const std::vector<std::filesystem::path>& files);
void write_junit(const SuiteRun& run, const std::filesystem::path& file);
void write_html(const SuiteRun& run, const std::filesystem::path& folder);
// Prints the summary line and the failures; returns 0, or 3 when a case failed.
int summarize(const SuiteRun& run);

}  // namespace qs
