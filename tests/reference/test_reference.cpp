// The correctness bar: every catalogue shader, rendered live by Mesa from its original GLSL
// (llvmpipe and softpipe, through quadshade-reference), against quadshade with the matching
// derivative rule. Coverage must be identical; colour differences are counted in 8-bit steps.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "core/framebuffer.h"
#include "images/image_io.h"
#include "render/frame_image.h"
#include "render/glsl_shaders.h"
#include "render/scene_render.h"
#include "render/volume_bake.h"
#include "scenes/gltf.h"
#include "shading/catalogue.h"
#include "tests/reference/comparison.h"
#include "tests/test_command.h"
#include "tests/test_paths.h"

namespace qs {

namespace {

using namespace test;

// Plane shaders are compared at the book's benchmark size, solid textures on the sphere scene's.
constexpr int kPlaneSize = 500, kSphereSize = 320;

// The bar: at least 99.9% of pixels within 1/255 and none beyond 2/255, except for documented
// causes, counted and bounded. The bounds are what was measured on Mesa 22.3.6 (Debian 12) at
// the sizes above, and that is zero pixels over 1/255 for every case but one:
struct Bound {
    std::size_t over_1 = 0, over_2 = 0, coverage_mismatch = 0;
    const char* cause = "none: measured 0 pixels over 1/255 at this size";
};
const std::map<std::pair<std::string, std::string>, Bound> kBounds = {
    {{"figure-1.1", "softpipe"},
     {6, 6, 4,
      "softpipe sets up edges in floating point without llvmpipe's 8-bit sub-pixel snapping, which "
      "quadshade follows: 2 pixels where the plane's far edge passes within 1/256 pixel of a pixel "
      "centre are covered by one and not the other (measured: 2 of 505600, 4 pixels over 2/255)"}},
    {{"perlin5", "softpipe"},
     {130, 110, 0,
      "softpipe sets up and interpolates varyings with its own arithmetic (neither llvmpipe's, which "
      "quadshade reproduces bit for bit, nor a plain unfused variant of it): st differs by an ulp, "
      "and the 40x and 80x octaves land in neighbouring noise cells (measured: 115 pixels over "
      "1/255, 95 over 2/255, of 250000)"}},
    {{"worley_tiles", "softpipe"},
     {8, 8, 0, "as for perlin5: an ulp of st moves a few pixels across a cell border (measured: 4)"}},
    {{"worley_tiles_fwidth", "softpipe"}, {8, 8, 0, "as for worley_tiles (measured: 4)"}},
    {{"worley_tiles_step", "softpipe"}, {6, 6, 0, "as for worley_tiles, and a step flips fully (measured: 2)"}},
    {{"halftone_step", "llvmpipe"},
     {3, 3, 0,
      "the un-anti-aliased variant: a plain step turns the last-ulp difference of a value lying on its "
      "threshold into a full flip, which aastep's ramp absorbs (measured: 1 pixel, 178/255)"}},
    {{"halftone_step", "softpipe"}, {6, 6, 0, "as against llvmpipe (measured: 3 pixels)"}},
    {{"scene_inputs", "softpipe"},
     {2, 2, 0, "measured: 1 pixel, 6/255, since the scene's transforms are composed in double; its cause is not yet isolated"}},
    {{"spots", "softpipe"},
     {4, 4, 0,
      "on the sphere scene: softpipe interpolates P with its own arithmetic (see perlin5), and 2 pixels on the rings' "
      "anti-aliased edges change by more than a step (measured: 2 pixels, 24/255; the conformance scenes count the "
      "same cause)"}},
    {{"spots_length", "softpipe"}, {4, 4, 0, "as spots (measured: 2 pixels, 29/255)"}},
    {{"noise_bumps_lit", "softpipe"},
     {2, 2, 0,
      "softpipe's P is an ulp off (see perlin5) and the lighting depends on it through the noise's gradient and the "
      "face normal cross(dFdx(P), dFdy(P)): 1 pixel, 14/255, at (280, 145) of the 320x320 sphere (not analysed "
      "further; against llvmpipe none)"}},
    {{"simplex3d_contour_aa", "softpipe"},
     {4, 4, 0,
      "the chapter's 3D noise (radius^2 0.6) jumps across simplex faces, and softpipe's P is an ulp off quadshade's "
      "(see perlin5): 2 pixels inside the sphere cross the contour line's edge (measured: 2 pixels, 42/255)"}},
    // The sine hashes: softpipe calls the C library's sinf, within 2^-24 of llvmpipe's polynomial
    // (which quadshade's sin is, to the bit: the sin_cos_probe test), and 43758.5453 sin(x) moves
    // by under a step but crosses fract's wrap on a few pixels: a full step there.
    {{"es_random_square", "softpipe"}, {60, 60, 0, "sinf against llvmpipe's sin across fract's wrap (measured: 29 pixels)"}},
    {{"es_random_square_minus1", "softpipe"}, {60, 60, 0, "as es_random_square (measured: 29 pixels)"}},
    {{"es_random_square_plus1", "softpipe"}, {50, 50, 0, "as es_random_square (measured: 24 pixels)"}},
    {{"es_tiles128", "softpipe"}, {60, 60, 0, "as es_random_square, per tile (measured: 30 pixels)"}},
    {{"gltf_material", "softpipe"},
     {3, 0, 0,
      "the sRGB decoding and encoding around a texel: softpipe filters with float weights where llvmpipe (and "
      "quadshade) round them to 1/256 and lerp in 8 bits (docs/design.md, Textures), and takes pow from the C library; "
      "one pixel lands across a rounding (measured: 1 pixel, 2/255; not analysed further; against llvmpipe none)"}},
    {{"lawlor_texture_two_octaves", "softpipe"},
     {8, 0, 0,
      "softpipe filters with float weights where llvmpipe (and quadshade) round them to 1/256 and lerp in 8 bits "
      "(docs/design.md, Textures): within a step per lookup, and the two octaves' sum rounds to 2 steps on a few "
      "pixels (measured: 4)"}},
};
// Shaders whose softpipe colours and coverage are counted (the CSV) but not held to the bar, and
// why (measured on Mesa 22.3.6 at 500x500). quadshade follows llvmpipe, which they match.
const std::map<std::string, const char*> kSoftpipeCountedOnly = {
    {"hash_pcg",
     "a hash of floor(st * 32): softpipe's st differs from llvmpipe's by an ulp (see perlin5), and with 31 cell "
     "borders each way an ulp picks the neighbouring cell's hash on 1495 pixels (0.6%)"},
    {"hash_perm289", "as hash_pcg (measured: 1495 pixels over 1/255)"},
    {"fbm_simplex2d",
     "the Noise is Beautiful simplex noise jumps where luv.x == luv.y exactly (its step() pair takes the far corner twice and "
     "leaves one out), lines that pixel centres of the plane hit exactly at the finer octaves: quadshade's st is "
     "llvmpipe's to the bit and lands on them as it does, softpipe's is an ulp off (see perlin5) and misses them "
     "(measured: 706 pixels over 1/255, 539 over 2/255, along those lines)"},
    {"multifractal_simplex2d", "as fbm_simplex2d (measured: 587 pixels over 1/255, 412 over 2/255)"},
    {"hash_sin",
     "as hash_pcg (1495 pixels over 1/255); elsewhere softpipe's sinf, within 2^-24 of llvmpipe's polynomial, moves the "
     "hash by under 1/255 (39044 pixels differ in their bits)"},
    {"hash_hoskins",
     "as hash_pcg: 1703 pixels over 1/255 (hash_pcg's cell borders give 1495 on this plane; the other 208 not "
     "analysed)"},
    {"es_smooth9_tiles128",
     "nine sine hashes per pixel (see es_random_square's bound), each able to cross fract's wrap with softpipe's sinf: "
     "266 pixels over 1/255 (0.15%, up to 29/255)"},
    {"lawlor_mandelbrot",
     "softpipe's texcoords are an ulp off llvmpipe's (see perlin5) and the iteration makes an ulp a different escape "
     "time near the set's boundary (1062 pixels over 1/255)"},
    {"lawlor_dots_moved",
     "dot centres read from tex1: softpipe filters with float weights where llvmpipe (and quadshade) round them "
     "to 1/256 and lerp in 8 bits (docs/design.md, Textures), so its dots move and their rims flip (1186 pixels)"},
    {"lawlor_dots_search", "as lawlor_dots_moved, with tex4 (3506 pixels, and 1096 in alpha, which is colour here)"},
    {"lawlor_voronoi_f1", "as lawlor_dots_moved: the feature points move (515 pixels over 1/255; alpha is F1)"},
    {"lawlor_voronoi_f2", "as lawlor_voronoi_f1 (alpha is F2: 914 pixels cross 1/2)"},
    {"lawlor_stained_glass", "as lawlor_voronoi_f1 (43996 pixels over 1/255, none over 5/255)"},
    {"proctexgen-spheres",
     "fast_noise's two trilinear lookups of the volume: softpipe filters with float weights where llvmpipe (and "
     "quadshade) round them to 1/256 and lerp in 8 bits, and the low octave turns the high one by up to 2 pi "
     "(3790 pixels over 1/255, 574 over 2/255, of 505600; the other shaders of the scene: its 2 silhouette pixels)"},
};
constexpr double kMaxFractionOver1 = 0.001;  // the bar itself, never loosened by a bound

struct Case {
    std::string name;  // a shader, or "figure-1.1" for the whole scene
    std::filesystem::path scene;
    std::string shader;  // override, empty for the scene's own
    int width, height;
};

// The OpenGL ES tutorial's shaders discard what lies above a square viewport as wide as the window: they are
// compared in a window taller than wide (the tutorial's iPhone 5 screen, 320x568 points), where
// the 248 rows above the square are discarded.
bool portrait(std::string_view shader) { return shader.starts_with("es_"); }
constexpr int kPortraitWidth = 320, kPortraitHeight = 568;

std::vector<Case> cases() {
    std::vector<Case> all = {{"figure-1.1", kFigure, "", 1264, 400}, {"proctexgen-spheres", kProcTexGenSpheres, "", 1264, 400}};
    for (const Program* p : catalogue()) {
        const ShaderInfo& info = p->info();
        if (info.name.find("probe") != std::string_view::npos) continue;
        if (compiled_glsl(*p, false)) continue;  // a GLSL twin check_interpreted added in an earlier section
        // Solid textures on the sphere (Figure 1.1 draws the chapter's own there too), those with
        // no texture to bind.
        if (info.needs.coordinates == Coordinates::Object3D) {
            if (!samples_textures(info.needs)) all.push_back({std::string(info.name), kSphere, std::string(info.name), kSphereSize, kSphereSize});
            continue;
        }
        // Figure 1.1's object-plane pattern is compared on Figure 1.1.
        if (info.needs.coordinates == Coordinates::Object2D) continue;
        // A shader whose named samplers its plane does not bind is compared where they are
        // (baked_lit: on the baked scenes it draws, test_atlas_bake.cpp).
        if (!plane_binds_samplers(info)) continue;
        const bool tall = portrait(info.name);
        all.push_back({std::string(info.name), plane_for(info.name), std::string(info.name), tall ? kPortraitWidth : kPlaneSize,
                       tall ? kPortraitHeight : kPlaneSize});
    }
    return all;
}

std::filesystem::path work_dir() {
    static const auto dir = temp_dir("reference");
    return dir;
}

// `options`: more of quadshade-reference's options (--uniform ...); the case's name must tell
// renders with different options apart.
Image reference(const Case& c, const std::string& driver, int width, int height, const std::string& options = "") {
    const auto out = work_dir() / (c.name + "." + driver + "." + std::to_string(width) + "x" + std::to_string(height) + ".exr");
    if (!std::filesystem::exists(out)) {
        std::string cmd = (kBin / "quadshade-reference").string() + " " + c.scene.string() + " -o " + out.string() +
                          " --glsl " + QUADSHADE_GLSL_DIR + " --driver " + driver + " --size " + std::to_string(width) +
                          "x" + std::to_string(height) + " " + options;
        if (!c.shader.empty()) cmd += " --shader " + c.shader;
        cmd += " 2> /dev/null";
        if (std::system(cmd.c_str()) != 0) throw std::runtime_error("reference render failed: " + cmd);
    }
    return read_image(out);
}

// quadshade set up as the driver whose rule this is (comparison.h).
Framebuffer ours(const Case& c, Derivatives rule, int width, int height, std::vector<UniformSetting> uniforms = {}) {
    Scene scene = load_scene(c.scene);
    FrameRequest r;
    r.width = width, r.height = height;
    r.uniforms = std::move(uniforms);
    r.shader_override = c.shader;
    r.set(raster_options_as(rule == Derivatives::CoarseLower ? GlDriver::Softpipe : GlDriver::Llvmpipe));
    return render_frame(scene, r);
}

// One CSV per driver (ctest runs the two test cases in parallel processes), in the build folder.
void record(const std::string& driver, const std::string& line) {
    static std::map<std::string, std::ofstream> files;
    auto [it, fresh] = files.try_emplace(driver, std::filesystem::path(QUADSHADE_BIN_DIR) / ".." /
                                                     ("reference-comparison-" + driver + ".csv"));
    if (fresh) it->second << "case,driver,rule,pixels,coverage_mismatch,over_1,over_2,max_steps\n";
    it->second << line << "\n" << std::flush;
}

// The case's GLSL run by the interpreter (render/glsl_shaders.h) against the same llvmpipe
// image, held to the translation's bound; recorded as driver "llvmpipe-interpreted".
void check_interpreted(const Case& c, const Image& ref) {
    Case twin = c;
    twin.shader = interpreted_twin(c.shader);
    const Framebuffer q = ours(twin, Derivatives::Fine, c.width, c.height);
    const Counts n = count(q, ref);
    record("llvmpipe-interpreted", c.name + ",llvmpipe,fine," + std::to_string(n.pixels) + "," + std::to_string(n.coverage_mismatch) +
                                       "," + std::to_string(n.over_1) + "," + std::to_string(n.over_2) + "," + std::to_string(n.max_steps));
    INFO(c.name << "'s GLSL run by the interpreter vs llvmpipe: " << n.over_1 << " pixels over 1/255, " << n.over_2
                << " over 2/255, max " << n.max_steps << "/255, coverage mismatches " << n.coverage_mismatch);
    auto it = kBounds.find({c.name, "llvmpipe"});
    const Bound bound = it == kBounds.end() ? Bound{} : it->second;
    CHECK(n.coverage_mismatch <= bound.coverage_mismatch);
    if (test::kReassociatedByMesa.contains(c.name)) return;  // counted, not held to the bar
    CHECK(n.over_1 <= bound.over_1);
    CHECK(double(n.over_1) <= kMaxFractionOver1 * double(n.pixels));
    CHECK(n.over_2 <= bound.over_2);
}

void check_against(const std::string& driver, Derivatives rule, const char* rule_name) {
    for (const Case& c : cases()) {
        DYNAMIC_SECTION(c.name << " vs " << driver) {
            const Framebuffer q = ours(c, rule, c.width, c.height);
            const Image ref = reference(c, driver, c.width, c.height);
            const Counts n = count(q, ref);
            write_comparison(q, ref, std::filesystem::path(QUADSHADE_BIN_DIR) / ".." / "reference-comparison" /
                                         (c.name + "-" + driver + ".png"));
            record(driver, c.name + "," + driver + "," + rule_name + "," + std::to_string(n.pixels) + "," +
                   std::to_string(n.coverage_mismatch) + "," + std::to_string(n.over_1) + "," +
                   std::to_string(n.over_2) + "," + std::to_string(n.max_steps));
            INFO(c.name << " vs " << driver << ": " << n.over_1 << " pixels over 1/255, " << n.over_2
                        << " over 2/255, max " << n.max_steps << "/255, coverage mismatches " << n.coverage_mismatch);
            if (driver == "llvmpipe" && !c.shader.empty()) check_interpreted(c, ref);
            if (driver == "softpipe" && kSoftpipeCountedOnly.count(c.name)) continue;
            auto it = kBounds.find({c.name, driver});
            const Bound bound = it == kBounds.end() ? Bound{} : it->second;
            INFO("bound: " << bound.cause);
            CHECK(n.coverage_mismatch <= bound.coverage_mismatch);
            CHECK(n.over_1 <= bound.over_1);
            CHECK(double(n.over_1) <= kMaxFractionOver1 * double(n.pixels));
            CHECK(n.over_2 <= bound.over_2);
        }
    }
}

}  // namespace

TEST_CASE("every shader matches OSMesa llvmpipe under the fine rule", "[reference][llvmpipe]") {
    check_against("llvmpipe", Derivatives::Fine, "fine");
}

TEST_CASE("every shader matches OSMesa softpipe under the coarse-lower rule", "[reference][softpipe]") {
    check_against("softpipe", Derivatives::CoarseLower, "coarse-lower");
}

TEST_CASE("the OpenGL ES tutorial's square viewport: what lies above it in a portrait window is discarded, as by llvmpipe", "[reference][discard]") {
    // The plane's clear colour is black, and so is es_tiles2's tile at the origin (sin(0) = 0):
    // the other three tiles are drawn, nothing above the square (the image's first rows).
    const Case c{"es_tiles2", kPlane, "es_tiles2", kPortraitWidth, kPortraitHeight};
    const Framebuffer q = ours(c, Derivatives::Fine, c.width, c.height);
    const Image ref = reference(c, "llvmpipe", c.width, c.height);
    auto drawn = [](std::span<const float> rgba, std::size_t first_row, std::size_t rows) {
        std::size_t n = 0;
        for (std::size_t p = first_row * kPortraitWidth * 4; p < (first_row + rows) * kPortraitWidth * 4; p += 4) {
            n += rgba[p] != 0.0f || rgba[p + 1] != 0.0f || rgba[p + 2] != 0.0f;
        }
        return n;
    };
    constexpr std::size_t above = kPortraitHeight - kPortraitWidth;
    CHECK(drawn(ref.rgba, 0, above) == 0);
    CHECK(drawn(ref.rgba, above, kPortraitWidth) == 3 * std::size_t(kPortraitWidth) * kPortraitWidth / 4);
    CHECK(std::equal(q.rgba.begin(), q.rgba.end(), ref.rgba.begin()));
}

TEST_CASE("derivative probe: fine equals llvmpipe and coarse-lower equals softpipe, bit for bit", "[reference][derivatives]") {
    // 17x15: odd sizes, so quads stick out of the image on the right and at the bottom.
    const Case probe{"derivative_probe", kPlane, "derivative_probe", 17, 15};
    const Framebuffer fine = ours(probe, Derivatives::Fine, 17, 15);
    const Framebuffer coarse = ours(probe, Derivatives::CoarseLower, 17, 15);
    const Image lp = reference(probe, "llvmpipe", 17, 15), sp = reference(probe, "softpipe", 17, 15);
    CHECK(std::ranges::equal(fine.rgba, lp.rgba));
    CHECK(std::ranges::equal(coarse.rgba, sp.rgba));
    CHECK(fine.rgba != coarse.rgba);  // the rules really differ on this function
}

TEST_CASE("fill rule: llvmpipe owns left and bottom edges, softpipe right and top, as quadshade's two rules", "[reference][coverage]") {
    // A 16x16 window with a rectangle whose four edges pass through pixel centres.
    Scene s = load_scene(kPlane);
    auto at = [](float wx, float wy) { return glm::vec3(wx * 2.0f / 16.0f - 1.0f, wy * 2.0f / 16.0f - 1.0f, 0.0f); };
    s.meshes[0].vertices = {{at(2.5f, 1.5f), {}}, {at(6.5f, 1.5f), {}}, {at(6.5f, 4.5f), {}}, {at(2.5f, 4.5f), {}}};
    s.objects[0].shader = "constant_color";
    s.width = s.height = 16;
    const auto file = work_dir() / "fill-rule.gltf";
    test::copy_textures_into(s, work_dir());
    save_scene(s, file);
    const Case c{"fill-rule", file, "", 16, 16};
    auto coverage = [](std::span<const float> rgba) {
        std::vector<int> cov;
        for (std::size_t p = 0; p < rgba.size(); p += 4) cov.push_back(rgba[p] > 0.5f);  // red = drawn
        return cov;
    };
    const auto lp = coverage(reference(c, "llvmpipe", 16, 16).rgba);
    const auto sp = coverage(reference(c, "softpipe", 16, 16).rgba);
    CHECK(lp != sp);
    CHECK(coverage(ours(c, Derivatives::Fine, 16, 16).rgba) == lp);
    CHECK(coverage(ours(c, Derivatives::CoarseLower, 16, 16).rgba) == sp);
}

// llvmpipe interpolates with llvm.fmuladd, fused on FMA hardware; quadshade fuses on the same
// machines (raster/plane_equation.h), native or portable build alike.
TEST_CASE("interpolated varyings equal llvmpipe's bit for bit", "[reference][interpolation]") {
    const Case st{"pattern_s", kPlane, "pattern_s", 500, 500};  // writes st.s unchanged
    CHECK(std::ranges::equal(ours(st, Derivatives::Fine, 500, 500).rgba, reference(st, "llvmpipe", 500, 500).rgba));
}

TEST_CASE("division and mod are exact IEEE operations, bit for bit as llvmpipe", "[reference][arithmetic]") {
    const Case probe{"arithmetic_probe", kPlane, "arithmetic_probe", 64, 64};
    CHECK(std::ranges::equal(ours(probe, Derivatives::Fine, 64, 64).rgba, reference(probe, "llvmpipe", 64, 64).rgba));
}

TEST_CASE("smoothstep with equal edges matches llvmpipe's run-time result", "[reference][undefined]") {
    const Case probe{"smoothstep_probe", kPlane, "smoothstep_probe", 32, 4};
    const Framebuffer q = ours(probe, Derivatives::Fine, 32, 4);
    const Image lp = reference(probe, "llvmpipe", 32, 4);
    CHECK(std::ranges::equal(q.rgba, lp.rgba));
    // ...which is x > e: 0 below and on the edge, 1 above (column 2 sits on it, x = 2.5).
    CHECK(q.pixel(1, 0)[0] == 0.0f);
    CHECK(q.pixel(2, 0)[0] == 0.0f);
    CHECK(q.pixel(3, 0)[0] == 1.0f);
    CHECK(q.pixel(2, 0)[1] == 1.0f);  // while step(e, x) is 1 on the edge
}


TEST_CASE("float environment: GLSL's undefined cases and denormals as llvmpipe", "[reference][undefined][stability]") {
    const Case probe{"float_env_probe", kPlane, "float_env_probe", 8, 1};
    const Framebuffer q = ours(probe, Derivatives::Fine, 8, 1);
    const Image lp = reference(probe, "llvmpipe", 8, 1);
    const char* names[8] = {"normalize(vec3(0)).x", "inversesqrt(0)", "pow(-2, 1.5)", "mod(1, 0)", "1e-41 * 1e30",
                            "sqrt(-1)", "log(0)", "0 * inversesqrt(0)"};
    for (int x = 0; x < 8; ++x) {
        const float a = q.pixel(x, 0)[0], b = lp.rgba[std::size_t(x) * 4];
        std::printf("float environment: %-22s quadshade %-12g llvmpipe %g\n", names[x], double(a), double(b));
        INFO(names[x] << ": quadshade " << a << ", llvmpipe " << b);
        // Same class of result (NaN's sign bit is not meaningful), and equal when not NaN.
        CHECK(std::isnan(a) == std::isnan(b));
        if (!std::isnan(a)) CHECK(a == b);
    }
    CHECK(q.pixel(4, 0)[0] == 0.0f);  // denormals flushed, as llvmpipe: a documented choice
    CHECK(std::isinf(q.pixel(1, 0)[0]));
}


TEST_CASE("helper lanes at silhouettes: derivatives of the position match llvmpipe's, the largest reported",
          "[reference][derivatives][stability]") {
    // Every Figure 1.1 object drawn with the probe: on the spheres' rims helper lanes extrapolate
    // the position far outside their triangles, and dFdx/dFdy take those values.
    const Case probe{"position_derivative_probe", kFigure, "position_derivative_probe", 1264, 400};
    const Framebuffer q = ours(probe, Derivatives::Fine, 1264, 400);
    const Image lp = reference(probe, "llvmpipe", 1264, 400);
    std::size_t differ = 0, drawn = 0;
    double largest = 0.0, interior_median_scale = 0.0, worst_relative = 0.0;
    int lx = 0, ly = 0;
    std::vector<double> magnitudes;
    for (int y = 0; y < q.height; ++y) {
        for (int x = 0; x < q.width; ++x) {
            const float* a = q.pixel(x, y);
            const float* b = &lp.rgba[(std::size_t(y) * std::size_t(q.width) + std::size_t(x)) * 4];
            differ += !std::equal(a, a + 4, b);
            double scale = 1e-30, diff = 0.0;
            for (int c = 0; c < 4; ++c) {
                scale = std::max(scale, std::abs(double(b[c])));
                diff = std::max(diff, std::abs(double(a[c]) - double(b[c])));
            }
            worst_relative = std::max(worst_relative, diff / scale);
            if (a[3] == 0.0f) continue;
            ++drawn;
            const double m = std::max(std::sqrt(double(a[0]) * a[0] + double(a[1]) * a[1] + double(a[2]) * a[2]), double(a[3]));
            magnitudes.push_back(m);
            if (m > largest) largest = m, lx = x, ly = y;
        }
    }
    std::nth_element(magnitudes.begin(), magnitudes.begin() + magnitudes.size() / 2, magnitudes.end());
    interior_median_scale = magnitudes[magnitudes.size() / 2];
    std::printf("silhouettes: %zu of %zu pixels differ from llvmpipe; largest |d(P)| %.4g at (%d, %d), median %.4g\n",
                differ, drawn, largest, lx, ly, interior_median_scale);
    std::printf("silhouettes: largest difference from llvmpipe, relative to the pixel's largest derivative: %.3g\n",
                worst_relative);
    // Not bit for bit on every pixel: the probe's arithmetic is reassociated by Mesa's GLSL
    // compiler (test_conformance.cpp), and a difference of neighbours magnifies a value's ulp.
    // Measured: 25495 of 376098 pixels differ, by at most 1.44e-7 of the pixel's largest
    // derivative, rims included (8.6e-4 before the vertices' window coordinates and attribute
    // planes followed Mesa's arithmetic: clipper.h, triangle_setup.cpp).
    CHECK(worst_relative < 1e-6);
    CHECK(largest > 10.0 * interior_median_scale);  // the rims do stretch the derivatives
}


TEST_CASE("stiff geometry: slivers, sub-pixel triangles, the near plane, vertices a million units out: as llvmpipe",
          "[reference][stability][geometry]") {
    // One mesh, drawn with Figure 1.2's s ramp so interpolation shows too, seen in perspective.
    Scene s = load_scene(kPlane);
    s.camera.kind = Camera::Kind::Perspective;
    s.camera.yfov = glm::radians(60.0f);
    s.camera.znear = 0.1f, s.camera.zfar = 100.0f;
    s.camera.view = glm::lookAt(glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    s.width = 400, s.height = 300;
    s.clear_color = glm::vec4(0.0f);  // alpha 0 where nothing is drawn: alpha is coverage
    Mesh m;
    m.name = "stiff";
    auto tri = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c) {
        for (const glm::vec3& p : {a, b, c}) {
            m.indices.push_back(std::uint32_t(m.vertices.size()));
            m.vertices.push_back({p, {0.1f * p.x + 0.5f, 0.1f * p.y + 0.5f}});
        }
    };
    // A background triangle with vertices a million units out, far outside the view, whose
    // diagonal edge crosses the image: the lower right half is covered, the rest is not.
    tri({-1e6f, -1e6f, -40.0f}, {1e6f, -1e6f, -40.0f}, {1e6f, 1e6f, -40.0f});
    // Slivers: 20 triangles 4 units long and 1/1000 to 1/300 unit thin (a pixel is about 1/70).
    for (int k = 0; k < 20; ++k) {
        const float y = -2.5f + 0.13f * float(k), w = 0.001f + 0.0001f * float(k);
        tri({-2.0f, y, 0.0f}, {2.0f, y + w, 0.0f}, {2.0f, y + 3.0f * w, 0.0f});
    }
    // Sub-pixel triangles: a 20 x 10 grid, each about a fifth of a pixel across.
    for (int j = 0; j < 10; ++j) {
        for (int i = 0; i < 20; ++i) {
            const glm::vec3 o(0.5f + 0.071f * float(i), 0.5f + 0.0713f * float(j), 0.0f);
            tri(o, o + glm::vec3(0.003f, 0.0f, 0.0f), o + glm::vec3(0.0f, 0.003f, 0.0f));
        }
    }
    // Across the near plane: one vertex behind the eye (z = 5), the others in front.
    tri({-1.5f, -1.8f, 4.5f}, {-0.5f, -1.8f, 4.5f}, {-1.0f, -1.0f, 6.0f});
    // A fan sharing edges and a centre vertex, in perspective.
    for (int k = 0; k < 16; ++k) {
        const float a0 = 6.2831853f * float(k) / 16.0f, a1 = 6.2831853f * float(k + 1) / 16.0f;
        const glm::vec3 c(-1.5f, 1.2f, -2.0f);
        tri(c, c + glm::vec3(std::cos(a0), std::sin(a0), 0.5f), c + glm::vec3(std::cos(a1), std::sin(a1), 0.5f));
    }
    s.meshes = {m};
    s.objects.resize(1);
    s.objects[0].mesh = 0;
    s.objects[0].world_from_object = glm::mat4(1.0f);
    s.objects[0].shader = "pattern_s";
    const auto file = work_dir() / "stiff.gltf";
    test::copy_textures_into(s, work_dir());
    save_scene(s, file);

    const Case stiff{"stiff-geometry", file, "", 400, 300};
    const Framebuffer q = ours(stiff, Derivatives::Fine, 400, 300);
    const Image lp = reference(stiff, "llvmpipe", 400, 300);
    const Counts n = count(q, lp);
    std::size_t nan = 0;
    for (float v : q.rgba) nan += std::isnan(v);
    std::size_t covered = 0;
    for (std::size_t p = 0; p < lp.rgba.size(); p += 4) covered += lp.rgba[p + 3] > 0.5f;
    std::printf("stiff geometry vs llvmpipe: %zu of %zu pixels covered; %zu coverage mismatches, %zu pixels over 1/255 "
                "(max %d/255), %zu NaN values\n", covered, n.pixels, n.coverage_mismatch, n.over_1, n.max_steps, nan);
    CHECK(covered > n.pixels / 3);
    CHECK(covered < n.pixels * 2 / 3);
    CHECK(n.coverage_mismatch == 0);
    CHECK(nan == 0);
    // Colour: the background triangle, its vertices a million units out, is clipped at the view
    // volume in Mesa's order and arithmetic (clipper.h), so its s plane is llvmpipe's too.
    // Measured: 0 pixels over 1/255 (1331, up to 2/255, when quadshade clipped at a guard band).
    CHECK(n.over_1 == 0);
    CHECK(n.max_steps <= 1);
}


TEST_CASE("the spots' anti-aliasing variants match llvmpipe on Figure 1.1", "[reference][derivatives]") {
    for (const char* shader : {"spots_length", "spots_step"}) {
        const Case c{shader, kFigure, shader, 1264, 400};
        const Counts n = count(ours(c, Derivatives::Fine, 1264, 400), reference(c, "llvmpipe", 1264, 400));
        INFO(shader << ": " << n.coverage_mismatch << " coverage mismatches, " << n.over_1 << " pixels over 1/255");
        std::printf("%s vs llvmpipe: %zu coverage mismatches, %zu pixels over 1/255 (max %d/255)\n", shader,
                    n.coverage_mismatch, n.over_1, n.max_steps);
        CHECK(n.coverage_mismatch == 0);
        CHECK(double(n.over_1) <= kMaxFractionOver1 * double(n.pixels));
    }
}


TEST_CASE("quadshade-reference: bad usage exits 2, bad input 1, naming what is wrong", "[reference][cli]") {
    const auto dir = temp_dir("reference-cli");
    auto run = [&](const std::string& args) {
        const std::string cmd = (kBin / "quadshade-reference").string() + " " + args + " > '" + (dir / "err.txt").string() + "' 2>&1";
        const int status = std::system(cmd.c_str());
        std::ifstream in(dir / "err.txt");
        std::string text((std::istreambuf_iterator<char>(in)), {});
        return std::pair(WIFEXITED(status) ? WEXITSTATUS(status) : -1, text);
    };
    const std::string scene = kPlane.string(), out = " -o " + (dir / "x.exr").string();
    const std::string glsl = std::string(" --glsl ") + QUADSHADE_GLSL_DIR;
    CHECK(run(scene + out).first == 2);  // no --glsl
    CHECK(run(scene + out + glsl + " --driver swiftshader").first == 2);
    CHECK(run(scene + out + glsl + " --size 10y3").first == 2);
    const auto [code, text] = run(scene + out + glsl + " --shader no_such_shader");
    CHECK(code == 1);
    CHECK(text.find("no_such_shader.vert") != std::string::npos);
    CHECK(!std::filesystem::exists(dir / "x.exr"));
    CHECK(run(scene + out + glsl + " --size 8x8").first == 0);
    CHECK(std::filesystem::exists(dir / "x.exr"));
}

}  // namespace qs

