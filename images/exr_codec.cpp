// OpenEXR through the OpenEXR library (exr_codec.h). Every call into it is inside a try block of
// the Decoder's or Encoder's own: its Iex exceptions (and std::bad_alloc) become messages here.
#include "images/exr_codec.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <ImfThreading.h>
#include <strings.h>

#include <Iex.h>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <thread>
#include <vector>

#include "images/image_io.h"

namespace qs::image_library {

namespace {

// OpenEXR checks a header's sizes against these before it allocates for them: no image or tile
// larger than quadshade reads or writes.
void set_size_limits() {
    static const bool once = [] {
        Imf::Header::setMaxImageSize(kMaxImageSide, kMaxImageSide);
        Imf::Header::setMaxTileSize(kMaxImageSide, kMaxImageSide);
        return true;
    }();
    (void)once;
}

// The threads of OpenEXR's pool that (de)compress an image of `rows` rows: a thread per core, as
// OpenImageIO sets it, for images of many blocks of rows; none (the calling thread does it all)
// for a few blocks, where starting the pool would cost more than it saves.
int threads_for(std::int64_t rows) {
    if (rows < 256) return 0;
    static const int threads = [] {
        const int n = int(std::max(1u, std::thread::hardware_concurrency()));
        Imf::setGlobalThreadCount(n);
        return n;
    }();
    return threads;
}

std::string openexr_error(const char* what) { return std::string("OpenEXR: ") + what; }

// The file's bytes in memory, as OpenEXR reads a file.
class MemoryStream final : public Imf::IStream {
public:
    MemoryStream(std::span<const unsigned char> bytes, const std::string& name)
        : IStream(name.c_str()), bytes_(bytes) {}
    bool isMemoryMapped() const override { return true; }
    bool read(char c[], int n) override {
        std::memcpy(c, take(n), std::size_t(n));
        return at_ < bytes_.size();
    }
    char* readMemoryMapped(int n) override {
        // OpenEXR only reads what it is given; the const_cast is its interface's.
        return const_cast<char*>(reinterpret_cast<const char*>(take(n)));
    }
    std::uint64_t tellg() override { return at_; }
    void seekg(std::uint64_t pos) override { at_ = pos; }

private:
    const unsigned char* take(int n) {
        if (n < 0 || at_ > bytes_.size() || std::size_t(n) > bytes_.size() - at_)
            throw Iex::InputExc("the file ends before its image does (truncated)");
        const unsigned char* p = bytes_.data() + at_;
        at_ += std::size_t(n);
        return p;
    }
    std::span<const unsigned char> bytes_;
    std::uint64_t at_ = 0;
};

// An Encoder's bytes, positioned, into its ByteSink: OpenEXR seeks back to the start of the file
// to write the offsets of the blocks of rows once they are known.
class SinkStream final : public Imf::OStream {
public:
    SinkStream(ByteSink& sink, const std::string& name) : OStream(name.c_str()), sink_(sink) {}
    void write(const char c[], int n) override {
        if (n < 0 || sink_.write_at(c, std::size_t(n), std::int64_t(at_)) != std::size_t(n))
            throw Iex::IoExc("a write to the file failed");
        at_ += std::uint64_t(n);
    }
    std::uint64_t tellp() override { return at_; }
    void seekp(std::uint64_t pos) override { at_ = pos; }

private:
    ByteSink& sink_;
    std::uint64_t at_ = 0;
};

// A channel in the order OpenImageIO presents it: by layer (the name up to its last dot), then the
// known names (R, G, B, Y, A and the rest of this list, in its order, in any case), then as stored
// (the file's channel list, by name).
struct OrderedChannel {
    std::string name, layer;
    int known = 0, stored = 0;
    Imf::PixelType type = Imf::HALF;
};

std::vector<OrderedChannel> oiio_channel_order(const Imf::ChannelList& list) {
    static const char* const kKnown[] = {"R",  "Red", "G",  "Green", "B",  "Blue", "Y", "real", "imag", "A",
                                         "Alpha", "AR", "RA", "AG", "GA", "AB", "BA", "Z", "Depth", "Zback"};
    std::vector<OrderedChannel> channels;
    int stored = 0;
    for (auto c = list.begin(); c != list.end(); ++c, ++stored) {
        if (c.channel().xSampling != 1 || c.channel().ySampling != 1)
            throw Iex::ArgExc(std::string("channel '") + c.name() + "' is subsampled, which quadshade does not read");
        OrderedChannel o{c.name(), "", int(std::size(kKnown)), stored, c.channel().type};
        const std::size_t dot = o.name.rfind('.');
        const std::string suffix = dot == std::string::npos ? o.name : o.name.substr(dot + 1);
        if (dot != std::string::npos) o.layer = o.name.substr(0, dot + 1);
        for (int k = 0; k < int(std::size(kKnown)); ++k) {
            if (::strcasecmp(suffix.c_str(), kKnown[k]) == 0) {
                o.known = k;
                break;
            }
        }
        channels.push_back(std::move(o));
    }
    std::sort(channels.begin(), channels.end(), [](const OrderedChannel& a, const OrderedChannel& b) {
        if (a.layer != b.layer) return a.layer < b.layer;
        return a.known != b.known ? a.known < b.known : a.stored < b.stored;
    });
    return channels;
}

int sample_bytes(Imf::PixelType type) { return type == Imf::HALF ? 2 : 4; }

// A float as OpenImageIO converts it to 8 bits: scaled, half added away from zero (in float
// arithmetic, so that 0.49999997 / 255 becomes 1), clamped (NaN to 0), truncated.
std::uint8_t to_unorm8(float v) {
    float s = v * 255.0f;
    s += s < 0.0f ? -0.5f : 0.5f;
    return std::uint8_t(s >= 0.0f ? (s <= 255.0f ? s : 255.0f) : 0.0f);
}

class ExrDecoder final : public Decoder {
public:
    ExrDecoder(std::span<const unsigned char> bytes, const std::string& name) : stream_(bytes, name) {}

