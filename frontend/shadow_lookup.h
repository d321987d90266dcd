#pragma once
// The forms of a lookup in a sampler2DShadow, as the lowering and the C++ translation writer both
// read a glslang texture operation. Internal to frontend/.

#include <optional>

#include <glslang/Include/intermediate.h>

namespace qs::frontend {

struct ShadowLookupForm {
    bool projective = false;  // P is (s, t, reference, q)
    // The argument holding the texel offsets (the sampler is argument 0, P argument 1: the offset
    // follows P, or P and the level, or the two derivatives), 0 for none.
    int offset_arg = 0;
};

// nullopt for a texture operation GLSL does not define on a sampler2DShadow, or that is not
// supported on one (textureSize is, and reads the texture as any sampler2D).
inline std::optional<ShadowLookupForm> shadow_lookup_form(glslang::TOperator op) {
    switch (op) {
        case glslang::EOpTexture: case glslang::EOpTextureLod: case glslang::EOpTextureGrad: return ShadowLookupForm{};
        case glslang::EOpTextureProj: case glslang::EOpTextureProjLod: case glslang::EOpTextureProjGrad:
            return ShadowLookupForm{true, 0};
        case glslang::EOpTextureOffset: return ShadowLookupForm{false, 2};
        case glslang::EOpTextureProjOffset: return ShadowLookupForm{true, 2};
        case glslang::EOpTextureLodOffset: return ShadowLookupForm{false, 3};
        case glslang::EOpTextureProjLodOffset: return ShadowLookupForm{true, 3};
        case glslang::EOpTextureGradOffset: return ShadowLookupForm{false, 4};
        case glslang::EOpTextureProjGradOffset: return ShadowLookupForm{true, 4};
        default: return std::nullopt;
    }
}

}  // namespace qs::frontend
