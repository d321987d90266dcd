#include "files/temporary_file.h"

#include <fcntl.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

#include "files/output_file.h"

namespace qs {

namespace fs = std::filesystem;

namespace {

// Live temporaries, for the thread that handles the signals. Its lock is held from a temporary's
// creation until it is registered, and by the signal thread from the signal to the end of the
// process: a temporary is either created and registered before a signal is handled (and
// removed) or never created. The signal thread is an ordinary thread (it waits in sigwait), so
// the list may allocate and the removal may walk folders; it has no fixed size.
struct Temporaries {
    std::mutex lock;
    std::uint64_t next = 1;
    std::map<std::uint64_t, std::pair<std::string, bool>> live;  // path, whether a folder
};

Temporaries& temporaries() {
    static Temporaries* t = new Temporaries;  // never destroyed: the signal thread may outlive main
    return *t;
}

// Called with the lock held.
std::uint64_t register_locked(const std::string& path, bool folder) {
    Temporaries& t = temporaries();
    const std::uint64_t id = t.next++;
    t.live.emplace(id, std::make_pair(path, folder));
    return id;
}

void unregister_temporary(std::uint64_t id) {
    if (id == 0) return;
    Temporaries& t = temporaries();
    const std::lock_guard guard(t.lock);
    t.live.erase(id);
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
    Temporaries& t = temporaries();
    t.lock.lock();  // never unlocked: no temporary is created from here to the end
    for (const auto& [id, entry] : t.live) {
        std::error_code ec;
        if (entry.second)
            fs::remove_all(entry.first, ec);
        else
            ::unlink(entry.first.c_str());
    }
    std::signal(sig, SIG_DFL);
    ::pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
    ::raise(sig);
}

// Six random letters and digits: the temporary's name cannot be guessed in advance.
std::string random_suffix() {
    static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
    unsigned char bytes[6];
    if (::getentropy(bytes, sizeof bytes) != 0) throw OutputError("no random bytes for a temporary file name");
    std::string s;
    for (unsigned char b : bytes) s += kAlphabet[b % (sizeof kAlphabet - 1)];
    return s;
}

OutputError output_error(const fs::path& target, const std::string& what) {
    return OutputError(target.string() + ": " + what);
}

fs::path folder_of(const fs::path& target) {
    return target.parent_path().empty() ? fs::path(".") : target.parent_path();
}

// The folder a target goes into: it must exist (outputs never create the folders they are
// named in, so that a mistyped folder is reported rather than made).
fs::path existing_folder(const fs::path& target) {
    const fs::path folder = folder_of(target);
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) throw output_error(target, "no folder " + folder.string() + " to write into");
    return folder;
}

// A fresh folder ".NAME.XXXXXX" in `folder` (mode 0700), registered for removal on signals.
std::pair<fs::path, std::uint64_t> make_temporary_folder(const fs::path& folder, const std::string& name,
                                                         const fs::path& target) {
    std::string pattern = (folder / ("." + name + ".XXXXXX")).string();
    const std::lock_guard guard(temporaries().lock);
    if (!::mkdtemp(pattern.data())) {
        throw output_error(target,
                           "cannot create a temporary folder in " + folder.string() + ": " + std::strerror(errno));
    }
    return {fs::path(pattern), register_locked(pattern, true)};
}

void fsync_folder(const fs::path& folder) {
    const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir >= 0) ::fsync(dir), ::close(dir);
}

}  // namespace

TemporaryFile::TemporaryFile(const fs::path& target) : target_(target) {
    if (target.empty() || target.filename().empty() || target.filename() == "." || target.filename() == "..") {
        throw output_error(target, "not a file name");
    }
    output_place(target, Streams::Refused);
    const fs::path folder = existing_folder(target);
    std::string hidden = ".";  // built in steps: GCC 12 warns falsely (-Wrestrict) on "." + string
    hidden += target.stem().string();
    hidden += '.';
    const std::string stem = (folder / hidden).string();
    const std::string extension = target.extension().string();
    // O_EXCL: a file or symlink already there is never opened; the mode is 0666 less the umask,
    // what any new file gets.
    const std::lock_guard guard(temporaries().lock);
    int error = 0;
    for (int attempt = 0; attempt < 100 && fd_ < 0; ++attempt) {
        std::string name = stem + random_suffix() + extension;
        fd_ = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd_ >= 0) {
            path_ = name;
            registration_ = register_locked(name, false);
        } else if ((error = errno) != EEXIST) {
            break;
        }
    }
    if (fd_ < 0) {
        throw output_error(target,
                           "cannot create a temporary file in " + folder.string() + ": " + std::strerror(error));
    }
}

TemporaryFile::~TemporaryFile() { discard(); }

void TemporaryFile::note_write_error(int error) {
    if (!write_error_) write_error_ = error ? error : EIO;
}