    // Reads the header; false, error() saying why, on failure.
    bool start() {
        try {
            set_size_limits();
            file_ = std::make_unique<Imf::InputFile>(stream_, 0);
            const Imf::Header& header = file_->header();
            window_ = header.dataWindow();
            channels_ = oiio_channel_order(header.channels());
            const std::int64_t width = std::int64_t(window_.max.x) - window_.min.x + 1;
            const std::int64_t height = std::int64_t(window_.max.y) - window_.min.y + 1;
            int bytes = 0;
            for (const OrderedChannel& c : channels_) bytes = std::max(bytes, sample_bytes(c.type));
            // The sides fit an int: the header's sanity check refused larger ones (set_size_limits).
            shape_ = {int(width), int(height), 1, int(channels_.size()), bytes};
            const int threads = threads_for(height);
            if (threads > 0) {  // reopened on the pool, now that the image is known to be large
                stream_.seekg(0);
                file_ = std::make_unique<Imf::InputFile>(stream_, threads);
            }
            return true;
        } catch (const std::exception& e) {
            return fail(openexr_error(e.what()));
        }
    }
    ImageShape shape() const override { return shape_; }

    bool read(int channels, float* out) override {
        if (channels < 1 || channels > shape_.channels)
            return fail("cannot read " + std::to_string(channels) + " channels");
        return read_rows(0, shape_.height, channels, out);
    }

    // Blocks of rows read as floats, then converted.
    bool read(int channels, std::uint8_t* out) override {
        if (channels < 1 || channels > shape_.channels)
            return fail("cannot read " + std::to_string(channels) + " channels");
        const std::size_t row = std::size_t(shape_.width) * std::size_t(channels);
        const int block = int(std::clamp<std::size_t>((std::size_t(1) << 20) / row, 1, std::size_t(shape_.height)));
        std::vector<float> floats(row * std::size_t(block));
        for (int y = 0; y < shape_.height; y += block) {
            const int end = std::min(y + block, shape_.height);
            if (!read_rows(y, end, channels, floats.data())) return false;
            std::transform(floats.begin(), floats.begin() + std::ptrdiff_t(row * std::size_t(end - y)),
                           out + std::size_t(y) * row, to_unorm8);
        }
        return true;
    }
    std::string error() override { return error_; }

private:
    bool fail(std::string message) {
        error_ = std::move(message);
        return false;
    }

    // Rows [first, end) of the data window, the first `channels` channels, into `out` as floats:
    // half and float by OpenEXR, unsigned samples read as they are into the floats' places and
    // scaled to [0, 1] as OpenImageIO scales them.
    bool read_rows(int first, int end, int channels, float* out) {
        try {
            const std::size_t x_stride = std::size_t(channels) * sizeof(float);
            const Imath::V2i origin(window_.min.x, window_.min.y + first);
            Imf::FrameBuffer frame;
            for (int c = 0; c < channels; ++c) {
                const Imf::PixelType type = channels_[std::size_t(c)].type == Imf::UINT ? Imf::UINT : Imf::FLOAT;
                frame.insert(channels_[std::size_t(c)].name,
                             Imf::Slice::Make(type, out + c, origin, shape_.width, end - first, x_stride,
                                              x_stride * std::size_t(shape_.width)));
            }
            file_->setFrameBuffer(frame);
            file_->readPixels(window_.min.y + first, window_.min.y + end - 1);
        } catch (const std::exception& e) {
            return fail(openexr_error(e.what()));
        }
        const std::size_t pixels = std::size_t(shape_.width) * std::size_t(end - first);
        for (int c = 0; c < channels; ++c) {
            if (channels_[std::size_t(c)].type != Imf::UINT) continue;
            for (std::size_t p = 0; p < pixels; ++p) {
                float& v = out[p * std::size_t(channels) + std::size_t(c)];
                std::uint32_t u;
                std::memcpy(&u, &v, sizeof u);
                v = float(u) * (1.0f / float(std::numeric_limits<std::uint32_t>::max()));
            }
        }
        return true;
    }

