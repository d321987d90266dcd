#pragma once
// The lookups in a sampler2DShadow, as the lowering and the C++ translation writer both read a
// glslang texture operation. Internal to frontend/.

#include <glslang/Include/intermediate.h>

namespace qs::frontend {

// The vocabulary's function of a lookup in a sampler2DShadow (shading/glsl/texture_shadow.h),
// which takes GLSL's arguments in GLSL's order; null for a texture operation GLSL does not define
// on a sampler2DShadow, or that reads it as any sampler2D (textureSize, the gathers,
// textureQueryLod).
inline const char* shadow_lookup_function(glslang::TOperator op) {
    switch (op) {
        case glslang::EOpTexture: return "textureShadow";
        case glslang::EOpTextureProj: return "textureShadowProj";
        case glslang::EOpTextureLod: return "textureShadowLod";
        case glslang::EOpTextureProjLod: return "textureShadowProjLod";
        case glslang::EOpTextureGrad: return "textureShadowGrad";
        case glslang::EOpTextureProjGrad: return "textureShadowProjGrad";
        case glslang::EOpTextureOffset: return "textureShadowOffset";
        case glslang::EOpTextureProjOffset: return "textureShadowProjOffset";
        case glslang::EOpTextureLodOffset: return "textureShadowLodOffset";
        case glslang::EOpTextureProjLodOffset: return "textureShadowProjLodOffset";
        case glslang::EOpTextureGradOffset: return "textureShadowGradOffset";
        case glslang::EOpTextureProjGradOffset: return "textureShadowProjGradOffset";
        default: return nullptr;
    }
}

}  // namespace qs::frontend
