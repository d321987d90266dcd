#pragma once
// How every output of quadshade is written (docs/reliability.md, "Outputs", states it for users):
//  - a file is written to a unique temporary beside it, created exclusively (O_EXCL, O_NOFOLLOW),
//    every write checked, flushed, then renamed over the target (temporary_file.h): a reader sees
//    the old file or the new one, never a part, and a failure leaves the old one;
//  - a symbolic link at the target is replaced by that rename, never written through: what it
//    points to is not opened;
//  - a folder, block device or socket at the target is refused; so is a FIFO or character device,
//    except for text reports, which are streamed into one (never renamed over it): the process's
//    own standard streams (/dev/stdout, /dev/stderr, /dev/fd/N), and a FIFO or character device
//    named directly (/dev/null, a named pipe);
//  - a command refuses an output that is one of its own inputs (apps/command_line.h).

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace qs {

// An output that cannot be written where it is asked for, or whose write failed; the message
// names the target.
class OutputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// What an output `target` is written as.
enum class OutputPlace {
    File,    // nothing there yet, a regular file or a symbolic link: a new file replaces it
    Stream,  // a standard stream, FIFO or character device: written into
};

// Whether a stream at the target is written into (text reports) or refused (every other output).
enum class Streams { Refused, Allowed };

// What `target` is written as, decided without following a link at it. Throws OutputError
// naming `target` for a folder, a block device, a socket, a descriptor that is not open for
// writing, and a stream unless `streams` allows one.
OutputPlace output_place(const std::filesystem::path& target, Streams streams);

// Writes `bytes` whole as `target` by the rule above; throws OutputError naming `target` and
// the cause (the previous file, if any, untouched).
void write_output(const std::filesystem::path& target, std::string_view bytes, Streams streams = Streams::Refused);

// Whether a folder an output goes into may be a symbolic link: a folder the user names may
// (it is where they send the output); a folder the command names inside it (an HTML report's
// images/, check's glsl/) may not, so that a link planted there cannot send files elsewhere.
enum class FolderLink { Followed, Refused };

// `folder`, made if missing (with its missing parents). Throws OutputError naming it when it or
// a parent is not a folder, or `folder` itself is a symbolic link and `link` refuses one.
void make_output_folder(const std::filesystem::path& folder, FolderLink link);

// Copies the regular file `source` (never a device or FIFO) whole as `target`, as write_output
// writes a file. Throws OutputError naming what failed.
void copy_to_output(const std::filesystem::path& source, const std::filesystem::path& target);

// The entry a path names: its folder resolved (symlinks, . and ..), its own name kept. An output
// replaces that entry, never what a link there points to.
std::filesystem::path entry_path(const std::filesystem::path& path);

// The files a command reads (a scene and the files it names, a suite, expected images...), to
// refuse an output that would overwrite one. Cheap for many: only an output with an input's file
// name has its folder resolved.
class InputFiles {
public:
    // `file` as named (its entry) and, when that is a link, the file it leads to.
    void add(const std::filesystem::path& file);
    // Whether `output`'s entry is one of the inputs: the input written over, not a link to it
    // (replacing a link leaves what it pointed to untouched).
    bool contains(const std::filesystem::path& output) const;

private:
    std::unordered_map<std::string, std::vector<std::string>> by_name_;  // file name -> entries
};

}  // namespace qs