// ---- the GLSL vocabulary beyond the chapter (shading/shaders/vocabulary_probes.h) --------------
#include <bit>
#include <cstdint>

#include "tests/discard_scene.h"

namespace qs {

namespace {

// A probe's integer result from its two 16-bit halves (channels `first`, `first + 1`).
std::uint32_t halves(const float* px, int first) {
    return std::uint32_t(px[first]) << 16 | std::uint32_t(px[first + 1]);
}

// Bit-exact comparison of quadshade with a driver over a probe, channel by channel, printing the
// first difference.
std::size_t differing_values(const Framebuffer& q, const Image& ref, int channel_mask = 0xF) {
    std::size_t differ = 0;
    for (std::size_t i = 0; i < q.rgba.size(); ++i) {
        if (!(channel_mask >> (i % 4) & 1)) continue;
        const float a = q.rgba[i], b = ref.rgba[i];
        if (std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b) || (std::isnan(a) && std::isnan(b)) || a == b) continue;
        if (differ++ == 0) {
            const std::size_t p = i / 4;
            std::printf("  first difference at pixel (%zu, %zu) channel %zu: quadshade %.9g, driver %.9g\n",
                        p % std::size_t(q.width), p / std::size_t(q.width), i % 4, double(a), double(b));
        }
    }
    return differ;
}

}  // namespace

