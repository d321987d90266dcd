#pragma once
// Probes of the GLSL vocabulary beyond the chapter's (integers, bools, loops, discard, matrices,
// built-ins), compared with llvmpipe by tests/reference. Translated from the .frag files beside
// this header, line for line; a GLSL if/else chain on varying data is every branch computed
// and selected.

#include "shading/glsl.h"
#include "shading/program.h"
#include "shading/program_of.h"
#include "shading/shaders/collections.h"
#include "shading/shaders/vertex_stages.h"

namespace qs::shaders {
using namespace qs::glsl;

inline constexpr Needs kWindowProbeNeeds{.coordinates = Coordinates::None, .frag_coord = true};

struct IntegerProbe {
    static constexpr ShaderInfo info{
        .name = "integer_probe",
        .description = "probe: int and uint arithmetic, bit operations, shifts, conversions (GLSL 1.30)",
        .needs = kWindowProbeNeeds,
        .glsl_fragment = {"shaders/integer_probe.frag"},
        .glsl_version = 130,
        .wide_batches = true,
    };
    using VertexStage = PlanePosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        using Int = int_t<F>;
        using Uint = uint_t<F>;
        Int x = Int(in.gl_FragCoord.x), y = Int(in.gl_FragCoord.y);
        Int a = x * 7919 - y * 104729 + (x << 20) - 3;
        Int b = (y % 7 + 1) * (x % 11 + 2);
        Uint u = Uint(a) * 2654435761u + Uint(b) * 40503u;
        Uint v = Uint(b) + 0x9E3779B9u * Uint(y);
        Int column = x % 8;
        const Int r0 = a * b + b * b * b;
        const Uint s0 = u * v + (u ^ v);
        const Int r1 = a / b + (-a) / (b + 1);
        const Uint s1 = u / (v | 1u) + u / 3u;
        const Int r2 = (a & 0x7FFFFFFF) % b;
        const Uint s2 = u % (v | 1u);
        const Int r3 = (a >> (b & 31)) + (a << (y & 15));
        const Uint s3 = (u >> Uint(b & 31)) ^ (u << 7u);
        const Int r4 = (a & b) | (a ^ ~b);
        const Uint s4 = ~u & (v | 0xF0F0F0F0u);
        const Int r5 = Int(F(a) * 0.001f) + Int(-2.75f * F(b));
        const Uint s5 = Uint(abs(F(a)) * 0.5f) + Uint(F(b) * 1.5f);
        const Int r6 = min(a, b) + max(a, b) * sign(a) + abs(a) + clamp(a, -100, 100);
        const Uint s6 = min(u, v) + max(u, 7u) + clamp(u, 3u, 9u);
        ivec2<F> p = ivec2<F>(a, b) * 3 - ivec2<F>(1, 2);
        uvec3<F> q = uvec3<F>(u, v, 5u) >> uvec3<F>(1u, 2u, 3u);
        const Int r7 = p.x ^ p.y;
        const Uint s7 = q.x + q.y * q.z;
        const Int r = select(column == 0, r0, select(column == 1, r1, select(column == 2, r2, select(column == 3, r3,
                      select(column == 4, r4, select(column == 5, r5, select(column == 6, r6, r7)))))));
        const Uint s = select(column == 0, s0, select(column == 1, s1, select(column == 2, s2, select(column == 3, s3,
                       select(column == 4, s4, select(column == 5, s5, select(column == 6, s6, s7)))))));
        Uint rb = Uint(r);
        return vec4<F>(F(rb >> 16u), F(rb & 0xFFFFu), F(s >> 16u), F(s & 0xFFFFu));
    }
};

