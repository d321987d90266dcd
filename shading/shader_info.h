#pragma once
// What a shader is and what it needs (ShaderInfo, Needs): the description the renderer reads to
// leave out everything a shader does not use, and the bounds `quadshade check` holds it to.

#include <array>
#include <cstddef>
#include <span>
#include <string_view>

#include "shading/uniform_decl.h"

namespace qs {

// The pattern's coordinate space: what the vertex stage feeds the fragment stage. None exactly
// when it hands over no varying (ProgramOf checks); `quadshade render` warns when a Texcoord2D
// shader draws a mesh without texture coordinates, and `quadshade shaders` lists it.
enum class Coordinates {
    None,        // window position only (gl_FragCoord)
    Texcoord2D,  // st from TEXCOORD_0
    Object2D,    // the object-space position's x and y
    Object3D,    // the object-space position (a solid texture)
};

inline constexpr int kMaxSamplers = 4;

// A sampler uniform a shader declares besides `teximage`: its GLSL name, its kind (2: sampler2D,
// 3: sampler3D, 6: samplerCube, glsl::kCubeDims) and whether it is a shadow sampler
// (sampler2DShadow, samplerCubeShadow), which reads a depth comparison texture and nothing else.
// Scenes bind a texture to it by name (scenes/gltf.h: a material's extras.textures).
struct SamplerUse {
    std::string_view name;  // empty: none
    int dims = 2;
    bool shadow = false;
};

// What a shader uses, so that the renderer leaves out everything else.
struct Needs {
    Coordinates coordinates = Coordinates::Texcoord2D;
    bool derivatives = false;  // dFdx/dFdy/fwidth: quads with helper lanes
    bool texture = false;      // the scene must provide `teximage`
    bool time = false;         // output changes with the `time` uniform
    // Interpolated floats the vertex stage writes, and (bit v) those that are `flat`, the
    // provoking (last) vertex's value. Shader structs leave both unset: ProgramOf counts them
    // from the vertex stage's Varyings (shading/varyings.h).
    int varyings = 0;
    unsigned flat_varyings = 0;
    // (bit v) those that are `noperspective`: interpolated linearly in the window.
    unsigned noperspective_varyings = 0;
    // The fragment stage reads gl_FragCoord. When false the rasterizer does not interpolate it
    // and it reads as NaN; the reference tests against OSMesa would catch a shader that reads it
    // without saying so.
    bool frag_coord = false;
    // Its other samplers, Uniforms::samplers in this order.
    std::array<SamplerUse, kMaxSamplers> samplers{};
};

// A documented departure from the bar `quadshade check` holds a shader to (regression/check.h): on the
// scene whose file is named `scene` without its extension (empty: every scene), under the
// derivative rule `rule` ("fine" or "coarse-lower"; empty: both), at most `over_1` pixels more
// than 1/255 off OSMesa's, `over_2` more than 2/255 off, and `coverage` pixels covered by one and
// not the other, because of `cause` (which the report prints).
struct CheckBound {
    std::string_view scene;
    std::string_view rule;
    std::size_t over_1 = 0, over_2 = 0, coverage = 0;
    std::string_view cause;
};

// Whether a shader samples any texture: `teximage` or a named sampler.
constexpr bool samples_textures(const Needs& n) { return n.texture || !n.samplers[0].name.empty(); }

// GLSL files of one stage, relative to the shader's GLSL folder (catalogue.h), concatenated in
// order: the shared functions first (noise/simplex3d.glsl), the stage's main last.
using GlslFiles = std::array<std::string_view, 4>;

// What a shader is: named fields, each with a default, so that a shader states only what differs:
//
//     static constexpr ShaderInfo info{
//         .name = "stripes",
//         .description = "diagonal stripes anti-aliased with fwidth",
//         .needs = {.derivatives = true},
//         .glsl_fragment = {"shaders/stripes.frag"},
//     };
//
// The vertex stage's GLSL is the vertex stage's own (its `glsl`: shading/varyings.h).
struct ShaderInfo {
    std::string_view name;         // what scenes and command lines ask for: letters, digits and '_'
    std::string_view description;  // one line, for listings
    Needs needs = {};
    GlslFiles glsl_fragment = {};
    std::string_view glsl_defines = {};  // prepended to both stages after #version
    // The GLSL version its sources are compiled as (the #version line the exporter writes): 0 for
    // the #version line of the stage's first file if it has one (glsl_export.h), else 120; 130 and
    // later for integers, bit operations and the like; from 150 on the compatibility profile,
    // which keeps gl_Vertex, gl_FragColor and the matrix uniforms. OSMesa's llvmpipe compiles up
    // to 450, softpipe up to 330.
    int glsl_version = 0;
    // The uniforms the GLSL declares besides the scene's (time, teximage, the samplers of
    // Needs::samplers, the transforms of scenes/shader_inputs.h), in the order of Uniforms::user.
    std::span<const UniformDecl> uniforms = {};
    // Seconds after which the output repeats exactly (the noise's hash period along the axis
    // time moves): lets a renderer keep long animations' time in double and hand the shader
    // time modulo the period. 0: time unused, or no exact period.
    double time_period = 0.0;
    // Program::shade_pair runs two batches as one number of twice the width, as a GPU driver
    // picks a wave size per shader. It pays where a shader is long dependency chains on few
    // values (the noises: 5-30% faster) or short (the call's fixed cost halves), and costs
    // where its values outgrow the registers (five octaves of 3D simplex noise, the 3D Worley
    // searches: 1.4-1.6x slower). Pixels wide, or quads wide with llvmpipe's rule (Fine; each
    // quad's derivatives shuffle inside its register). Set where quadshade-bench-batch-width,
    // which times both for every shader, found the pair at most 0.95 of two batches' time.
    bool wide_batches = false;
    // Where `quadshade check` should not hold it to the bar, and why.
    std::span<const CheckBound> check_bounds = {};

    // Filled by ProgramOf from the vertex stage (leave them unset): its GLSL files, and whether
    // they are quadshade's own (a stock stage, shading/shaders/vertex_stages.h), read from the
    // built-in shaders' GLSL folder even for a plugin's shader.
    GlslFiles glsl_vertex = {};
    bool stock_vertex_glsl = false;
};

}  // namespace qs
