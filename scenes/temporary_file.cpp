#include "scenes/temporary_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace qs {

namespace {

// Live temporaries, for the signal handler: fixed storage (a handler may not allocate), each
// slot claimed, filled, then marked live; the handler removes only live ones.
constexpr int kSlots = 16;
constexpr std::size_t kPathBytes = 4096;
enum SlotState : int { kFree, kClaimed, kLive };
struct Slot {
    std::atomic<int> state{kFree};
    char path[kPathBytes];
};
std::array<Slot, kSlots> g_slots;

int register_temporary(const std::string& path) {
    if (path.size() >= kPathBytes) return -1;
    for (int i = 0; i < kSlots; ++i) {
        Slot& s = g_slots[std::size_t(i)];
        int expected = kFree;
        if (!s.state.compare_exchange_strong(expected, kClaimed)) continue;
        std::memcpy(s.path, path.c_str(), path.size() + 1);
        s.state.store(kLive);
        return i;
    }
    return -1;
}

void unregister_temporary(int slot) {
    if (slot >= 0) g_slots[std::size_t(slot)].state.store(kFree);
}

extern "C" void remove_temporaries_and_reraise(int sig) {
    for (Slot& s : g_slots) {
        if (s.state.load() == kLive) ::unlink(s.path);
    }
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

// Six random letters and digits: the temporary's name cannot be guessed in advance.
std::string random_suffix() {
    static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
    unsigned char bytes[6];
    if (::getentropy(bytes, sizeof bytes) != 0) throw std::runtime_error("no random bytes for a temporary file name");
    std::string s;
    for (unsigned char b : bytes) s += kAlphabet[b % (sizeof kAlphabet - 1)];
    return s;
}

std::runtime_error output_error(const std::filesystem::path& target, const std::string& what) {
    return std::runtime_error(target.string() + ": " + what);
}

}  // namespace

TemporaryFile::TemporaryFile(const std::filesystem::path& target) : target_(target) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (target.empty() || target.filename().empty()) throw output_error(target, "not a file name");
    if (fs::is_directory(target, ec)) throw output_error(target, "is a folder; the output must be a file name");
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    if (!fs::is_directory(folder, ec)) throw output_error(target, "no folder " + folder.string() + " to write into");
    std::string hidden = ".";  // built in steps: GCC 12 warns falsely (-Wrestrict) on "." + string
    hidden += target.stem().string();
    hidden += '.';
    const std::string stem = (folder / hidden).string();
    const std::string extension = target.extension().string();
    // O_EXCL: a file or symlink already there is never opened; the mode is 0666 less the umask,
    // what any new file gets.
    for (int attempt = 0; attempt < 100 && fd_ < 0; ++attempt) {
        std::string name = stem + random_suffix() + extension;
        fd_ = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd_ >= 0) {
            path_ = name;
            slot_ = register_temporary(name);
        } else if (errno != EEXIST) {
            break;
        }
    }
    if (fd_ < 0) {
        throw output_error(target, "cannot create a temporary file in " + folder.string() + ": " + std::strerror(errno));
    }
}

TemporaryFile::~TemporaryFile() { discard(); }

void TemporaryFile::note_write_error(int error) {
    if (!write_error_) write_error_ = error ? error : EIO;
}

void TemporaryFile::discard() noexcept {
    if (fd_ >= 0) ::close(fd_), fd_ = -1;
    if (!path_.empty()) ::unlink(path_.c_str()), path_.clear();
    unregister_temporary(slot_), slot_ = -1;
}

void TemporaryFile::commit() {
    int error = write_error_;
    if (!error && ::fsync(fd_) != 0) error = errno;
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0 && !error) error = errno;
    if (error) {
        discard();
        throw output_error(target_, std::string("cannot write: ") + std::strerror(error) + " (the previous file, if any, is untouched)");
    }
    if (::rename(path_.c_str(), target_.c_str()) != 0) {
        error = errno;
        discard();
        throw output_error(target_, std::string("cannot move the finished file into place: ") + std::strerror(error));
    }
    path_.clear();
    unregister_temporary(slot_), slot_ = -1;
    // The rename itself reaches the disk with the folder.
    const std::filesystem::path folder = target_.parent_path().empty() ? "." : target_.parent_path();
    const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir >= 0) ::fsync(dir), ::close(dir);
}

void remove_temporaries_on_signals() {
    struct sigaction action {};
    action.sa_handler = &remove_temporaries_and_reraise;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(sig, &action, nullptr);
}

}  // namespace qs