TEST_CASE("integer probe: int and uint arithmetic, bit operations, shifts, conversions bit for bit as Mesa", "[reference][integers]") {
    const Case probe{"integer_probe", kPlane, "integer_probe", 64, 32};
    const Framebuffer q = ours(probe, Derivatives::Fine, 64, 32);
    CHECK(differing_values(q, reference(probe, "llvmpipe", 64, 32)) == 0);
    CHECK(differing_values(q, reference(probe, "softpipe", 64, 32)) == 0);
}

TEST_CASE("integer cases GLSL leaves undefined: division by zero, shifts by >= 32, conversions out of range as llvmpipe",
          "[reference][integers][undefined]") {
    const Case probe{"integer_undefined_probe", kPlane, "integer_undefined_probe", 14, 1};
    const Framebuffer q = ours(probe, Derivatives::Fine, 14, 1);
    const Image lp = reference(probe, "llvmpipe", 14, 1);
    const char* names[14][2] = {{"7 / 0", "7u / 0u"},           {"7 % 0", "7u % 0u"},
                                {"-7 % 3", "7 % -3"},           {"INT_MIN / -1", "INT_MIN % -1"},
                                {"5 << 33", "5u >> 33u"},       {"-5 >> 32", "5u << 32u"},
                                {"5 << -1", "5u >> 0xFFFFFFFFu"}, {"int(-1.5)", "uint(-1.0)"},
                                {"int(3e9)", "uint(5e9)"},      {"int(-3e9)", "uint(-3e9)"},
                                {"int(NaN)", "uint(NaN)"},      {"int(+inf)", "uint(+inf)"},
                                {"int(-inf)", "uint(-inf)"},    {"int(2147483520.0)", "uint(4294967040.0)"}};
    // llvmpipe's float-to-uint conversion is the host's: on AVX2 hosts (measured here) LLVM's
    // two-conversion sequence, which quadshade reproduces; AVX-512 has vcvttps2udq, which answers
    // 0xFFFFFFFF out of range. There only the in-range columns are compared.
    const bool avx512 = __builtin_cpu_supports("avx512f");
    for (int x = 0; x < 14; ++x) {
        const float* a = q.pixel(x, 0);
        const float* b = &lp.rgba[std::size_t(x) * 4];
        const std::uint32_t qr = halves(a, 0), qs = halves(a, 2), lr = halves(b, 0), ls = halves(b, 2);
        std::printf("undefined integers: %-18s quadshade 0x%08x llvmpipe 0x%08x | %-20s quadshade 0x%08x llvmpipe 0x%08x\n",
                    names[x][0], qr, lr, names[x][1], qs, ls);
        INFO(names[x][0] << ", " << names[x][1]);
        CHECK(qr == lr);
        if (!avx512 || x < 7 || x == 13) CHECK(qs == ls);
    }
}

