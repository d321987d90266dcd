#pragma once
// The portable target: every operation of the SIMD layer on a vector of any size, by the
// compiler's own vector operators or element by element, with the results the x86 instructions
// that the other targets use give (out-of-range conversions to INT_MIN, minps's second operand
// on NaN, ...). The other targets' files overload these for the vectors that are one of their
// registers; what they leave out comes from here. No intrinsics: the build for any CPU.

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "shading/number/simd/vector.h"

namespace qs::simd::isa {

template <Rounding R, class V>
[[gnu::always_inline]] inline V round(const V& x) {
    return per_element(x, [](auto e) {
        if constexpr (R == Rounding::Floor) return std::floor(e);
        else if constexpr (R == Rounding::Ceil) return std::ceil(e);
        else if constexpr (R == Rounding::Trunc) return std::trunc(e);
        else return std::nearbyint(e);  // the rounding mode shading threads never change: to even
    });
}

template <class V>
[[gnu::always_inline]] inline V sqrt(const V& x) {
    return per_element(x, [](auto e) { return std::sqrt(e); });
}

template <Extremum E, class V>
[[gnu::always_inline]] inline V extremum_or_second(const V& a, const V& b) {
    if constexpr (E == Extremum::Min) {
        return a < b ? a : b;
    } else {
        return a > b ? a : b;
    }
}

// a * b + c, the product exact (one rounding or two: the same bits).
template <class V>
[[gnu::always_inline]] inline V exact_product_add(const V& a, const V& b, const V& c) {
    return a * b + c;
}

// a * b + c rounded once, as std::fma.
template <class V>
[[gnu::always_inline]] inline V fma(const V& a, const V& b, const V& c) {
    V r;
    for (int i = 0; i < size_v<V>; ++i) r[i] = std::fma(a[i], b[i], c[i]);
    return r;
}

template <class V>
[[gnu::always_inline]] inline bool any(const V& m) {
    const V zero{};
    return std::memcmp(&m, &zero, sizeof m) != 0;
}

// cvtps2dq: to nearest even (the rounding mode shading threads keep); NaN and out of range give
// INT_MIN.
template <class V>
[[gnu::always_inline]] inline ints_of_t<V> convert_nearest(const V& x) {
    ints_of_t<V> r;
    for (int i = 0; i < size_v<V>; ++i) {
        const auto e = std::nearbyint(x[i]);
        r[i] = e >= -2147483648.0 && e < 2147483648.0 ? std::int32_t(e) : INT32_MIN;
    }
    return r;
}
// cvttps2dq, cvttpd2dq: toward zero; NaN and out of range (after truncation) give INT_MIN.
template <class V>
[[gnu::always_inline]] inline ints_of_t<V> convert_truncate(const V& x) {
    using S = element_t<V>;
    ints_of_t<V> r;
    for (int i = 0; i < size_v<V>; ++i) {
        r[i] = (x[i] > S(-2147483649.0) && x[i] < S(2147483648.0)) ? std::int32_t(x[i]) : std::int32_t(INT32_MIN);
    }
    return r;
}

// base[index[i]] in lane i (the texels of a texture, a table's entries).
template <class I>
[[gnu::always_inline]] inline like_t<std::uint32_t, I> gather(const std::uint32_t* base, const I& index) {
    like_t<std::uint32_t, I> r;
    for (int i = 0; i < size_v<I>; ++i) r[i] = base[index[i]];
    return r;
}
// gather for the lanes whose bit `lanes` has, src's value in the others.
template <class U, class I>
[[gnu::always_inline]] inline U gather_into(const U& src, LaneBits lanes, const std::uint32_t* base, const I& index) {
    U r = src;
    for (int i = 0; i < size_v<I>; ++i)
        if (lanes >> i & 1u) r[i] = base[index[i]];
    return r;
}

// (a b + 2^14) >> 15 on 16-bit lanes (pmulhrsw).
template <class S>
[[gnu::always_inline]] inline S multiply_high_rounded(const S& a, const S& b) {
    S r;
    for (int i = 0; i < size_v<S>; ++i) r[i] = std::int16_t((std::int32_t(a[i]) * b[i] + (1 << 14)) >> 15);
    return r;
}

// table[index[i]] in lane i, index taken modulo the lanes (vpermd).
template <class V, class I>
[[gnu::always_inline]] inline V permute(const V& table, const I& index) {
    V r;
    for (int i = 0; i < size_v<V>; ++i) r[i] = table[index[i] & (size_v<V> - 1)];
    return r;
}
// permute for the lanes whose bit `lanes` has, src's value in the others.
template <class V, class I>
[[gnu::always_inline]] inline V permute_into(const V& src, LaneBits lanes, const V& table, const I& index) {
    V r = src;
    for (int i = 0; i < size_v<V>; ++i)
        if (lanes >> i & 1u) r[i] = table[index[i] & (size_v<V> - 1)];
    return r;
}
// Element index[i] of the table of 2N elements (low, high) in lane i, index modulo 2N (vpermt2d,
// vpermt2ps).
template <class V, class I>
[[gnu::always_inline]] inline V lookup(const V& low, const V& high, const I& index) {
    constexpr int n = size_v<V>;
    V r;
    for (int i = 0; i < n; ++i) {
        const int at = index[i] & (2 * n - 1);
        r[i] = at < n ? low[at] : high[at - n];
    }
    return r;
}
// b in the lanes whose bit Lanes has, a in the others (vpblendd).
template <unsigned Lanes, class V>
[[gnu::always_inline]] inline V blend(const V& a, const V& b) {
    V r;
    for (int i = 0; i < size_v<V>; ++i) r[i] = (Lanes >> i & 1u) ? b[i] : a[i];
    return r;
}
// a in the lanes whose bit `lanes` has, b in the others.
template <class V>
[[gnu::always_inline]] inline V select(LaneBits lanes, const V& a, const V& b) {
    V r;
    for (int i = 0; i < size_v<V>; ++i) r[i] = (lanes >> i & 1u) ? a[i] : b[i];
    return r;
}

// Comparisons as lane bits.
template <class V>
[[gnu::always_inline]] inline LaneBits less_bits(const V& a, const V& b) {
    LaneBits r = 0;
    for (int i = 0; i < size_v<V>; ++i) r |= LaneBits(a[i] < b[i]) << i;
    return r;
}
template <class V>
[[gnu::always_inline]] inline LaneBits greater_bits(const V& a, const V& b) {
    LaneBits r = 0;
    for (int i = 0; i < size_v<V>; ++i) r |= LaneBits(a[i] > b[i]) << i;
    return r;
}
template <class V>
[[gnu::always_inline]] inline LaneBits equal_bits(const V& a, const V& b) {
    LaneBits r = 0;
    for (int i = 0; i < size_v<V>; ++i) r |= LaneBits(a[i] == b[i]) << i;
    return r;
}
// a < b as unsigned integers.
template <class V>
[[gnu::always_inline]] inline LaneBits less_unsigned_bits(const V& a, const V& b) {
    LaneBits r = 0;
    for (int i = 0; i < size_v<V>; ++i) r |= LaneBits(std::uint32_t(a[i]) < std::uint32_t(b[i])) << i;
    return r;
}
// (a & b) == 0 (vptestnmd).
template <class V>
[[gnu::always_inline]] inline LaneBits none_common_bits(const V& a, const V& b) {
    LaneBits r = 0;
    for (int i = 0; i < size_v<V>; ++i) r |= LaneBits((a[i] & b[i]) == 0) << i;
    return r;
}

// `to` with the lanes of v at the set bits of `lanes` packed into its lanes first, first + 1, ...
// in order (vpcompressd, then vpexpandd), its other lanes as they were.
template <class V>
[[gnu::always_inline]] inline V append(const V& to, int first, LaneBits lanes, const V& v) {
    V r = to;
    for (LaneBits m = lanes; m != 0; m &= m - 1) r[first++] = v[std::countr_zero(m)];
    return r;
}

// v at p, a cache line, past the caches where the target can (a plain store here).
template <class V>
[[gnu::always_inline]] inline void stream(element_t<V>* p, const V& v) {
    std::memcpy(p, &v, sizeof v);
}
// What is not an operation on vectors, as static members: the targets' own (sse.h, avx2.h,
// avx512.h) derive from this one and hide what they do otherwise.
struct Portable {
    static constexpr const char* name = "portable";
    // The widest vector register, in bytes: what a GCC vector is taken apart into.
    static constexpr std::size_t register_bytes = 16;

