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

// A set of outputs written together (a glTF, its buffer, its textures): each is written into a
// fresh folder beside the targets (".NAME.XXXXXX", created exclusively), and commit() renames them
// all into place, the file that names the others last. Until then nothing of them is in the
// targets' folder, and the folder is removed when its owner is destroyed. (A signal leaves it
// behind: it is hidden and holds only complete or temporary files.)
class OutputSet {
public:
    // Throws std::runtime_error naming `target` when its folder is missing or not writable.
    explicit OutputSet(const std::filesystem::path& target);
    ~OutputSet();
    OutputSet(const OutputSet&) = delete;
    OutputSet& operator=(const OutputSet&) = delete;
    // Where to write the output named `name` (a file name) until commit().
    std::filesystem::path staged(const std::string& name) const { return staging_ / name; }
    // Renames every staged file into the targets' folder, `last` last.
    void commit(const std::string& last);

private:
    std::filesystem::path staging_, folder_;
};

// On SIGINT, SIGTERM or SIGHUP, removes every live temporary, then ends the process as the
// signal would have (the default action, raised again). The signals are blocked in the calling
// thread and handled by a thread of their own: call it first thing in main(), before any other
// thread starts, from a program that writes outputs.
void remove_temporaries_on_signals();

}  // namespace qs
