#include "scenes/scene_files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
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
    const std::string name = path.string();
    const int fd = ::open(name.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK | (follow_symlink ? 0 : O_NOFOLLOW));
    if (fd < 0) {
        const int e = errno;
        if (e == ENOENT) throw SceneError(name + ": no such file");
        if (e == ELOOP) throw SceneError(name + ": is a symbolic link (links are resolved before reading; this one changed)");
        throw SceneError(name + ": cannot open: " + std::strerror(e));
    }
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0) throw SceneError(name + ": cannot stat: " + std::strerror(errno));
    if (S_ISDIR(st.st_mode)) throw SceneError(name + ": is a folder, not a file");
    if (!S_ISREG(st.st_mode)) throw SceneError(name + ": is not a regular file (a device, FIFO or socket is never read)");
    const std::uint64_t size = std::uint64_t(st.st_size);
    if (size > max_bytes) {
        throw SceneError(name + ": is " + byte_size_text(size) + ", more than the " + byte_size_text(max_bytes) +
                         " quadshade reads");
    }
    std::vector<unsigned char> bytes(size);
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw SceneError(name + ": cannot read: " + std::strerror(errno));
        if (n == 0) throw SceneError(name + ": became shorter while being read");
        done += std::size_t(n);
    }
    return bytes;
}

std::string byte_size_text(std::uint64_t bytes) {
    const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    double v = double(bytes);
    int u = 0;
    while (v >= 1024.0 && u < 6) v /= 1024.0, ++u;
    char text[32];
    if (u == 0) {
        std::snprintf(text, sizeof text, "%llu bytes", (unsigned long long)bytes);
    } else {
        std::snprintf(text, sizeof text, "%.1f %s", v, units[u]);
    }
    return text;
}

}  // namespace qs
