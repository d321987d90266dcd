// Fuzz target: clipping, triangle setup and the tile rasterizer on one triangle with hostile
// clip coordinates (NaN, infinities, huge, denormal, degenerate, behind the eye) and varyings,
// in a small image, any derivative rule, pairing, fill rule and row band. Checked: nothing
// crashes or overflows (UBSan), clipping keeps at most a fan of seven, setup's bounds stay inside
// the image, and every pixel of the frame (or band) is written.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "fuzz/fuzz_check.h"
#include "raster/clipper.h"
#include "raster/rasterizer.h"
#include "raster/triangle_setup.h"

namespace {

using namespace qs;

// Reads the input front to back; past its end, zeros.
class Bytes {
public:
    Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
    template <class T>
    T next() {
        T v{};
        unsigned char raw[sizeof(T)] = {};
        for (std::size_t i = 0; i < sizeof(T) && at_ < size_; ++i) raw[i] = data_[at_++];
        std::memcpy(&v, raw, sizeof(T));
        return v;
    }

private:
    const std::uint8_t* data_;
    std::size_t size_, at_ = 0;
};

constexpr float kUnwritten = -7777.25f;

// Vertex i's clip position and varyings come from the input; the fragment stage writes the first
// varying, gl_FragCoord.x and 1/w (never kUnwritten).
class FuzzProgram final : public Program {
public:
    FuzzProgram(const Needs& needs, const std::array<VertexOut, 3>& vertices) : vertices_(vertices) {
        info_.name = "fuzz", info_.needs = needs;
    }
    const ShaderInfo& info() const override { return info_; }
    void vertex(const VertexIn& in, const Uniforms&, VertexOut& out) const override {
        out = vertices_[std::size_t(in.texcoord.x)];
    }
    void shade(ShadeMode mode, const FragmentBatch& in, const Uniforms&, ColorBatch& out) const override {
        for (int i = 0; i < kBatchLanes; ++i) {
            const float v[4] = {info_.needs.varyings > 0 ? in.varying[0][i] : 0.0f, in.frag_coord[0][i], in.frag_coord[3][i], 1.0f};
            for (int c = 0; c < 4; ++c) out.rgba[c][i] = v[c] == kUnwritten ? 0.0f : v[c];
            if (mode.check_undefined) out.undefined[i] = 0;
        }
    }
    void shade_pair(ShadeMode mode, const FragmentBatch& a, const FragmentBatch& b, const Uniforms& u, ColorBatch& out_a,
                    ColorBatch& out_b) const override {
        shade(mode, a, u, out_a);
        shade(mode, b, u, out_b);
    }

private:
    ShaderInfo info_;
    const std::array<VertexOut, 3>& vertices_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    Bytes in(data, size);
    const int width = 1 + in.next<std::uint16_t>() % 200, height = 1 + in.next<std::uint16_t>() % 200;
    const std::uint8_t flags = in.next<std::uint8_t>(), mode = in.next<std::uint8_t>();
    const int varyings = in.next<std::uint8_t>() % (kMaxVaryings + 1);
    const unsigned flat = in.next<std::uint8_t>();
    const int band_rows = 64 * (1 + in.next<std::uint8_t>() % 4), band_pick = in.next<std::uint8_t>();
    std::array<VertexOut, 3> v{};
    for (VertexOut& vo : v) {
        for (int k = 0; k < 4; ++k) vo.clip[k] = in.next<float>();
        for (int k = 0; k < varyings; ++k) vo.varyings[std::size_t(k)] = in.next<float>();
    }
    const FillRule fill = flags & 1 ? FillRule::RightTop : FillRule::LeftBottom;

    // Clipping and setup on their own: what setup keeps lies inside the image.
    const Viewport viewport(width, height);
    const bool fused = flags & 32;
    std::array<ClipVertex, 3> cv;
    for (int i = 0; i < 3; ++i) {
        const glm::vec4& clip = v[std::size_t(i)].clip;
        cv[std::size_t(i)] = {clip, viewport.window(clip, fused), v[std::size_t(i)].varyings};
    }
    std::vector<std::array<ClipVertex, 3>> clipped;
    clip_triangle(cv[0], cv[1], cv[2], varyings, viewport, clipped);
    FUZZ_CHECK(clipped.size() <= 7);  // six planes cut a triangle into at most nine corners
    for (const auto& tri : clipped) {
        // A clipped vertex can still overflow (interpolating between coordinates near float's
        // largest); setup drops what does not map to finite window coordinates near the image.
        if (auto t = setup_triangle(tri, varyings, width, height, fill, flat, cv[2])) {
            FUZZ_CHECK(0 <= t->min_x && t->min_x <= t->max_x && t->max_x < width);
            FUZZ_CHECK(0 <= t->min_y && t->min_y <= t->max_y && t->max_y < height);
        }
    }

    // The whole rasterizer, one thread, into a frame or a band whose every pixel must be written.
    Needs needs;
    needs.coordinates = Coordinates::Object3D;
    needs.derivatives = mode & 1;
    needs.frag_coord = mode & 4;
    needs.varyings = varyings;
    needs.flat_varyings = flat;
    const FuzzProgram program(needs, v);
    const std::vector<VertexIn> vertices = {{{0, 0, 0}, {0, 0}}, {{0, 0, 0}, {1, 0}}, {{0, 0, 0}, {2, 0}}};
    const std::vector<std::uint32_t> indices = {0, 1, 2};
    DrawCall draw;
    draw.vertices = vertices, draw.indices = indices, draw.program = &program;
    RasterOptions options;
    const Derivatives rules[] = {Derivatives::Fine, Derivatives::CoarseLower, Derivatives::CoarseUpper, Derivatives::Analytic};
    options.derivatives = rules[(mode >> 3) & 3];
    options.pairing = flags & 2 ? QuadPairing::BottomUp : QuadPairing::TopDown;
    options.fill_rule = fill;
    options.fused_interpolation = flags & 4;
    options.fused_viewport = fused;
    options.force_general_path = flags & 8;
    options.check_undefined = (flags & 16) && options.derivatives != Derivatives::Analytic;
    options.threads = 1;
    const std::vector<RowBand> bands = image_bands(height, options.pairing, band_rows);
    const RowBand band = bands[std::size_t(band_pick) % bands.size()];
    Framebuffer fb;
    fb.rgba.assign(std::size_t(width) * std::size_t(band.end - band.begin) * 4, kUnwritten);
    rasterize_into(fb, width, height, glm::vec4(0.5f), std::span<const DrawCall>(&draw, 1), options, nullptr, band);
    FUZZ_CHECK(fb.rows == band.end - band.begin);
    FUZZ_CHECK(fb.rgba.size() == std::size_t(width) * std::size_t(fb.rows) * 4);
    for (float c : fb.rgba) FUZZ_CHECK(c != kUnwritten);
    return 0;
}
