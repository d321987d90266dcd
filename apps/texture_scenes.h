#pragma once
// The texture conformance scenes: glTF scenes that exercise what a texture lookup depends on, for
// the comparisons against OSMesa (tests/reference/test_texture_conformance.cpp).

#include <filesystem>
#include <string>
#include <vector>

namespace qs::conformance {

struct SceneFile {
    std::string file;         // relative to the folder
    std::string description;  // what it exercises
};

// Writes the scenes and their images into `dir`; returns them in a stable order.
std::vector<SceneFile> write_texture_scenes(const std::filesystem::path& dir);

}  // namespace qs::conformance
