#pragma once
// The built-in shaders' collections (QUADSHADE_SHADERS_IN): the texts in ../shared/seeds they
// translate, and the probes that check the renderer against Mesa. `quadshade shaders` lists and
// `quadshade gallery` draws the catalogue by collection, in this order of names.

#include <string_view>

namespace qs::shaders {

inline constexpr std::string_view kSeed000 = "seed 000: Gustavson, Procedural Textures in GLSL";
inline constexpr std::string_view kSeed001 = "seed 001: ProcTexGen, procedural textures and baking";
inline constexpr std::string_view kSeed002 = "seed 002: Noise is Beautiful";
inline constexpr std::string_view kSeed003 = "seed 003: OpenGL ES tutorial, procedural textures";
inline constexpr std::string_view kSeed004 = "seed 004: Lawlor, Procedural Solid Texturing";
inline constexpr std::string_view kProbes = "tests: probes of the renderer against Mesa";

}  // namespace qs::shaders
