#pragma once
// The reason a test is skipped for GLSL the front end does not run, from its message: the
// construct, without the file, the position and the test's own names, so that the tests skipped
// for one reason count together ("GLSL: sampler type 'sampler2DShadow' is not supported").

#include <string>

namespace qs::piglit {

// `message` is the front end's ("FILE:LINE:COL: what"), `file` the FILE it names.
std::string skip_reason_of(const std::string& message, const std::string& file);

}  // namespace qs::piglit