struct IntegerUndefinedProbe {
    static constexpr ShaderInfo info{
        .name = "integer_undefined_probe",
        .description = "probe: integer cases GLSL leaves undefined, one per column (x = 0..13)",
        .needs = kWindowProbeNeeds,
        .glsl_fragment = {"shaders/integer_undefined_probe.frag"},
        .glsl_version = 130,
        .wide_batches = true,
    };
    using VertexStage = PlanePosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        using Int = int_t<F>;
        using Uint = uint_t<F>;
        Int column = Int(in.gl_FragCoord.x);
        Int z = Int(in.gl_FragCoord.y);
        Uint uz = Uint(z);
        F fz = F(z);
        const F n = sqrt(-1.0f + fz), i = 1.0f / fz;
        // Each column's pair (r, s), selected from the last column back to the first.
        Int r = Int(2147483520.0f + fz);
        Uint s = Uint(4294967040.0f + fz);
        auto at = [&](int c, const Int& rc, const Uint& sc) {
            r = select(column == c, rc, r);
            s = select(column == c, sc, s);
        };
        at(12, Int(-i), Uint(-i));
        at(11, Int(i), Uint(i));
        at(10, Int(n), Uint(n));
        at(9, Int(-3e9f + fz), Uint(-3e9f + fz));
        at(8, Int(3e9f + fz), Uint(5e9f + fz));
        at(7, Int(-1.5f + fz), Uint(-1.0f + fz));
        at(6, (5 + z) << (-1 + z), (5u + uz) >> Uint(-1 + z));
        at(5, (-5 + z) >> (32 + z), (5u + uz) << (32u + uz));
        at(4, (5 + z) << (33 + z), (5u + uz) >> (33u + uz));
        at(3, (-2147483647 - 1 + z) / (z - 1), Uint((-2147483647 - 1 + z) % (z - 1)));
        at(2, (-7 + z) % 3, Uint((7 + z) % -3));
        at(1, 7 % z, 7u % uz);
        at(0, 7 / z, 7u / uz);
        Uint rb = Uint(r);
        return vec4<F>(F(rb >> 16u), F(rb & 0xFFFFu), F(s >> 16u), F(s & 0xFFFFu));
    }
};

struct BoolProbe {
    static constexpr ShaderInfo info{
        .name = "bool_probe",
        .description = "probe: bools and bvecs: && || ^^ ! == !=, component-wise comparisons, any, all, not, mix",
        .needs = kWindowProbeNeeds,
        .glsl_fragment = {"shaders/bool_probe.frag"},
        .glsl_version = 130,
        .wide_batches = true,
    };
    using VertexStage = PlanePosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> p = in.gl_FragCoord.xy();
        Bool<F> a = p.x < 9.0f, b = mod(p.y, 3.0f) < 1.5f, c = p.x + p.y > 15.0f;
        bvec3<F> v(a, b != c, !a || b);  // b ^^ c
        bvec3<F> w = lessThan(vec3<F>(p, p.x - p.y), vec3<F>(8.0f, 5.0f, 0.0f));
        bvec2<F> g = greaterThanEqual(p, vec2<F>(4.0f, 6.0f));
        F red = F(any(v)) + 2.0f * F(all(w)) + 4.0f * F(v == w) + 8.0f * F(any(not(equal(v, w))));
        F green = F(a && b) + 2.0f * F(a != b) + 4.0f * F(!(a || c)) + 8.0f * F(a != c) + 16.0f * F(all(g)) +
                  32.0f * F(lessThanEqual(p, vec2<F>(5.0f)) == notEqual(p, p));
        vec3<F> m = mix(vec3<F>(1.0f, 2.0f, 3.0f), vec3<F>(-1.0f, -2.0f, -3.0f), w);
        return vec4<F>(red, green, m.x + 10.0f * m.y + 100.0f * m.z, F(greaterThan(p, vec2<F>(3.0f)) != bvec2<F>(b, c)));
    }
};

struct LoopProbe {
    static constexpr ShaderInfo info{
        .name = "loop_probe",
        .description = "probe: loops that exit per fragment: break, continue, return, while, nested",
        .needs = kWindowProbeNeeds,
        .glsl_fragment = {"shaders/loop_probe.frag"},
        .wide_batches = true,
    };
    using VertexStage = PlanePosition;

