#include "files/read_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace qs {

std::vector<unsigned char> read_regular_file(const std::filesystem::path& path, std::uint64_t max_bytes,
                                             bool follow_symlink) {
    const std::string name = path.string();
    const int fd = ::open(name.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK | (follow_symlink ? 0 : O_NOFOLLOW));
    if (fd < 0) {
        const int e = errno;
        if (e == ENOENT) throw FileError(name + ": no such file");
        if (e == ELOOP) throw FileError(name + ": is a symbolic link (links are resolved before reading; this one changed)");
        throw FileError(name + ": cannot open: " + std::strerror(e));
    }
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0) throw FileError(name + ": cannot stat: " + std::strerror(errno));
    if (S_ISDIR(st.st_mode)) throw FileError(name + ": is a folder, not a file");
    if (!S_ISREG(st.st_mode)) throw FileError(name + ": is not a regular file (a device, FIFO or socket is never read)");
    const std::uint64_t size = std::uint64_t(st.st_size);
    if (size > max_bytes) {
        throw FileError(name + ": is " + byte_size_text(size) + ", more than the " + byte_size_text(max_bytes) +
                         " quadshade reads");
    }
    std::vector<unsigned char> bytes(size);
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw FileError(name + ": cannot read: " + std::strerror(errno));
        if (n == 0) throw FileError(name + ": became shorter while being read");
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