void TemporaryFile::discard() noexcept {
    if (fd_ >= 0) ::close(fd_), fd_ = -1;
    if (!path_.empty()) ::unlink(path_.c_str()), path_.clear();
    unregister_temporary(registration_), registration_ = 0;
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
    unregister_temporary(registration_), registration_ = 0;
    fsync_folder(folder_of(target_));  // the rename itself reaches the disk with the folder
}

void remove_temporaries_on_signals() {
    // Blocked here, before any other thread exists, the signals stay blocked in every thread
    // started later (threads inherit the mask) and reach only the signal thread's sigwait. A
    // handler instead runs on whichever thread the signal lands, possibly while another thread
    // is between creating a temporary and registering it, which then stays behind.
    static std::once_flag once;
    std::call_once(once, [] {
        std::signal(SIGXFSZ, SIG_IGN);
        std::signal(SIGPIPE, SIG_IGN);
        const sigset_t set = ending_signals();
        ::pthread_sigmask(SIG_BLOCK, &set, nullptr);
        temporaries();  // made before the signal thread can need it
        std::thread(handle_ending_signals).detach();
    });
}

OutputSet::OutputSet(const fs::path& target) {
    folder_ = existing_folder(target);
    std::tie(staging_, registration_) = make_temporary_folder(folder_, target.filename().string(), target);
}

OutputSet::~OutputSet() {
    std::error_code ec;
    if (!keep_staging_) fs::remove_all(staging_, ec);
    unregister_temporary(registration_);
}

void OutputSet::commit(const std::string& last) {
    std::vector<std::string> names;
    for (const fs::directory_entry& e : fs::directory_iterator(staging_)) {
        if (e.path().filename() != last) names.push_back(e.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    names.push_back(last);
    // Only files and links are replaced (and kept until the end): anything else at a target is
    // refused before a rename, so that nothing of it is moved aside.
    for (const std::string& name : names) {
        struct stat st {};
        const fs::path target = folder_ / name;
        if (::lstat(target.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISLNK(st.st_mode)) {
            throw output_error(target, "is not a file (a folder or a device); nothing of the set was written");
        }
    }
    const fs::path previous = staging_ / ".previous";  // no staged name starts with a '.'
    if (::mkdir(previous.c_str(), 0700) != 0) {
        throw output_error(folder_ / last, std::string("cannot keep the previous files: ") + std::strerror(errno));
    }
    struct Done {
        fs::path target, kept;  // kept: the previous file, empty when there was none
    };
    std::vector<Done> done;
    // Puts back every target renamed so far; returns what could not be put back.
    auto roll_back = [&] {
        std::string lost;
        for (auto d = done.rbegin(); d != done.rend(); ++d) {
            const bool ok =
                d->kept.empty() ? ::unlink(d->target.c_str()) == 0 : ::rename(d->kept.c_str(), d->target.c_str()) == 0;
            if (!ok) lost += (lost.empty() ? "" : ", ") + d->target.string();
        }
        return lost;
    };
    for (const std::string& name : names) {
        const fs::path target = folder_ / name, kept = previous / name;
        struct stat st {};
        Done step{target, {}};
        if (::lstat(target.c_str(), &st) == 0) {
            // A hard link keeps the previous file in place for readers until the rename; where the
            // file system has none, it is moved aside instead.
            if (::linkat(AT_FDCWD, target.c_str(), AT_FDCWD, kept.c_str(), 0) != 0 &&
                ::rename(target.c_str(), kept.c_str()) != 0) {
                const int error = errno;
                const std::string lost = roll_back();
                keep_staging_ = !lost.empty();
                throw output_error(target, std::string("cannot keep the previous file: ") + std::strerror(error) +
                                               (lost.empty() ? "; nothing was changed" : "; not restored: " + lost));
            }
            step.kept = kept;
        }
        if (::rename((staging_ / name).c_str(), target.c_str()) != 0) {
            const int error = errno;
            if (!step.kept.empty() && ::lstat(target.c_str(), &st) != 0)
                ::rename(kept.c_str(), target.c_str());  // moved aside
            const std::string lost = roll_back();
            keep_staging_ = !lost.empty();
            throw output_error(target, std::string("cannot move the finished file into place: ") +
                                           std::strerror(error) +
                                           (lost.empty() ? "; every file of the set is as it was"
                                                         : "; not restored: " + lost + " (the previous files are in " +
                                                               previous.string() + ")"));
        }
        done.push_back(step);
    }
    fsync_folder(folder_);
}

ScratchFolder::ScratchFolder(const fs::path& near) {
    std::tie(path_, registration_) = make_temporary_folder(existing_folder(near), near.filename().string(), near);
}

ScratchFolder::~ScratchFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
    unregister_temporary(registration_);
}

}  // namespace qs
