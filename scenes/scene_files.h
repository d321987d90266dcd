#pragma once
// The files a scene refers to: glTF buffers and images, materials' extras.teximage. Every name a
// scene file gives for another file goes through resolve_scene_uri, so one rule decides what a
// scene may read: files inside the scene's own folder (symlinks resolved), unless the user lifts
// it (--allow-outside-paths); never anything fetched over a network. read_scene_file then reads
// only regular files (no folders, FIFOs or devices such as /dev/zero) of bounded size.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "files/read_file.h"

namespace qs {

struct ScenePathPolicy {
    // Allow absolute paths and paths that leave the scene's folder (by ../ or a symlink).
    bool allow_outside = false;
};

// The file that `reference` (a relative path as written in the scene, with percent-escapes
// already decoded for glTF URIs) names for the scene file `scene_file`, with `.`/`..` and every
// symlink of its existing part resolved. The file need not exist (a texture is read only when a
// shader samples it). Throws SceneError saying what is wrong with `reference` (the caller adds
// the file and the field): empty, a URI scheme (http:, https:, file:, ...), a NUL byte, an
// absolute path or a path outside the scene's folder without policy.allow_outside. Other files
// that name files (golden-image suites, their report fragments) follow the same rule: `kind`
// names such a file in the messages.
std::filesystem::path resolve_scene_uri(const std::filesystem::path& scene_file, std::string_view reference,
                                        const ScenePathPolicy& policy, std::string_view kind = "scene");

// read_regular_file (files/read_file.h), throwing SceneError.
std::vector<unsigned char> read_scene_file(const std::filesystem::path& path, std::uint64_t max_bytes,
                                           bool follow_symlink = false);

}  // namespace qs
