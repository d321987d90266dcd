#pragma once
// What the command-line tests of tests/apps share: running quadshade as a user does (through the
// shell), files read and written whole, and a scratch folder holding a scene to render.

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/test_paths.h"

namespace qs::test {

inline const std::string kQuadshade = (kBin / "quadshade").string();

inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

inline void write_file(const std::filesystem::path& p, const std::string& bytes) {
    std::ofstream(p, std::ios::binary) << bytes;
}

// A shell command line's exit code (-1 when a signal ended it), standard output and error.
struct Ran {
    int code = 0;
    std::string out, err;
};

// Runs `cmd` through the shell in `dir`, its output kept in dir/.. files of the test's own.
inline Ran sh(const std::string& cmd, const std::filesystem::path& dir) {
    const std::filesystem::path out = dir.parent_path() / (dir.filename().string() + ".out"),
                                err = dir.parent_path() / (dir.filename().string() + ".err");
    const int status = std::system(
        ("cd '" + dir.string() + "' && " + cmd + " > '" + out.string() + "' 2> '" + err.string() + "'").c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
}

// A fresh folder with the Table 1.1 plane (its buffer and texture) in scenes/: a suite written
// into it names scenes/table-1.1-plane.gltf.
inline std::filesystem::path plane_folder(const std::string& name) {
    namespace fs = std::filesystem;
    const fs::path dir = temp_dir(name);
    fs::create_directories(dir / "scenes/textures");
    for (const char* f : {"table-1.1-plane.gltf", "table-1.1-plane.bin", "textures/halftone-source.png"}) {
        fs::copy_file(kSource / "scenes/assets" / f, dir / "scenes" / f);
    }
    return dir;
}

// Whether any entry under `dir` (at any depth) is hidden: a temporary left behind.
inline bool has_hidden(const std::filesystem::path& dir) {
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
        if (e.path().filename().string().rfind('.', 0) == 0) return true;
    }
    return false;
}

}  // namespace qs::test
