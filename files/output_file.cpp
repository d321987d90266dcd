#include "files/output_file.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>

#include "files/temporary_file.h"

namespace qs {

namespace fs = std::filesystem;

namespace {

OutputError output_error(const fs::path& target, const std::string& what) {
    return OutputError(target.string() + ": " + what);
}

// The descriptor of this process that `target` names: /dev/stdin, /dev/stdout, /dev/stderr,
// /dev/fd/N or /proc/self/fd/N (links to whatever the descriptor is open on: a terminal, a pipe,
// a file a shell redirected it to), else none.
std::optional<int> own_descriptor(const fs::path& target) {
    const std::string p = target.lexically_normal().string();
    if (p == "/dev/stdin") return 0;
    if (p == "/dev/stdout") return 1;
    if (p == "/dev/stderr") return 2;
    for (const std::string_view prefix : {"/dev/fd/", "/proc/self/fd/"}) {
        if (!p.starts_with(prefix)) continue;
        const char* first = p.data() + prefix.size();
        const char* end = p.data() + p.size();
        int fd = -1;
        const auto [stop, ec] = std::from_chars(first, end, fd);
        if (ec == std::errc() && stop == end && first != end && fd >= 0) return fd;
    }
    return std::nullopt;
}

std::string kind_of(mode_t mode) {
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

// Writes all of `bytes` to a descriptor that may be a pipe or a terminal (short writes,
// interruptions, a descriptor left non-blocking by another program).
void write_all(int fd, std::string_view bytes, const fs::path& target) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
            pollfd p{fd, POLLOUT, 0};
            ::poll(&p, 1, -1);
            continue;
        }
        if (n <= 0) throw output_error(target, std::string("cannot write: ") + std::strerror(n < 0 ? errno : EIO));
        done += std::size_t(n);
    }
}

void write_stream(const fs::path& target, std::string_view bytes) {
    if (const std::optional<int> fd = own_descriptor(target)) {
        // What the program printed before comes first.
        if (*fd == STDOUT_FILENO) std::fflush(stdout);
        if (*fd == STDERR_FILENO) std::fflush(stderr);
        write_all(*fd, bytes, target);
        return;
    }
    // O_NONBLOCK: a FIFO nobody reads is reported (ENXIO) instead of waited on forever;
    // O_NOFOLLOW: a link put there since output_place looked is not followed.
    const int fd = ::open(target.c_str(), O_WRONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) {
        throw output_error(target, errno == ENXIO ? std::string("a FIFO no process reads")
                                                  : std::string("cannot open: ") + std::strerror(errno));
    }
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !(S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode))) {
        ::close(fd);
        throw output_error(target, "changed while it was opened; nothing was written");
    }
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    try {
        write_all(fd, bytes, target);
    } catch (...) {
        ::close(fd);
        throw;
    }
    if (::close(fd) != 0) throw output_error(target, std::string("cannot write: ") + std::strerror(errno));
}

}  // namespace

OutputPlace output_place(const fs::path& target, Streams streams) {
    const char* only_files = "; this output is written as a file (text reports may be streamed into one)";
    if (const std::optional<int> fd = own_descriptor(target)) {
        const int flags = ::fcntl(*fd, F_GETFL);
        if (flags < 0 || (flags & O_ACCMODE) == O_RDONLY) {
            throw output_error(
                target, "names descriptor " + std::to_string(*fd) + " of this process, which is not open for writing");
        }
        if (streams == Streams::Refused)
            throw output_error(target, std::string("is a stream of this process") + only_files);
        return OutputPlace::Stream;
    }
    struct stat st {};
    // Missing (or unreachable: the folder check that follows names why): a new file.
    if (::lstat(target.c_str(), &st) != 0) return OutputPlace::File;
    if (S_ISREG(st.st_mode) || S_ISLNK(st.st_mode)) return OutputPlace::File;
    if (S_ISDIR(st.st_mode)) throw output_error(target, "is a folder; the output must be a file name");
    if ((S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode)) && streams == Streams::Allowed) return OutputPlace::Stream;
    throw output_error(target, "is " + kind_of(st.st_mode) +
                                   (S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode) ? only_files : "; outputs are files"));
}

void write_output(const fs::path& target, std::string_view bytes, Streams streams) {
    if (output_place(target, streams) == OutputPlace::Stream) return write_stream(target, bytes);
    TemporaryFile file(target);
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(file.fd(), bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            file.note_write_error(n < 0 ? errno : ENOSPC);
            break;
        }
        done += std::size_t(n);
    }
    file.commit();
}

void make_output_folder(const fs::path& folder, FolderLink link) {
    if (folder.empty()) return;  // the working directory
    struct stat st {};
    if (::lstat(folder.c_str(), &st) == 0) {
        if (S_ISLNK(st.st_mode)) {
            if (link == FolderLink::Refused) {
                throw output_error(folder,
                                   "is a symbolic link; a folder this command fills must be a folder of its own");
            }
            std::error_code ec;
            if (fs::is_directory(folder, ec)) return;
            throw output_error(folder, "is a link to something that is not a folder");
        }
        if (S_ISDIR(st.st_mode)) return;
        throw output_error(folder, "is not a folder");
    }
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec) throw output_error(folder, "cannot create the folder: " + ec.message());
}

void copy_to_output(const fs::path& source, const fs::path& target) {
    const int in = ::open(source.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (in < 0) throw output_error(source, std::string("cannot open: ") + std::strerror(errno));
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{in};
    struct stat st {};
    if (::fstat(in, &st) != 0 || !S_ISREG(st.st_mode))
        throw output_error(source, "is not a regular file; nothing was copied");
    TemporaryFile file(target);
    std::vector<char> buffer(std::size_t(1) << 20);
    while (true) {
        const ssize_t n = ::read(in, buffer.data(), buffer.size());
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw output_error(source, std::string("cannot read: ") + std::strerror(errno));
        if (n == 0) break;
        for (ssize_t done = 0; done < n;) {
            const ssize_t w = ::write(file.fd(), buffer.data() + done, std::size_t(n - done));
            if (w < 0 && errno == EINTR) continue;
            if (w <= 0) {
                file.note_write_error(w < 0 ? errno : ENOSPC);
                file.commit();  // throws, naming the target and the cause
            }
            done += w;
        }
    }
    file.commit();
}

fs::path entry_path(const fs::path& path) {
    std::error_code ec;
    const fs::path folder = fs::weakly_canonical(path.parent_path().empty() ? fs::path(".") : path.parent_path(), ec);
    return ec ? fs::absolute(path, ec).lexically_normal() : folder / path.filename();
}

void InputFiles::add(const fs::path& file) {
    std::vector<std::string>& entries = by_name_[file.filename().string()];
    entries.push_back(entry_path(file).string());
    std::error_code ec;
    const fs::path target = fs::weakly_canonical(file, ec);
    if (!ec) by_name_[target.filename().string()].push_back(target.string());
}

bool InputFiles::contains(const fs::path& output) const {
    const auto it = by_name_.find(output.filename().string());
    if (it == by_name_.end()) return false;
    const std::string entry = entry_path(output).string();
    for (const std::string& e : it->second) {
        if (e == entry) return true;
    }
    return false;
}

}  // namespace qs
