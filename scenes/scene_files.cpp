#include "scenes/scene_files.h"

#include <algorithm>
#include <cctype>
#include <system_error>

#include "scenes/scene.h"

namespace qs {

namespace {

// RFC 3986: a scheme is a letter followed by letters, digits, '+', '-' or '.', then ':'. A
// relative reference cannot have a ':' in its first segment, so one there is a scheme.
std::string_view uri_scheme(std::string_view ref) {
    const std::size_t colon = ref.find(':');
    if (colon == std::string_view::npos || colon == 0 || ref.substr(0, colon).find('/') != std::string_view::npos) return {};
    const std::string_view scheme = ref.substr(0, colon);
    auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); };
    if (!alpha(scheme[0])) return {};
    for (char c : scheme) {
        if (!alpha(c) && !(c >= '0' && c <= '9') && c != '+' && c != '-' && c != '.') return {};
    }
    return scheme;
}

bool equal_ignoring_case(std::string_view a, std::string_view b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](char x, char y) { return std::tolower((unsigned char)x) == std::tolower((unsigned char)y); });
}

// Whether `path` is `folder` or lies under it; both canonical.
bool is_inside(const std::filesystem::path& path, const std::filesystem::path& folder) {
    auto p = path.begin();
    for (auto f = folder.begin(); f != folder.end(); ++f, ++p) {
        if (f->empty()) continue;  // a trailing separator
        if (p == path.end() || *p != *f) return false;
    }
    return true;
}

// Built in steps: GCC 12 warns falsely (-Wrestrict) on "'" + string.
std::string quoted(std::string_view s) {
    std::string q = "'";
    q += s;
    q += '\'';
    return q;
}

}  // namespace

std::filesystem::path resolve_scene_uri(const std::filesystem::path& scene_file, std::string_view reference,
                                        const ScenePathPolicy& policy, std::string_view kind) {
    const std::string of(kind);
    namespace fs = std::filesystem;
    if (reference.empty()) throw SceneError("an empty file name");
    if (reference.find('\0') != std::string_view::npos) throw SceneError("a file name with a NUL byte");
    if (const std::string_view scheme = uri_scheme(reference); !scheme.empty()) {
        if (equal_ignoring_case(scheme, "http") || equal_ignoring_case(scheme, "https")) {
            throw SceneError(quoted(reference) + " is a network address: quadshade reads only files beside the " + of);
        }
        throw SceneError(quoted(reference) + " has a URI scheme (" + std::string(scheme) +
                         ":): only paths relative to the " + of + " file are read");
    }
    const fs::path ref(reference);
    const fs::path folder = scene_file.parent_path().empty() ? fs::path(".") : scene_file.parent_path();
    if (ref.is_absolute() && !policy.allow_outside) {
        throw SceneError(quoted(reference) + " is an absolute path: files are named relative to the " + of +
                         " file (--allow-outside-paths allows it)");
    }
    std::error_code ec;
    const fs::path target = ref.is_absolute() ? ref : folder / ref;
    fs::path resolved = fs::weakly_canonical(target, ec);
    if (ec) throw SceneError(quoted(reference) + ": cannot resolve " + target.string() + ": " + ec.message());
    if (!policy.allow_outside) {
        const fs::path home = fs::canonical(folder, ec);
        if (ec) throw SceneError("cannot resolve the " + of + "'s folder " + folder.string() + ": " + ec.message());
        if (!is_inside(resolved, home)) {
            throw SceneError(quoted(reference) + " leads outside the " + of + "'s folder " + home.string() + " (to " +
                             resolved.string() + "; --allow-outside-paths allows it)");
        }
    }
    return resolved;
}

std::vector<unsigned char> read_scene_file(const std::filesystem::path& path, std::uint64_t max_bytes,
                                           bool follow_symlink) {
    try {
        return read_regular_file(path, max_bytes, follow_symlink);
    } catch (const FileError& e) {
        throw SceneError(e.what());
    }
}

}  // namespace qs
