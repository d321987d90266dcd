// GLSL run as written by the interpreter, against OSMesa llvmpipe running the same GLSL on the
// Table 1.1 plane: every noise function of Stefan Gustavson's and Ashima Arts' webgl-noise
// (tests/glsl/webgl-noise, MIT), which nobody here wrote, each called from a small main; and the
// language's constructs where lanes diverge (loops each lane leaves on its own, returns, switch,
// discard beside derivatives, a loop that never ends). The bar is the catalogue's: llvmpipe's
// coverage, and no pixel more than 1/255 off unless a bound below names the pixels and the cause.

#include <catch2/catch.hpp>

#include <bit>
#include <cstdint>
#include <fstream>
#include <sstream>

#include "frontend/compile.h"
#include "reference/depth_mipmaps.h"
#include "reference/gl_renderer.h"
#include "render/glsl_shaders.h"
#include "render/scene_render.h"
#include "shading/glsl/texture.h"
#include "tests/cube_map.h"
#include "tests/reference/comparison.h"
#include "tests/test_paths.h"

namespace qs {

namespace {

using namespace test;

std::string read_text(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// The file's functions under the #version a caller needs, its own #version line dropped.
std::string library(const std::string& file) {
    std::string text = read_text(kSource / "tests/glsl/webgl-noise" / file);
    if (text.rfind("#version", 0) == 0) text = "//" + text;  // a comment now, the line count kept
    return text;
}

struct Case {
    const char* name;  // also the file name the test writes
    const char* file;
    const char* main;  // the body of main(): reads `st`, writes `c` (vec3)
    std::size_t over_1 = 0;  // pixels the bound allows over 1/255
    const char* cause = nullptr;
};

const Case kCases[] = {
    {"noise2D", "noise2D.glsl", "c = vec3(0.5 + 0.5 * snoise(st * 8.0));"},
    {"noise3D", "noise3D.glsl", "c = vec3(0.5 + 0.5 * snoise(vec3(st * 8.0, 0.7)));"},
    {"noise3Dgrad", "noise3Dgrad.glsl", "vec3 g; float n = snoise(vec3(st * 8.0, 0.7), g); c = 0.5 + 0.5 * vec3(n, 0.1 * g.xy);"},
    {"noise4D", "noise4D.glsl", "c = vec3(0.5 + 0.5 * snoise(vec4(st * 8.0, 0.3, 0.9)));"},
    {"classicnoise2D", "classicnoise2D.glsl", "c = 0.5 + 0.5 * vec3(cnoise(st * 8.0), pnoise(st * 8.0, vec2(4.0)), 0.0);"},
    {"classicnoise3D", "classicnoise3D.glsl",
     "c = 0.5 + 0.5 * vec3(cnoise(vec3(st * 8.0, 0.7)), pnoise(vec3(st * 8.0, 0.7), vec3(4.0)), 0.0);"},
    {"classicnoise4D", "classicnoise4D.glsl",
     "c = 0.5 + 0.5 * vec3(cnoise(vec4(st * 8.0, 0.3, 0.9)), pnoise(vec4(st * 8.0, 0.3, 0.9), vec4(4.0)), 0.0);"},
    {"cellular2D", "cellular2D.glsl", "vec2 F = cellular(st * 8.0); c = vec3(F, F.y - F.x);"},
    {"cellular2x2", "cellular2x2.glsl", "vec2 F = cellular2x2(st * 8.0); c = vec3(F, F.y - F.x);"},
    {"cellular2x2x2", "cellular2x2x2.glsl", "vec2 F = cellular2x2x2(vec3(st * 8.0, 0.7)); c = vec3(F, F.y - F.x);"},
    {"cellular3D", "cellular3D.glsl", "vec2 F = cellular(vec3(st * 8.0, 0.7)); c = vec3(F, F.y - F.x);"},
    {"psrdnoise2D", "psrdnoise2D.glsl",
     "vec3 n = psrdnoise(st * 8.0, vec2(4.0, 6.0), 0.5); c = vec3(0.5 + 0.5 * n.x, 0.5 + 0.05 * n.yz);"},
    {"psnoise2D", "psrdnoise2D.glsl", "c = vec3(0.5 + 0.5 * psnoise(st * 8.0, vec2(4.0, 6.0)), 0.5 + 0.5 * srnoise(st * 8.0, 1.5), 0.0);"},
};


// Whole fragment shaders (GLSL 1.30: integers, switch) that read `st` and write `color`.
struct LanguageCase {
    const char* name;
    const char* source;
    std::size_t over_1 = 0;  // pixels the bound allows over 1/255
    const char* cause = nullptr;
};

const LanguageCase kLanguage[] = {
    {"divergent_loops", R"(
in vec2 st;
out vec4 color;
void main() {
    int n = 0;
    float x = 0.0;
    for (int i = 0; i < 64; ++i) {
        if (i % 3 == 1) continue;
        x += sin(float(i) * st.x * 7.0);
        if (x > 2.0 * st.y + 0.5) break;
        n++;
    }
    int m = 0;
    do { m += 2; } while (float(m) < st.y * 20.0);
    color = vec4(float(n) / 64.0, fract(x), float(m) / 20.0, 1.0);
})"},
    {"functions_and_returns", R"(
in vec2 st;
out vec4 color;
struct Ring { vec2 centre; float radius; };
float rings(in Ring r, inout int visits, out bool inside) {
    visits += 1;
    float d = distance(st, r.centre);
    inside = d < r.radius;
    if (inside) return d / r.radius;
    for (int k = 0; k < 8; k++) {
        if (d < r.radius * float(k + 2)) return float(k) / 8.0;
    }
    return 1.0;
}
void main() {
    Ring r[3] = Ring[3](Ring(vec2(0.3), 0.1), Ring(vec2(0.7, 0.4), 0.05), Ring(vec2(0.5, 0.8), 0.08));
    int visits = 0;
    bool inside;
    int pick = int(floor(st.x * 3.0)) % 3;
    float a = rings(r[pick], visits, inside);
    float b = rings(r[(pick + 1) % 3], visits, inside);
    color = vec4(a, b, inside ? 1.0 : 0.0, float(visits) / 4.0);
})"},
    {"switch_and_integers", R"(
in vec2 st;
out vec4 color;
void main() {
    ivec2 cell = ivec2(st * 16.0);
    uint h = uint(cell.x * 73856093 ^ cell.y * 19349663);
    h = (h >> 13u) * 2654435761u + (h << 7u);
    vec3 c;
    switch (int(h % 5u)) {
    case 0: c = vec3(1.0, 0.2, 0.2); break;
    case 1:
    case 2: c = vec3(0.2, float((h >> 5u) & 31u) / 31.0, 0.2); break;
    case 3: c = vec3(float(h % 97u) / 96.0); break;
    default: c = vec3(float(h & 255u) / 255.0, 0.0, 1.0);
    }
    color = vec4(c, 1.0);
})"},
    {"discard_beside_derivatives", R"(
in vec2 st;
out vec4 color;
void main() {
    vec2 p = st * 12.0;
    if (fract(p.x + p.y) < 0.3) discard;
    float w = 0.0;
    for (int i = 0; i < 4; i++) {
        if (fract(p.x * float(i + 1)) > 0.8) break;
        w += fwidth(p.x * p.y * float(i + 1));
    }
    color = vec4(w, dFdx(p.y * p.y), dFdy(sin(p.x)) * 0.5 + 0.5, 1.0);
})",
     // llvmpipe's discarded lanes do not advance the loop: their i stays 0, so a pixel whose quad
     // neighbour discarded takes fwidth of p.x p.y (i + 1) against the neighbour's p.x p.y from
     // the second iteration on, where quadshade's helper lanes carry the loop's i. A float model
     // of the quads with discarded lanes kept at i = 0 gives llvmpipe's red on exactly these 7
     // pixels, the one with helpers carrying i gives ours; w saturates elsewhere (red = w).
     7, "llvmpipe's discarded lanes keep i = 0 in the loop, quadshade's helpers carry it: fwidth differs beside "
        "them where w < 1, on 7 of 4096 pixels"},
    {"loop_that_never_ends", R"(
in vec2 st;
out vec4 color;
void main() {
    // llvmpipe leaves a loop after 65,535 iterations of the shader's loops together; the lanes
    // that would never leave it end with x whatever that many iterations left.
    float x = 0.0;
    int i = 0;
    while (x < 2.0 * st.x) {
        x += st.y < 0.5 ? 0.0 : 0.001;
        i++;
    }
    color = vec4(x, float(i % 256) / 255.0, float(i) / 65535.0, 1.0);
})"},
};

// `fragment` (with the vertex shader the front end writes for it) drawn on `scene` by the
// interpreter and by llvmpipe, held to the bar with `over_1` pixels allowed past 1/255, or
// (`exact`) to llvmpipe's 8-bit colours.
void check_against_llvmpipe(const std::filesystem::path& dir, GlContext& context, GlPrograms& programs, int size,
                            const std::string& name, const std::string& fragment, std::size_t over_1, const char* cause,
                            Scene scene, bool exact = false) {
    const std::filesystem::path frag = dir / (name + ".frag"), vert = dir / (name + ".vert");
    std::ofstream(frag) << fragment;
    std::ofstream(vert) << frontend::default_vertex_shader({frag.string(), fragment}).text;
    const GlslShader shader = load_glsl_shader(frag, vert);

    FrameRequest r;
    r.width = r.height = size;
    r.shader_override = std::string(shader.program->info().name);
    r.set(raster_options_as(GlDriver::Llvmpipe));
    const Framebuffer ours = render_frame(scene, r);
    const Image reference = GlSceneRenderer(scene, {size, size, {}, name, {}}, context, programs).render();
    const Counts n = count(ours, reference);
    INFO(name << ": " << n.over_1 << " pixels over 1/255, " << n.over_2 << " over 2/255, at most " << n.max_steps
              << " steps, coverage differs on " << n.coverage_mismatch
              << (cause ? std::string(" (") + cause + ")" : std::string()));
    CHECK(n.coverage_mismatch == 0);
    CHECK(n.over_1 <= over_1);
    if (exact) CHECK(n.max_steps == 0);
    if (n.over_1 > 0 || (exact && n.max_steps > 0)) write_comparison(ours, reference, dir / (name + "-comparison.png"));
}
// ... on the Table 1.1 plane.
void check_against_llvmpipe(const std::filesystem::path& dir, GlContext& context, GlPrograms& programs, int size,
                            const std::string& name, const std::string& fragment, std::size_t over_1, const char* cause) {
    check_against_llvmpipe(dir, context, programs, size, name, fragment, over_1, cause, load_scene(kPlane));
}

// Texture lookups with explicit derivatives (textureGrad) and texel offsets (the *Offset forms):
// whole fragment shaders (GLSL 1.30) that read `st`, `teximage` (2D) and `volume` (3D) and write
// `color`, each drawn on the plane under every sampler below. The derivatives vary within a
// quad (llvmpipe takes its upper-left pixel's), reach every level, and overflow to infinity on
// a band (llvmpipe reads level 0 there); the offsets go past the texture's edges under each wrap.
const LanguageCase kTextureLookups[] = {
    {"texture_grad", R"(
in vec2 st;
out vec4 color;
uniform sampler2D teximage;
void main() {
    vec2 p = st * 3.0 - 1.0;
    float k = exp2(fract(st.x * 5.0) * 9.0 - 3.0);
    vec2 dx = vec2(0.01 * k, 0.003 * gl_FragCoord.y / 64.0), dy = vec2(0.002, 0.012 * k) * (0.5 + st.y);
    if (st.y > 0.9) dx.x = 1e30;
    color = vec4(textureGrad(teximage, p, dx, dy).rgb, 1.0);
})"},
    {"texture_proj_grad_3d", R"(
in vec2 st;
out vec4 color;
uniform sampler3D volume;
void main() {
    vec4 p = vec4(st * 2.0 - 0.5, st.x * 0.75 - st.y * 0.5, 1.0) * (1.0 + st.y);
    vec3 dx = dFdx(p.xyz) * exp2(st.x * 6.0 - 1.0), dy = vec3(0.0, 0.004, 0.03 * st.y);
    color = vec4(0.5 * (textureGrad(volume, p.xyz / p.w, dx, dy).rgb + textureProjGrad(volume, p, dy, dx).rgb), 1.0);
})"},
    {"texture_offset", R"(
in vec2 st;
out vec4 color;
uniform sampler2D teximage;
void main() {
    vec2 p = st * 4.0 - 1.5;
    vec3 a = textureOffset(teximage, p, ivec2(-3, 2)).rgb;
    vec3 b = textureOffset(teximage, p * 0.5, ivec2(7, -8), st.x * 3.0 - 1.0).rgb;
    vec3 c = textureProjOffset(teximage, vec3(p, 1.0 + st.y), ivec2(1, 5)).rgb;
    color = vec4(st.x < 0.33 ? a : st.x < 0.67 ? b : c, 1.0);
})"},
    {"texture_lod_grad_offset", R"(
in vec2 st;
out vec4 color;
uniform sampler2D teximage;
void main() {
    vec2 p = st * 2.5 - 0.75;
    vec3 a = textureLodOffset(teximage, p, st.y * 6.0 - 1.0, ivec2(-8, 7)).rgb;
    vec3 b = textureGradOffset(teximage, p, vec2(0.05 * st.y, 0.0), vec2(0.0, 0.02), ivec2(4, -1)).rgb;
    vec3 c = textureProjLodOffset(teximage, vec4(p, 0.0, 2.0), 1.0, ivec2(-2, -6)).rgb;
    color = vec4(st.x < 0.33 ? a : st.x < 0.67 ? b : c, 1.0);
})"},
    {"texel_fetch_offset", R"(
in vec2 st;
out vec4 color;
uniform sampler2D teximage;
uniform sampler3D volume;
void main() {
    ivec2 size = textureSize(teximage, 0);
    ivec2 texel = ivec2(st * vec2(size + 8)) - 4;
    vec4 a = texelFetchOffset(teximage, texel, int(st.y * 3.0), ivec2(3, -2));
    vec4 b = texelFetchOffset(volume, ivec3(texel, int(st.x * 40.0) - 4), 0, ivec3(-1, 2, 3));
    color = vec4(st.x < 0.5 ? a.rgb : b.rgb, 1.0);
})"},
    {"texture_offset_3d", R"(
in vec2 st;
out vec4 color;
uniform sampler3D volume;
void main() {
    vec3 p = vec3(st * 3.0 - 1.0, st.x - st.y);
    vec3 a = textureOffset(volume, p, ivec3(2, -3, 1)).rgb;
    vec3 b = textureLodOffset(volume, p, st.y * 4.0 - 0.5, ivec3(-5, 0, 6)).rgb;
    vec3 c = textureGradOffset(volume, p, vec3(0.03, 0.0, 0.01) * st.y, vec3(0.0, 0.02, 0.0), ivec3(1, 1, -7)).rgb;
    color = vec4(st.x < 0.33 ? a : st.x < 0.67 ? b : c, 1.0);
})"},
};

// GLSL 4.00's gathers and level-of-detail query: whole fragment shaders, drawn as the lookups
// above. Each gather's four texels show in stripes; the gathers go past the texture's edges
// under each wrap; the level of detail spans magnified and minified quads and every level.
const LanguageCase kTextureQueries[] = {
    {"texture_gather", R"(
in vec2 st;
out vec4 color;
uniform sampler2D teximage;
void main() {
    vec2 p = st * 3.0 - 1.0;
    vec4 r = textureGather(teximage, p);
    vec4 g = textureGather(teximage, p * 0.5 + 0.25, 1);
    vec4 b = textureGatherOffset(teximage, p, ivec2(-3, 5), 2);
    vec4 a = textureGatherOffset(teximage, p * 1.5, ivec2(7, -8), 3);
    vec4 q = st.y < 0.5 ? (st.x < 0.5 ? r : g) : (st.x < 0.5 ? b : a);
    color = vec4(fract(st.x * 8.0) < 0.5 ? q.xyz : q.yzw, 1.0);
})"},
    {"texture_gather_offsets_levels", R"(
in vec2 st;
out vec4 color;
uniform sampler2D teximage;
uniform sampler3D volume;
void main() {
    vec2 p = st * 3.0 - 1.0;
    const ivec2 offsets[4] = ivec2[4](ivec2(0, 0), ivec2(-8, 1), ivec2(3, -4), ivec2(7, 7));
    vec4 a = textureGatherOffsets(teximage, p, offsets);
    vec4 b = textureGatherOffsets(teximage, p * 1.5, offsets, 3);
    vec2 levels = vec2(textureQueryLevels(teximage), textureQueryLevels(volume)) / 16.0;
    color = st.y < 0.45 ? a : st.y < 0.9 ? b : vec4(levels, 0.0, 1.0);
})"},
    {"texture_query_lod", R"(
in vec2 st;
out vec4 color;
uniform sampler2D teximage;
uniform sampler3D volume;
void main() {
    vec2 p = st * exp2(st.x * 8.0 - 2.0);
    vec2 a = textureQueryLod(teximage, p);
    vec2 b = textureQueryLod(volume, vec3(p.yx, st.y * exp2(st.y * 6.0)));
    color = vec4(a.x / 6.0, a.y / 16.0 + 0.5, st.x < 0.5 ? b.x / 6.0 : b.y / 16.0 + 0.5, 1.0);
})"},
};

// sampler2DShadow's lookups: whole fragment shaders that read `st` and a depth comparison
// texture `depth`. The reference values run from below 0 to above 1 across the depths, and meet
// them exactly in a band (where GL_LEQUAL and GL_LESS differ); the lookups go past the
// texture's edges under each wrap, and their levels, biases and derivatives span magnified and
// minified pixels and every level of a mipmapped texture.
const LanguageCase kShadowLookups[] = {
    {"shadow_texture", R"(#version 130
in vec2 st;
out vec4 color;
uniform sampler2DShadow depth;
void main() {
    vec2 p = st * 2.5 - 0.7;
    float ref = fract(st.x * 3.0 + st.y * 1.7) * 1.2 - 0.1;
    float a = texture(depth, vec3(p, ref));
    float b = textureOffset(depth, vec3(p, ref), ivec2(-3, 2));
    float c = textureProj(depth, vec4(vec3(p, ref) * (1.0 + st.y), 1.0 + st.y));
    float d = textureLod(depth, vec3(p * 1.3, ref), 2.0);
    float e = textureGrad(depth, vec3(p, ref), vec2(0.1, 0.0), vec2(0.0, 0.3) * st.x);
    float f = texture(depth, vec3(p * 0.7, ref), st.y * 4.0 - 2.0);
    float g = textureProjOffset(depth, vec4(p, ref, 1.0) * (2.0 - st.x), ivec2(5, -7));
    float h = textureLodOffset(depth, vec3(p, ref), 0.5, ivec2(1, 1));
    float i = textureGradOffset(depth, vec3(p, ref), vec2(0.2), vec2(0.1), ivec2(-8, 7));
    float j = texture(depth, vec3(p, floor(st.x * 256.0) * (1.0 / 255.0)));  // equal to depths
    vec2 size = vec2(textureSize(depth, 0)) / 64.0;
    color = st.y < 0.25 ? vec4(a, b, c, 1.0) : st.y < 0.5 ? vec4(d, e, f, 1.0) : st.y < 0.75 ? vec4(g, h, i, 1.0)
                        : vec4(j, size, 1.0);
})"},
    {"shadow_legacy", R"(#version 120
#extension GL_ARB_shader_texture_lod : require
varying vec2 st;
uniform sampler2DShadow depth;
void main() {
    vec2 p = st * 3.0 - 1.0;
    float ref = fract(st.y * 2.0 + st.x * 0.6) * 1.1 - 0.05;
    vec4 a = shadow2D(depth, vec3(p, ref));
    vec4 b = shadow2DProj(depth, vec4(p, ref, 1.0) * (0.5 + st.x));
    vec4 c = shadow2DLod(depth, vec3(p.yx, ref), 1.0);
    gl_FragColor = st.x < 0.33 ? a : st.x < 0.67 ? vec4(b.xy, a.w, b.w) : vec4(c.x, b.x, c.zw);
})"},
};

// samplerCube's lookups: whole fragment shaders that read `st` and a cube map `env`, drawn on the
// plane under every sampler below. The directions sweep every face, its edges and corners, and
// the ties between axes (z over y over x); the derivatives span magnified and minified quads and
// every level, and differ within a quad where a direction crosses from face to face.
const LanguageCase kCubeLookups[] = {
    {"cube_faces", R"(#version 130
in vec2 st;
out vec4 color;
uniform samplerCube env;
void main() {
    vec2 p = st * 2.0 - 1.0;
    vec3 a = texture(env, vec3(p * 2.5, 1.0)).rgb;                      // +Z, its four sides and corners
    vec3 b = texture(env, vec3(-1.0, p.yx * vec2(3.0, -2.0))).rgb;      // -X
    vec3 c = texture(env, vec3(p.x * 1.7, -1.0 + 0.1 * p.y, p.y * 2.2)).rgb;  // -Y, +Y beyond
    color = vec4(st.y < 0.33 ? a : st.y < 0.67 ? b : c, 1.0);
})"},
    {"cube_ties", R"(#version 130
in vec2 st;
out vec4 color;
uniform samplerCube env;
void main() {
    vec2 p = st * 2.0 - 1.0;
    vec3 d = texture(env, vec3(p.x, p.x, 1.0) * (st.y < 0.5 ? 1.0 : -1.0)).rgb;
    vec3 e = texture(env, vec3(1.0, p.y, 1.0) * (0.5 + st.x)).rgb;
    color = vec4(st.x < 0.5 ? d : e, 1.0);
})"},
    {"cube_bias", R"(#version 130
in vec2 st;
out vec4 color;
uniform samplerCube env;
void main() {
    vec2 p = st * 2.0 - 1.0;
    color = vec4(texture(env, vec3(p.x * 3.0, 1.0, p.y * 2.0 - 0.4), p.x * 2.0 + p.y).rgb, 1.0);
})"},
    {"cube_minified", R"(#version 130
in vec2 st;
out vec4 color;
uniform samplerCube env;
void main() {
    vec2 p = st * 2.0 - 1.0;
    color = vec4(texture(env, vec3(p * 40.0, 3.0)).rgb, 1.0);
})"},
    {"cube_gather", R"(#version 400
in vec2 st;
out vec4 color;
uniform samplerCube env;
void main() {
    vec2 p = st * 2.0 - 1.0;
    vec3 dir = vec3(p.x * 2.5, p.y * 2.5, st.x < 0.5 ? 1.0 : -1.0);
    vec4 r = textureGather(env, dir);
    vec4 g = textureGather(env, dir.zxy, 1);
    vec4 b = textureGather(env, dir.yzx * vec3(1.0, -1.0, 1.0), 2);
    vec4 q = st.y < 0.33 ? r : st.y < 0.67 ? g : b;
    color = vec4(fract(st.x * 8.0) < 0.5 ? q.xyz : q.yzw, 1.0);
})"},
    {"cube_lod_grad_size", R"(#version 130
in vec2 st;
out vec4 color;
uniform samplerCube env;
void main() {
    vec2 p = st * 2.0 - 1.0;
    vec3 dir = vec3(p.x * 3.0, 0.8 - p.y, p.y * 2.0 - 0.3);
    vec3 a = textureLod(env, dir, st.y * 7.0 - 1.0).rgb;
    float k = exp2(fract(st.x * 5.0) * 9.0 - 6.0);
    vec3 dx = vec3(0.05 * k, 0.01 * gl_FragCoord.y / 64.0, 0.0), dy = vec3(0.0, 0.02, 0.08 * k) * (0.5 + st.y);
    if (st.y > 0.9) dx.x = 1e30;
    vec3 b = textureGrad(env, dir, dx, dy).rgb;
    vec3 c = textureGrad(env, dir.zxy, dFdx(dir) * 8.0, dFdy(dir.yxz)).rgb;
    vec2 size = vec2(textureSize(env, 0) + textureSize(env, 2)) / 64.0;
    color = vec4(st.x < 0.33 ? a : st.x < 0.67 ? (st.y < 0.5 ? b : c) : vec3(size, 0.5), 1.0);
})"},
    {"cube_legacy", R"(#version 120
#extension GL_ARB_shader_texture_lod : require
varying vec2 st;
uniform samplerCube env;
void main() {
    vec2 p = st * 2.0 - 1.0;
    vec4 a = textureCube(env, vec3(1.0, p * 1.5));
    vec4 b = textureCube(env, vec3(p.y * 6.0, p.x * 6.0, -1.0), st.x * 3.0 - 1.0);
    vec4 c = textureCubeLod(env, vec3(p, -0.5), st.x * 5.0);
    gl_FragColor = st.y < 0.33 ? a : st.y < 0.67 ? b : c;
})"},
    {"cube_query_lod", R"(#version 400
in vec2 st;
out vec4 color;
uniform samplerCube env;
void main() {
    vec2 p = st * 2.0 - 1.0;
    vec2 a = textureQueryLod(env, vec3(p * exp2(st.x * 8.0 - 2.0), 1.0));  // magnified to minified
    vec2 b = textureQueryLod(env, vec3(p.x * 2.5, -1.0 + 0.1 * p.y, p.y * 2.5));  // across faces
    color = vec4(a.x / 6.0, a.y / 16.0 + 0.5, st.y < 0.5 ? b.x / 6.0 : b.y / 16.0 + 0.5, 1.0);
})"},
};

// samplerCubeShadow's lookups on a depth comparison cube map `depth` (each face's red channel
// its depth): the reference values cross the depths; a bias or derivatives change nothing on a
// texture of one level and one filter.
const LanguageCase kCubeShadowLookups[] = {
    {"cube_shadow", R"(#version 130
in vec2 st;
out vec4 color;
uniform samplerCubeShadow depth;
void main() {
    vec2 p = st * 2.0 - 1.0;
    float ref = fract(st.x * 3.0 + st.y * 1.7) * 1.2 - 0.1;
    float a = texture(depth, vec4(p * 2.5, 1.0, ref));
    float b = texture(depth, vec4(-1.0, p.yx * 3.0, ref), st.y * 4.0 - 2.0);
    float c = textureGrad(depth, vec4(p.x, -1.0, p.y * 1.5, ref), vec3(0.1, 0.0, 0.0), vec3(0.0, 0.3 * st.x, 0.0));
    float d = texture(depth, vec4(p.x, p.x, 1.0, floor(st.y * 256.0) * (1.0 / 255.0)));  // ties, equal to depths
    vec2 size = vec2(textureSize(depth, 0)) / 64.0;
    color = st.y < 0.5 ? vec4(a, b, c, 1.0) : vec4(d, size, 1.0);
})"},
    {"cube_shadow_gather", R"(#version 400
in vec2 st;
out vec4 color;
uniform samplerCubeShadow depth;
void main() {
    vec2 p = st * 2.0 - 1.0;
    float ref = fract(st.x * 3.0 + st.y * 1.7) * 1.2 - 0.1;
    vec4 q = textureGather(depth, vec3(p * 2.5, st.y < 0.5 ? 1.0 : -1.0), ref);
    color = vec4(fract(st.x * 8.0) < 0.5 ? q.xyz : q.yzw, 1.0);
})"},
};

// Lookups of a depth comparison texture that tell its compare functions apart: reference values
// below, equal to and above the depths, and NaN (which passes NOTEQUAL alone), through a
// filtered lookup and gathers; `depth` is 2D or a cube map. The 2D one's level query, which no
// function changes, rides along.
const LanguageCase kCompareLookups[] = {
    {"compare", R"(#version 400
in vec2 st;
out vec4 color;
uniform sampler2DShadow depth;
void main() {
    vec2 p = st * 2.5 - 0.7;
    float ref = fract(st.x * 3.0 + st.y * 1.7) * 1.2 - 0.1;
    float a = texture(depth, vec3(p, ref));
    float b = texture(depth, vec3(p, floor(st.x * 256.0) * (1.0 / 255.0)));  // equal to depths
    float c = texture(depth, vec3(p, sqrt(st.x - 0.75)));                     // NaN left of x = 0.75
    vec4 g = st.x < 0.33 ? textureGather(depth, p, st.y < 0.75 ? ref : sqrt(-st.x))
           : st.x < 0.67 ? textureGatherOffset(depth, p, ref, ivec2(-3, 2))
                         : textureGatherOffsets(depth, p, ref, ivec2[4](ivec2(0), ivec2(1, -2), ivec2(-5, 3), ivec2(2)));
    vec2 q = textureQueryLod(depth, p * exp2(st.x * 6.0 - 2.0));
    color = st.y < 0.5 ? vec4(a, b, c, 1.0) : st.y < 0.9 ? vec4(fract(st.x * 8.0) < 0.5 ? g.xyz : g.yzw, 1.0)
                       : vec4(q.x, q.y / 16.0 + 0.5, 0.0, 1.0);
})"},
    {"compare_cube", R"(#version 400
in vec2 st;
out vec4 color;
uniform samplerCubeShadow depth;
void main() {
    vec2 p = st * 2.0 - 1.0;
    float ref = fract(st.x * 3.0 + st.y * 1.7) * 1.2 - 0.1;
    float a = texture(depth, vec4(p * 2.5, 1.0, ref));
    float b = texture(depth, vec4(p.x, p.x, 1.0, floor(st.y * 256.0) * (1.0 / 255.0)));  // equal to depths
    float c = texture(depth, vec4(-1.0, p.yx * 3.0, sqrt(st.x - 0.75)));                  // NaN left of x = 0.75
    vec4 g = textureGather(depth, vec3(p * 2.5, -1.0), st.y < 0.75 ? ref : sqrt(-st.x));
    color = st.y < 0.5 ? vec4(a, b, c, 1.0) : vec4(fract(st.x * 8.0) < 0.5 ? g.xyz : g.yzw, 1.0);
})"},
};

}  // namespace

TEST_CASE("webgl-noise run by the interpreter matches OSMesa llvmpipe", "[interpreter][reference]") {
    const std::filesystem::path dir = temp_dir("glsl-reference");
    const int size = 128;
    auto context = create_osmesa_context(size, size, GlDriver::Llvmpipe, 0);
    GlPrograms programs(dir);
    for (const Case& c : kCases) {
        const std::string fragment = "#version 120\n" + library(c.file) + "\nvarying vec2 st;\nvoid main() {\n    vec3 c;\n    " +
                                     c.main + "\n    gl_FragColor = vec4(c, 1.0);\n}\n";
        check_against_llvmpipe(dir, *context, programs, size, c.name, fragment, c.over_1, c.cause);
    }
}

TEST_CASE("the language where lanes diverge, run by the interpreter, matches OSMesa llvmpipe", "[interpreter][reference]") {
    const std::filesystem::path dir = temp_dir("glsl-language");
    const int size = 64;
    auto context = create_osmesa_context(size, size, GlDriver::Llvmpipe, 0);
    GlPrograms programs(dir);
    for (const LanguageCase& c : kLanguage) {
        check_against_llvmpipe(dir, *context, programs, size, c.name, std::string("#version 130") + c.source + "\n", c.over_1,
                               c.cause);
    }
}

TEST_CASE("textureGrad, the Offset lookups, gathers and textureQueryLod, run by the interpreter, match OSMesa llvmpipe "
          "under each sampler",
          "[interpreter][reference][textures]") {
    const std::filesystem::path dir = temp_dir("glsl-textures");
    const int size = 64;
    auto context = create_osmesa_context(size, size, GlDriver::Llvmpipe, 0);
    GlPrograms programs(dir);
    constexpr Wrap kRepeat = Wrap::Repeat, kMirror = Wrap::MirroredRepeat, kClamp = Wrap::ClampToEdge;
    constexpr Filter kLinear = Filter::Linear, kNearest = Filter::Nearest;
    struct SamplerCase {
        const char* name;
        const char* image;  // 2D; the volume is the shipped 32^3 one
        Sampler sampler;
    };
    // The 8-bit path (REPEAT, CLAMP_TO_EDGE) and the float one (MIRRORED_REPEAT, or different min
    // and mag filters with a level per pixel); sizes that are powers of two and that are not;
    // every mipmap filter.
    const SamplerCase samplers[] = {
        {"trilinear", "texture-64x32.png", {kLinear, Filter::LinearMipmapLinear, kRepeat, kRepeat, kRepeat}},
        {"nearest-mipmaps-npot", "texture-37x19.png", {kNearest, Filter::NearestMipmapNearest, kRepeat, kClamp, kRepeat}},
        {"linear-mipmap-nearest-npot", "texture-37x19.png", {kLinear, Filter::LinearMipmapNearest, kRepeat, kRepeat, kClamp}},
        {"mirrored", "texture-13x7.png", {kLinear, Filter::NearestMipmapLinear, kMirror, kMirror, kMirror}},
        {"clamp-min-mag", "texture-16x8.png", {kNearest, Filter::LinearMipmapLinear, kClamp, kClamp, kClamp}},
        {"one-level", "texture-16x16.png", {kLinear, kLinear, kRepeat, kMirror, kRepeat}},
    };
    for (const SamplerCase& sc : samplers) {
        Scene scene = load_scene(kPlane);
        scene.textures.at(0).image.file = kSource / "scenes/assets/conformance/images" / sc.image;
        scene.textures.at(0).sampler = sc.sampler;
        Texture volume;
        volume.image.file = kSource / "scenes/assets/textures/fast-noise-volume.png";
        volume.sampler = sc.sampler;
        volume.dims = 3, volume.depth = 32;
        volume.field = "volume";
        scene.textures.push_back(volume);
        scene.objects.at(0).samplers = {{"volume", int(scene.textures.size()) - 1}};
        for (const LanguageCase& c : kTextureLookups) {
            const std::string name = std::string(c.name) + "-" + sc.name;
            check_against_llvmpipe(dir, *context, programs, size, name, std::string("#version 130") + c.source + "\n", c.over_1,
                                   c.cause, scene);
        }
        for (const LanguageCase& c : kTextureQueries) {
            const std::string name = std::string(c.name) + "-" + sc.name;
            check_against_llvmpipe(dir, *context, programs, size, name, std::string("#version 430") + c.source + "\n",
                                   c.over_1, c.cause, scene);
        }
    }
}

TEST_CASE("sampler2DShadow's lookups, run by the interpreter, match OSMesa llvmpipe under each filter and wrap",
          "[interpreter][reference][textures]") {
    const std::filesystem::path dir = temp_dir("glsl-shadow");
    const int size = 64;
    auto context = create_osmesa_context(size, size, GlDriver::Llvmpipe, 0);
    GlPrograms programs(dir);
    constexpr Wrap kRepeat = Wrap::Repeat, kMirror = Wrap::MirroredRepeat, kClamp = Wrap::ClampToEdge;
    struct SamplerCase {
        const char* name;
        const char* image;  // its red channel is the depth
        Sampler sampler;
    };
    // Sizes that are powers of two and that are not, each wrap, both filters, every mipmap filter
    // (float mipmaps, as llvmpipe's glGenerateMipmap blits them), and different minification and
    // magnification filters with and without mipmaps.
    const SamplerCase samplers[] = {
        {"nearest-clamp", "texture-16x16.png", {Filter::Nearest, Filter::Nearest, kClamp, kClamp, kRepeat}},
        {"linear-repeat", "texture-16x8.png", {Filter::Linear, Filter::Linear, kRepeat, kRepeat, kRepeat}},
        {"linear-npot", "texture-37x19.png", {Filter::Linear, Filter::Linear, kRepeat, kClamp, kRepeat}},
        {"linear-mirrored", "texture-13x7.png", {Filter::Linear, Filter::Linear, kMirror, kMirror, kRepeat}},
        {"nearest-mirrored-npot", "texture-13x7.png", {Filter::Nearest, Filter::Nearest, kMirror, kRepeat, kRepeat}},
        {"trilinear", "texture-64x32.png", {Filter::Linear, Filter::LinearMipmapLinear, kRepeat, kRepeat, kRepeat}},
        {"trilinear-npot", "texture-37x19.png", {Filter::Linear, Filter::LinearMipmapLinear, kClamp, kMirror, kRepeat}},
        {"nearest-mipmaps-npot", "texture-37x19.png", {Filter::Nearest, Filter::NearestMipmapNearest, kClamp, kRepeat, kRepeat}},
        {"linear-mipmap-nearest", "texture-13x7.png", {Filter::Linear, Filter::LinearMipmapNearest, kMirror, kMirror, kRepeat}},
        {"min-mag-mipmap-linear", "texture-16x8.png", {Filter::Linear, Filter::NearestMipmapLinear, kRepeat, kClamp, kRepeat}},
        {"min-mag-one-level", "texture-37x19.png", {Filter::Linear, Filter::Nearest, kClamp, kClamp, kRepeat}},
    };
    for (const SamplerCase& sc : samplers) {
        Scene scene = load_scene(kPlane);
        Texture depth;
        depth.image.file = kSource / "scenes/assets/conformance/images" / sc.image;
        depth.sampler = sc.sampler;
        depth.compare = CompareFunc::LessEqual;
        depth.field = "depth";
        scene.textures.push_back(depth);
        scene.objects.at(0).samplers = {{"depth", int(scene.textures.size()) - 1}};
        for (const LanguageCase& c : kShadowLookups) {
            const std::string name = std::string(c.name) + "-" + sc.name;
            check_against_llvmpipe(dir, *context, programs, size, name, std::string(c.source) + "\n", c.over_1, c.cause,
                                   scene, true);
        }
    }
}

TEST_CASE("samplerCube's lookups, run by the interpreter, match OSMesa llvmpipe under each filter",
          "[interpreter][reference][textures]") {
    const std::filesystem::path dir = temp_dir("glsl-cube");
    const int size = 64;
    auto context = create_osmesa_context(size, size, GlDriver::Llvmpipe, 0);
    GlPrograms programs(dir);
    constexpr Wrap kRepeat = Wrap::Repeat, kMirror = Wrap::MirroredRepeat, kClamp = Wrap::ClampToEdge;
    constexpr Filter kLinear = Filter::Linear, kNearest = Filter::Nearest;
    struct SamplerCase {
        const char* name;
        Sampler sampler;
    };
    // Every mipmap filter, the float path (different min and mag filters with a level per
    // pixel), one level; the wraps, which a cube map's lookup ignores, of every kind.
    const SamplerCase samplers[] = {
        {"trilinear", {kLinear, Filter::LinearMipmapLinear, kRepeat, kRepeat, kRepeat}},
        {"nearest-mipmaps", {kNearest, Filter::NearestMipmapNearest, kMirror, kClamp, kRepeat}},
        {"linear-mipmap-nearest", {kLinear, Filter::LinearMipmapNearest, kClamp, kClamp, kClamp}},
        {"min-mag-mipmap-linear", {kLinear, Filter::NearestMipmapLinear, kMirror, kMirror, kMirror}},
        {"min-mag-one-level", {kNearest, kLinear, kRepeat, kRepeat, kRepeat}},
        {"linear-one-level", {kLinear, kLinear, kRepeat, kMirror, kRepeat}},
    };
    for (const SamplerCase& sc : samplers) {
        Scene scene = load_scene(kPlane);
        scene.textures.push_back(cube_map(dir, 32, sc.sampler, std::nullopt, "env"));
        scene.objects.at(0).samplers = {{"env", int(scene.textures.size()) - 1}};
        for (const LanguageCase& c : kCubeLookups) {
            const std::string name = std::string(c.name) + "-" + sc.name;
            check_against_llvmpipe(dir, *context, programs, size, name, std::string(c.source) + "\n", c.over_1, c.cause,
                                   scene, true);
        }
    }
}

TEST_CASE("samplerCubeShadow's lookups, run by the interpreter, match OSMesa llvmpipe under each filter",
          "[interpreter][reference][textures]") {
    const std::filesystem::path dir = temp_dir("glsl-cube-shadow");
    const int size = 64;
    auto context = create_osmesa_context(size, size, GlDriver::Llvmpipe, 0);
    GlPrograms programs(dir);
    constexpr Wrap kRepeat = Wrap::Repeat;
    constexpr Filter kLinear = Filter::Linear, kNearest = Filter::Nearest;
    struct SamplerCase {
        const char* name;
        Sampler sampler;
    };
    const SamplerCase samplers[] = {
        {"nearest", {kNearest, kNearest, kRepeat, kRepeat, kRepeat}},
        {"linear", {kLinear, kLinear, kRepeat, kRepeat, kRepeat}},
        {"trilinear", {kLinear, Filter::LinearMipmapLinear, kRepeat, kRepeat, kRepeat}},
        {"nearest-mipmaps", {kNearest, Filter::NearestMipmapNearest, kRepeat, kRepeat, kRepeat}},
        {"min-mag-mipmap-linear", {kLinear, Filter::NearestMipmapLinear, kRepeat, kRepeat, kRepeat}},
        {"min-mag-one-level", {kNearest, kLinear, kRepeat, kRepeat, kRepeat}},
    };
    for (const SamplerCase& sc : samplers) {
        Scene scene = load_scene(kPlane);
        scene.textures.push_back(cube_map(dir, 16, sc.sampler, CompareFunc::LessEqual, "depth"));
        scene.objects.at(0).samplers = {{"depth", int(scene.textures.size()) - 1}};
        for (const LanguageCase& c : kCubeShadowLookups) {
            const std::string name = std::string(c.name) + "-" + sc.name;
            check_against_llvmpipe(dir, *context, programs, size, name, std::string(c.source) + "\n", c.over_1, c.cause,
                                   scene, true);
        }
    }
}

TEST_CASE("Every compare function of a depth comparison texture matches OSMesa llvmpipe, 2D and cube map",
          "[interpreter][reference][textures]") {
    const std::filesystem::path dir = temp_dir("glsl-compare");
    const int size = 64;
    auto context = create_osmesa_context(size, size, GlDriver::Llvmpipe, 0);
    GlPrograms programs(dir);
    const Sampler linear{Filter::Linear, Filter::Linear, Wrap::Repeat, Wrap::MirroredRepeat, Wrap::Repeat};
    using enum CompareFunc;
    for (const CompareFunc func : {Never, Less, Equal, LessEqual, Greater, NotEqual, GreaterEqual, Always}) {
        Scene scene = load_scene(kPlane);
        Texture flat;
        flat.image.file = kSource / "scenes/assets/conformance/images/texture-37x19.png";
        flat.sampler = linear;
        flat.compare = func;
        flat.field = "depth";
        scene.textures.push_back(flat);
        scene.textures.push_back(cube_map(dir, 16, linear, func, "cube-depth"));
        const int n = int(scene.textures.size());
        for (const LanguageCase& c : kCompareLookups) {
            const bool cube = std::string_view(c.name) == "compare_cube";
            scene.objects.at(0).samplers = {{"depth", cube ? n - 1 : n - 2}};
            const std::string name = std::string(c.name) + "-" + std::string(compare_func_name(func));
            check_against_llvmpipe(dir, *context, programs, size, name, std::string(c.source) + "\n", c.over_1, c.cause,
                                   scene, true);
        }
    }
}

TEST_CASE("A depth texture's mipmaps equal llvmpipe's glGenerateMipmap texel for texel", "[reference][textures]") {
    auto context = create_osmesa_context(8, 8, GlDriver::Llvmpipe, 0);
    glsl::SamplerState sampler;
    sampler.mip = glsl::MipFilter::Linear;
    // Powers of two and odd sizes, thin ones whose levels halve along one axis only.
    const int sizes[][2] = {{8, 4}, {37, 21}, {100, 3}, {3, 100}, {64, 64}, {255, 130}, {17, 17}};
    std::uint32_t seed = 12345;
    for (const auto& size : sizes) {
        const int w = size[0], h = size[1];
        std::vector<std::uint8_t> rgba(std::size_t(w) * std::size_t(h) * 4);
        std::vector<float> depths(std::size_t(w) * std::size_t(h));
        for (std::size_t i = 0; i < depths.size(); ++i) {
            seed = seed * 1664525u + 1013904223u;
            rgba[4 * i] = std::uint8_t(seed >> 24);
            depths[i] = float(rgba[4 * i]) * float(1.0 / 255.0);
        }
        const glsl::sampler2D texture(w, h, rgba.data(), sampler, glsl::TexelFormat::Depth32F);
        const std::vector<float> expected = generated_depth_mipmaps(w, h, depths);
        const std::size_t base = std::size_t(w) * std::size_t(h);
        REQUIRE(texture.texels.size() == base + expected.size());
        std::size_t differing = 0;
        for (std::size_t i = 0; i < expected.size(); ++i) {
            if (std::bit_cast<float>(texture.texels[base + i]) != expected[i]) ++differing;
        }
        INFO(w << "x" << h << ": " << differing << " of " << expected.size() << " texels below the base differ");
        CHECK(differing == 0);
    }
}

}  // namespace qs
