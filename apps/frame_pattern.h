#pragma once
// Output file names of animation frames. An output name may come from a script or a web form: it
// is expanded here, by rule, and never handed to printf as a format.

#include <string>

namespace qs {

// `pattern` for frame `frame`: %d and %0Nd (N = 1..9) become the frame number and %% a '%'; a
// pattern without '%' gets _NNNN before its extension. Throws std::invalid_argument for any other
// character after a '%', and for a pattern with '%' but no frame number (every frame would
// overwrite the last).
std::string frame_path(const std::string& pattern, int frame);

}  // namespace qs
