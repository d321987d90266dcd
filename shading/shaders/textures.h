#pragma once
// Shaders that sample named textures: the ProcTexGen articles' fast noise from a 3D volume, and the
// probes that compare each lookup (texture2D with a bias, texture2DLod, texture3D, texture3DLod,
// textureSize and texelFetch) with llvmpipe (tests/reference/test_texture_conformance.cpp).
// Translated from the .frag files beside this header.

#include "shading/glsl.h"
#include "shading/program.h"
#include "shading/program_of.h"
#include "shading/shaders/collections.h"
#include "shading/shaders/vertex_stages.h"

namespace qs::shaders {
using namespace qs::glsl;

inline constexpr Needs kTeximageProbeNeeds{.texture = true};
inline constexpr Needs kVolumeProbeNeeds{.samplers = {SamplerUse{"volume", 3}}};

struct TextureLodProbe {
    static constexpr ShaderInfo info{
        .name = "texture_lod_probe",
        .description = "probe: texture2DLod at a level from -1.5 to 8.375 in eighths",
        .needs = kTeximageProbeNeeds,
        .glsl_fragment = {"shaders/texture_lod_probe.frag"},
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        vec2<F> st = in.st;
        return texture2DLod(*u.teximage, st, floor(fract(st.x + st.y) * 80.0f) * 0.125f - 1.5f);
    }
};

struct TextureBiasProbe {
    static constexpr ShaderInfo info{
        .name = "texture_bias_probe",
        .description = "probe: texture2D with a bias from -1 to 2 per pixel",
        .needs = kTeximageProbeNeeds,
        .glsl_fragment = {"shaders/texture_bias_probe.frag"},
        .wide_batches = true,
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        vec2<F> st = in.st;
        return texture2D(*u.teximage, st, fract(st.y * 2.0f) * 3.0f - 1.0f);
    }
};

struct Texture3dProbe {
    static constexpr ShaderInfo info{
        .name = "texture3d_probe",
        .description = "probe: texture3D of the sampler3D `volume` at (st, 0.75 s - 0.5 t)",
        .needs = kVolumeProbeNeeds,
        .glsl_fragment = {"shaders/texture3d_probe.frag"},
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        const sampler3D& volume = u.sampler3D(0);
        vec2<F> st = in.st;
        return texture3D(volume, vec3<F>(st, st.x * 0.75f - st.y * 0.5f));
    }
};

struct Texture3dLodProbe {
    static constexpr ShaderInfo info{
        .name = "texture3d_lod_probe",
        .description = "probe: texture3DLod of `volume` at a level from -1 to 4.875 in eighths",
        .needs = kVolumeProbeNeeds,
        .glsl_fragment = {"shaders/texture3d_lod_probe.frag"},
    };
    using VertexStage = PlaneSt;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        const sampler3D& volume = u.sampler3D(0);
        vec2<F> st = in.st;
        return texture3DLod(volume, vec3<F>(st, st.x * 0.75f - st.y * 0.5f), floor(fract(st.x + st.y) * 48.0f) * 0.125f - 1.0f);
    }
};

inline constexpr Needs kTexelFetchNeeds{.coordinates = Coordinates::None, .texture = true, .frag_coord = true};

struct TexelFetchProbe {
    static constexpr ShaderInfo info{
        .name = "texel_fetch_probe",
        .description = "probe: textureSize (levels -1 to 4) and texelFetch (levels -1 to 2, texels 2 past each edge) of teximage (GLSL 1.30)",
        .needs = kTexelFetchNeeds,
        .glsl_fragment = {"shaders/texel_fetch_probe.frag"},
        .glsl_version = 130,
        .wide_batches = true,
    };
    using VertexStage = PlanePosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        using Int = int_t<F>;
        ivec2<F> pixel = ivec2<F>(in.gl_FragCoord.xy());
        Int level = (pixel.x / 4) % 6 - 1;
        ivec2<F> size = textureSize<F>(*u.teximage, level);
        ivec2<F> texel = (pixel * ivec2<F>(3, 5)) % (size + 5) - 2;
        vec4<F> c = texelFetch<F>(*u.teximage, texel, (pixel.x + pixel.y) % 4 - 1);
        return select(pixel.x % 2 == 0, vec4<F>(c.xyz(), 0.75f + 0.25f * c.w),
                      vec4<F>(vec2<F>(size) / 1024.0f, F(level + 1) / 8.0f, 1.0f));
    }
};

struct TexelFetch3dProbe {
    static constexpr ShaderInfo info{
        .name = "texel_fetch_3d_probe",
        .description = "probe: textureSize (levels -1 to 4) and texelFetch (levels -1 to 2, texels 2 past each face) of the sampler3D `volume` (GLSL 1.30)",
        .needs = {.coordinates = Coordinates::None, .frag_coord = true, .samplers = {SamplerUse{"volume", 3}}},
        .glsl_fragment = {"shaders/texel_fetch_3d_probe.frag"},
        .glsl_version = 130,
        .wide_batches = true,
    };
    using VertexStage = PlanePosition;
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        using Int = int_t<F>;
        const sampler3D& volume = u.sampler3D(0);
        ivec2<F> pixel = ivec2<F>(in.gl_FragCoord.xy());
        Int level = (pixel.x / 4) % 6 - 1;
        ivec3<F> size = textureSize<F>(volume, level);
        ivec3<F> texel = (ivec3<F>(pixel, pixel.x + pixel.y) * ivec3<F>(3, 5, 7)) % (size + 5) - 2;
        vec4<F> c = texelFetch<F>(volume, texel, (pixel.x + pixel.y) % 4 - 1);
        return select(pixel.x % 2 == 0, vec4<F>(c.xyz(), 0.75f + 0.25f * c.w), vec4<F>(vec3<F>(size) / 1024.0f, 1.0f));
    }
};

// The ProcTexGen articles' noiseFast on the object position (as improved noise, which it approximates).
struct FastNoise {
    static constexpr ShaderInfo info{
        .name = "fast_noise",
        .description = "noiseFast, two trilinear lookups of a 32^3 looping-noise volume (sampler3D noise3dSampler)",
        .needs = {.coordinates = Coordinates::Object3D, .samplers = {SamplerUse{"noise3dSampler", 3}}},
        .glsl_fragment = {"shaders/fast_noise.frag"},
        .wide_batches = true,
    };
    using VertexStage = ObjectPosition;
    static constexpr float PI = 3.14159265358979f;
    template <class F>
    static F noiseFast(const sampler3D& noise3dSampler, vec3<F> p) {
        p = p / 8.0f;
        vec2<F> hi = texture3D(noise3dSampler, p).xy() * 2.0f - 1.0f;  // .rg
        F lo = texture3D(noise3dSampler, p / 9.0f).x * 2.0f - 1.0f;  // .r
        F angle = lo * 2.0f * PI;
        return hi.x * cos(angle) + hi.y * sin(angle);
    }
    template <class F>
    static vec4<F> fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {
        return vec4<F>(vec3<F>(0.5f + 0.5f * noiseFast(u.sampler3D(0), in.P)), 1.0f);
    }
};

QUADSHADE_SHADERS_IN(kProbes, TextureLodProbe, TextureBiasProbe, Texture3dProbe, Texture3dLodProbe, TexelFetchProbe,
                     TexelFetch3dProbe)
QUADSHADE_SHADERS_IN(kProcTexGen, FastNoise)

}  // namespace qs::shaders