TEST_CASE("bool probe: && || ^^ ! of bools, bvec comparisons, any, all, not, mix as Mesa", "[reference][booleans]") {
    const Case probe{"bool_probe", kPlane, "bool_probe", 32, 24};
    const Framebuffer q = ours(probe, Derivatives::Fine, 32, 24);
    CHECK(differing_values(q, reference(probe, "llvmpipe", 32, 24)) == 0);
    CHECK(differing_values(q, reference(probe, "softpipe", 32, 24)) == 0);
}

TEST_CASE("loop probe: break, continue, return from a loop, while, nested loops bit for bit as Mesa", "[reference][loops]") {
    const Case probe{"loop_probe", kPlane, "loop_probe", 64, 32};
    const Framebuffer q = ours(probe, Derivatives::Fine, 64, 32);
    CHECK(differing_values(q, reference(probe, "llvmpipe", 64, 32)) == 0);
    CHECK(differing_values(q, reference(probe, "softpipe", 64, 32)) == 0);
}

TEST_CASE("matrix probe: constructors, products of every shape, transpose, inverse, determinant bit for bit as Mesa",
          "[reference][matrices]") {
    const Case probe{"matrix_probe", kPlane, "matrix_probe", 64, 16};
    const Framebuffer q = ours(probe, Derivatives::Fine, 64, 16);
    CHECK(differing_values(q, reference(probe, "llvmpipe", 64, 16)) == 0);
    CHECK(differing_values(q, reference(probe, "softpipe", 64, 16)) == 0);
}

