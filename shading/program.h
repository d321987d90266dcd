#pragma once
// The contract between the shader translations and whatever produces fragments (the rasterizer,
// the ray caster). A Program is one catalogue shader with its vertex stage and its fragment
// stage instantiated for every number type; the caller picks the instantiation per batch with a
// ShadeMode. Nothing here knows about images, tiles or threads: a FragmentBatch is just
// kBatchLanes fragments' inputs, laid out as 4 quads when a quad mode is used.

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shading/glsl/texture.h"

namespace qs {

inline constexpr int kBatchLanes = 16;   // 4 quads: one AVX-512 register of floats
inline constexpr int kBatchQuads = kBatchLanes / 4;
inline constexpr int kMaxVaryings = 8;
inline constexpr int kMaxClipDistances = 8;  // GL_MAX_CLIP_DISTANCES: user clip planes

// How a batch's lanes relate and so how dFdx/dFdy are formed.
enum class Derivatives {
    None,         // independent pixels; only for shaders that take no derivatives
    Fine,         // 2x2 quads, llvmpipe's rule
    CoarseLower,  // 2x2 quads, softpipe's rule in OSMesa's buffer
    CoarseUpper,  // 2x2 quads, first pixel of a top-down quad
    Analytic,     // Dual2: exact partials carried from the interpolated varyings
};
enum class Precision { Float, Double };

struct ShadeMode {
    Derivatives derivatives = Derivatives::Fine;
    Precision precision = Precision::Float;
    // Also report, per lane, the GLSL cases with undefined results the colour depends on
    // (ColorBatch::undefined; number/checked.h). Float pixels or quads only: not with Analytic
    // or Double. The colours are the same as without.
    bool check_undefined = false;
};

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

// A sampler uniform a shader declares besides `teximage`: its GLSL name, and whether it is a
// sampler2D or a sampler3D. Scenes bind a texture to it by name (scenes/gltf.h: a material's
// extras.textures).
struct SamplerUse {
    std::string_view name;  // empty: none
    int dims = 2;
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

// GL_MAX_VERTEX_ATTRIBS: the generic vertex attributes a draw can feed (glVertexAttribPointer).
inline constexpr int kMaxGenericAttributes = 16;
// A generic attribute's value at one vertex: four 32-bit words, floats' bits or integers.
using AttributeValue = std::array<std::uint32_t, 4>;

// What the scene and the frame give every shader: its transforms (a GLSL 1.30 vertex stage reads
// them as the uniforms mvp, model, view, projection and normalMatrix: scenes/shader_inputs.h),
// time, its textures, and its own uniforms' values.
struct Uniforms {
    glm::mat4 model_view_projection{1.0f};  // gl_ModelViewProjectionMatrix, mvp
    glm::mat4 model{1.0f};                  // world from object
    glm::mat4 view{1.0f};                   // view from world
    glm::mat4 projection{1.0f};             // clip from view
    glm::mat3 normal_matrix{1.0f};          // transpose(inverse(mat3(view * model)))
    float time = 0.0f;
    const glsl::sampler2D* teximage = nullptr;  // set when Needs::texture
    // ShaderInfo::uniforms' values, kUniformWords 32-bit words each in their order: floats' bits
    // or 32-bit integers. Read through glsl::uniform (glsl/uniform.h).
    const std::uint32_t* user = nullptr;
    // Needs::samplers' textures, in their order, each of the kind the shader declares.
    std::array<const glsl::Texture*, kMaxSamplers> samplers{};
    // Per generic attribute location, its value at each vertex of the draw (VertexIn::id); null:
    // GL's current value, (0, 0, 0, 1), at every vertex.
    std::array<const AttributeValue*, kMaxGenericAttributes> attributes{};
    // glClipPlane's planes in eye space: a vertex stage that writes gl_ClipVertex clips at
    // dot(plane, gl_ClipVertex) >= 0 (VertexOut::clip_distances).
    std::array<glm::vec4, kMaxClipDistances> clip_planes{};

