#pragma once
// Where tests find the sources, the built programs and a scratch folder of their own.

#include <unistd.h>

#include <filesystem>
#include <string>

namespace qs::test {

inline const std::filesystem::path kSource = QUADSHADE_SOURCE_DIR;
inline const std::filesystem::path kBin = QUADSHADE_BIN_DIR;
inline const std::filesystem::path kFigure = kSource / "scenes/assets/figure-1.1.gltf";
inline const std::filesystem::path kPlane = kSource / "scenes/assets/table-1.1-plane.gltf";

// A fresh, empty folder under the system's temporary directory, unique to this process.
inline std::filesystem::path temp_dir(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("quadshade-test-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace qs::test