TEST_CASE("built-ins probe: exact built-ins bit for bit as llvmpipe, rounded and approximated ones within bounds",
          "[reference][builtins]") {
    const Case probe{"builtins_probe", kPlane, "builtins_probe", 64, 16};
    const Framebuffer q = ours(probe, Derivatives::Fine, 64, 16);
    const Image lp = reference(probe, "llvmpipe", 64, 16);
    std::size_t exact_differ = 0;
    double refract_worst = 0.0, worst[4] = {};
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 64; ++x) {
            const float* a = q.pixel(x, y);
            const float* b = &lp.rgba[(std::size_t(y) * 64 + std::size_t(x)) * 4];
            for (int c = 0; c < 4; ++c) {
                const double d = std::abs(double(a[c]) - double(b[c])) / std::max(1.0, std::abs(double(b[c])));
                if (x == 31 && y == 8 && c == 3) {  // atan(0, 0): GLSL leaves it undefined
                    std::printf("built-ins: atan(0, 0) quadshade %g, llvmpipe %g\n", double(a[c]), double(b[c]));
                } else if (x % 8 == 7) {  // asin, acos, tan, atan: Mesa evaluates polynomials
                    worst[c] = std::max(worst[c], d);
                } else if (x % 8 == 3 && c < 3) {  // refract: a square root and three roundings after it
                    refract_worst = std::max(refract_worst, d);
                } else if (!(a[c] == b[c] || (std::isnan(a[c]) && std::isnan(b[c])))) {
                    if (exact_differ++ == 0) std::printf("  first difference at (%d, %d) channel %d: %.9g vs %.9g\n", x, y, c, double(a[c]), double(b[c]));
                }
            }
        }
    }
    std::printf("built-ins vs llvmpipe: refract %.3g; asin %.3g, acos %.3g, tan %.3g, atan %.3g (largest difference, relative above 1)\n",
                refract_worst, worst[0], worst[1], worst[2], worst[3]);
    CHECK(exact_differ == 0);
    CHECK(refract_worst < 1e-6);
    // Mesa evaluates asin and acos as polynomials (builtin_functions.cpp, asin_expr), tan as
    // sin / cos and atan with its own approximations. Bounds from what was measured on Mesa
    // 22.3.6, with room for another host's llvmpipe: see docs/results.md.
    CHECK(worst[0] < 4e-4);
    CHECK(worst[1] < 2e-4);
    CHECK(worst[2] < 1e-5);
    CHECK(worst[3] < 1e-5);
}

