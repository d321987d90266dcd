// texture2D's lanes, as Mesa 22.3's llvmpipe samples GL_RGBA8 (lp_bld_sample_aos.c,
// lp_bld_sample_soa.c, lp_bld_sample.c), and glGenerateMipmap as llvmpipe makes the levels.
// Every rule here was checked bit for bit against OSMesa (docs/design.md, "Textures").
//
// Sixteen lanes at a time as GCC/Clang generic vectors; the conversions, rounding and gathers
// llvmpipe's code compiles to are x86 instructions with the same rounding and out-of-range
// results (cvtps2dq, cvttps2dq, roundps), written with intrinsics where the ISA has them.

#include "shading/glsl/texture.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <utility>
#include <string>

#include <immintrin.h>

// Sixteen-lane vectors are passed between this file's functions only (all inlined or internal):
// GCC's note that their calling convention differs with AVX-512 concerns nothing here.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace qs::glsl {

namespace {

constexpr int L = texture_detail::kMaxLanes;
typedef float Floats __attribute__((vector_size(L * sizeof(float))));
typedef std::int32_t Ints __attribute__((vector_size(L * sizeof(std::int32_t))));
typedef std::uint32_t Uints __attribute__((vector_size(L * sizeof(std::uint32_t))));

Floats splat(float v) { return Floats{} + v; }
Ints splat(std::int32_t v) { return Ints{} + v; }
Floats to_float(const Ints& v) { return __builtin_convertvector(v, Floats); }
Ints bits(const Floats& v) {
    Ints r;
    std::memcpy(&r, &v, sizeof r);
    return r;
}
Floats from_bits(const Ints& v) {
    Floats r;
    std::memcpy(&r, &v, sizeof r);
    return r;
}
// a + b modulo 2^32, as llvmpipe's integer adds (no undefined overflow).
Ints wrapping_add(const Ints& a, const Ints& b) { return Ints(Uints(a) + Uints(b)); }

// SSE semantics: minps/maxps return the second operand when either is NaN.
Floats minps(const Floats& a, const Floats& b) { return a < b ? a : b; }
Floats maxps(const Floats& a, const Floats& b) { return a > b ? a : b; }
Ints imin(const Ints& a, const Ints& b) { return a < b ? a : b; }
bool any(const Ints& m) {
    Ints zero{};
    return std::memcmp(&m, &zero, sizeof m) != 0;
}
Ints imax(const Ints& a, const Ints& b) { return a > b ? a : b; }

// Applies a 128-, 256- or 512-bit intrinsic to every register's worth of a 16-lane vector.
template <class Out, class In, class Op>
Out per_register(const In& v, Op op) {
    Out r;
    constexpr int kBytes = sizeof(decltype(op(std::declval<const char*>())));
    for (int i = 0; i < int(sizeof v); i += kBytes) {
        const auto x = op(reinterpret_cast<const char*>(&v) + i);
        std::memcpy(reinterpret_cast<char*>(&r) + i, &x, kBytes);
    }
    return r;
}

// cvtps2dq: round to nearest even (the default MXCSR mode); NaN and out of range give INT_MIN.
Ints cvt_rne(const Floats& v) {
#if defined(__AVX512F__)
    return per_register<Ints>(v, [](const char* p) { return _mm512_cvtps_epi32(_mm512_loadu_ps(reinterpret_cast<const float*>(p))); });
#elif defined(__AVX__)
    return per_register<Ints>(v, [](const char* p) { return _mm256_cvtps_epi32(_mm256_loadu_ps(reinterpret_cast<const float*>(p))); });
#else
    return per_register<Ints>(v, [](const char* p) { return _mm_cvtps_epi32(_mm_loadu_ps(reinterpret_cast<const float*>(p))); });
#endif
}
// cvttps2dq: toward zero; NaN and out of range give INT_MIN.
Ints cvt_trunc(const Floats& v) {
#if defined(__AVX512F__)
    return per_register<Ints>(v, [](const char* p) { return _mm512_cvttps_epi32(_mm512_loadu_ps(reinterpret_cast<const float*>(p))); });
#elif defined(__AVX__)
    return per_register<Ints>(v, [](const char* p) { return _mm256_cvttps_epi32(_mm256_loadu_ps(reinterpret_cast<const float*>(p))); });
#else
    return per_register<Ints>(v, [](const char* p) { return _mm_cvttps_epi32(_mm_loadu_ps(reinterpret_cast<const float*>(p))); });
#endif
}
// roundps toward -inf, and to nearest even.
Floats floor(const Floats& v) {
#if defined(__AVX512F__)
    return per_register<Floats>(v, [](const char* p) {
        return _mm512_roundscale_ps(_mm512_loadu_ps(reinterpret_cast<const float*>(p)), _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
    });
#elif defined(__AVX__)
    return per_register<Floats>(v, [](const char* p) { return _mm256_floor_ps(_mm256_loadu_ps(reinterpret_cast<const float*>(p))); });
#else
    Floats r;
    for (int i = 0; i < L; ++i) r[i] = std::floor(v[i]);
    return r;
#endif
}
Floats round_even(const Floats& v) {
#if defined(__AVX512F__)
    return per_register<Floats>(v, [](const char* p) {
        return _mm512_roundscale_ps(_mm512_loadu_ps(reinterpret_cast<const float*>(p)), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
    });
#elif defined(__AVX__)
    return per_register<Floats>(v, [](const char* p) {
        return _mm256_round_ps(_mm256_loadu_ps(reinterpret_cast<const float*>(p)), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
    });
#else
    Floats r;
    for (int i = 0; i < L; ++i) r[i] = std::nearbyint(v[i]);
    return r;
#endif
}
Floats abs(const Floats& v) { return from_bits(bits(v) & 0x7fffffff); }

// llvmpipe's lerps are llvm.fmuladd, which its JIT fuses on CPUs with FMA; so do we there.
[[maybe_unused]] bool host_fuses() {
    static const bool fma = __builtin_cpu_supports("fma");
    return fma;
}
// w * (b - a) + a, fused where llvmpipe fuses it.
Floats lerp(const Floats& w, const Floats& a, const Floats& b) {
    const Floats d = b - a;
#if defined(__AVX512F__)
    return per_register<Floats>(w, [&](const char* p) {
        const std::ptrdiff_t i = p - reinterpret_cast<const char*>(&w);
        return _mm512_fmadd_ps(_mm512_loadu_ps(reinterpret_cast<const float*>(p)),
                               _mm512_loadu_ps(reinterpret_cast<const float*>(reinterpret_cast<const char*>(&d) + i)),
                               _mm512_loadu_ps(reinterpret_cast<const float*>(reinterpret_cast<const char*>(&a) + i)));
    });
#elif defined(__FMA__)
    return per_register<Floats>(w, [&](const char* p) {
        const std::ptrdiff_t i = p - reinterpret_cast<const char*>(&w);
        return _mm256_fmadd_ps(_mm256_loadu_ps(reinterpret_cast<const float*>(p)),
                               _mm256_loadu_ps(reinterpret_cast<const float*>(reinterpret_cast<const char*>(&d) + i)),
                               _mm256_loadu_ps(reinterpret_cast<const float*>(reinterpret_cast<const char*>(&a) + i)));
    });
#else
    if (!host_fuses()) return w * d + a;
    Floats r;
    for (int i = 0; i < L; ++i) r[i] = std::fma(w[i], d[i], a[i]);
    return r;
#endif
}

// texels[index] for every lane: one gather instruction per register where the ISA has one.
Uints gather(const std::uint32_t* texels, const Ints& index) {
#if defined(__AVX512F__)
    return per_register<Uints>(index, [&](const char* p) {
        return _mm512_i32gather_epi32(_mm512_loadu_si512(p), texels, 4);
    });
#elif defined(__AVX2__)
    return per_register<Uints>(index, [&](const char* p) {
        return _mm256_i32gather_epi32(reinterpret_cast<const int*>(texels), _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p)), 4);
    });
#else
    Uints r;
    for (int i = 0; i < L; ++i) r[i] = texels[index[i]];
    return r;
#endif
}

// llvmpipe's 8-bit lerp (lp_build_lerp with pre-scaled weights, pmulhrsw): weight w in 1/256,
// rounded half up, on 8-bit values: a + ((w (b - a) + 128) >> 8).
//
// On two channels at once: red and blue (or green and alpha) of a lane's texel in the two 16-bit
// halves of its 32-bit lane, as llvmpipe unpacks them, and w in both halves. pmulhrsw computes
// (w (d << 7) + 2^14) >> 15, which is the same; the sum stays in [0, 255], so nothing carries.
typedef std::int16_t Shorts __attribute__((vector_size(L * sizeof(std::int32_t))));
Shorts mulhrs(const Shorts& a, const Shorts& b) {
#if defined(__AVX512BW__)
    return per_register<Shorts>(a, [&](const char* p) {
        const std::ptrdiff_t i = p - reinterpret_cast<const char*>(&a);
        return _mm512_mulhrs_epi16(_mm512_loadu_si512(p), _mm512_loadu_si512(reinterpret_cast<const char*>(&b) + i));
    });
#elif defined(__AVX2__)
    return per_register<Shorts>(a, [&](const char* p) {
        const std::ptrdiff_t i = p - reinterpret_cast<const char*>(&a);
        return _mm256_mulhrs_epi16(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(p)),
                                   _mm256_loadu_si256(reinterpret_cast<const __m256i*>(reinterpret_cast<const char*>(&b) + i)));
    });
#else
    Shorts r;
    for (int i = 0; i < 2 * L; ++i) r[i] = std::int16_t((std::int32_t(a[i]) * b[i] + (1 << 14)) >> 15);
    return r;
#endif
}
Uints lerp8_pairs(const Uints& w_pairs, const Uints& a, const Uints& b) {
    const Shorts d = (Shorts(b) - Shorts(a)) * std::int16_t(128);
    return Uints(Shorts(a) + mulhrs(Shorts(w_pairs), d));
}
// A weight in both 16-bit halves.
Uints pairs(const Ints& w) { return Uints(w) | (Uints(w) << 16); }

// Texels split into (red, blue) and (green, alpha) 16-bit pairs, and back to channels.
struct Pairs {
    Uints rb, ga;
};
Pairs split(const Uints& t) { return {t & 0x00ff00ffu, (t >> 8) & 0x00ff00ffu}; }
Pairs lerp8(const Ints& w, const Pairs& a, const Pairs& b) {
    const Uints w2 = pairs(w);
    return {lerp8_pairs(w2, a.rb, b.rb), lerp8_pairs(w2, a.ga, b.ga)};
}
Ints channel(const Pairs& q, int c) {
    const Uints& v = (c & 1) ? q.ga : q.rb;
    return Ints(c < 2 ? (v & 0xffffu) : (v >> 16));
}

// The unorm8 value q as the shader sees it: q times the float nearest 1/255 (a multiply, not a
// division: lp_build_unsigned_norm_to_float).
Floats unorm(const Ints& q) { return to_float(q) * float(1.0 / 255.0); }

// ---- level of detail (lp_bld_sample.c, lp_build_lod_selector with the default sampler state) ----

// The biased exponent field minus (127 - bias): floor(log2 x) + bias for normal x
// (lp_build_extract_exponent).
Ints exponent(const Floats& x, int bias) { return ((bits(x) >> 23) & 255) - (127 - bias); }
// lp_build_fast_log2: exponent plus mantissa - 1, piecewise linear and exact at powers of two.
Floats fast_log2(const Floats& x) {
    return to_float(exponent(x, -1)) + from_bits((bits(x) & 0x7fffff) | 0x3f800000);
}

// Per lane: which levels, how much of the second, which filter.
struct LevelChoice {
    Ints level0, level1;  // level1 only read where blend > 0
    Floats blend;         // weight of level1: 0 where none
    Ints linear;          // lanes filtered linearly (-1), the others nearest (0)
};

LevelChoice choose_levels(const sampler2D& tex, const float* rho2_lanes) {
    const SamplerState& st = tex.sampler;
    LevelChoice c{};
    const int last = int(tex.levels.size()) - 1;
    if (!rho2_lanes) {  // needs_lod() is false: min == mag, no mipmaps
        c.linear = splat(st.min == Filter::Linear ? -1 : 0);
        return c;
    }
    Floats rho2;
    std::memcpy(&rho2, rho2_lanes, sizeof rho2);
    Ints positive, ipart{};
    Floats fpart{};
    if (st.mip != MipFilter::Linear) {
        ipart = exponent(rho2, 1) >> 1;  // lp_build_ilog2_sqrt: level k from rho >= sqrt(2) 2^(k-1)
        positive = rho2 > 1.0f;
    } else {
        const Floats lod = fast_log2(rho2) * 0.5f;
        positive = lod > 0.0f;
        const Floats fl = floor(lod);
        ipart = cvt_trunc(fl);
        fpart = lod - fl;
    }
    if (st.mip == MipFilter::Nearest) {
        c.level0 = c.level1 = imin(imax(ipart, splat(0)), splat(last));
    } else if (st.mip == MipFilter::Linear) {
        const Ints below = ipart < 0, beyond = ipart >= last;
        c.level0 = below ? splat(0) : beyond ? splat(last) : ipart;
        c.level1 = below ? splat(0) : beyond ? splat(last) : ipart + 1;
        c.blend = from_bits(bits(fpart) & ~(below | beyond));
    }
    // Magnified lanes take the magnification filter at level0, unblended.
    const Ints minified = st.min == st.mag ? splat(-1) : positive;
    c.blend = from_bits(bits(c.blend) & minified);
    const Ints min_linear = splat(st.min == Filter::Linear ? -1 : 0), mag_linear = splat(st.mag == Filter::Linear ? -1 : 0);
    c.linear = minified ? min_linear : mag_linear;
    return c;
}

// ---- one level's texels ---------------------------------------------------------------------

// Per lane, a level's size and where its texels start.
struct LevelLanes {
    Ints width, height, offset;
};
LevelLanes level_lanes(const sampler2D& tex, const Ints& level) {
    LevelLanes r;
    if (tex.levels.size() == 1) {
        r.width = splat(tex.levels[0].width), r.height = splat(tex.levels[0].height), r.offset = Ints{};
        return r;
    }
    r.width = imax(splat(tex.width) >> level, splat(1));  // lp_build_minify
    r.height = imax(splat(tex.height) >> level, splat(1));
    static_assert(sizeof(sampler2D::Level) == 3 * sizeof(std::int32_t) && offsetof(sampler2D::Level, offset) == 8);
    r.offset = Ints(gather(reinterpret_cast<const std::uint32_t*>(tex.levels.data()), level * 3 + 2));
    return r;
}

// Two texels and a weight along one axis: (x0, x1, w) with w in 1/256 (8-bit path) or a float.
struct Axis {
    Ints i0, i1, w8;
    Floats w;
};

// lp_bld_sample_aos.c: the 8-bit fixed-point path, REPEAT and CLAMP_TO_EDGE. Linear filtering
// along one axis (lp_build_sample_wrap_linear_int).
Axis aos_linear(const Floats& s, const Ints& size, Wrap wrap, bool pot) {
    Axis a{};
    const Ints last = size - 1;
    // Linear: 8 fractional bits of s * size - 0.5, rounded to even.
    Ints u;
    if (wrap == Wrap::Repeat && !pot) {
        const Floats f = s - floor(s);  // lp_build_coord_repeat_npot_linear_int
        u = wrapping_add(cvt_rne((f * to_float(size)) * 256.0f), splat(-128));
    } else {
        u = wrapping_add(cvt_rne(s * to_float(size << 8)), splat(-128));
    }
    Ints i0 = u >> 8, l0, l1;
    const Ints w = u & 255;
    if (wrap == Wrap::Repeat) {
        if (pot) {
            l0 = i0 & last;
        } else {
            l0 = imin(i0 < 0 ? last : i0, last);
        }
        l1 = l0 != last ? l0 + 1 : Ints{};
    } else {
        l0 = imin(imax(i0, Ints{}), last);
        l1 = ((i0 >= 0) & (i0 < last)) ? l0 + 1 : l0;
    }
    a.i0 = l0, a.i1 = l1, a.w8 = w;
    a.w = to_float(a.w8) * (1.0f / 256.0f);
    return a;
}

// The nearest texel along one axis (lp_build_sample_wrap_nearest_int).
Ints aos_nearest(const Floats& s, const Ints& size, Wrap wrap, bool pot) {
    const Ints last = size - 1;
    if (wrap == Wrap::Repeat && !pot) return cvt_trunc(minps(s - floor(s), splat(0x1.fffffep-1f)) * to_float(size));
    const Ints i = cvt_trunc(floor(s * to_float(size)));
    return wrap == Wrap::Repeat ? (i & last) : imin(imax(i, Ints{}), last);
}

// Linear lanes as aos_linear gives them, the others their nearest texel with weight 0 (which
// llvmpipe's lerp returns exactly); each part computed only when some lane needs it.
Axis aos_axis(const Floats& s, const Ints& size, Wrap wrap, bool pot, const Ints& linear) {
    const bool some_linear = any(linear), all_linear = !any(~linear);
    Axis a{};
    if (some_linear) a = aos_linear(s, size, wrap, pot);
    if (!all_linear) {
        const Ints n = aos_nearest(s, size, wrap, pot);
        a.i0 = linear ? a.i0 : n;
        a.i1 = linear ? a.i1 : n;
        a.w8 = a.w8 & linear;
        a.w = from_bits(bits(a.w) & linear);
    }
    return a;
}

// lp_build_coord_mirror: |2 (s/2 - round_even(s/2))|, NaN to 0.
Floats mirror(const Floats& s) {
    Floats c = s * 0.5f;
    c = c - round_even(c);
    c = c + c;
    return maxps(abs(c), Floats{});
}

// lp_bld_sample_soa.c: the float path, every wrap mode. `linear`: lanes filtered linearly;
// `weights_only`: the other lanes go through the linear code too, with weights rounded to 0 or
// 1 (llvmpipe's lp_build_sample_mipmap_both when some lane of the vector is linear).
Axis soa_axis(const Floats& s, const Ints& size, Wrap wrap, bool pot, const Ints& linear, const Ints& weights_only) {
    Axis a{};
    const Ints last = size - 1;
    const Floats fsize = to_float(size);
    Floats c, fl;
    Ints l0, l1;
    switch (wrap) {
        case Wrap::Repeat:
            if (pot) {
                c = s * fsize - 0.5f;
                fl = floor(c);
                const Ints i = cvt_trunc(fl);
                l0 = i & last;
                l1 = wrapping_add(i, splat(1)) & last;
            } else {
                c = (s - floor(s)) * fsize - 0.5f;
                fl = floor(c);
                l0 = c < 0.0f ? last : cvt_trunc(fl);
                l1 = l0 != last ? l0 + 1 : Ints{};
            }
            break;
        case Wrap::ClampToEdge: {
            c = s * fsize;
            c = (c < fsize ? c : fsize) - 0.5f;
            c = maxps(c, Floats{});
            fl = floor(c);
            const Ints i = cvt_trunc(fl);
            l0 = i;
            l1 = imin(i + 1, last);
            break;
        }
        case Wrap::MirroredRepeat: {
            c = mirror(s) * fsize - 0.5f;
            fl = floor(c);
            const Ints i = cvt_trunc(fl);
            l0 = imax(i, Ints{});
            l1 = imin(i + 1, last);
            break;
        }
    }
    Floats w = c - fl;
    const Ints rounded = weights_only & ~linear;
    w = rounded ? (w > 0.5f ? splat(1.0f) : Floats{}) : w;
    Ints n;
    switch (wrap) {
        case Wrap::Repeat:
            n = pot ? cvt_trunc(floor(s * fsize)) & last : cvt_trunc(minps(s - floor(s), splat(0x1.fffffep-1f)) * fsize);
            break;
        case Wrap::ClampToEdge: n = imin(imax(cvt_trunc(s * fsize), Ints{}), last); break;
        case Wrap::MirroredRepeat: n = imin(cvt_trunc(mirror(s) * fsize), last); break;
    }
    const Ints through_linear = linear | weights_only;
    a.i0 = through_linear ? l0 : n;
    a.i1 = through_linear ? l1 : n;
    a.w = from_bits(bits(w) & through_linear);
    return a;
}

struct Texels {
    Uints t00, t10, t01, t11;  // t<dx><dy>
};
Texels fetch(const sampler2D& tex, const LevelLanes& level, const Axis& x, const Axis& y) {
    const Ints row0 = level.offset + y.i0 * level.width, row1 = level.offset + y.i1 * level.width;
    const std::uint32_t* t = tex.texels.data();
    return {gather(t, row0 + x.i0), gather(t, row0 + x.i1), gather(t, row1 + x.i0), gather(t, row1 + x.i1)};
}

// Channel c (0: red) of packed RGBA8 texels.
Ints channel(const Uints& texels, int c) { return Ints((texels >> (8 * c)) & 255u); }

// d(colour)/ds and /dt of the bilinear interpolant (texels as floats), for Dual2.
void bilinear_gradient(const Texels& k, const Axis& x, const Axis& y, const LevelLanes& level, int c, Floats& ds,
                       Floats& dt) {
    const Floats t00 = unorm(channel(k.t00, c)), t10 = unorm(channel(k.t10, c)), t01 = unorm(channel(k.t01, c)),
                 t11 = unorm(channel(k.t11, c));
    const Ints linear_x = x.i0 != x.i1, linear_y = y.i0 != y.i1;
    const Floats gx = ((1.0f - y.w) * (t10 - t00) + y.w * (t11 - t01)) * to_float(level.width);
    const Floats gy = ((1.0f - x.w) * (t01 - t00) + x.w * (t11 - t10)) * to_float(level.height);
    ds = from_bits(bits(gx) & linear_x);
    dt = from_bits(bits(gy) & linear_y);
}

struct Sample {
    Floats rgba[4];
    Floats ds[4], dt[4];
};

// One level, 8-bit path: the filtered texel's channels in (red, blue) and (green, alpha) pairs.
Pairs aos_level(const sampler2D& tex, const Floats& s, const Floats& t, const Ints& level, const Ints& linear,
                bool gradient, Floats (&ds)[4], Floats (&dt)[4]) {
    const SamplerState& st = tex.sampler;
    const LevelLanes lv = level_lanes(tex, level);
    const bool pot_w = std::has_single_bit(unsigned(tex.width)), pot_h = std::has_single_bit(unsigned(tex.height));
    const Axis x = aos_axis(s, lv.width, st.wrap_s, pot_w, linear), y = aos_axis(t, lv.height, st.wrap_t, pot_h, linear);
    const Texels k = fetch(tex, lv, x, y);
    if (gradient) {
        for (int c = 0; c < 4; ++c) bilinear_gradient(k, x, y, lv, c, ds[c], dt[c]);
    }
    return lerp8(y.w8, lerp8(x.w8, split(k.t00), split(k.t10)), lerp8(x.w8, split(k.t01), split(k.t11)));
}

// One level, float path.
void soa_level(const sampler2D& tex, const Floats& s, const Floats& t, const Ints& level, const Ints& linear,
               const Ints& weights_only, bool gradient, Floats (&out)[4], Floats (&ds)[4], Floats (&dt)[4]) {
    const SamplerState& st = tex.sampler;
    const LevelLanes lv = level_lanes(tex, level);
    const bool pot_w = std::has_single_bit(unsigned(tex.width)), pot_h = std::has_single_bit(unsigned(tex.height));
    const Axis x = soa_axis(s, lv.width, st.wrap_s, pot_w, linear, weights_only);
    const Axis y = soa_axis(t, lv.height, st.wrap_t, pot_h, linear, weights_only);
    const Texels k = fetch(tex, lv, x, y);
    for (int c = 0; c < 4; ++c) {
        const Floats r0 = lerp(x.w, unorm(channel(k.t00, c)), unorm(channel(k.t10, c)));
        const Floats r1 = lerp(x.w, unorm(channel(k.t01, c)), unorm(channel(k.t11, c)));
        out[c] = lerp(y.w, r0, r1);
        if (gradient) bilinear_gradient(k, x, y, lv, c, ds[c], dt[c]);
    }
}

// llvmpipe decides per 8-lane vector whether a MIRRORED_REPEAT lookup with different min and mag
// filters runs its linear code: every lane of a vector where one lane filters linearly. An OR
// across each half of the batch, in three shuffles.
Ints any_per_vector(const Ints& linear, bool quad_vectors) {
    static_assert(L == 16);
    if (!quad_vectors) return linear;
    Ints r = linear | __builtin_shufflevector(linear, linear, 1, 0, 3, 2, 5, 4, 7, 6, 9, 8, 11, 10, 13, 12, 15, 14);
    r |= __builtin_shufflevector(r, r, 2, 3, 0, 1, 6, 7, 4, 5, 10, 11, 8, 9, 14, 15, 12, 13);
    return r | __builtin_shufflevector(r, r, 4, 5, 6, 7, 0, 1, 2, 3, 12, 13, 14, 15, 8, 9, 10, 11);
}

Sample sample_lanes(const sampler2D& tex, const Floats& s, const Floats& t, const float* rho2, bool quad_vectors,
                    bool gradient) {
    const SamplerState& st = tex.sampler;
    const LevelChoice lc = choose_levels(tex, rho2);
    const bool blend = st.mip == MipFilter::Linear && any(bits(lc.blend) != 0);
    Sample out{};
    if (st.wrap_s != Wrap::MirroredRepeat && st.wrap_t != Wrap::MirroredRepeat) {
        // The 8-bit path; the second level blends in with an 8-bit weight truncated from the
        // fraction (lp_build_sample_mipmap).
        Pairs q = aos_level(tex, s, t, lc.level0, lc.linear, gradient, out.ds, out.dt);
        if (blend) {
            Floats ds1[4], dt1[4];
            const Pairs q1 = aos_level(tex, s, t, lc.level1, lc.linear, gradient, ds1, dt1);
            q = lerp8(imax(cvt_trunc(lc.blend * 256.0f), Ints{}), q, q1);
            if (gradient) {
                for (int c = 0; c < 4; ++c) out.ds[c] += lc.blend * (ds1[c] - out.ds[c]), out.dt[c] += lc.blend * (dt1[c] - out.dt[c]);
            }
        }
        for (int c = 0; c < 4; ++c) out.rgba[c] = unorm(channel(q, c));
        return out;
    }
    // The float path (a mirrored axis); lp_build_sample_mipmap, or lp_build_sample_mipmap_both
    // when min and mag filters differ.
    const Ints weights_only = st.min != st.mag ? any_per_vector(lc.linear, quad_vectors) & ~lc.linear : Ints{};
    soa_level(tex, s, t, lc.level0, lc.linear, weights_only, gradient, out.rgba, out.ds, out.dt);
    if (blend) {
        Floats c1[4], ds1[4], dt1[4];
        soa_level(tex, s, t, lc.level1, lc.linear, weights_only, gradient, c1, ds1, dt1);
        const Floats f = maxps(lc.blend, Floats{});
        for (int c = 0; c < 4; ++c) {
            out.rgba[c] = lerp(f, out.rgba[c], c1[c]);
            if (gradient) out.ds[c] += f * (ds1[c] - out.ds[c]), out.dt[c] += f * (dt1[c] - out.dt[c]);
        }
    }
    return out;
}

// ---- glGenerateMipmap ----------------------------------------------------------------------
// llvmpipe has no mipmap generator of its own: Mesa's state tracker blits each level from the
// one above (util_gen_mipmap) through a quad that samples it with LINEAR, CLAMP_TO_EDGE at the
// destination texel's centre, on the 8-bit path above. For even sizes that is
// avg(avg(a, b), avg(c, d)) rounded half up, not a box filter; for odd sizes the weights are
// not one half (37 -> 18 samples at 37 (x + 0.5) / 18).
void next_level(const std::uint32_t* src, int sw, int sh, std::uint32_t* dst, int dw, int dh) {
    struct Tap {
        int i0, i1, w;
    };
    auto taps = [](int src_size, int dst_size) {
        std::vector<Tap> r{std::size_t(dst_size)};
        for (int x = 0; x < dst_size; ++x) {
            const float s = (float(x) + 0.5f) / float(dst_size);
            const int u = int(std::nearbyint(s * float(src_size << 8))) - 128;  // rounds to even, as cvtps2dq
            const int i0 = u >> 8;
            const int l0 = std::clamp(i0, 0, src_size - 1);
            r[std::size_t(x)] = {l0, (i0 >= 0 && i0 < src_size - 1) ? l0 + 1 : l0, u & 255};
        }
        return r;
    };
    const std::vector<Tap> xs = taps(sw, dw), ys = taps(sh, dh);
    auto lerp = [](int w, int a, int b) { return a + ((w * (b - a) + 128) >> 8); };
    for (int y = 0; y < dh; ++y) {
        const Tap ty = ys[std::size_t(y)];
        for (int x = 0; x < dw; ++x) {
            const Tap tx = xs[std::size_t(x)];
            const std::uint32_t k00 = src[std::size_t(ty.i0) * std::size_t(sw) + std::size_t(tx.i0)],
                                k10 = src[std::size_t(ty.i0) * std::size_t(sw) + std::size_t(tx.i1)],
                                k01 = src[std::size_t(ty.i1) * std::size_t(sw) + std::size_t(tx.i0)],
                                k11 = src[std::size_t(ty.i1) * std::size_t(sw) + std::size_t(tx.i1)];
            std::uint32_t out = 0;
            for (int c = 0; c < 4; ++c) {
                const auto ch = [c](std::uint32_t k) { return int((k >> (8 * c)) & 255u); };
                const int r0 = lerp(tx.w, ch(k00), ch(k10)), r1 = lerp(tx.w, ch(k01), ch(k11));
                out |= std::uint32_t(lerp(ty.w, r0, r1)) << (8 * c);
            }
            dst[std::size_t(y) * std::size_t(dw) + std::size_t(x)] = out;
        }
    }
}

}  // namespace