    const glsl::sampler2D& sampler2D(int i) const { return static_cast<const glsl::sampler2D&>(*samplers[std::size_t(i)]); }
    const glsl::sampler3D& sampler3D(int i) const { return static_cast<const glsl::sampler3D&>(*samplers[std::size_t(i)]); }
};

struct VertexIn {
    glm::vec3 position;           // object space (gl_Vertex.xyz)
    glm::vec2 texcoord;           // gl_MultiTexCoord0.st
    glm::vec3 normal{0.0f};       // gl_Normal: glTF's NORMAL, (0, 0, 0) where the mesh has none
    glm::vec4 color{1.0f};        // gl_Color: COLOR_0, (1, 1, 1, 1) where none; a vec3 colour has alpha 1
    glm::vec2 texcoord1{0.0f};    // gl_MultiTexCoord1.st: TEXCOORD_1
    std::uint32_t id = 0;         // gl_VertexID: its index in the draw's vertex arrays
};
struct VertexOut {
    glm::vec4 clip;  // gl_Position
    std::array<float, kMaxVaryings> varyings{};
    // gl_ClipDistance, or each clip plane's distance to gl_ClipVertex: what a draw that clips
    // against user planes (DrawCall::clip_distances) keeps where it is >= 0.
    std::array<float, kMaxClipDistances> clip_distances{};
};

// Inputs of kBatchLanes fragments, structure of arrays. In quad modes lanes 4q..4q+3 are quad q
// in the layout of number/lanes.h; helper lanes carry extrapolated values like the others.
struct FragmentBatch {
    alignas(64) float frag_coord[4][kBatchLanes];  // gl_FragCoord: x, y, z, 1/w
    alignas(64) float varying[kMaxVaryings][kBatchLanes];
    // d(varying)/dx and /dy in window space; filled only for Derivatives::Analytic.
    alignas(64) float varying_dx[kMaxVaryings][kBatchLanes];
    alignas(64) float varying_dy[kMaxVaryings][kBatchLanes];
    // d/dx and d/dy of gl_FragCoord.z and .w (1/w), per lane: planes for the rasterizer, ray
    // differentials for the ray caster. Filled only for Derivatives::Analytic.
    alignas(64) float frag_coord_dx[2][kBatchLanes];
    alignas(64) float frag_coord_dy[2][kBatchLanes];
    // gl_FrontFacing: bit i set when lane i's primitive faces front (counter-clockwise in GL's
    // window, glFrontFace's default).
    std::uint32_t front_facing = ~0u;
};

struct ColorBatch {
    alignas(64) float rgba[4][kBatchLanes];
    // Bit i: lane i executed GLSL's discard. Its fragment writes neither colour nor depth; it
    // was shaded to the end all the same, as a helper for its quad's derivatives. Always written.
    std::uint32_t discarded = 0;
    // Per lane, the Undefined bits (number/checked.h) of its colour; written only when
    // ShadeMode::check_undefined.
    std::uint8_t undefined[kBatchLanes];
};

class Program {
public:
    virtual ~Program() = default;
    virtual const ShaderInfo& info() const = 0;
    virtual void vertex(const VertexIn& in, const Uniforms& u, VertexOut& out) const = 0;
    // Precondition: mode.derivatives != None unless !info().needs.derivatives.
    virtual void shade(ShadeMode mode, const FragmentBatch& in, const Uniforms& u, ColorBatch& out) const = 0;
    // Shades two batches at once, with the same results as shade() on each. For a shader with
    // ShaderInfo::wide_batches, shaded in float on AVX-512 (a batch is then one register) per
    // pixel or in quads by llvmpipe's rule, both go through the shader as one number of twice
    // the width: every operation becomes two independent instructions, which the CPU overlaps,
    // while one batch alone leaves a noise shader's long dependency chains exposed. Otherwise
    // two shade() calls.
    virtual void shade_pair(ShadeMode mode, const FragmentBatch& a, const FragmentBatch& b, const Uniforms& u,
                            ColorBatch& out_a, ColorBatch& out_b) const = 0;
};

}  // namespace qs
