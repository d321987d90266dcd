#pragma once
// GLSL matrices over a number type F: mat<F, C, R> has C columns of R rows, GLSL's matCxR, with
// the names mat2, mat3, mat4 and mat2x3 ... mat4x3. Column-major as in GLSL: m[c] is column c,
// m[c][r] its row r; constructors take columns, or all components column by column, or one
// number for the diagonal, or another matrix (its upper left part, the identity elsewhere).
//
// Products are evaluated as Mesa lowers them, so that llvmpipe's results are reproduced bit for
// bit: m * v sums the columns scaled by v's components left to right, v * m takes dot(v, m[c])
// for each column, m * n is m * n[c] for each column. determinant and inverse (GLSL 1.50 and
// 1.40) follow Mesa's built-in definitions: cofactors (inverse: the adjugate) divided by the
// determinant, component by component.

#include <type_traits>
#include <utility>

#include "shading/glsl/vec.h"

namespace qs::glsl {

template <class F, int C, int R>
struct mat {
    static_assert(C >= 2 && C <= 4 && R >= 2 && R <= 4, "GLSL matrices have 2 to 4 columns and rows");
    using value_type = F;
    using column_type = vec<F, R>;
    using row_type = vec<F, C>;
    static constexpr int columns = C, rows = R;

    column_type col[C];

    mat() = default;
    // mat3(s): s on the diagonal, 0 elsewhere.
    explicit mat(const F& s) {
        for_each([&](int c, int r, F& x) { x = c == r ? s : F(0.0f); });
    }
    // mat3(c0, c1, c2)
    template <class... Cols>
        requires(sizeof...(Cols) == C && (std::is_convertible_v<const Cols&, const column_type&> && ...))
    mat(const Cols&... cols) : col{column_type(cols)...} {}  // NOLINT: GLSL's column constructor
    // mat2(a, b, c, d): first column (a, b), second (c, d).
    template <class... S>
        requires(sizeof...(S) == C * R && (std::is_convertible_v<const S&, F> && ...))
    mat(const S&... s) {  // NOLINT: GLSL's component constructor
        const F v[] = {F(s)...};
        for_each([&](int c, int r, F& x) { x = v[c * R + r]; });
    }
    // mat3(mat4), mat4(mat2x3), ...: the upper left part, the identity's components elsewhere.
    template <int C2, int R2>
        requires(C2 != C || R2 != R)
    explicit mat(const mat<F, C2, R2>& m) {
        for_each([&](int c, int r, F& x) { x = (c < C2 && r < R2) ? m[c][r] : F(c == r ? 1.0f : 0.0f); });
    }

    column_type& operator[](int c) { return col[c]; }
    const column_type& operator[](int c) const { return col[c]; }

    // f(c, r, component) for every component, column by column.
    template <class Fn>
    void for_each(Fn f) {
        for (int c = 0; c < C; ++c) {
            for (int r = 0; r < R; ++r) f(c, r, col[c][r]);
        }
    }
    template <class Fn>
    static mat map(const mat& a, const mat& b, Fn f) {
        mat m;
        for (int c = 0; c < C; ++c) m.col[c] = f(a.col[c], b.col[c]);
        return m;
    }
    template <class Fn>
    static mat map(const mat& a, Fn f) {
        mat m;
        for (int c = 0; c < C; ++c) m.col[c] = f(a.col[c]);
        return m;
    }

