#pragma once
// Reading a file whole, safely: only a regular file (never a folder, FIFO or device, which could
// block or never end), of bounded size, checked before anything is allocated for it.

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace qs {

class FileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The whole content of `path`, which must be a regular file of at most `max_bytes` (opened
// without following a final symlink unless `follow_symlink`, and without blocking, so that a FIFO
// or device is refused, never waited on or read forever). Throws FileError naming the path.
std::vector<unsigned char> read_regular_file(const std::filesystem::path& path, std::uint64_t max_bytes,
                                             bool follow_symlink = false);

// "2.0 GiB", "512 KiB": for messages about sizes.
std::string byte_size_text(std::uint64_t bytes);

}  // namespace qs
