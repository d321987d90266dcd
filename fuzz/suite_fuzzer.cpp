// Fuzz target: golden-image suite files (`quadshade test`): the JSON and its nesting, every field
// and limit, the paths a suite names (inside its folder) and the files its cases would write (each
// case's own). A std::runtime_error naming the file is the expected way out; anything else (a
// crash, a sanitizer report, std::bad_alloc, a loaded suite that breaks a promise) is a bug.
#include <unistd.h>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <string_view>

#include "fuzz/fuzz_check.h"
#include "regression/golden_suite.h"

namespace {

namespace fs = std::filesystem;

// The suite's folder, with a scene in it for the corpus's cases to name.
const fs::path& suite_folder() {
    static const fs::path dir = [] {
        const fs::path d =
            fs::canonical(fs::temp_directory_path()) / ("quadshade-fuzz-suite-" + std::to_string(::getpid()));
        fs::create_directories(d / "scenes");
        fs::copy_file(fs::path(QUADSHADE_SOURCE_DIR) / "scenes/assets/table-1.1-plane.gltf", d / "scenes/plane.gltf",
                      fs::copy_options::overwrite_existing);
        std::atexit([] {
            std::error_code ec;
            fs::remove_all(suite_folder(), ec);
        });
        return d;
    }();
    return dir;
}

bool inside(const fs::path& p, const fs::path& folder) {
    const std::string s = p.string(), f = folder.string() + "/";
    return s.compare(0, f.size(), f) == 0;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const qs::Suite suite = qs::parse_suite(text, suite_folder() / "suite.json");
        FUZZ_CHECK(!suite.cases.empty() && suite.cases.size() <= qs::kSuiteCases);
        std::set<std::string> names, files;
        for (const qs::SuiteCase& c : suite.cases) {
            FUZZ_CHECK(qs::is_case_name(c.name));
            FUZZ_CHECK(names.insert(c.name).second);
            FUZZ_CHECK(c.expected.extension() == ".png");
            for (const fs::path* f : {&c.expected, &c.actual, &c.diff}) {
                FUZZ_CHECK(inside(*f, suite_folder()));        // no --allow-outside-paths here
                FUZZ_CHECK(files.insert(f->string()).second);  // each case's files are its own
            }
            FUZZ_CHECK(inside(c.scene, suite_folder()));
            const qs::FrameRequest& r = c.request;
            FUZZ_CHECK(r.width >= 0 && r.width <= 32768 && r.height >= 0 && r.height <= 32768);
            FUZZ_CHECK(r.uniforms.size() <= text.size());
        }
    } catch (const std::runtime_error&) {}
    return 0;
}