TEST_CASE("sin and cos probe: llvmpipe's polynomial bit for bit, softpipe's C library sinf within half an ulp of 1 below 2^22",
          "[reference][builtins][sin]") {
    const Case probe{"sin_cos_probe", kPlane, "sin_cos_probe", 256, 256};
    // Every kind of float argument, huge, denormal, infinite and NaN ones included (the probe's
    // GLSL), and the sine hash of each: llvmpipe's to the bit (shading/number/sin_cos.h).
    CHECK(differing_values(ours(probe, Derivatives::Fine, 256, 256), reference(probe, "llvmpipe", 256, 256)) == 0);

    // softpipe calls the C library's sinf and cosf (glibc's: within an ulp of the true value),
    // llvmpipe's polynomial is within 2^-24 of them (half an ulp of 1) for |a| < 2^22 and has
    // no accuracy left beyond 2^24, where its reduction by multiples of pi/4 in float runs out.
    const Framebuffer q = ours(probe, Derivatives::CoarseLower, 256, 256);
    const Image sp = reference(probe, "softpipe", 256, 256);
    CHECK(differing_values(q, sp, 0x1) == 0);  // the arguments themselves
    std::size_t differ = 0, hash_differ = 0, compared = 0;
    double worst = 0.0;
    for (std::size_t p = 0; p < q.rgba.size(); p += 4) {
        const float a = q.rgba[p];
        for (int c = 1; c <= 2; ++c) differ += std::bit_cast<std::uint32_t>(q.rgba[p + c]) != std::bit_cast<std::uint32_t>(sp.rgba[p + c]);
        if (!(std::abs(a) < 0x1p22f)) continue;
        ++compared;
        hash_differ += q.rgba[p + 3] != sp.rgba[p + 3];
        for (int c = 1; c <= 2; ++c) worst = std::max(worst, std::abs(double(q.rgba[p + c]) - double(sp.rgba[p + c])));
    }
    std::printf("sin and cos vs softpipe: %zu of %zu values differ; for |a| < 2^22 (%zu pixels) at most %.3g, and %zu sine "
                "hashes differ\n", differ, q.rgba.size() / 2, compared, worst, hash_differ);
    CHECK(worst <= 0x1p-24);
}

TEST_CASE("discard probe: discarded fragments write nothing, derivatives after discard as llvmpipe", "[reference][discard]") {
    // 17x15: quads stick out of the image, so helper lanes discard too.
    const Case probe{"discard_probe", kPlane, "discard_probe", 17, 15};
    const Framebuffer q = ours(probe, Derivatives::Fine, 17, 15);
    const Image lp = reference(probe, "llvmpipe", 17, 15);
    std::size_t cleared = 0;
    for (std::size_t p = 0; p < q.rgba.size(); p += 4) cleared += lp.rgba[p + 3] == 1.0f && lp.rgba[p] == 0.0f && lp.rgba[p + 1] == 0.0f;
    std::printf("discard probe: %zu of %d pixels discarded by llvmpipe\n", cleared, 17 * 15);
    CHECK(cleared > 17 * 15 / 5);
    // Red and green: derivatives of a value computed after an earlier discard, for which the
    // discarded fragments ran on as helpers. Exact.
    CHECK(differing_values(q, lp, 0x3) == 0);
    // Blue and alpha: derivatives of a loop variable that some fragments of the quad left by
    // discarding inside the loop (GLSL: undefined, derivatives in non-uniform control flow).
    const std::size_t loop_differ = differing_values(q, lp, 0xC);
    std::printf("discard probe: %zu values differ from llvmpipe after a discard inside a loop\n", loop_differ);
    CHECK(loop_differ == 0);
}

