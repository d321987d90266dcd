#include "scenes/temporary_file.h"

#include <fcntl.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

namespace qs {

namespace {

// Live temporaries, for the thread that handles the signals: fixed storage, each slot claimed,
// filled, then marked live; only live ones are removed.
constexpr int kSlots = 16;
constexpr std::size_t kPathBytes = 4096;
enum SlotState : int { kFree, kClaimed, kLive };
struct Slot {
    std::atomic<int> state{kFree};
    char path[kPathBytes];
};
std::array<Slot, kSlots> g_slots;
// Held from a temporary's creation until it is registered, and by the signal thread from the
// signal to the end of the process: a temporary is either created and registered before a
// signal is handled (and removed) or never created.
std::mutex g_creating;

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

sigset_t ending_signals() {
    sigset_t set;
    sigemptyset(&set);
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&set, sig);
    return set;
}

// The signal thread: waits for an ending signal, removes the live temporaries, then ends the
// process as the signal would have (its default action, raised again with it unblocked).
void handle_ending_signals() {
    const sigset_t set = ending_signals();
    int sig = 0;
    if (::sigwait(&set, &sig) != 0) return;
    g_creating.lock();  // never unlocked: no temporary is created from here to the end
    for (Slot& s : g_slots) {
        if (s.state.load() == kLive) ::unlink(s.path);
    }
    std::signal(sig, SIG_DFL);
    ::pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
    ::raise(sig);
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
    const std::lock_guard creating(g_creating);
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
    // Blocked here, before any other thread exists, the signals stay blocked in every thread
    // started later (threads inherit the mask) and reach only the signal thread's sigwait. A
    // handler instead runs on whichever thread the signal lands, possibly while another thread
    // is between creating a temporary and registering it, which then stays behind.
    static std::once_flag once;
    std::call_once(once, [] {
        const sigset_t set = ending_signals();
        ::pthread_sigmask(SIG_BLOCK, &set, nullptr);
        std::thread(handle_ending_signals).detach();
    });
}

OutputSet::OutputSet(const std::filesystem::path& target) {
    folder_ = target.parent_path().empty() ? std::filesystem::path(".") : target.parent_path();
    std::string name = ".";
    name += target.filename().string();
    name += ".XXXXXX";
    std::string pattern = (folder_ / name).string();
    if (!::mkdtemp(pattern.data())) {
        throw std::runtime_error(target.string() + ": cannot create a temporary folder beside it: " + std::strerror(errno));
    }
    staging_ = pattern;
}

OutputSet::~OutputSet() {
    std::error_code ec;
    std::filesystem::remove_all(staging_, ec);
}

void OutputSet::commit(const std::string& last) {
    std::vector<std::filesystem::path> files;
    for (const std::filesystem::directory_entry& e : std::filesystem::directory_iterator(staging_)) {
        if (e.path().filename() != last) files.push_back(e.path());
    }
    files.push_back(staging_ / last);
    for (const std::filesystem::path& f : files) std::filesystem::rename(f, folder_ / f.filename());
}

}  // namespace qs