    template <class F>
    static F first_step(F start, F step) {
        Return<F> ret;
        F v = start;
        Loop loop(v);
        for (int i = 0; loop(i < 20); i++) {
            v += step;
            loop.return_if(ret, fract(v * 0.375f) > 0.8f, v);
        }
        return ret.value_or(-1.0f);
    }

    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> p = floor(in.gl_FragCoord.xy());
        F v = p.x + 64.0f * p.y + 1.0f, steps = 0.0f, peak = v;
        Loop collatz(v, steps, peak);
        for (int i = 0; collatz(i < 200); i++) {
            collatz.break_if(v == 1.0f);
            v = select(mod(v, 2.0f) == 0.0f, v * 0.5f, 3.0f * v + 1.0f);
            peak = max(peak, v);
            steps += 1.0f;
        }
        F sum = 0.0f;
        Loop summing(sum);
        for (int i = 0; summing(i < 12); i++) {
            summing.continue_if(mod(F(float(i)) + p.x, 3.0f) < 1.0f);
            sum += float(i) * 0.5f;
        }
        F t = 0.0f, k = 0.0f;
        Loop outer(t, k);
        while (outer(t < in.gl_FragCoord.y * 0.25f)) {
            Loop inner(outer, t);
            for (int j = 0; inner(j < 4); j++) {
                t += 0.75f;
                inner.break_if(t > in.gl_FragCoord.x * 0.5f);
            }
            k += 1.0f;
            outer.break_if(k > 6.0f);
        }
        return vec4<F>(steps, peak, sum + 64.0f * (t + 100.0f * k), first_step((p.x - 31.0f) * 0.0625f, F(0.125f)));
    }
};

struct DiscardProbe {
    static constexpr ShaderInfo info{
        .name = "discard_probe",
        .description = "probe: discard on a pattern, before a value and inside a loop; derivatives after it",
        .needs = {.coordinates = Coordinates::None, .derivatives = true, .frag_coord = true},
        .glsl_fragment = {"shaders/discard_probe.frag"},
    };
    using VertexStage = PlanePosition;
    template <class F>
    static FragmentOut<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        FragmentOut<F> out;
        vec2<F> p = in.gl_FragCoord.xy();
        F v = p.x * p.x + 3.0f * p.y * p.y + p.x * p.y;
        out.discard_if(mod(p.x + 2.0f * p.y, 5.0f) < 1.0f);
        F w = v * 0.5f + p.x;
        F acc = 0.0f;
        Loop loop(acc);
        for (int i = 0; loop(i < 8); i++) {
            acc += p.x * float(i + 1);
            loop.discard_if(out, acc > p.y * 9.0f && mod(p.x, 3.0f) < 1.0f);
        }
        out.gl_FragColor = vec4<F>(dFdx(w), dFdy(w), dFdx(acc), dFdy(acc));
        return out;
    }
};

struct MatrixProbe {
    static constexpr ShaderInfo info{
        .name = "matrix_probe",
        .description = "probe: mat2..mat4 and non-square matrices: products, transpose, inverse, determinant (GLSL 1.50)",
        .needs = kWindowProbeNeeds,
        .glsl_fragment = {"shaders/matrix_probe.frag"},
        .glsl_version = 150,
    };
    using VertexStage = PlanePosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> p = floor(in.gl_FragCoord.xy());
        vec4<F> q(mod(p.x, 9.0f) * 0.25f - 1.0f, mod(p.y, 7.0f) * 0.25f - 0.75f, mod(p.x + p.y, 5.0f) * 0.25f - 0.5f,
                  1.5f - mod(p.x * 3.0f + p.y, 11.0f) * 0.25f);
        mat2<F> m2(q.x, q.y, q.z, q.w + 1.25f);
        mat3<F> m3(q.xyz(), q.yzw() + 0.5f, vec3<F>(q.w, 1.0f, q.x - q.z));
        mat4<F> m4(q, q.wzyx() * 0.5f + 0.25f, vec4<F>(1.0f, q.x, -q.y, 0.5f), vec4<F>(q.zw(), 0.25f, q.x + 1.0f));
        mat2x3<F> a(q.xyz(), q.wxy());
        mat3x2<F> b(q.xy(), q.zw(), q.yx());
        mat4x3<F> c(m4);
        mat3x4<F> d = transpose(c);
        F column = mod(p.x, 8.0f);
        vec4<F> r = vec4<F>(mat3<F>(m4) * q.xyz(), (m2 * transpose(m2))[1][1]);
        r = select(column == 6.0f, vec4<F>(outerProduct(q.xy(), q.zwx())[2], matrixCompMult(m3, mat3<F>(q.w))[1].yz()), r);
        r = select(column == 5.0f, inverse(m4)[2] + vec4<F>(inverse(m3)[0], inverse(m2)[1][0]), r);
        r = select(column == 4.0f, vec4<F>((b * a)[1], (d * c)[2].zw()), r);
        r = select(column == 3.0f, vec4<F>(a * b * q.xyz(), determinant(m4)), r);
        r = select(column == 2.0f, m4 * q + q * m4, r);
        r = select(column == 1.0f, vec4<F>(m3 * q.xyz(), determinant(m3)), r);
        r = select(column == 0.0f, vec4<F>(m2 * q.xy(), q.zw() * m2), r);
        return r;
    }
};