sampler2D::sampler2D(int w, int h, const std::uint8_t* rgba, SamplerState s) : width(w), height(h), sampler(s) {
    if (w < 1 || h < 1 || w > (1 << 15) || h > (1 << 15)) {
        throw std::invalid_argument("texture size " + std::to_string(w) + "x" + std::to_string(h) +
                                    " is outside 1..32768");
    }
    std::int64_t total = 0;  // at most 4/3 of 2^30 texels: an int32 index
    for (int lw = w, lh = h;; lw = std::max(1, lw / 2), lh = std::max(1, lh / 2)) {
        levels.push_back({lw, lh, std::int32_t(total)});
        total += std::int64_t(lw) * lh;
        if (sampler.mip == MipFilter::None || (lw == 1 && lh == 1)) break;
    }
    // A single level makes a mipmap filter a plain one (llvmpipe: level_zero_only).
    if (levels.size() == 1) sampler.mip = MipFilter::None;
    texels.resize(std::size_t(total));
    for (std::size_t i = 0; i < std::size_t(w) * std::size_t(h); ++i) {
        texels[i] = std::uint32_t(rgba[4 * i]) | std::uint32_t(rgba[4 * i + 1]) << 8 |
                    std::uint32_t(rgba[4 * i + 2]) << 16 | std::uint32_t(rgba[4 * i + 3]) << 24;
    }
    for (std::size_t l = 1; l < levels.size(); ++l) {
        const Level& a = levels[l - 1];
        const Level& b = levels[l];
        next_level(&texels[std::size_t(a.offset)], a.width, a.height, &texels[std::size_t(b.offset)], b.width, b.height);
    }
}

