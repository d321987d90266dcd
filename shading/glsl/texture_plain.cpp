// The plain 2D lookup, the kind most shaders make: one level, one filter, the 8-bit path of
// llvmpipe's sampler (lp_bld_sample_aos.c) with the axes' wrap modes fixed at compile time, and
// texels read by loads and permutes where a register's lanes read neighbouring ones.
// Every rule here was checked bit for bit against OSMesa (docs/design.md, "Textures").

#include "shading/glsl/texture.h"
#include "shading/glsl/texture_filter_8bit.h"
#include "shading/glsl/texture_lanes.h"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>

namespace qs::glsl {

namespace texture_detail {

namespace {

// ---- the plain 2D lookup: one level, one filter, the 8-bit path ---------------------------
// What single_texture and the halftone do: a 2D texture whose sampler needs no level of detail
// (min == mag, no mipmaps), REPEAT or CLAMP_TO_EDGE, no derivatives. The same arithmetic as
// sample_lanes takes there (choose_levels' first case, aos_level at level 0), with the axes'
// modes fixed at compile time, and one more thing: a texel is gathered only when some lane's
// weight reads it. llvmpipe's 8-bit lerp with weight 0 returns its first operand exactly
// (a + ((0 (b - a) + 128) >> 8) = a), so where every lane's weight along x (or y) is 0 the
// second column (row) changes nothing; lookups at texel centres, as the halftone's explicit
// bilinear filter makes them, read one texel per lane instead of four.
enum class AxisMode { Clamp, RepeatPot, RepeatNpot };

template <AxisMode M, class F>
[[gnu::always_inline]] inline AxisLanes<F> plain_linear_axis(const F& s, const IntsLike<F>& size, const IntsLike<F>& active) {
    AxisLanes<F> a = aos_linear(s, size, M == AxisMode::Clamp ? Wrap::ClampToEdge : Wrap::Repeat, M != AxisMode::RepeatNpot);
    a.w8 = a.w8 & active;  // lanes past the lookup's end weigh nothing (their results are dropped)
    return a;
}
template <AxisMode M, class F>
[[gnu::always_inline]] inline IntsLike<F> plain_nearest_axis(const F& s, const IntsLike<F>& size) {
    return aos_nearest(s, size, M == AxisMode::Clamp ? Wrap::ClampToEdge : Wrap::Repeat, M != AxisMode::RepeatNpot);
}

// gather(texels, index) where the lanes read texels close together, as a magnified texture's
// neighbouring pixels do: when every lane's index lies within 8 texels from lane 0's (and those
// 8 are inside the texture), one load of those 8 and a permute across lanes (vpermd) instead of
// the gather, which costs about as much as 8 separate loads; else, when the register's two
// pixel rows (lanes 0, 1, 4, 5 and 2, 3, 6, 7 of two quads, number/lanes.h) read two texel
// rows, each within 8 texels of its first lane's, two loads, two permutes and a blend. The same
// texels in every case. The plain lookup's on a CPU without AVX-512 (with it, the one below).
[[maybe_unused]] Uints gather_near(const std::uint32_t* texels, std::size_t count, const Ints& index) {
    if constexpr (simd::register_bytes >= sizeof(Uints)) {
        const std::int32_t base = index[0];
        const Ints d = index - base;
        const auto window = [&](std::int32_t at) { return simd::load<Uints>(texels + at); };
        if (std::size_t(base) + L <= count) {
            if (!any(d & ~(L - 1))) return simd::permute(window(base), d);
            const std::int32_t upper_base = index[2];
            static constexpr Ints kUpper{0, 0, -1, -1, 0, 0, -1, -1};
            const Ints d2 = kUpper ? index - upper_base : d;
            if (std::size_t(upper_base) + L <= count && !any(d2 & ~(L - 1))) {
                return simd::blend<0xcc>(simd::permute(window(base), d2), simd::permute(window(upper_base), d2));
            }
        }
    }
    return gather(texels, index);
}

// Sixteen lanes, a 4x4 block of pixels (four quads, core/block_layout.h), where the TexelWindow
// below does not hold their texels (a minified or wrapped texture, lanes in another order):
// windows of 16 texels, one per texel row the lanes read, each lane permuted from the window
// that holds its texel. The first window starts at the lesser index of lane 8, the block's
// lower left pixel in GL's window, and lane 0, the first of a row of pixels laid out in order:
// on a texture mapped without a flip, the least index either way. Each next window starts at
// the first lane still left; lanes that four windows do not hold are gathered. The plain
// lookup's where a register holds sixteen lanes.
[[maybe_unused]] LanesOf<16>::Uints gather_near(const std::uint32_t* texels, std::size_t count, const LanesOf<16>::Ints& index) {
    using U = LanesOf<16>::Uints;
    using I = LanesOf<16>::Ints;
    U texel{};
    simd::LaneBits left = 0xffff;
    std::int32_t first = std::min(index[0], index[8]);
    for (int window = 0; window < 4 && std::size_t(first) + 16 <= count; ++window) {
        const I d = index - first;
        const simd::LaneBits held = left & simd::none_common_bits(d, simd::splat<I>(~15));  // 0 <= d < 16
        texel = simd::permute_into(texel, held, simd::load<U>(texels + first), d);
        left &= ~held;
        if (left == 0) return texel;
        first = index[std::countr_zero(left)];
    }
    return simd::gather_into(texel, left, texels, index);
}

// Four texel rows of eight texels from (x0, y0), in two registers: what a 4x4 block reads where
// the texture is magnified (at 1x to 4x its 16 pixels reach two to four rows and columns, their
// bilinear neighbours one more each). Each lane's texel is one two-source permute (vpermt2d) by
// its offset in the window: straight code in place of gather_near's chain of windows, whose
// every step waits on the one before (single texture's square at 500x500: 0.82 against 1.12 ms
// at best). Opened at the least column and row the block's lanes read, moved back from the
// texture's far edges so that its loads stay inside level 0 (every index is in [0, size) after
// wrap or clamp). Used where a register holds sixteen lanes.
class TexelWindow {
public:
    using Uints = LanesOf<16>::Uints;
    using Ints = LanesOf<16>::Ints;
    static constexpr int kColumns = 8, kRows = 4;
    static bool fits(const Texture& tex) { return tex.width >= kColumns && tex.height >= kRows; }

