#pragma once
// A shader's own uniforms as its GLSL declares them, and their values as 32-bit words.

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace qs {

// A shader's own uniform: `uniform vec3 uTint = vec3(1.0, 0.5, 0.2);` is
// {"uTint", UniformType::Vec3, {1.0f, 0.5f, 0.2f}}. The initial value is the GLSL initializer's
// (0 where it has none), used where neither the scene nor the command line sets the uniform.
// A uniform named uResolution (scenes/uniforms.h) is the frame's size in pixels, set by the
// renderer. Matrices are column by column.
// Bools and bool vectors are set as ints (0 or 1), as glUniform1i sets them.
enum class UniformType : std::uint8_t {
    Float, Vec2, Vec3, Vec4, Int, IVec2, IVec3, IVec4, Uint, UVec2, UVec3, UVec4,
    Mat2, Mat3, Mat4, Mat2x3, Mat2x4, Mat3x2, Mat3x4, Mat4x2, Mat4x3,  // MatCxR: C columns of R rows
};
struct UniformDecl {
    std::string_view name;
    UniformType type;
    std::array<float, 16> initial{};
};
constexpr int components(UniformType t) {
    constexpr int n[] = {1, 2, 3, 4, 1, 2, 3, 4, 1, 2, 3, 4, 4, 9, 16, 6, 8, 6, 12, 8, 12};
    return n[int(t)];
}
constexpr bool is_integer(UniformType t) { return t >= UniformType::Int && t <= UniformType::UVec4; }
constexpr bool is_unsigned(UniformType t) { return t >= UniformType::Uint && t <= UniformType::UVec4; }
// GLSL's name of the type, for messages.
constexpr std::string_view glsl_name(UniformType t) {
    constexpr std::string_view n[] = {"float",  "vec2",   "vec3",   "vec4",   "int",    "ivec2",  "ivec3",
                                      "ivec4",  "uint",   "uvec2",  "uvec3",  "uvec4",  "mat2",   "mat3",
                                      "mat4",   "mat2x3", "mat2x4", "mat3x2", "mat3x4", "mat4x2", "mat4x3"};
    return n[int(t)];
}
// Each uniform's value takes this many 32-bit words in Uniforms::user (a mat4's).
inline constexpr int kUniformWords = 16;
// Word i of a value: a float's bits, or a 32-bit integer (wrapping, as GLSL's uint(int)).
constexpr std::uint32_t uniform_word(UniformType t, double value) {
    if (is_integer(t)) return std::uint32_t(std::int64_t(value));
    return std::bit_cast<std::uint32_t>(float(value));
}
// The words of a shader's uniforms at their initial values.
template <std::size_t N>
constexpr std::array<std::uint32_t, N * kUniformWords> initial_uniform_words(std::span<const UniformDecl, N> decls) {
    std::array<std::uint32_t, N * kUniformWords> w{};
    for (std::size_t u = 0; u < N; ++u) {
        for (int i = 0; i < components(decls[u].type); ++i) {
            w[u * kUniformWords + std::size_t(i)] = uniform_word(decls[u].type, double(decls[u].initial[std::size_t(i)]));
        }
    }
    return w;
}

}  // namespace qs
