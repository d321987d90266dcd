#pragma once
// An off-screen OpenGL context with a float RGBA colour buffer, behind a small interface so
// that the OSMesa implementation (removed from Mesa in 25.1) can be replaced by an
// EGL-surfaceless one without touching the renderer.

#include <memory>
#include <string>
#include <vector>

namespace qs {

enum class GlDriver { Llvmpipe, Softpipe };

struct GlContextInfo {
    std::string vendor, renderer, version;
};

class GlContext {
public:
    virtual ~GlContext() = default;
    virtual GlContextInfo info() const = 0;
    // The colour buffer after glFinish, RGBA float, rows top-down.
    virtual std::vector<float> read_rgba() const = 0;
    virtual int width() const = 0;
    virtual int height() const = 0;
    // Makes this context the current one (a new context is current once created).
    virtual void make_current() = 0;
};

// Creates and makes current an OSMesa context of width x height with a 24-bit depth buffer.
// The Gallium driver is chosen through GALLIUM_DRIVER before the first context of the process;
// `threads` sets LP_NUM_THREADS (0: llvmpipe's default). Throws std::runtime_error on failure.
std::unique_ptr<GlContext> create_osmesa_context(int width, int height, GlDriver driver, int threads);

}  // namespace qs
