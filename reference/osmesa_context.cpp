// The one file that includes OSMesa.
#include <GL/osmesa.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

#include "reference/gl_context.h"

namespace qs {

namespace {

class OsmesaContext final : public GlContext {
public:
    OsmesaContext(int w, int h) : width_(w), height_(h), buffer_(std::size_t(w) * std::size_t(h) * 4) {
        const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 0,
                               OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, 0};
        ctx_ = OSMesaCreateContextAttribs(attribs, nullptr);
        if (!ctx_) throw std::runtime_error("OSMesaCreateContextAttribs failed");
        try {
            make_current();
        } catch (...) {
            OSMesaDestroyContext(ctx_);
            throw;
        }
    }
    void make_current() override {
        if (OSMesaGetCurrentContext() == ctx_) return;
        if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_FLOAT, width_, height_)) {
            throw std::runtime_error("OSMesaMakeCurrent with a float buffer failed");
        }
        // Rows in `buffer_` top-down, like image files.
        OSMesaPixelStore(OSMESA_Y_UP, 0);
    }
    ~OsmesaContext() override { OSMesaDestroyContext(ctx_); }

    GlContextInfo info() const override {
        auto str = [](GLenum e) {
            const GLubyte* s = glGetString(e);
            return s ? std::string(reinterpret_cast<const char*>(s)) : std::string();
        };
        return {str(GL_VENDOR), str(GL_RENDERER), str(GL_VERSION)};
    }
    std::vector<float> read_rgba() const override {
        glFinish();
        return buffer_;
    }
    int width() const override { return width_; }
    int height() const override { return height_; }

private:
    int width_, height_;
    std::vector<float> buffer_;
    OSMesaContext ctx_ = nullptr;
};

}  // namespace

std::unique_ptr<GlContext> create_osmesa_context(int width, int height, GlDriver driver, int threads) {
    ::setenv("GALLIUM_DRIVER", driver == GlDriver::Softpipe ? "softpipe" : "llvmpipe", 1);
    if (threads > 0) ::setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), 1);
    return std::make_unique<OsmesaContext>(width, height);
}

}  // namespace qs
