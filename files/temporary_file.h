#pragma once
// Outputs are written to a temporary file beside their target and renamed over it once complete,
// so that a reader never sees a partial file and an existing file is never half-overwritten.
// The temporary is created exclusively (a fresh, unpredictable name opened with O_EXCL and
// O_NOFOLLOW, so a planted file or symlink is never followed), every write to it is checked, and
// it is flushed to the disk (fsync) before the rename. It is removed when anything fails, when its
// owner is destroyed without commit(), and on SIGINT/SIGTERM/SIGHUP once
// remove_temporaries_on_signals() ran. files/output_file.h states the whole rule and writes
// whole outputs through it; docs/reliability.md ("Outputs") says it once for users.

#include <cstdint>
#include <filesystem>
#include <string>

namespace qs {

class TemporaryFile {
public:
    // A temporary in `target`'s folder, named after it (".NAME.XXXXXX.EXT", the extension kept
    // for libraries that look at it). Throws OutputError (output_file.h) naming `target` when its
    // folder is missing or not writable, or `target` is a folder, a device, a FIFO or a socket
    // (a symbolic link there is replaced by the rename, what it points to left untouched).
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
    // target. Throws OutputError naming the target and the cause; the temporary is gone either
    // way.
    void commit();

private:
    void discard() noexcept;
    std::filesystem::path target_, path_;
    int fd_ = -1;
    std::uint64_t registration_ = 0;  // in the list the signal thread removes
    int write_error_ = 0;
};

// A set of outputs written together (a glTF, its buffer, its textures): each is written into a
// fresh folder beside the targets (".NAME.XXXXXX", created exclusively), and commit() renames them
// all into place, the file that names the others last. Until then nothing of them is in the
// targets' folder; the folder is removed when its owner is destroyed and on the signals above.
class OutputSet {
public:
    // Throws OutputError naming `target` when its folder is missing or not writable: made before
    // the work whose files it holds, so that a missing folder is reported before that work.
    explicit OutputSet(const std::filesystem::path& target);
    ~OutputSet();
    OutputSet(const OutputSet&) = delete;
    OutputSet& operator=(const OutputSet&) = delete;
    // Where to write the output named `name` (a file name) until commit().
    std::filesystem::path staged(const std::string& name) const { return staging_ / name; }
    // Renames every staged file into the targets' folder, `last` last, all or nothing: each
    // target's previous file is kept (a hard link in the staging folder) until every rename is
    // done, and a failed rename puts every previous file back and removes the new ones. Throws
    // OutputError naming the target that failed and the cause.
    void commit(const std::string& last);

private:
    std::filesystem::path staging_, folder_;
    std::uint64_t registration_ = 0;
    bool keep_staging_ = false;  // a previous file could not be put back: it is still in staging_
};

// A folder of scratch files beside `near` (".NAME.XXXXXX", created exclusively, mode 0700) that
// is removed with everything in it when its owner is destroyed and on the signals above: where
// a command keeps files only it reads (check's reference images), so that concurrent runs sharing
// an output folder never see each other's.
class ScratchFolder {
public:
    // Throws OutputError when it cannot be created in `near`'s folder.
    explicit ScratchFolder(const std::filesystem::path& near);
    ~ScratchFolder();
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
    std::uint64_t registration_ = 0;
};

// On SIGINT, SIGTERM or SIGHUP, removes every live temporary (files and folders), then ends the
// process as the signal would have (the default action, raised again). The signals are blocked
// in the calling thread and handled by a thread of their own: call it first thing in main(),
// before any other thread starts, from a program that writes outputs. SIGXFSZ (a file size
// limit, `ulimit -f`) and SIGPIPE are ignored from then on, so that the write that exceeds the
// limit or meets a closed pipe fails with an error (EFBIG, EPIPE) the output's writer reports,
// removing its temporary, instead of ending the process silently with the temporary left.
void remove_temporaries_on_signals();

}  // namespace qs
