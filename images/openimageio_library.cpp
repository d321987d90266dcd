// The one file that includes OpenImageIO: image_library.h's Library over it, built into the
// module libquadshade-openimageio.so (modules/module_loader.h), whose one exported symbol is
// quadshade_image_library.

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include "images/image_library.h"

namespace qs::image_library {

namespace {

OIIO::ImageBuf wrap(int width, int height, const float* rgba) {
    // Read only: OpenImageIO's wrapping constructor takes a non-const pointer.
    return OIIO::ImageBuf(OIIO::ImageSpec(width, height, 4, OIIO::TypeDesc::FLOAT), const_cast<float*>(rgba));
}

class OiioDecoder final : public Decoder {
public:
    OiioDecoder(std::unique_ptr<OIIO::ImageInput> in, std::unique_ptr<OIIO::Filesystem::IOMemReader> memory)
        : memory_(std::move(memory)), in_(std::move(in)) {}
    ImageShape shape() const override {
        const OIIO::ImageSpec& s = in_->spec();
        return {s.width, s.height, s.depth, s.nchannels, int(s.format.size())};
    }
    bool read(int channels, float* out) override {
        return in_->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, out);
    }
    bool read(int channels, std::uint8_t* out) override {
        return in_->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, out);
    }
    std::string error() override { return in_->geterror(); }

private:
    std::unique_ptr<OIIO::Filesystem::IOMemReader> memory_;
    std::unique_ptr<OIIO::ImageInput> in_;  // destroyed first: it reads through memory_
};

// OpenImageIO writes through this into the sink, every write positioned.
class SinkProxy final : public OIIO::Filesystem::IOProxy {
public:
    SinkProxy(const std::string& name, ByteSink& sink) : IOProxy(name, Write), sink_(sink) {}
    const char* proxytype() const override { return "quadshade-sink"; }
    size_t write(const void* buf, size_t size) override {
        const size_t n = pwrite(buf, size, m_pos);
        m_pos += std::int64_t(n);
        return n;
    }
    size_t pwrite(const void* buf, size_t size, int64_t offset) override { return sink_.write_at(buf, size, offset); }
    size_t read(void* buf, size_t size) override {
        const size_t n = pread(buf, size, m_pos);
        m_pos += std::int64_t(n);
        return n;
    }
    size_t pread(void* buf, size_t size, int64_t offset) override { return sink_.read_at(buf, size, offset); }
    size_t size() const override { return size_t(sink_.size()); }

private:
    ByteSink& sink_;
};

class OiioEncoder final : public Encoder {
public:
    explicit OiioEncoder(std::unique_ptr<OIIO::ImageOutput> out) : out_(std::move(out)) {}
    ~OiioEncoder() override {
        if (out_) out_->close();
    }
    bool open(const std::string& file_name, ByteSink& sink, const EncoderSpec& s) override {
        proxy_ = std::make_unique<SinkProxy>(file_name, sink);
        OIIO::ImageSpec spec(s.width, s.height, s.channels, s.floats ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
        for (const auto& [key, value] : s.attributes) spec.attribute(key, value);
        return out_->set_ioproxy(proxy_.get()) && out_->open(file_name, spec);
    }
    bool write_rows(int first, int end, bool floats, const void* pixels) override {
        return out_->write_scanlines(first, end, 0, floats ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8, pixels);
    }
    bool close() override {
        const bool closed = out_->close();
        close_error_ = closed ? "" : OIIO::geterror();
        out_.reset();
        return closed;
    }
    std::string error() override { return out_ ? out_->geterror() : close_error_; }

private:
    std::unique_ptr<SinkProxy> proxy_;
    std::unique_ptr<OIIO::ImageOutput> out_;  // destroyed first: it writes through proxy_
    std::string close_error_;
};

class OpenImageIO final : public Library {
public:
    std::unique_ptr<Decoder> open(std::span<const unsigned char> bytes, const std::string& name, const std::string& format,
                                  bool unassociated_alpha, std::string& error) const override {
        auto memory = std::make_unique<OIIO::Filesystem::IOMemReader>(bytes.data(), bytes.size());
        auto in = OIIO::ImageInput::create(format, false);
        OIIO::ImageSpec config;
        if (unassociated_alpha) config.attribute("oiio:UnassociatedAlpha", 1);
        // OpenImageIO 2.4 reads from memory through this hint (its open()'s proxy argument alone
        // still looks for a file).
        void* proxy = memory.get();
        config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
        OIIO::ImageSpec opened;
        if (!in || !in->set_ioproxy(memory.get()) || !in->open(name, opened, config)) {
            error = in ? in->geterror() : OIIO::geterror();
            return nullptr;
        }
        return std::make_unique<OiioDecoder>(std::move(in), std::move(memory));
    }

    std::unique_ptr<Encoder> create(const std::string& file_name, std::string& error) const override {
        auto out = OIIO::ImageOutput::create(file_name);
        if (!out) {
            error = "no image format for this file name: " + OIIO::geterror();
            return nullptr;
        }
        if (!out->supports("ioproxy")) {
            error = "OpenImageIO cannot write this format through a checked file";
            return nullptr;
        }
        return std::make_unique<OiioEncoder>(std::move(out));
    }

    Comparison compare(int width, int height, const float* a, const float* b, float fail_threshold,
                       float warn_threshold) const override {
        const OIIO::ImageBuf A = wrap(width, height, a), B = wrap(width, height, b);
        OIIO::ROI rgb = A.roi();
        rgb.chbegin = 0, rgb.chend = 3;
        const OIIO::ImageBufAlgo::CompareResults r = OIIO::ImageBufAlgo::compare(A, B, fail_threshold, warn_threshold, rgb);
        // r.error is also set whenever a pixel fails (OIIO 2.4), so it is not an error here.
        Comparison c;
        c.mean_error = r.meanerror, c.rms_error = r.rms_error, c.psnr = r.PSNR, c.max_error = r.maxerror;
        c.max_x = r.maxx, c.max_y = r.maxy, c.max_channel = r.maxc;
        c.pixels_over_fail = r.nfail, c.pixels_over_warn = r.nwarn;
        return c;
    }

    void absolute_difference(int width, int height, const float* a, const float* b, float* out) const override {
        const OIIO::ImageBuf diff = OIIO::ImageBufAlgo::absdiff(wrap(width, height, a), wrap(width, height, b));
        diff.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, out);
    }

    bool draw_text(int width, int height, float* rgba, int x, int y, std::string_view text, int size,
                   const std::string& font, std::string& error) const override {
        OIIO::ImageBuf buf(OIIO::ImageSpec(width, height, 4, OIIO::TypeDesc::FLOAT), rgba);
        const float white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
        if (!OIIO::ImageBufAlgo::render_text(buf, x, y, text, size, font, OIIO::cspan<float>(white, 4))) {
            error = buf.geterror();
            return false;
        }
        return true;
    }
};

}  // namespace

}  // namespace qs::image_library

extern "C" __attribute__((visibility("default"))) const qs::image_library::Library* quadshade_image_library() {
    static const qs::image_library::OpenImageIO library;
    return &library;
}