struct BuiltinsProbe {
    static constexpr ShaderInfo info{
        .name = "builtins_probe",
        .description = "probe: rounding, angles, reflect, refract, faceforward, isnan, isinf, modf, bits of floats, write swizzles, asin, acos (GLSL 3.30)",
        .needs = kWindowProbeNeeds,
        .glsl_fragment = {"shaders/builtins_probe.frag"},
        .glsl_version = 330,
    };
    using VertexStage = PlanePosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        vec2<F> p = floor(in.gl_FragCoord.xy());
        F z = floor(p.x / 4096.0f);  // 0 at run time
        F s = (p.x - 31.0f) * 0.0625f, t = (p.y - 7.0f) * 0.5f;
        vec3<F> I(s, -1.0f, t * 0.25f), N(0.25f, 1.0f, s * 0.5f);
        F column = mod(p.x, 8.0f);
        vec4<F> r(asin(clamp(s, -1.0f, 1.0f)), acos(clamp(s * 0.5f, -1.0f, 1.0f)), tan(s), atan(t, s));
        r = select(column == 6.0f, vec4<F>(mix(s, t, t > 0.0f), step(0.0f, s) + 2.0f * F(any(lessThan(vec3<F>(s, t, s + t), vec3<F>(0.0f)))),
                                           F(all(greaterThanEqual(vec2<F>(s, t), vec2<F>(-0.5f)))),
                                           F(notEqual(vec2<F>(s, t), vec2<F>(s, 0.0f)).y)), r);
        vec4<F> v(s, t, s * t, 1.0f);
        v.xy() -= vec2<F>(t, 2.0f);
        v.wz() = v.xy() * 0.5f;
        v.yxw() *= vec3<F>(1.5f, -1.0f, 0.25f);
        r = select(column == 5.0f, v + vec4<F>(F(floatBitsToUint(s) >> 20u), F(floatBitsToInt(t) & 0xFFFF), 0.0f, 0.0f), r);
        F i;
        F f = modf(t * 3.0f + s, i);
        r = select(column == 4.0f, vec4<F>(f, i, intBitsToFloat(floatBitsToInt(s) ^ int(0x80000000)), uintBitsToFloat(floatBitsToUint(t) + 1u)), r);
        r = select(column == 3.0f, vec4<F>(refract(I * 0.5f, N * 0.5f, 0.75f + s * 0.25f),
                                           F(isnan(z / z)) + 2.0f * F(isinf(s / z)) + 4.0f * F(isnan(s))), r);
        r = select(column == 2.0f, vec4<F>(reflect(I, N), dot(faceforward(N, I, vec3<F>(0.0f, t, 1.0f)), vec3<F>(1.0f))), r);
        r = select(column == 1.0f, vec4<F>(degrees(s), radians(t), sign(s), fract(-t)), r);
        r = select(column == 0.0f, vec4<F>(round(t), roundEven(s * 8.0f + 0.5f), trunc(t), ceil(-t)), r);
        return r;
    }
};