    // The lowest n set bits of `mask`, n < 32 (pdep of n ones).
    [[gnu::always_inline]] static std::uint32_t deposit_low_bits(int n, std::uint32_t mask) {
        std::uint32_t r = 0;
        for (; mask != 0 && n > 0; mask &= mask - 1, --n) r |= mask & -mask;
        return r;
    }
    // The bits of `bits` at the set bits of `mask`, packed from bit 0 up (pext).
    [[gnu::always_inline]] static std::uint32_t extract_bits(std::uint32_t bits, std::uint32_t mask) {
        std::uint32_t r = 0;
        for (int n = 0; mask != 0; mask &= mask - 1, ++n) r |= (bits >> std::countr_zero(mask) & 1u) << n;
        return r;
    }

    // Whether the CPU running this has FMA (what LLVM's JIT, targeting it, fuses with).
    [[gnu::always_inline]] static bool cpu_has_fma() { return false; }

    // Orders the streaming stores before whatever follows.
    [[gnu::always_inline]] static void streaming_stores_done() {}

    // The thread's float control (x86's MXCSR): denormals flushed to zero and read as zero where the
    // target can set them; elsewhere the platform's default, documented as such.
    static constexpr bool kControlsDenormals = false;
    [[gnu::always_inline]] static unsigned float_control() { return 0; }
    [[gnu::always_inline]] static void set_float_control(unsigned) {}
    [[gnu::always_inline]] static unsigned flush_denormals(unsigned control) { return control; }
};

}  // namespace qs::simd::isa
