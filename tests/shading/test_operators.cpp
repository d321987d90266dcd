// Every assignment form GLSL has (++ and -- before and after, the compound assignments with a
// value of the same type or a scalar) on every number type and on vectors, swizzles and
// matrices of it: each is the binary operation it stands for, lane for lane and bit for bit.
#include <catch2/catch.hpp>

#include <cstdint>

#include "tests/shading/number_types.h"

namespace qs::glsl {
using test::from_values;
using test::lanes_of;

namespace {

const double kA[] = {1.5, -2.25, 1e7, -0.0, 3.0, 7.5, -1e-3, 65535.0, 0.5, 2.0, -9.0, 12.25, 100.0, -3.5, 0.125, 42.0};
const double kB[] = {0.25, 3.0, -2.0, 1.5, -8.0, 0.5, 4.0, 1024.0, -0.75, 6.0, 2.5, -1.0, 9.0, 0.375, -5.0, 1.0};

// Bit-equal lanes (both NaN counts as equal: GLSL results), for numbers, integers and masks.
template <class X>
void same(const X& a, const X& b) {
    if constexpr (AnyVector<X>) {
        for (int i = 0; i < X::N; ++i) same(a[i], b[i]);
    } else if constexpr (requires { X::columns; }) {
        for (int c = 0; c < X::columns; ++c) same(a[c], b[c]);
    } else {
        for (int i = 0; i < lanes_of<X>(); ++i) {
            INFO("lane " << i);
            CHECK(test::same(double(lane(a, i)), double(lane(b, i))));
        }
    }
}

template <class I>
I ints(const std::int64_t (&v)[16], int shift = 0) {
    using T = typename I::value_type;
    T tmp[16];
    for (int k = 0; k < 16; ++k) tmp[k] = T(v[(k + shift) % 16]);
    if constexpr (lanes_of<I>() == 1) {
        return I(tmp[0]);
    } else {
        return I::load(tmp);
    }
}
const std::int64_t kI[] = {0, 1, -1, 7, -8, 31, 33, 255, -256, 65536, 123456, -7654321, 2147483647, -2147483647, 5, 12};
const std::int64_t kJ[] = {3, -2, 5, 1, 31, 2, -7, 17, 4, 9, 1000, 6, 2, 3, 33, -1};

}  // namespace

#define NUMBER_TYPES float, double, (Pixels<float, 16>), (Quads<float, 4>), (Pixels<double, 8>), Dual2<float>, \
                     (Dual2<Pixels<float, 16>>), (Checked<Pixels<float, 16>>), (Checked<Quads<float, 4>>)

TEMPLATE_TEST_CASE("++ and -- on floats: before and after, as x + 1 and x - 1", "[operators]", NUMBER_TYPES) {
    using F = TestType;
    const F a = from_values<F>(kA);
    F x = a;
    same(F(x++), a);
    same(x, F(a + F(1.0f)));
    same(F(++x), F(a + F(1.0f) + F(1.0f)));
    x = a;
    same(F(x--), a);
    same(x, F(a - F(1.0f)));
    same(F(--x), F(a - F(1.0f) - F(1.0f)));
}

TEMPLATE_TEST_CASE("++, -- and every compound assignment on int and uint", "[operators][integers]", NUMBER_TYPES) {
    using F = TestType;
    auto check = []<class I>(I a, I b) {
        I x = a;
        same(I(x++), a);
        same(x, I(a + I(1)));
        same(I(++x), I(a + I(1) + I(1)));
        x = a;
        same(I(x--), a);
        same(I(--x), I(a - I(1) - I(1)));
        x = a, x += b, same(x, I(a + b));
        x = a, x -= b, same(x, I(a - b));
        x = a, x *= b, same(x, I(a * b));
        x = a, x /= b, same(x, I(a / b));
        x = a, x %= b, same(x, I(a % b));
        x = a, x &= b, same(x, I(a & b));
        x = a, x |= b, same(x, I(a | b));
        x = a, x ^= b, same(x, I(a ^ b));
        x = a, x <<= 3, same(x, I(a << 3));
        x = a, x >>= 3, same(x, I(a >> 3));
        x = a, x += 1, same(x, I(a + I(1)));  // a literal on the right, as GLSL writes it
    };
    check(ints<int_t<F>>(kI), ints<int_t<F>>(kJ));
    check(ints<uint_t<F>>(kI), ints<uint_t<F>>(kJ));
}

TEMPLATE_TEST_CASE("vectors and swizzles: ++, --, compound assignments with a vector or a scalar", "[operators]", NUMBER_TYPES) {
    using F = TestType;
    const F a = from_values<F>(kA), b = from_values<F>(kB);
    const vec3<F> u(a, b, a * b), w(b, a - b, F(2.0f));
    vec3<F> v = u;
    same(vec3<F>(v++), u);
    same(v, vec3<F>(u + F(1.0f)));
    same(vec3<F>(--v), vec3<F>(u + F(1.0f) - F(1.0f)));
    v = u, v += w, same(v, vec3<F>(u + w));
    v = u, v -= w, same(v, vec3<F>(u - w));
    v = u, v *= w, same(v, vec3<F>(u * w));
    v = u, v /= w, same(v, vec3<F>(u / w));
    v = u, v += b, same(v, vec3<F>(u + b));
    v = u, v -= b, same(v, vec3<F>(u - b));
    v = u, v *= b, same(v, vec3<F>(u * b));
    v = u, v /= b, same(v, vec3<F>(u / b));
    // Swizzles write back what they name.
    v = u, v.zx() += b, same(v, vec3<F>(u.x + b, u.y, u.z + b));
    v = u, v.yz() -= w.xy(), same(v, vec3<F>(u.x, u.y - w.x, u.z - w.y));
    v = u;
    same(vec2<F>(v.xy()++), u.xy());
    same(v, vec3<F>(u.x + F(1.0f), u.y + F(1.0f), u.z));
    same(vec2<F>(--v.xy()), vec2<F>(u.xy() + F(1.0f) - F(1.0f)));

    using I = int_t<F>;
    const ivec3<F> p(ints<I>(kI), ints<I>(kJ), ints<I>(kI, 5)), q(ints<I>(kJ, 3), ints<I>(kJ, 7), ints<I>(kI, 9));
    ivec3<F> n = p;
    same(ivec3<F>(n++), p);
    same(n, ivec3<F>(p + I(1)));
    n = p, n %= q, same(n, ivec3<F>(p % q));
    n = p, n &= q, same(n, ivec3<F>(p & q));
    n = p, n |= q, same(n, ivec3<F>(p | q));
    n = p, n ^= q, same(n, ivec3<F>(p ^ q));
    n = p, n <<= q, same(n, ivec3<F>(p << q));
    n = p, n >>= q, same(n, ivec3<F>(p >> q));
    n = p, n %= I(7), same(n, ivec3<F>(p % I(7)));
    n = p, n &= I(0xFF), same(n, ivec3<F>(p & I(0xFF)));
    n = p, n |= I(1), same(n, ivec3<F>(p | I(1)));
    n = p, n ^= I(5), same(n, ivec3<F>(p ^ I(5)));
    n = p, n <<= I(2), same(n, ivec3<F>(p << I(2)));
    n = p, n >>= I(2), same(n, ivec3<F>(p >> I(2)));
    n = p, n.xz() <<= I(1), same(n, ivec3<F>(p.x << I(1), p.y, p.z << I(1)));
    n = p, n.yx() ^= q.xy(), same(n, ivec3<F>(p.x ^ q.y, p.y ^ q.x, p.z));
}

TEMPLATE_TEST_CASE("matrices: ++, --, compound assignments, and v *= m", "[operators]", NUMBER_TYPES) {
    using F = TestType;
    const F a = from_values<F>(kA), b = from_values<F>(kB);
    const mat2<F> m(a, b, F(1.5f), a - b), k(b, F(0.5f), a, F(3.0f));
    mat2<F> x = m;
    same(mat2<F>(x++), m);
    same(x, mat2<F>(m + F(1.0f)));
    same(mat2<F>(--x), mat2<F>(m + F(1.0f) - F(1.0f)));
    x = m, x += k, same(x, mat2<F>(m + k));
    x = m, x -= k, same(x, mat2<F>(m - k));
    x = m, x /= k, same(x, mat2<F>(m / k));
    x = m, x += b, same(x, mat2<F>(m + b));
    x = m, x -= b, same(x, mat2<F>(m - b));
    x = m, x *= b, same(x, mat2<F>(m * b));
    x = m, x /= b, same(x, mat2<F>(m / b));
    x = m, x *= k, same(x, mat2<F>(m * k));
    same(mat2<F>(b - m), mat2<F>(vec2<F>(b - m[0][0], b - m[0][1]), vec2<F>(b - m[1][0], b - m[1][1])));
    same(mat2<F>(m / k), mat2<F>(vec2<F>(m[0][0] / k[0][0], m[0][1] / k[0][1]), vec2<F>(m[1][0] / k[1][0], m[1][1] / k[1][1])));
    vec2<F> v(a, b);
    const vec2<F> v0 = v;
    v *= m;
    same(v, vec2<F>(v0 * m));
}

}  // namespace qs::glsl
