#pragma once
// A shader's own uniforms (ShaderInfo::uniforms), read as GLSL reads them: one value for every
// fragment, with no derivative. `index` is the uniform's place in ShaderInfo::uniforms.
//
//     uniform float uScale = 4.0;        const F uScale = uniform<F>(u, kScale);
//     uniform vec3 uTint;                const vec3<F> uTint = uniform<vec3<F>>(u, kTint);
//     uniform ivec2 uCells;              const ivec2<F> uCells = uniform<ivec2<F>>(u, kCells);
//     uniform mat3 uWarp;                const mat3<F> uWarp = uniform<mat3<F>>(u, kWarp);

#include <bit>
#include <cstdint>

#include "shading/glsl/mat.h"
#include "shading/program.h"

namespace qs::glsl {

namespace uniform_detail {

// One component from its 32-bit word: a float's bits, or an integer.
template <class X>
X component(std::uint32_t word) {
    if constexpr (IntegerNumber<X>) {
        return X(std::bit_cast<typename X::value_type>(word));
    } else {
        return X(std::bit_cast<float>(word));
    }
}

}  // namespace uniform_detail

template <class T>
T uniform(const Uniforms& u, int index) {
    const std::uint32_t* w = u.user + index * kUniformWords;
    if constexpr (requires { typename T::column_type; }) {  // a matrix, column by column
        T m;
        for (int c = 0; c < T::columns; ++c) {
            for (int r = 0; r < T::rows; ++r) m[c][r] = uniform_detail::component<typename T::value_type>(w[c * T::rows + r]);
        }
        return m;
    } else if constexpr (AnyVector<T>) {
        T v;
        for (int i = 0; i < T::N; ++i) v[i] = uniform_detail::component<typename T::value_type>(w[i]);
        return v;
    } else {
        return uniform_detail::component<T>(w[0]);
    }
}

}  // namespace qs::glsl