    // The least column and row a register's lanes read are at its block's corners, where its
    // texels are a monotonic function of its pixels' position (an affine or projective map,
    // clamped): lanes 2, 7, 8 and 13 of core/block_layout.h's 4x4 block. Lanes in any other
    // order may find the window short and take gather_near.
    TexelWindow(const std::uint32_t* texels, int width, int height, const Ints& x, const Ints& y) {
        // x's corners in lanes 0-3, y's in 4-7; the least of each in lanes 0 and 4.
        static constexpr Ints kCorners{2, 7, 8, 13, 18, 23, 24, 29, 0, 0, 0, 0, 0, 0, 0, 0};
        using Eight = LanesOf<8>::Ints;
        const Ints corners = simd::lookup(x, y, kCorners);
        Eight m = __builtin_shufflevector(corners, corners, 0, 1, 2, 3, 4, 5, 6, 7);
        m = imin(m, __builtin_shufflevector(m, m, 2, 3, 0, 1, 6, 7, 4, 5));
        m = imin(m, __builtin_shufflevector(m, m, 1, 0, 3, 2, 5, 4, 7, 6));
        const int x0 = std::min(m[0], width - kColumns);
        const int y0 = std::min(m[4], height - kRows);
        const auto row = [&](int r) { return simd::load<LanesOf<8>::Uints>(texels + std::ptrdiff_t(y0 + r) * width + x0); };
        rows01_ = __builtin_shufflevector(row(0), row(1), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
        rows23_ = __builtin_shufflevector(row(2), row(3), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
        x0_ = simd::splat<Ints>(x0), y0_ = simd::splat<Ints>(y0);
    }
    // Whether the window holds every texel of the lanes whose columns are xa's or xb's and
    // rows ya's or yb's (a bilinear lookup's four; a nearest one's, xb = xa and yb = ya).
    bool holds(const Ints& xa, const Ints& ya, const Ints& xb, const Ints& yb) const {
        const Ints dx = (xa - x0_) | (xb - x0_);
        const Ints dy = (ya - y0_) | (yb - y0_);
        return (simd::less_unsigned_bits(dx, simd::splat<Ints>(kColumns)) &
                simd::less_unsigned_bits(dy, simd::splat<Ints>(kRows))) == 0xffff;
    }
    // The texels at (x, y), for lanes the window holds.
    Uints texels(const Ints& x, const Ints& y) const { return simd::lookup(rows01_, rows23_, ((y - y0_) << 3) + (x - x0_)); }

private:
    Uints rows01_, rows23_;  // rows y0, y0 + 1 | y0 + 2, y0 + 3, each from column x0
    Ints x0_, y0_;
};

// The plain lookup's register: one AVX-512 register of sixteen lanes where the CPU has one
// (a bilinear lookup in about half the time of two 8-lane registers).
constexpr int kPlainLanes = simd::register_floats >= 16 ? 16 : L;
// kPlainLanes as a value of a lookup's template: the sixteen-lane code below is compiled only
// where it is taken.
template <AxisMode>
constexpr int kPlainLanesOf = kPlainLanes;

// 0, 1, 2, ... in the lanes of I.
template <class I>
I lane_indices() {
    I r;
    for (int i = 0; i < lanes_in<I>; ++i) r[i] = i;
    return r;
}

// A register's filtered texels as the lookup's four channels.
template <class U>
[[gnu::always_inline]] inline void store_texels(const PlainLookup& l, int base, int n, const PairsOf<U>& q) {
    // Unrolled, the texels stay in registers (as a loop, GCC picked each channel's half
    // through memory: the halftone's frame took 7% longer).
#pragma GCC unroll 4
    for (int c = 0; c < 4; ++c) store_lanes(l.rgba[std::size_t(c)], base, n, unorm(channel(q, c)));
}

// llvmpipe's 8-bit filter of the texels texel(x, y) returns: the nearest, or the bilinear lerps
// of the four (x.i0 or x.i1, y.i0 or y.i1) by the weights x.w8 and y.w8, skipping a column or
// row of texels that no lane weighs (the lerp by 0 returns its first operand).
template <bool Linear, class F, class Texel>
[[gnu::always_inline]] inline auto filter(const AxisLanes<F>& x, const AxisLanes<F>& y, Texel texel) {
    auto q = split(texel(x.i0, y.i0));
    if constexpr (Linear) {
        const bool along_x = any(x.w8), along_y = any(y.w8);
        if (along_x) q = lerp8(x.w8, q, split(texel(x.i1, y.i0)));
        if (along_y) {
            auto q1 = split(texel(x.i0, y.i1));
            if (along_x) q1 = lerp8(x.w8, q1, split(texel(x.i1, y.i1)));
            q = lerp8(y.w8, q, q1);
        }
    }
    return q;
}

// Flattened, so that gather_near is inlined whatever GCC would choose: a variant of it with one
// more branch became a call (its index vector then went through memory), and the
// single-texture square took 5.7 ms against 3.6 at best.
template <AxisMode MS, AxisMode MT, bool Linear>
[[gnu::flatten]] void sample_plain_2d(const Texture& tex, const PlainLookup& l) {
    constexpr int kLanes = kPlainLanesOf<MS>;
    using F = typename LanesOf<kLanes>::Floats;
    using I = typename LanesOf<kLanes>::Ints;
    const I width = I{} + tex.width, height = I{} + tex.height;
    const std::uint32_t* t = tex.texels.data();
    const std::size_t count = tex.texels.size();
    const bool window_fits = kLanes == 16 && TexelWindow::fits(tex);
    for (int base = 0; base < l.lanes; base += kLanes) {
        const int n = std::min(l.lanes - base, kLanes);
        const F s = load_lanes<F>(l.s, base, n), tc = load_lanes<F>(l.t, base, n);
        AxisLanes<F> x, y;
        if constexpr (Linear) {
            const I active = lane_indices<I>() < n;
            x = plain_linear_axis<MS>(s, width, active), y = plain_linear_axis<MT>(tc, height, active);
        } else {
            x.i0 = plain_nearest_axis<MS>(s, width), y.i0 = plain_nearest_axis<MT>(tc, height);
        }
        if constexpr (kLanes == 16) {
            if (window_fits && n == kLanes) {
                const TexelWindow window(t, tex.width, tex.height, x.i0, y.i0);
                if (window.holds(x.i0, y.i0, Linear ? x.i1 : x.i0, Linear ? y.i1 : y.i0)) {
                    store_texels(l, base, n, filter<Linear>(x, y, [&](const I& xi, const I& yi) { return window.texels(xi, yi); }));
                    continue;
                }
            }
        }
        store_texels(l, base, n, filter<Linear>(x, y, [&](const I& xi, const I& yi) { return gather_near(t, count, yi * width + xi); }));
    }
}

using PlainSampler = void (*)(const Texture&, const PlainLookup&);
template <AxisMode MS, AxisMode MT>
PlainSampler plain_sampler(bool linear) {
    return linear ? &sample_plain_2d<MS, MT, true> : &sample_plain_2d<MS, MT, false>;
}
template <AxisMode MS>
PlainSampler plain_sampler(AxisMode mt, bool linear) {
    switch (mt) {
        case AxisMode::Clamp: return plain_sampler<MS, AxisMode::Clamp>(linear);
        case AxisMode::RepeatPot: return plain_sampler<MS, AxisMode::RepeatPot>(linear);
        case AxisMode::RepeatNpot: break;
    }
    return plain_sampler<MS, AxisMode::RepeatNpot>(linear);
}
// The plain lookup's function for this texture, or null where its lookups are not plain ones.
PlainSampler plain_sampler(const Texture& tex) {
    const SamplerState& st = tex.sampler;
    if (tex.dims != 2 || tex.format != TexelFormat::Rgba8 || st.min != st.mag || st.mip != MipFilter::None ||
        st.wrap_s == Wrap::MirroredRepeat || st.wrap_t == Wrap::MirroredRepeat) {
        return nullptr;
    }
    auto mode = [](Wrap w, int size) {
        return w == Wrap::ClampToEdge ? AxisMode::Clamp : std::has_single_bit(unsigned(size)) ? AxisMode::RepeatPot : AxisMode::RepeatNpot;
    };
    const AxisMode ms = mode(st.wrap_s, tex.width), mt = mode(st.wrap_t, tex.height);
    const bool linear = st.min == Filter::Linear;
    switch (ms) {
        case AxisMode::Clamp: return plain_sampler<AxisMode::Clamp>(mt, linear);
        case AxisMode::RepeatPot: return plain_sampler<AxisMode::RepeatPot>(mt, linear);
        case AxisMode::RepeatNpot: break;
    }
    return plain_sampler<AxisMode::RepeatNpot>(mt, linear);
}
}  // namespace

bool sample_plain(const Texture& tex, const PlainLookup& l) {
    const PlainSampler plain = plain_sampler(tex);
    if (plain) plain(tex, l);
    return plain != nullptr;
}

}  // namespace texture_detail

}  // namespace qs::glsl