    MemoryStream stream_;
    std::unique_ptr<Imf::InputFile> file_;  // reads through stream_
    Imath::Box2i window_;
    std::vector<OrderedChannel> channels_;
    ImageShape shape_;
    std::string error_;
};

// OpenImageIO's names for an image's 1 to 4 channels.
const char* const kChannelNames[4][4] = {{"Y"}, {"R", "G"}, {"R", "G", "B"}, {"R", "G", "B", "A"}};

class ExrEncoder final : public Encoder {
public:
    bool open(const std::string& file_name, ByteSink& sink, const EncoderSpec& spec) override {
        if (!spec.floats) return fail("OpenEXR is written with float samples only");
        if (spec.channels < 1 || spec.channels > 4)
            return fail("OpenEXR is written with 1 to 4 channels here, not " + std::to_string(spec.channels));
        if (spec.width <= 0 || spec.height <= 0) return fail("OpenEXR cannot hold an image of no pixels");
        try {
            set_size_limits();
            Imf::Header header(spec.width, spec.height);  // ZIP compression, rows top-down, as OpenImageIO's
            for (int c = 0; c < spec.channels; ++c)
                header.channels().insert(kChannelNames[spec.channels - 1][c], Imf::FLOAT);
            for (const auto& [key, value] : spec.attributes) header.insert(key, Imf::StringAttribute(value));
            stream_ = std::make_unique<SinkStream>(sink, file_name);
            file_ = std::make_unique<Imf::OutputFile>(*stream_, header, threads_for(spec.height));
        } catch (const std::exception& e) {
            return fail(openexr_error(e.what()));
        }
        width_ = spec.width, height_ = spec.height, channels_ = spec.channels;
        return true;
    }

    bool write_rows(int first, int end, bool floats, const void* pixels) override {
        if (!file_) return fail("the OpenEXR writer is not open");
        if (!floats) return fail("OpenEXR is written with float samples only");
        if (first != next_row_ || end < first || end > height_) return fail("rows written out of order");
        try {
            const std::size_t x_stride = std::size_t(channels_) * sizeof(float);
            Imf::FrameBuffer frame;
            for (int c = 0; c < channels_; ++c) {
                frame.insert(kChannelNames[channels_ - 1][c],
                             Imf::Slice::Make(Imf::FLOAT, static_cast<const float*>(pixels) + c, Imath::V2i(0, first),
                                              width_, end - first, x_stride, x_stride * std::size_t(width_)));
            }
            file_->setFrameBuffer(frame);
            file_->writePixels(end - first);
        } catch (const std::exception& e) {
            return fail(openexr_error(e.what()));
        }
        next_row_ = end;
        return true;
    }

    // OpenEXR writes the blocks' offsets as the file closes, and reports nothing of it: a write
    // that fails there is the sink's to record (ByteSink).
    bool close() override {
        if (!file_) return fail("the OpenEXR writer is not open");
        if (next_row_ != height_) {
            file_.reset();
            return fail("closed after " + std::to_string(next_row_) + " of " + std::to_string(height_) + " rows");
        }
        file_.reset();
        return true;
    }

    std::string error() override { return error_; }

private:
    bool fail(std::string message) {
        error_ = std::move(message);
        return false;
    }

    std::unique_ptr<SinkStream> stream_;
    std::unique_ptr<Imf::OutputFile> file_;  // destroyed first: it writes through stream_
    int width_ = 0, height_ = 0, channels_ = 0, next_row_ = 0;
    std::string error_;
};

}  // namespace

std::unique_ptr<Decoder> open_exr(std::span<const unsigned char> bytes, const std::string& name, std::string& error) {
    auto decoder = std::make_unique<ExrDecoder>(bytes, name);
    if (!decoder->start()) {
        error = decoder->error();
        return nullptr;
    }
    return decoder;
}

std::unique_ptr<Encoder> create_exr() { return std::make_unique<ExrEncoder>(); }

}  // namespace qs::image_library
