#pragma once
// `quadshade test`: golden-image suites. A suite file (JSON, docs/golden-suites.md) lists cases:
// a scene rendered with given settings and compared with an expected image under a tolerance as
// OpenImageIO's idiff states one (a pixel fails above `fail`, the case fails when more than
// `fail_percent` of its pixels do; likewise `warn`). Cases run in parallel; a shard (K/N) runs
// every N-th case; each run can write a report fragment, and fragments merge into one report
// (suite_reports.h).

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "files/output_file.h"
#include "render/compiled_glsl.h"
#include "render/scene_render.h"

namespace qs {

// What a suite or fragment file may hold, checked before anything is allocated for it.
inline constexpr std::uint64_t kSuiteFileBytes = std::uint64_t(256) << 20;
inline constexpr std::size_t kSuiteCases = 1000000;
inline constexpr int kSuiteShards = 100000;
inline constexpr int kSuiteJsonDepth = 64;  // objects and arrays nested, as a scene's JSON
// Memory reading a suite or fragment takes, per byte of its JSON (the parsed document), with room.
inline constexpr std::uint64_t kJsonBytesPerByte = 16;

// Differences in 8-bit steps of the largest RGB channel difference (images are 8-bit RGB PNG, as
// `quadshade render -o FILE.png` writes them).
struct Tolerance {
    double fail = 1.0, fail_percent = 0.0;  // a pixel fails above `fail` steps; at most fail_percent % may
    double warn = 0.0, warn_percent = 0.0;
    std::optional<double> hard_fail;        // any pixel above this fails the case
};

struct SuiteCase {
    std::string name;
    std::filesystem::path scene;
    // The expected image and, beside it, what a failure keeps: NAME.actual.png and NAME.diff.png.
    // Each is the entry the suite names (its folder resolved, a link kept: replaced on a write).
    std::filesystem::path expected, actual, diff;
    FrameRequest request;  // size, time, shader, rule, backend, precision, uniforms
    Tolerance tolerance;
};

struct Suite {
    std::filesystem::path file;
    std::string name;
    std::vector<SuiteCase> cases;
    // What the suite reads beside its expected images: its file, its scenes and the files they name
    // (add_scene_inputs); no output of the run may be one of them.
    InputFiles inputs;
};

struct SuiteLoadOptions {
    // Scenes and expected images outside the suite's folder (absolute paths, ../, links leading
    // out); by default a suite names only files in its own folder, and its scenes read only
    // theirs (--allow-outside-paths).
    bool allow_outside = false;
    std::uint64_t memory_limit = 0;  // what reading it may take; 0: what the system has available
    // How the cases' GLSL files run: as render runs --glsl (the cached translation where there is
    // one; with --compile compiled first).
    GlslWay glsl_way = GlslWay::Cached;
};

// Reads a suite file; throws std::runtime_error naming the file and the field of anything wrong
// (MemoryError when its JSON would not fit).
Suite load_suite(const std::filesystem::path& file, const SuiteLoadOptions& options = {});
// The same from the file's text, `file` naming it (its folder is where its paths lead from).
Suite parse_suite(std::string_view text, const std::filesystem::path& file, const SuiteLoadOptions& options = {});
// Loads each of the suite's scenes once and adds the files it reads to suite.inputs (a scene
// that does not load adds itself only: its cases fail with its message).
void add_scene_inputs(Suite& suite, const SuiteLoadOptions& options);

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
    bool update = false;  // re-bless: write each case's image as its expected image
    int jobs = 0;         // cases rendered at once; 0: one per core
    int shard = 1, shards = 1;
    SuiteLoadOptions load;  // also how the scenes load
};

// Runs the suite's cases of the shard, printing progress and a summary (stdout). The cases share
// one memory budget (load.memory_limit): each renders in bands of rows as `render` does and holds
// its images as 8 bits per channel, and waits while the others hold what it needs; a case that
// cannot fit alone fails with the size it needs. Throws std::runtime_error, before any case runs,
// when a case would write over a file the suite reads.
SuiteRun run_suite(const Suite& suite, const SuiteRequest& request);

// The JSON of a suite or fragment file, for load_suite and merge_fragments: a regular file of
// at most kSuiteFileBytes whose parsed form (kJsonBytesPerByte per byte) fits in `memory_limit`
// (0: what the system has available), nested at most kSuiteJsonDepth deep (checked on the text:
// a parser would recurse into it). Throws std::runtime_error (MemoryError) naming the file.
std::string read_suite_json(const std::filesystem::path& file, std::uint64_t memory_limit);
void check_json_depth(std::string_view text, const std::string& file);

// Whether `name` may name a case: letters, digits, '-', '_' and '.', not starting with '.', at
// most 200 characters (it names files).
bool is_case_name(std::string_view name);

}  // namespace qs
