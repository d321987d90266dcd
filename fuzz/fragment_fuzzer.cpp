// Fuzz target: report fragments (`quadshade test --report`, read by --merge): the JSON and its
// nesting, every field's kind and range (shards, cases, counts), case names (they name the HTML
// report's files) and, when the images are to be read, their paths (inside the fragment's folder).
// The first byte says whether the images are read; the rest is the fragment. A
// std::runtime_error naming the file is the expected way out.
#include <cstdint>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <string_view>

#include "fuzz/fuzz_check.h"
#include "regression/suite_reports.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace fs = std::filesystem;
    if (size < 1) return 0;
    static const fs::path folder = fs::canonical(fs::temp_directory_path());
    qs::MergeOptions options;
    options.reads_images = data[0] & 1;
    const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
    try {
        const qs::SuiteRun part = qs::parse_fragment(text, folder / "fragment.json", options);
        FUZZ_CHECK(part.shards >= 1 && part.shards <= qs::kSuiteShards);
        FUZZ_CHECK(part.shard >= 1 && part.shard <= part.shards);
        FUZZ_CHECK(part.suite_cases >= 1 && part.suite_cases <= qs::kSuiteCases);
        FUZZ_CHECK(part.results.size() <= part.suite_cases);
        std::set<std::string> names;
        for (const qs::CaseResult& r : part.results) {
            FUZZ_CHECK(qs::is_case_name(r.name) && names.insert(r.name).second);
            FUZZ_CHECK(r.index < part.suite_cases);
            FUZZ_CHECK(r.failing >= 0 && r.failing <= r.pixels && r.warning >= 0 && r.warning <= r.pixels);
            FUZZ_CHECK(r.message.find('\0') == std::string::npos);
            if (!options.reads_images) continue;
            for (const fs::path* p : {&r.expected, &r.actual, &r.diff}) {
                FUZZ_CHECK(p->empty() || p->string().rfind(folder.string() + "/", 0) == 0);
            }
        }
    } catch (const std::runtime_error&) {}
    return 0;
}