TEST_CASE("discard under depth testing: discarded fragments write no depth, in either drawing order, as llvmpipe",
          "[reference][discard][depth]") {
    for (bool front_first : {true, false}) {
        Scene s = test::discard_scene(front_first, 63, 47);
        const auto file = work_dir() / (front_first ? "discard-front-first.gltf" : "discard-back-first.gltf");
        test::copy_textures_into(s, work_dir());
        save_scene(s, file);
        const Case c{front_first ? "discard-front-first" : "discard-back-first", file, "", 63, 47};
        const Framebuffer q = ours(c, Derivatives::Fine, 63, 47);
        const Image lp = reference(c, "llvmpipe", 63, 47);
        INFO((front_first ? "front first" : "back first"));
        CHECK(differing_values(q, lp, 0x3) == 0);
        CHECK(differing_values(q, lp, 0xC) == 0);
    }
}

TEST_CASE("uniforms: initializers, the material's extras.uniforms and --uniform bind the same values as in llvmpipe, bit for bit",
          "[reference][uniforms]") {
    // 61x37: uResolution is not a power of two, and quads stick out of the image.
    constexpr int w = 61, h = 37;
    const Case initial{"uniform-initial", kPlane, "uniform_probe", w, h};
    Scene s = load_scene(kPlane);
    for (Object& o : s.objects) {
        o.shader = "uniform_probe";
        o.uniforms = {{"uScale", {6.5}, ""},           {"uTint", {0.25, 1.0, 0.75}, ""},
                      {"uBands", {5}, ""},             {"uCells", {3, -2}, ""},
                      {"uSeed", {4000000000.0}, ""},   {"uRotate", {0.8, 0.6, -0.6, 0.8}, ""},
                      {"uWarp", {1.0, 0.25, 0.0, -0.5, 1.0, 0.0, 0.125, 0.5, 1.0}, ""}};
    }
    const auto file = work_dir() / "uniforms.gltf";
    test::copy_textures_into(s, work_dir());
    save_scene(s, file);
    const Case material{"uniform-material", file, "", w, h};
    const Case option{"uniform-option", file, "", w, h};
    const std::string options = "--uniform uScale=3 --uniform 'uTint=[1,0,0.5]' --uniform uWarp=1,0,0,0,1,0,0.3,0.1,1 --uniform uBands=-4";
    const std::vector<UniformSetting> settings = {parse_uniform_option("uScale=3"), parse_uniform_option("uTint=[1,0,0.5]"),
                                                  parse_uniform_option("uWarp=1,0,0,0,1,0,0.3,0.1,1"), parse_uniform_option("uBands=-4")};
    const Framebuffer q0 = ours(initial, Derivatives::Fine, w, h), q1 = ours(material, Derivatives::Fine, w, h),
                      q2 = ours(option, Derivatives::Fine, w, h, settings);
    CHECK(differing_values(q0, reference(initial, "llvmpipe", w, h)) == 0);
    CHECK(differing_values(q1, reference(material, "llvmpipe", w, h)) == 0);
    CHECK(differing_values(q2, reference(option, "llvmpipe", w, h, options)) == 0);
    CHECK(differing_values(q1, reference(material, "softpipe", w, h)) == 0);
    // Each source of values changed the image.
    const Image i0 = colour_image(q0), i1 = colour_image(q1);
    CHECK(differing_values(q1, i0) > std::size_t(w * h / 4));
    CHECK(differing_values(q2, i1) > std::size_t(w * h / 4));
}

TEST_CASE("uniforms: quadshade-reference refuses an unknown --uniform (exit 2) and a material's unknown or mistyped one (exit 1)",
          "[reference][uniforms]") {
    Scene s = load_scene(kPlane);
    for (Object& o : s.objects) o.shader = "uniform_probe", o.uniforms = {{"uNope", {1.0}, ""}};
    test::copy_textures_into(s, work_dir());
    const auto unknown = work_dir() / "uniforms-unknown.gltf";
    save_scene(s, unknown);
    for (Object& o : s.objects) o.uniforms = {{"uBands", {0.5}, ""}};
    const auto mistyped = work_dir() / "uniforms-mistyped.gltf";
    save_scene(s, mistyped);
    auto exit_code = [](const std::filesystem::path& scene, const std::string& options) {
        const std::string cmd = (kBin / "quadshade-reference").string() + " " + scene.string() + " --glsl " + QUADSHADE_GLSL_DIR +
                                " --size 8x8 -o " + (work_dir() / "refused.exr").string() + " " + options + " 2> /dev/null";
        const int status = std::system(cmd.c_str());
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    };
    CHECK(exit_code(kPlane, "--shader uniform_probe --uniform uBands=2") == 0);
    CHECK(exit_code(kPlane, "--shader uniform_probe --uniform uNope=1") == 2);
    CHECK(exit_code(kPlane, "--shader uniform_probe --uniform uScale") == 2);
    CHECK(exit_code(kPlane, "--shader uniform_probe --uniform uBands=1.5") == 2);
    CHECK(exit_code(kPlane, "--shader uniform_probe --uniform uTint=1,2") == 2);
    CHECK(exit_code(unknown, "") == 1);
    CHECK(exit_code(mistyped, "") == 1);
    CHECK(exit_code(unknown, "--shader uniform_probe") == 0);  // under --shader, only the names it declares apply
}

// `shader` baked at n^3 (time 0.5), each slice compared with OSMesa's llvmpipe render of that
// slice's square: the texels over 1/255 and the coverage mismatches, summed.
std::pair<std::size_t, std::size_t> bake_against_osmesa(const std::string& shader, int n, Image& volume) {
    VolumeRequest req;
    req.shader = shader, req.size = n;
    req.frame.time = 0.5;
    req.frame.set(raster_options_as(GlDriver::Llvmpipe));
    volume = bake_volume(req);
    REQUIRE(volume.width == n);
    REQUIRE(volume.height == n * n);
    std::size_t over_1 = 0, coverage = 0;
    for (int k = 0; k < n; ++k) {
        const auto file = work_dir() / ("volume-" + shader + "-" + std::to_string(n) + "-" + std::to_string(k) + ".gltf");
        save_scene(volume_slice_scene(req, k), file);
        const Case c{"volume-" + shader + "-" + std::to_string(n) + "-" + std::to_string(k), file, "", n, n};
        const Image ref = reference(c, "llvmpipe", n, n, "--time 0.5");
        // The frame's row r is the slice's texel row n - 1 - r (y = +1 at the top).
        Framebuffer slice;
        slice.width = slice.height = slice.rows = n;
        for (int r = 0; r < n; ++r) {
            const float* row = volume.rgba.data() + (std::size_t(k) * n + std::size_t(n - 1 - r)) * n * 4;
            slice.rgba.insert(slice.rgba.end(), row, row + n * 4);
        }
        const Counts counts = count(slice, ref);
        over_1 += counts.over_1, coverage += counts.coverage_mismatch;
    }
    return {over_1, coverage};
}

