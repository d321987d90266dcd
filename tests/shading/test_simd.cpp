// The SIMD layer (shading/number/simd/): each operation on vectors of 4, 8 and 16 lanes (one
// register of the SSE, AVX2 and AVX-512 targets, and pieces of registers on the narrower ones)
// against its definition stated lane by lane here, on the values where instructions differ from
// the C++ one might expect: NaN, infinities, -0, halves, and conversions out of range.
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "shading/number/simd/simd.h"

namespace qs {

namespace {

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

// Values that each conversion and rounding treats in its own way.
const std::vector<float> kEdges = {0.5f,          1.5f,          2.5f,           -0.5f,           -1.5f,  -2.5f,
                                   3.7f,          -3.7f,         0.0f,           -0.0f,           kNaN,   kInf,
                                   -kInf,         2147483520.0f, 2147483648.0f,  -2147483648.0f, 1e10f,  -2147483904.0f,
                                   8388607.5f,    -8388607.5f,   1e-40f,         16777215.0f,     0.49999997f, 1.0f};

template <int N>
using F = simd::Vector<float, N>;
template <int N>
using I = simd::Vector<std::int32_t, N>;

template <int N>
F<N> floats_from(std::size_t first) {
    F<N> v;
    for (int i = 0; i < N; ++i) v[i] = kEdges[(first + std::size_t(i)) % kEdges.size()];
    return v;
}

bool same_bits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }

std::int32_t x86_nearest(float x) {
    const float r = std::nearbyint(x);
    return r >= -2147483648.0f && r < 2147483648.0f ? std::int32_t(r) : INT32_MIN;
}
std::int32_t x86_truncate(float x) {
    return x > -2147483904.0f && x < 2147483648.0f ? std::int32_t(x) : INT32_MIN;
}

template <int N>
void check_float_operations() {
    for (std::size_t first = 0; first < kEdges.size(); ++first) {
        const F<N> x = floats_from<N>(first), y = floats_from<N>(first + 5);
        const I<N> nearest = simd::convert_nearest(x), truncated = simd::convert_truncate(x);
        const F<N> floor = simd::round<simd::Rounding::Floor>(x), ceil = simd::round<simd::Rounding::Ceil>(x);
        const F<N> trunc = simd::round<simd::Rounding::Trunc>(x), even = simd::round<simd::Rounding::NearestEven>(x);
        const F<N> root = simd::sqrt(x);
        const F<N> low = simd::extremum_or_second<simd::Extremum::Min>(x, y);
        const F<N> high = simd::extremum_or_second<simd::Extremum::Max>(x, y);
        const F<N> fused = simd::fma(x, y, x);
        const simd::LaneBits less = simd::less_bits(x, y);
        for (int i = 0; i < N; ++i) {
            INFO("lanes " << N << ", x = " << x[i] << ", y = " << y[i]);
            CHECK(nearest[i] == x86_nearest(x[i]));
            CHECK(truncated[i] == x86_truncate(x[i]));
            CHECK(same_bits(floor[i], std::floor(x[i])));
            CHECK(same_bits(ceil[i], std::ceil(x[i])));
            CHECK(same_bits(trunc[i], std::trunc(x[i])));
            CHECK(same_bits(even[i], std::nearbyint(x[i])));
            CHECK((std::isnan(root[i]) ? std::isnan(std::sqrt(x[i])) : same_bits(root[i], std::sqrt(x[i]))));
            CHECK(same_bits(low[i], x[i] < y[i] ? x[i] : y[i]));   // y where unordered or equal
            CHECK(same_bits(high[i], x[i] > y[i] ? x[i] : y[i]));
            const float expected = std::fma(x[i], y[i], x[i]);
            CHECK((std::isnan(expected) ? std::isnan(fused[i]) : same_bits(fused[i], expected)));
            CHECK(bool(less >> i & 1u) == (x[i] < y[i]));
        }
    }
}

template <int N>
void check_integer_operations() {
    I<N> index, other;
    for (int i = 0; i < N; ++i) index[i] = (7 * i + 3) % N, other[i] = i % 3 == 0 ? index[i] : -i - 1;
    std::vector<std::uint32_t> table(64);
    for (std::size_t k = 0; k < table.size(); ++k) table[k] = std::uint32_t(1000 + k * k);
    const auto gathered = simd::gather(table.data(), index * 2);
    const simd::LaneBits equal = simd::equal_bits(index, other);
    const simd::LaneBits below = simd::less_unsigned_bits(other, index);
    const simd::LaneBits disjoint = simd::none_common_bits(index, simd::splat<I<N>>(~3));
    CHECK(simd::any(index) == true);
    CHECK(simd::any(I<N>{}) == false);
    I<N> one_lane{};
    one_lane[N - 1] = 1;
    CHECK(simd::any(one_lane) == true);
    for (int i = 0; i < N; ++i) {
        INFO("lanes " << N << ", lane " << i);
        CHECK(gathered[i] == table[std::size_t(2 * index[i])]);
        CHECK(bool(equal >> i & 1u) == (index[i] == other[i]));
        CHECK(bool(below >> i & 1u) == (std::uint32_t(other[i]) < std::uint32_t(index[i])));
        CHECK(bool(disjoint >> i & 1u) == ((index[i] & ~3) == 0));
    }
    // The 8-bit lerp's multiply: (a b + 2^14) >> 15 on each 16-bit half.
    using S = simd::Vector<std::int16_t, 2 * N>;
    S a, b;
    for (int i = 0; i < 2 * N; ++i) a[i] = std::int16_t(i * 97 - 255), b[i] = std::int16_t((i * 37) % 256 * 128 - 16384);
    const S product = simd::multiply_high_rounded(a, b);
    for (int i = 0; i < 2 * N; ++i) CHECK(product[i] == std::int16_t((std::int32_t(a[i]) * b[i] + (1 << 14)) >> 15));
}

template <int N>
void check_splat_and_streams() {
    const F<N> zero = simd::splat<F<N>>(-0.0f);
    std::vector<float> out(N, 1.0f);
    simd::store_pieces(out.data(), zero);
    for (int i = 0; i < N; ++i) CHECK(std::signbit(out[std::size_t(i)]));
}

TEST_CASE("SIMD layer: rounding, conversions, extrema and fused products give x86's answers on every width", "[simd]") {
    check_float_operations<4>();
    check_float_operations<8>();
    check_float_operations<16>();
}

TEST_CASE("SIMD layer: gathers, integer comparisons, tests and pmulhrsw on every width", "[simd]") {
    check_integer_operations<4>();
    check_integer_operations<8>();
    check_integer_operations<16>();
}

TEST_CASE("SIMD layer: a broadcast keeps -0 and a store by pieces writes every lane", "[simd]") {
    check_splat_and_streams<4>();
    check_splat_and_streams<8>();
    check_splat_and_streams<16>();
}

TEST_CASE("SIMD layer: permutes, table lookups, blends, selects and appends move the lanes they name", "[simd]") {
    using I8 = I<8>;
    using U8 = simd::Vector<std::uint32_t, 8>;
    using I16 = I<16>;
    using U16 = simd::Vector<std::uint32_t, 16>;
    U8 t8;
    I8 i8;
    U16 t16, u16;
    I16 i16;
    for (int i = 0; i < 8; ++i) t8[i] = std::uint32_t(100 + i), i8[i] = (5 * i + 2) % 8;
    for (int i = 0; i < 16; ++i) t16[i] = std::uint32_t(200 + i), u16[i] = std::uint32_t(300 + i), i16[i] = (11 * i + 5) % 32;
    const U8 p8 = simd::permute(t8, i8);
    const U8 b8 = simd::blend<0xcc>(t8, p8);
    for (int i = 0; i < 8; ++i) {
        CHECK(p8[i] == t8[i8[i]]);
        CHECK(b8[i] == ((0xcc >> i & 1) ? p8[i] : t8[i]));
    }
    const U16 p16 = simd::permute(t16, i16 & 15), into = simd::permute_into(u16, 0x5a5au, t16, i16 & 15);
    const U16 looked = simd::lookup(t16, u16, i16);
    const F<16> floats = __builtin_convertvector(t16, F<16>), other = __builtin_convertvector(u16, F<16>);
    const F<16> looked_up = simd::lookup(floats, other, i16), selected = simd::select(0x3c3cu, floats, other);
    std::vector<std::uint32_t> table(64, 7u);
    const U16 gathered = simd::gather_into(u16, 0x0ff0u, table.data(), i16);
    const I16 appended = simd::append(i16, 3, 0x8421u, i16 + 100);
    int next = 3;
    for (int i = 0; i < 16; ++i) {
        INFO("lane " << i);
        CHECK(p16[i] == t16[i16[i] & 15]);
        CHECK(into[i] == ((0x5a5a >> i & 1) ? t16[i16[i] & 15] : u16[i]));
        CHECK(looked[i] == (i16[i] < 16 ? t16[i16[i]] : u16[i16[i] - 16]));
        CHECK(looked_up[i] == float(looked[i]));
        CHECK(selected[i] == ((0x3c3c >> i & 1) ? floats[i] : other[i]));
        CHECK(gathered[i] == ((0x0ff0 >> i & 1) ? 7u : u16[i]));
        if (0x8421 >> i & 1) CHECK(appended[next++] == i16[i] + 100);
    }
    for (int i = 0; i < 16; ++i)
        if (i < 3 || i >= 7) CHECK(appended[i] == i16[i]);
    CHECK(simd::lowest_bits(0xf0f0u, 5) == 0x10f0u);
    CHECK(simd::lowest_bits(0xf0f0u, 32) == 0xf0f0u);
    CHECK(simd::compress_bits(0b1010'0110u, 0b1111'0000u) == 0b1010u);
    CHECK(simd::greater_bits(simd::Vector<std::int64_t, 16>{} + 5, simd::Vector<std::int64_t, 16>{} + 4) == 0xffffu);
}

}  // namespace

}  // namespace qs
