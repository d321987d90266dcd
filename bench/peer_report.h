#pragma once
// What a peer child (quadshade-bench-throughput --peer-only) tells its parent on stdout: the
// GL_RENDERER string, which names the vector width llvmpipe compiled for ("llvmpipe (LLVM 15.0.6,
// 256 bits)"), and the frame times. Two lines, each starting with a tag, so that anything else
// a library prints on stdout is ignored, and parsed strictly: a missing, repeated, unknown or
// non-finite field is an error, never a measurement.
//
//   quadshade-peer-renderer llvmpipe (LLVM 15.0.6, 256 bits)
//   quadshade-peer-timing median_ms=12.5 min_ms=12.1 max_ms=13.9 setup_ms=31

#include <optional>
#include <string>
#include <string_view>

namespace qs::bench {

struct PeerReport {
    std::string renderer;  // GL_RENDERER
    double median_ms = 0, min_ms = 0, max_ms = 0;  // per frame
    double setup_ms = 0;   // context, GLSL compile, first frame
};

std::string format_peer_report(const PeerReport& report);

// Throws std::runtime_error saying what is wrong with `text` (the child's stdout).
PeerReport parse_peer_report(std::string_view text);

// The width in a llvmpipe GL_RENDERER string ("..., 512 bits)"), or nothing when it names none.
std::optional<int> vector_bits_of(std::string_view renderer);

}  // namespace qs::bench