struct SinCosProbe {
    static constexpr ShaderInfo info{
        .name = "sin_cos_probe",
        .description = "probe: sin, cos and the sine hash over every kind of float argument, huge ones included (GLSL 3.30)",
        .needs = kWindowProbeNeeds,
        .glsl_fragment = {"shaders/sin_cos_probe.frag"},
        .glsl_version = 330,
        .wide_batches = true,
    };
    using VertexStage = PlanePosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms&) {
        using Uint = uint_t<F>;
        vec2<F> p = floor(in.gl_FragCoord.xy());
        Uint i = Uint(p.x) + 256u * Uint(p.y);
        Uint h = i * 2654435761u;
        vec2<F> q = vec2<F>(p.x * 0.5f, (p.y - 192.0f) * 2.0f) + fract(vec2<F>(F(h & 1023u), F(h >> 22u)) / 1024.0f);
        F a = select(p.y < 96.0f, uintBitsToFloat(h),
                     select(p.y < 192.0f, uintBitsToFloat((h & 0x807FFFFFu) | ((96u + i % 64u) << 23u)),
                            dot(q, vec2<F>(12.9898f, 78.233f))));
        F s = sin(a);
        return vec4<F>(a, s, cos(a), fract(s * 43758.5453f));
    }
};

struct UniformProbe {
    static constexpr UniformDecl kUniforms[] = {
        {"uScale", UniformType::Float, {4.0f}},
        {"uTint", UniformType::Vec3, {1.0f, 0.5f, 0.2f}},
        {"uBands", UniformType::Int, {3.0f}},
        {"uCells", UniformType::IVec2, {2.0f, 5.0f}},
        {"uSeed", UniformType::Uint, {7.0f}},
        {"uRotate", UniformType::Mat2, {1.0f, 0.0f, 0.0f, 1.0f}},
        {"uWarp", UniformType::Mat3, {1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f}},
        // Always the frame's size in both renderers; this is only for a draw without a scene
        // (tests of every shader on bare batches), where 0 would make every pixel alike.
        {"uResolution", UniformType::Vec2, {64.0f, 64.0f}},
    };
    enum : int { uScale, uTint, uBands, uCells, uSeed, uRotate, uWarp, uResolution };
    static_assert(kUniforms[uResolution].name == "uResolution" && kUniforms[uWarp].name == "uWarp");
    static constexpr ShaderInfo info{
        .name = "uniform_probe",
        .description = "probe: a shader's own uniforms (float, vec3, int, ivec2, uint, mat2, mat3) and uResolution (GLSL 1.30)",
        .needs = kWindowProbeNeeds,
        .glsl_fragment = {"shaders/uniform_probe.frag"},
        .glsl_version = 130,
        .uniforms = kUniforms,
        .wide_batches = true,
    };
    using VertexStage = PlanePosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        using Int = int_t<F>;
        using Uint = uint_t<F>;
        vec2<F> p = in.gl_FragCoord.xy() / uniform<vec2<F>>(u, uResolution) - 0.5f;
        vec2<F> q = uniform<mat2<F>>(u, uRotate) * p * uniform<F>(u, uScale);
        vec3<F> w = uniform<mat3<F>>(u, uWarp) * vec3<F>(q, 1.0f);
        ivec2<F> cell = ivec2<F>(floor(abs(w.xy()))) * uniform<ivec2<F>>(u, uCells);
        Int bands = max(uniform<Int>(u, uBands), Int(1));
        Int band = Int((Uint(cell.x + cell.y) * uniform<Uint>(u, uSeed)) % Uint(bands));
        return vec4<F>(uniform<vec3<F>>(u, uTint) * (F(band + 1) / F(bands)), fract(w.z));
    }
};

QUADSHADE_SHADERS_IN(kProbes, IntegerProbe, IntegerUndefinedProbe, BoolProbe, LoopProbe, DiscardProbe, MatrixProbe, BuiltinsProbe,
                     UniformProbe, SinCosProbe)

}  // namespace qs::shaders
