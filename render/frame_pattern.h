#pragma once
// Output file names of animation frames. An output name may come from a script or a web form: it
// is expanded here, by rule, and never handed to printf as a format.

#include <optional>
#include <string>

namespace qs {

// `pattern` for frame `frame`: %d and %0Nd (N = 1..9) become the frame number and %% a '%'; a
// pattern without '%' gets _NNNN before its extension. Throws std::invalid_argument for any other
// character after a '%', and for a pattern with '%' but no frame number (every frame would
// overwrite the last).
std::string frame_path(const std::string& pattern, int frame);

// The frame in [first, last] whose name under `pattern` is `name`, if there is one: whether two
// patterns ever name the same file, decided without listing every name (a frame's digits are
// read back from `name` and the few candidates expanded). Throws as frame_path for a bad pattern.
std::optional<int> frame_named(const std::string& pattern, const std::string& name, int first, int last);

// `pattern` with a folder of its own resolved (symlinks, . and ..), written as a '%' pattern
// (a name without '%' as its _%04d form), so that two spellings of one folder compare equal.
std::string resolved_pattern(const std::string& pattern);

}  // namespace qs