    friend mat operator-(const mat& a) { return map(a, [](const column_type& p) { return -p; }); }
    friend mat operator+(const mat& a, const mat& b) { return map(a, b, [](const column_type& p, const column_type& q) { return p + q; }); }
    friend mat operator-(const mat& a, const mat& b) { return map(a, b, [](const column_type& p, const column_type& q) { return p - q; }); }
    friend mat operator*(const mat& a, const F& s) { return map(a, [&](const column_type& p) { return p * s; }); }
    friend mat operator*(const F& s, const mat& a) { return map(a, [&](const column_type& p) { return s * p; }); }
    friend mat operator/(const mat& a, const F& s) { return map(a, [&](const column_type& p) { return p / s; }); }
    friend mat operator+(const mat& a, const F& s) { return map(a, [&](const column_type& p) { return p + s; }); }
    friend mat operator-(const mat& a, const F& s) { return map(a, [&](const column_type& p) { return p - s; }); }
    friend mat operator+(const F& s, const mat& a) { return map(a, [&](const column_type& p) { return s + p; }); }
    friend mat operator-(const F& s, const mat& a) { return map(a, [&](const column_type& p) { return s - p; }); }
    friend mat operator/(const F& s, const mat& a) { return map(a, [&](const column_type& p) { return s / p; }); }
    // GLSL's / of two matrices is component by component (* is the product, below).
    friend mat operator/(const mat& a, const mat& b) { return map(a, b, [](const column_type& p, const column_type& q) { return p / q; }); }
    mat& operator+=(const mat& b) & { return *this = *this + b; }
    mat& operator-=(const mat& b) & { return *this = *this - b; }
    mat& operator/=(const mat& b) & { return *this = *this / b; }
    mat& operator+=(const F& s) & { return *this = *this + s; }
    mat& operator-=(const F& s) & { return *this = *this - s; }
    mat& operator*=(const F& s) & { return *this = *this * s; }
    mat& operator/=(const F& s) & { return *this = *this / s; }
    // ++m, m++, --m, m--: every component.
    mat& operator++() & { return *this += F(1.0f); }
    mat& operator--() & { return *this -= F(1.0f); }
    mat operator++(int) & {
        const mat before = *this;
        *this += F(1.0f);
        return before;
    }
    mat operator--(int) & {
        const mat before = *this;
        *this -= F(1.0f);
        return before;
    }

    // m * v: v's components weight the columns, summed left to right.
    friend column_type operator*(const mat& m, const row_type& v) {
        column_type r = m.col[0] * v.x;
        [&]<int... I>(std::integer_sequence<int, I...>) {
            ((r = r + m.col[I + 1] * v.template get<I + 1>()), ...);
        }(std::make_integer_sequence<int, C - 1>());
        return r;
    }
    // v * m: dot(v, m[c]) for each column.
    friend row_type operator*(const column_type& v, const mat& m) {
        return [&]<int... I>(std::integer_sequence<int, I...>) {
            return row_type(dot(v, m.col[I])...);
        }(std::make_integer_sequence<int, C>());
    }
    // (C x R) * (K x C) = (K x R): column k is m * n[k].
    template <int K>
    friend mat<F, K, R> operator*(const mat& m, const mat<F, K, C>& n) {
        mat<F, K, R> p;
        for (int k = 0; k < K; ++k) p.col[k] = m * n.col[k];
        return p;
    }
    mat& operator*=(const mat<F, C, C>& n) & requires(C == R) { return *this = *this * n; }
    // v *= m: v = v * m.
    friend column_type& operator*=(column_type& v, const mat& m) requires(C == R) { return v = v * m; }

    // GLSL's == and != of whole matrices: one bool.
    friend auto operator==(const mat& a, const mat& b) {
        auto e = a.col[0] == b.col[0];
        for (int c = 1; c < C; ++c) e = e && a.col[c] == b.col[c];
        return e;
    }
    friend auto operator!=(const mat& a, const mat& b) { return !(a == b); }