namespace texture_detail {

void throw_lod_without_quads() {
    throw std::logic_error("texture2D: this texture's sampler needs a level of detail, i.e. the quad's derivatives, "
                           "but the shader was run on independent pixels");
}

// Flattened: the helpers above become one straight body (called as functions, their 64-byte
// vectors would travel through memory on targets without AVX-512).
[[gnu::flatten]] void sample(const sampler2D& tex, const Lookup& l) {
    alignas(64) float s[L] = {}, t[L] = {}, rho2[L] = {};
    std::copy_n(l.s, l.lanes, s);
    std::copy_n(l.t, l.lanes, t);
    if (l.rho2) std::copy_n(l.rho2, l.lanes, rho2);
    Floats sv, tv;
    std::memcpy(&sv, s, sizeof sv);
    std::memcpy(&tv, t, sizeof tv);
    const bool gradient = l.d_ds[0] != nullptr;
    const Sample r = sample_lanes(tex, sv, tv, l.rho2 ? rho2 : nullptr, l.quad_vectors, gradient);
    for (int c = 0; c < 4; ++c) {
        std::memcpy(l.rgba[std::size_t(c)], &r.rgba[c], sizeof(float) * std::size_t(l.lanes));
        if (gradient) {
            std::memcpy(l.d_ds[std::size_t(c)], &r.ds[c], sizeof(float) * std::size_t(l.lanes));
            std::memcpy(l.d_dt[std::size_t(c)], &r.dt[c], sizeof(float) * std::size_t(l.lanes));
        }
    }
}

}  // namespace texture_detail

}  // namespace qs::glsl
