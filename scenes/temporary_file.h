#pragma once
// Outputs are written to a temporary file beside their target and renamed over it once complete,
// so that a reader never sees a partial file and an existing file is never half-overwritten.
// The temporary is created exclusively (a fresh, unpredictable name opened with O_EXCL, so a
// planted file or symlink is never followed), every write to it is checked, and it is flushed
// to the disk (fsync) before the rename. It is removed when anything fails, when its owner is
// destroyed without commit(), and on SIGINT/SIGTERM/SIGHUP once remove_temporaries_on_signals() ran.

#include <filesystem>
#include <string>

namespace qs {

class TemporaryFile {
public:
    // A temporary in `target`'s folder, named after it (".NAME.XXXXXX.EXT", the extension kept
    // for libraries that look at it). Throws std::runtime_error naming `target` when its folder
    // is missing or not writable, or `target` is a folder.
    explicit TemporaryFile(const std::filesystem::path& target);
    ~TemporaryFile();  // removes the temporary unless committed
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;

    int fd() const { return fd_; }
    const std::filesystem::path& path() const { return path_; }
    const std::filesystem::path& target() const { return target_; }

    // Records a failed write (errno `error`); commit() then refuses. The first one is kept.
    void note_write_error(int error);
    // Flushes the data to the disk, closes the file (each checked) and renames it over the
    // target. Throws std::runtime_error naming the target and the cause; the temporary is gone
    // either way.
    void commit();

private:
    void discard() noexcept;
    std::filesystem::path target_, path_;
    int fd_ = -1;
    int slot_ = -1;  // in the signal handler's list
    int write_error_ = 0;
};

// On SIGINT, SIGTERM or SIGHUP, removes every live temporary, then ends the process as the
// signal would have (the default action, raised again). The signals are blocked in the calling
// thread and handled by a thread of their own: call it first thing in main(), before any other
// thread starts, from a program that writes outputs.
void remove_temporaries_on_signals();

}  // namespace qs
