#pragma once
// The "Noise is Beautiful" notes' two float hashes, each shown on 32 cells across the Table 1.1
// plane (the notes say how to hash, not what they drew): a family of its own, compiled without the
// other families' scheduling (shading/CMakeLists.txt says why). Translated from the .frag files
// beside this header, line for line. (The integer hashes are in noise_is_beautiful.h.)

#include "shading/glsl.h"
#include "shading/program.h"
#include "shading/program_of.h"
#include "shading/shaders/collections.h"
#include "shading/shaders/vertex_stages.h"

namespace qs::shaders {
using namespace qs::glsl;

// The sine hash ("trash bits"): fract(sin(x) * 43758.5453) turns the last bits of sin into the
// hash, so it is llvmpipe's only because quadshade's sin on float is llvmpipe's polynomial to
// the bit (shading/number/sin_cos.h). softpipe calls the C library's sinf, half an ulp of 1 away
// from it on many cells, which the factor 43758.5453 makes a different hash.
struct HashSin {
    static constexpr ShaderInfo info{
        .name = "hash_sin",
        .description = "the sine hash fract(sin(dot(p, (12.9898, 78.233))) * 43758.5453) of 32 cells across",
        .glsl_fragment = {"shaders/hash_sin.frag"},
        .wide_batches = true,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static F cellnoise_sin(const vec2<F>& p) {
        return fract(sin(dot(p, vec2<F>(12.9898f, 78.233f))) * 43758.5453f);
    }
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return vec4<F>(vec3<F>(cellnoise_sin(floor(in.st * 32.0f))), 1.0f);
    }
};

// Dave Hoskins' hash12: fract of products, no sin. Mesa's optimizer (NIR) rewrites its dot
// product, as GLSL allows without `precise`: p3 is (a, b, a) (p.xyx), so p3.yzx + 33.33 is
// (b + 33.33, a + 33.33, a + 33.33), the last two terms share their factor a + 33.33 and NIR
// factors them: a (b + 33.33) + (a + b)(a + 33.33). The translation computes that form, so the
// two round alike; computed as written (in any order of the three terms), the dot differs from
// llvmpipe's by an ulp on 16-29% of the pixels (measured on llvmpipe's own st, Table 1.1 plane at
// 500x500), which the final fract makes a different grey on some cells.
struct HashHoskins {
    static constexpr ShaderInfo info{
        .name = "hash_hoskins",
        .description = "Dave Hoskins' hash12 (fract of products) of 32 cells across",
        .glsl_fragment = {"shaders/hash_hoskins.frag"},
    };
    using VertexStage = PlaneSt;
    template <class F>
    static F hash12(const vec2<F>& p) {
        vec3<F> p3 = fract(vec3<F>(p.xyx()) * 0.1031f);
        p3 += vec3<F>(p3.x * (p3.y + 33.33f) + (p3.x + p3.y) * (p3.x + 33.33f));  // dot(p3, p3.yzx + 33.33), factored as Mesa does
        return fract((p3.x + p3.y) * p3.z);
    }
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        return vec4<F>(vec3<F>(hash12(floor(in.st * 32.0f))), 1.0f);
    }
};

QUADSHADE_SHADERS_IN(kNoiseIsBeautiful, HashSin, HashHoskins)

}  // namespace qs::shaders