    template <class M>
    friend mat select(const M& m, const mat& a, const mat& b) {
        return map(a, b, [&](const column_type& p, const column_type& q) { return select(m, p, q); });
    }
};

template <class F> using mat2 = mat<F, 2, 2>;
template <class F> using mat3 = mat<F, 3, 3>;
template <class F> using mat4 = mat<F, 4, 4>;
template <class F> using mat2x2 = mat<F, 2, 2>;
template <class F> using mat2x3 = mat<F, 2, 3>;
template <class F> using mat2x4 = mat<F, 2, 4>;
template <class F> using mat3x2 = mat<F, 3, 2>;
template <class F> using mat3x3 = mat<F, 3, 3>;
template <class F> using mat3x4 = mat<F, 3, 4>;
template <class F> using mat4x2 = mat<F, 4, 2>;
template <class F> using mat4x3 = mat<F, 4, 3>;
template <class F> using mat4x4 = mat<F, 4, 4>;

// ---- matrix built-ins ---------------------------------------------------------------------
template <class F, int C, int R>
mat<F, C, R> matrixCompMult(const mat<F, C, R>& a, const mat<F, C, R>& b) {
    return mat<F, C, R>::map(a, b, [](const vec<F, R>& p, const vec<F, R>& q) { return p * q; });
}

template <class F, int C, int R>
mat<F, R, C> transpose(const mat<F, C, R>& m) {
    mat<F, R, C> t;
    for (int c = 0; c < C; ++c) {
        for (int r = 0; r < R; ++r) t[r][c] = m[c][r];
    }
    return t;
}

// outerProduct(c, r): the matrix c * r^T, column k = c * r[k].
template <class Vc, class Vr>
    requires(Vector<Vc> && Vector<Vr>)
auto outerProduct(const Vc& c, const Vr& r) {
    using F = typename Vc::value_type;
    mat<F, Vr::N, Vc::N> m;
    const vec_t<Vc> column = c;
    const vec_t<Vr> row = r;
    for (int k = 0; k < Vr::N; ++k) m.col[k] = column * row[k];
    return m;
}

// The determinants Mesa computes (GLSL 1.50).
template <class F>
F determinant(const mat<F, 2, 2>& m) {
    return m[0][0] * m[1][1] - m[1][0] * m[0][1];
}
template <class F>
F determinant(const mat<F, 3, 3>& m) {
    const F f1 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
    const F f2 = m[1][0] * m[2][2] - m[1][2] * m[2][0];
    const F f3 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    return m[0][0] * f1 - m[0][1] * f2 + m[0][2] * f3;
}

namespace mat_detail {
// The 2x2 minors the 4x4 adjugate and determinant are made of: sNN is Mesa's SubFactorNN, the
// minor of columns i < k and rows j, l: m[i][j] m[k][l] - m[k][j] m[i][l] (s11 is s07).
template <class F>
struct Minors4 {
    F s00, s01, s02, s03, s04, s05, s06, s07, s08, s09, s10, s12, s13, s14, s15, s16, s17, s18;
    explicit Minors4(const mat<F, 4, 4>& m) {
        auto minor = [&](int i, int j, int k, int l) { return m[i][j] * m[k][l] - m[k][j] * m[i][l]; };
        s00 = minor(2, 2, 3, 3), s01 = minor(2, 1, 3, 3), s02 = minor(2, 1, 3, 2), s03 = minor(2, 0, 3, 3);
        s04 = minor(2, 0, 3, 2), s05 = minor(2, 0, 3, 1), s06 = minor(1, 2, 3, 3), s07 = minor(1, 1, 3, 3);
        s08 = minor(1, 1, 3, 2), s09 = minor(1, 0, 3, 3), s10 = minor(1, 0, 3, 2), s12 = minor(1, 0, 3, 1);
        s13 = minor(1, 2, 2, 3), s14 = minor(1, 1, 2, 3), s15 = minor(1, 1, 2, 2), s16 = minor(1, 0, 2, 3);
        s17 = minor(1, 0, 2, 2), s18 = minor(1, 0, 2, 1);
    }
};
// a * p - b * q + c * r, summed left to right.
template <class F>
F cofactor(const F& a, const F& p, const F& b, const F& q, const F& c, const F& r) {
    return a * p - b * q + c * r;
}
}  // namespace mat_detail

template <class F>
F determinant(const mat<F, 4, 4>& m) {
    using mat_detail::cofactor;
    const mat_detail::Minors4<F> s(m);
    const vec4<F> adj0(cofactor(m[1][1], s.s00, m[1][2], s.s01, m[1][3], s.s02),
                       -cofactor(m[1][0], s.s00, m[1][2], s.s03, m[1][3], s.s04),
                       cofactor(m[1][0], s.s01, m[1][1], s.s03, m[1][3], s.s05),
                       -cofactor(m[1][0], s.s02, m[1][1], s.s04, m[1][2], s.s05));
    return dot(m[0], adj0);
}

// The inverses Mesa computes (GLSL 1.40): the adjugate divided by the determinant.
template <class F>
mat<F, 2, 2> inverse(const mat<F, 2, 2>& m) {
    const mat<F, 2, 2> adj(m[1][1], -m[0][1], -m[1][0], m[0][0]);
    return adj / determinant(m);
}
template <class F>
mat<F, 3, 3> inverse(const mat<F, 3, 3>& m) {
    const F f11_22_21_12 = m[1][1] * m[2][2] - m[2][1] * m[1][2];
    const F f10_22_20_12 = m[1][0] * m[2][2] - m[2][0] * m[1][2];
    const F f10_21_20_11 = m[1][0] * m[2][1] - m[2][0] * m[1][1];
    const mat<F, 3, 3> adj(vec3<F>(f11_22_21_12, -(m[0][1] * m[2][2] - m[2][1] * m[0][2]), m[0][1] * m[1][2] - m[1][1] * m[0][2]),
                           vec3<F>(-f10_22_20_12, m[0][0] * m[2][2] - m[2][0] * m[0][2], -(m[0][0] * m[1][2] - m[1][0] * m[0][2])),
                           vec3<F>(f10_21_20_11, -(m[0][0] * m[2][1] - m[2][0] * m[0][1]), m[0][0] * m[1][1] - m[1][0] * m[0][1]));
    const F det = m[0][0] * f11_22_21_12 - m[0][1] * f10_22_20_12 + m[0][2] * f10_21_20_11;
    return adj / det;
}
template <class F>
mat<F, 4, 4> inverse(const mat<F, 4, 4>& m) {
    using mat_detail::cofactor;
    const mat_detail::Minors4<F> s(m);
    const mat<F, 4, 4> adj(vec4<F>(cofactor(m[1][1], s.s00, m[1][2], s.s01, m[1][3], s.s02),
                                   -cofactor(m[0][1], s.s00, m[0][2], s.s01, m[0][3], s.s02),
                                   cofactor(m[0][1], s.s06, m[0][2], s.s07, m[0][3], s.s08),
                                   -cofactor(m[0][1], s.s13, m[0][2], s.s14, m[0][3], s.s15)),
                           vec4<F>(-cofactor(m[1][0], s.s00, m[1][2], s.s03, m[1][3], s.s04),
                                   cofactor(m[0][0], s.s00, m[0][2], s.s03, m[0][3], s.s04),
                                   -cofactor(m[0][0], s.s06, m[0][2], s.s09, m[0][3], s.s10),
                                   cofactor(m[0][0], s.s13, m[0][2], s.s16, m[0][3], s.s17)),
                           vec4<F>(cofactor(m[1][0], s.s01, m[1][1], s.s03, m[1][3], s.s05),
                                   -cofactor(m[0][0], s.s01, m[0][1], s.s03, m[0][3], s.s05),
                                   cofactor(m[0][0], s.s07, m[0][1], s.s09, m[0][3], s.s12),
                                   -cofactor(m[0][0], s.s14, m[0][1], s.s16, m[0][3], s.s18)),
                           vec4<F>(-cofactor(m[1][0], s.s02, m[1][1], s.s04, m[1][2], s.s05),
                                   cofactor(m[0][0], s.s02, m[0][1], s.s04, m[0][2], s.s05),
                                   -cofactor(m[0][0], s.s08, m[0][1], s.s10, m[0][2], s.s12),
                                   cofactor(m[0][0], s.s15, m[0][1], s.s17, m[0][2], s.s18)));
    // det = m00 adj00 + (m01 adj10 + (m02 adj20 + m03 adj30)), Mesa's association.
    const F det = m[0][0] * adj[0][0] + (m[0][1] * adj[1][0] + (m[0][2] * adj[2][0] + m[0][3] * adj[3][0]));
    return adj / det;
}

}  // namespace qs::glsl