TEST_CASE("bake-volume: every slice of a baked volume is OSMesa's render of that slice's square", "[reference][volume]") {
    // 13^3: odd, so each slice's quads stick out of its frame. A solid texture without
    // derivatives and one with them (per texel along x and y, from quads of texels).
    std::vector<std::string> shaders;
    for (const Program* p : catalogue()) {
        const ShaderInfo& info = p->info();
        if (info.needs.coordinates != Coordinates::Object3D || samples_textures(info.needs) || !info.uniforms.empty()) continue;
        if (info.name.find("probe") != std::string_view::npos) continue;
        const bool with = info.needs.derivatives;
        if (std::none_of(shaders.begin(), shaders.end(), [&](const std::string& s) { return find_program(s)->info().needs.derivatives == with; })) {
            shaders.emplace_back(info.name);
        }
    }
    REQUIRE(shaders.size() == 2);
    for (const std::string& shader : shaders) {
        Image volume;
        const auto [over_1, coverage] = bake_against_osmesa(shader, 13, volume);
        INFO(shader << ": " << over_1 << " texels over 1/255, coverage " << coverage);
        CHECK(coverage == 0);  // the square covers every texel centre
        CHECK(over_1 == 0);
    }
}

TEST_CASE("bake-volume: the shipped fast noise volume is fast_noise_volume's bake, and OSMesa's", "[reference][volume]") {
    Image volume;
    const auto [over_1, coverage] = bake_against_osmesa("fast_noise_volume", 32, volume);
    CHECK(coverage == 0);
    CHECK(over_1 == 0);
    // quadshade-make-scenes computes the shipped file from the noise at the exact texel centres;
    // the bake interpolates P over each slice's square, and GL stores its colour in 8 bits.
    const Image shipped = read_image(kSource / "scenes/assets/textures/fast-noise-volume.png");
    REQUIRE(shipped.width == 32);
    REQUIRE(shipped.height == 32 * 32);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < shipped.rgba.size(); ++i) {
        differ += std::lround(std::clamp(volume.rgba[i], 0.0f, 1.0f) * 255.0f) != std::lround(shipped.rgba[i] * 255.0f);
    }
    INFO(differ << " of " << shipped.rgba.size() << " channels differ");
    CHECK(differ == 0);
}

TEST_CASE("bake-volume: the command writes a volume that loads as a sampler3D, and refuses what it cannot do", "[reference][volume]") {
    const auto dir = work_dir();
    const std::string qs = (kBin / "quadshade").string();
    const auto out = dir / "noise3d.png";
    auto run = [](const std::string& cmd) {
        const int status = std::system((cmd + " 2> /dev/null").c_str());
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    };
    REQUIRE(run(qs + " bake-volume --shader simplex3d --size 8 -o " + out.string()) == 0);
    const Image png = read_image(out);
    CHECK(png.width == 8);
    CHECK(png.height == 64);
    // The volume bound to fast_noise's sampler3D, as a scene names it.
    Scene s = load_scene(kPlane);
    s.objects.resize(1);
    s.objects[0].shader = "fast_noise";
    Texture t;
    t.image.file = out;
    t.dims = 3, t.depth = 8;
    t.field = "test volume";
    s.textures = {t};
    s.objects[0].texture = -1;
    s.objects[0].samplers = {{"noise3dSampler", 0}};
    FrameRequest r;
    r.width = r.height = 32;
    CHECK_NOTHROW(render_frame(s, r));
    CHECK(run(qs + " bake-volume --shader simplex3d --size 129 -o " + (dir / "big.png").string()) == 2);
    CHECK(run(qs + " bake-volume --shader no_such_shader --size 4 -o " + (dir / "none.png").string()) == 2);
    CHECK(run(qs + " bake-volume --shader single_texture --size 4 -o " + (dir / "tex.png").string()) == 1);
    CHECK_FALSE(std::filesystem::exists(dir / "big.png"));
    CHECK_FALSE(std::filesystem::exists(dir / "none.png"));
    CHECK_FALSE(std::filesystem::exists(dir / "tex.png"));
}

}  // namespace qs

namespace qs {

TEST_CASE("scene inputs by name: mvp, position and texcoord draw what the compatibility profile's names draw, "
          "what the scene does not feed is refused by name",
          "[reference][inputs]") {
    using test::kBin;
    using test::kPlane;
    const auto dir = work_dir() / "inputs-glsl";
    std::filesystem::create_directories(dir);
    auto read = [](const std::filesystem::path& p) {
        std::ifstream in(p);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    auto write = [&](const std::string& name, const std::string& text) { std::ofstream(dir / name) << text; };
    // dots as exported (plane_st.vert: gl_ModelViewProjectionMatrix * gl_Vertex), and its fragment
    // stage after a GLSL 1.30 vertex stage that declares its inputs.
    const std::string frag = read(std::filesystem::path(QUADSHADE_GLSL_DIR) / "dots.frag");
    REQUIRE(frag.starts_with("#version 120\n"));
    write("dots.vert", read(std::filesystem::path(QUADSHADE_GLSL_DIR) / "dots.vert"));
    write("dots.frag", frag);
    const std::string declared_vert = "#version 130\nuniform mat4 mvp;\nin vec3 position;\nin vec2 texcoord;\nout vec2 st;\n"
                                      "void main() {\n    st = texcoord;\n    gl_Position = mvp * vec4(position, 1.0);\n}\n";
    const std::string frag130 = "#version 130\n" + frag.substr(frag.find('\n') + 1);
    write("declared.vert", declared_vert);
    write("declared.frag", frag130);
    auto render = [&](const std::string& shader, std::string* err = nullptr) {
        const std::string cmd = (kBin / "quadshade-reference").string() + " " + kPlane.string() + " --glsl " + dir.string() +
                                " --size 96x64 --shader " + shader + " -o " + (dir / (shader + ".exr")).string();
        return test::run(cmd, err, dir / (shader + ".txt"));
    };
    REQUIRE(render("dots") == 0);
    REQUIRE(render("declared") == 0);
    const Image a = read_image(dir / "dots.exr"), b = read_image(dir / "declared.exr");
    CHECK(a.rgba == b.rgba);
    std::size_t covered = 0;
    for (std::size_t p = 3; p < b.rgba.size(); p += 4) covered += b.rgba[p] > 0.5f;
    CHECK(covered == b.rgba.size() / 4);  // the plane fills the frame: nothing left black

    // A transform under a name the scene does not feed, an attribute it has no data for, a
    // scene transform of the wrong type: refused, named, exit 1.
    const std::vector<std::pair<std::string, std::string>> refused = {
        {"uniform mat4 modelViewMatrix;\nin vec3 position;\nvoid main() { gl_Position = modelViewMatrix * vec4(position, 1.0); }\n",
         "uniform mat4 'modelViewMatrix' is none of the scene's transforms"},
        {"uniform mat4 mvp;\nin vec3 position;\nin vec4 tangent;\nvoid main() { gl_Position = mvp * vec4(position + tangent.xyz, 1.0); }\n",
         "vertex input 'tangent' is none the scene feeds"},
        {"uniform mat3 mvp;\nin vec3 position;\nvoid main() { gl_Position = vec4(mvp * position, 1.0); }\n",
         "uniform 'mvp' is the scene's transform: declare it mat4"},
    };
    for (std::size_t i = 0; i < refused.size(); ++i) {
        const std::string name = "refused" + std::to_string(i);
        write(name + ".vert", "#version 130\n" + refused[i].first);
        write(name + ".frag", "#version 130\nvoid main() { gl_FragColor = vec4(1.0); }\n");
        std::string err;
        CHECK(render(name, &err) == 1);
        INFO(err);
        CHECK(err.find(refused[i].second) != std::string::npos);
        CHECK(err.find(name) != std::string::npos);
    }
}

}  // namespace qs
