#pragma once
// The reports of a golden-image suite run (golden_suite.h): the terminal summary, report
// fragments (JSON, one per shard) and their merge, JUnit XML (as CI systems read it) and an HTML
// page with the images side by side.

#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

#include "regression/golden_suite.h"

namespace qs {

// Reports are written by files/output_file.h's rule; a report may be streamed into /dev/stdout,
// a FIFO or a character device.
void write_fragment(const SuiteRun& run, const std::filesystem::path& file);

struct MergeOptions {
    // Whether the fragments' images will be read (an HTML report copies them): then each must lie
    // in its fragment's folder unless allow_outside.
    bool reads_images = false;
    bool allow_outside = false;
    std::uint64_t memory_limit = 0;  // 0: what the system has available
};
// Throws std::runtime_error naming the file (and the field) when fragments are unreadable, of
// other suites, break their limits or do not hold every shard 1..N and every case exactly once.
SuiteRun merge_fragments(const std::vector<std::filesystem::path>& files, const MergeOptions& options = {});
// One fragment from its text, `file` naming it: what merge_fragments reads of each (fuzz/).
SuiteRun parse_fragment(std::string_view text, const std::filesystem::path& file, const MergeOptions& options = {});

void write_junit(const SuiteRun& run, const std::filesystem::path& file);
void write_html(const SuiteRun& run, const std::filesystem::path& folder);
// The files write_html writes in `folder`, to check before the run that none is an input.
std::vector<std::filesystem::path> html_files(const SuiteRun& run, const std::filesystem::path& folder);
std::vector<std::filesystem::path> html_files(const Suite& suite, const std::filesystem::path& folder);
// Prints the summary line and the failures; returns 0, or 3 when a case failed.
int summarize(const SuiteRun& run);

}  // namespace qs
