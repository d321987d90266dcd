#pragma once
// Varyings by name. A vertex stage is a struct, one per GLSL vertex shader, holding the GLSL files
// it translates, its outputs as a struct template over the number type, and the stage itself:
//
//     // plane_st.vert                      struct PlaneSt {
//                                               static constexpr GlslFiles glsl{"plane_st.vert"};
//     varying vec2 st;                          template <class T>
//     void main() {                             struct Varyings {
//         st = gl_MultiTexCoord0.st;                glsl::vec2<T> st;
//         gl_Position = ftransform();               auto fields() { return std::tie(st); }
//     }                                         };
//                                               static void vertex(const VertexIn& in, const Uniforms& u,
//                                                                  VertexOutputs<PlaneSt>& out) {
//                                                   out.st = {in.texcoord.x, in.texcoord.y};
//                                                   out.gl_Position = transform_point(...);
//                                               }
//                                           };
//
// A shader names its stage (`using VertexStage = PlaneSt;`) and its fragment stage reads
// FragmentIn<F, VertexStage>: `in.st`, `in.gl_FragCoord`. fields() lists the varyings once, in
// declaration order; how many floats are interpolated (Needs::varyings) and which are `flat`
// follow from it, so nothing keeps indices in step by hand, and a fragment stage that reads a
// varying its vertex stage does not write fails to compile.
//
// A `flat varying` (the provoking vertex's value, not interpolated) is a field whose bit is set
// in the Varyings struct's `static constexpr unsigned flat_fields` (bit i: the i-th of fields()).

#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include <glm/vec4.hpp>

#include "shading/glsl/vec.h"
#include "shading/program.h"

namespace qs {

// A vertex stage's outputs: gl_Position (clip space) and its varyings, in float.
template <class Stage>
struct VertexOutputs : Stage::template Varyings<float> {
    glm::vec4 gl_Position{0.0f};
};

// A fragment stage's inputs in number type F: gl_FragCoord and the varyings of `Stage`.
template <class F, class Stage>
struct FragmentIn : Stage::template Varyings<F> {
    glsl::vec4<F> gl_FragCoord;
};

namespace varyings_detail {

// Floats in one varying of type X: a scalar or a glsl vector.
template <class X>
constexpr int components() {
    if constexpr (glsl::AnyVector<X>) {
        return X::N;
    } else {
        return 1;
    }
}

template <class Stage>
using FieldTuple = decltype(std::declval<typename Stage::template Varyings<float>&>().fields());

template <class Stage>
constexpr unsigned flat_fields() {
    using V = typename Stage::template Varyings<float>;
    if constexpr (requires { V::flat_fields; }) {
        return V::flat_fields;
    } else {
        return 0u;
    }
}

// Calls fn(component, index) for every float component of every field, index counting from 0.
// Components are named at compile time (get<K>, not v[k]), so that after inlining each varying
// stays in registers: a component picked at run time made the vector live in memory (the
// rasterized simplex 2D square was 4% slower).
template <class Tuple, class Fn>
[[gnu::always_inline]] inline void for_each_component(Tuple&& fields, Fn&& fn) {
    int index = 0;
    std::apply(
        [&](auto&... field) {
            [[maybe_unused]] auto one = [&](auto& f) {
                using X = std::remove_reference_t<decltype(f)>;
                if constexpr (glsl::AnyVector<X>) {
                    [&]<int... K>(std::integer_sequence<int, K...>) {
                        (fn(f.template get<K>(), index++), ...);
                    }(std::make_integer_sequence<int, X::N>());
                } else {
                    fn(f, index++);
                }
            };
            (one(field), ...);
        },
        fields);
}

}  // namespace varyings_detail

// Interpolated floats a vertex stage writes (Needs::varyings).
template <class Stage>
constexpr int varying_count() {
    using Tuple = varyings_detail::FieldTuple<Stage>;
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        return (0 + ... + varyings_detail::components<std::remove_reference_t<std::tuple_element_t<I, Tuple>>>());
    }(std::make_index_sequence<std::tuple_size_v<Tuple>>());
}

// Bit v: float v of the varyings is flat (Needs::flat_varyings).
template <class Stage>
constexpr unsigned flat_varying_mask() {
    using Tuple = varyings_detail::FieldTuple<Stage>;
    constexpr unsigned flat = varyings_detail::flat_fields<Stage>();
    static_assert((flat >> std::tuple_size_v<Tuple>) == 0, "flat_fields names a field the Varyings struct does not list");
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        unsigned mask = 0;
        int first = 0;
        [[maybe_unused]] auto one = [&](std::size_t field, int n) {
            if (flat >> field & 1u) mask |= ((1u << n) - 1u) << first;
            first += n;
        };
        (one(I, varyings_detail::components<std::remove_reference_t<std::tuple_element_t<I, Tuple>>>()), ...);
        return mask;
    }(std::make_index_sequence<std::tuple_size_v<Tuple>>());
}

}  // namespace qs
