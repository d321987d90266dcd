// Run in the ASan + UBSan build (tools/ci-sanitizers), with the shader groups it compiles (Table
// 1.1's and the probes): every shader on both backends with every derivative rule and precision,
// in bands and whole, and image files of every format written band by band and read back. With
// the hostile-input and render tests this build also compiles, and the fuzz corpus replays.
// Combinations of rule and precision that no instantiation honours are skipped.
#include <catch2/catch.hpp>

#include <cstring>

#include "frontend/compile.h"
#include "frontend/cpp_writer.h"
#include "images/image_io.h"
#include "render/glsl_shaders.h"
#include "render/scene_render.h"
#include "scenes/gltf.h"
#include "shading/catalogue.h"
#include "shading/shade_choice.h"
#include "tests/test_paths.h"

namespace qs {

namespace {
using namespace test;
}

TEST_CASE("sanitized: every shader of this build, both backends, every rule and precision, whole and in bands",
          "[sanitize]") {
    Scene figure = load_scene(kFigure), plane = load_scene(kPlane);
    std::vector<Backend> backends = {Backend::Rasterizer};
#if defined(QUADSHADE_HAS_RAYCAST)
    backends.push_back(Backend::RayCaster);
#endif
    for (const Program* p : catalogue()) {
        for (Scene* scene : {&plane, &figure}) {
            if (scene == &figure && p->info().needs.texture) continue;  // the figure has no texture
            if (!plane_binds_samplers(p->info())) continue;               // baked_lit's normal map
            for (Backend backend : backends) {
                for (Derivatives rule : {Derivatives::Fine, Derivatives::CoarseLower, Derivatives::CoarseUpper, Derivatives::Analytic}) {
                    for (Precision precision : {Precision::Float, Precision::Double}) {
                        INFO(p->info().name << " backend " << int(backend) << " rule " << int(rule) << " precision " << int(precision));
                        FrameRequest r;
                        r.width = 37, r.height = 80;  // two bands of 64 rows
                        r.shader_override = std::string(p->info().name);
                        r.backend = backend;
                        r.shading.derivatives = rule;
                        r.shading.precision = precision;
                        r.shading.pairing = rule == Derivatives::CoarseLower ? QuadPairing::BottomUp : QuadPairing::TopDown;
                        r.shading.check_undefined = rule != Derivatives::Analytic && precision == Precision::Float;
                        try {  // combinations no instantiation honours are refused (tested elsewhere)
                            check_supported({rule, precision, r.shading.check_undefined});
                        } catch (const UnsupportedRequest&) {
                            continue;
                        }
                        SceneRenderer renderer(*scene, r);
                        Framebuffer whole, band;
                        renderer.render_into(whole, 0.5);
                        if (rule != Derivatives::Fine) continue;
                        for (const RowBand& b : image_bands(r.height, r.shading.pairing, 64)) {
                            renderer.render_into(band, 0.5, nullptr, b);
                            CHECK(std::memcmp(band.rgba.data(), whole.pixel(0, b.begin), band.rgba.size() * sizeof(float)) == 0);
                        }
                    }
                }
            }
        }
    }
}

TEST_CASE("sanitized: images of every format written band by band through the checked writer and read back",
          "[sanitize]") {
    const auto dir = temp_dir("sanitize-images");
    Image img{23, 19, {}};
    for (int i = 0; i < 23 * 19 * 4; ++i) img.rgba.push_back(float(i % 97) / 96.0f);
    for (const char* name : {"a.png", "a.exr", "a.tif", "a.hdr", "a.jpg"}) {
        INFO(name);
        const bool alpha = std::string(name) != "a.hdr" && std::string(name) != "a.jpg";  // RGB-only formats
        ImageWriter w(dir / name, img.width, img.height, alpha, {{"quadshade:test", "band by band"}});
        w.write_rows(5, img.rgba.data());
        w.write_rows(14, img.rgba.data() + 5 * 23 * 4);
        w.commit();
        const Image back = read_image(dir / name);
        CHECK(back.width == 23);
        CHECK(back.height == 19);
        if (alpha && std::string(name) != "a.png") CHECK(back.rgba == img.rgba);  // float formats
    }
    {
        ImageWriter abandoned(dir / "never.png", 4, 4, false);
    }
    CHECK_FALSE(std::filesystem::exists(dir / "never.png"));
    CHECK(std::distance(std::filesystem::directory_iterator(dir), {}) == 5);  // no temporary left
}

TEST_CASE("sanitized: GLSL run by the interpreter with its compiled blocks draws what its translation draws",
          "[sanitize]") {
    // The blocks' machine code is LLVM's and not instrumented; what is checked is the interpreter
    // around it, and that a slow-unwinding AddressSanitizer meets no frame the JIT registered.
    Scene scene = load_scene(test::kPlane);
    for (const char* name : {"perlin", "worley"}) {
        if (!find_program(name)) continue;  // a build without Table 1.1's shaders
        const std::string twin = interpreted_twin(name);
        FrameRequest r;
        r.width = r.height = 32;
        r.shader_override = name;
        const Framebuffer expected = render_frame(scene, r);
        r.shader_override = twin;
        const Framebuffer got = render_frame(scene, r);
        INFO(name);
        CHECK(std::memcmp(got.rgba.data(), expected.rgba.data(), got.rgba.size() * sizeof(float)) == 0);
    }
}

TEST_CASE("sanitized: the front end lowers and translates returns whose values call functions, calls deep",
          "[sanitize]") {
    // Each return's value calls the next function: lowering it pushes a call's frame while the
    // returning function's frame is in use.
    const frontend::GlslSource frag{"returns.frag", R"(varying vec2 st;
float f5(float x) { return x * 0.5 + 0.25; }
float f4(float x) { return 1.0 - f5(x) * f5(x + 0.5); }
float f3(float x) { return f4(x) + f4(x * 2.0); }
float f2(float x) { return 0.5 * f3(x) - f3(x + st.y); }
float f1(float x) { return fract(f2(x) + f2(st.x)); }
void main() { gl_FragColor = vec4(f1(st.x), f1(st.y), 0.0, 1.0); }
)"};
    const frontend::CompiledProgram program = frontend::compile_glsl(frag, std::nullopt);
    CHECK_FALSE(program.program.fragment.code.empty());
    CHECK(frontend::translate_glsl(frag, std::nullopt, "returns").header.find("return fract(f2(x) + f2(st.x));") !=
          std::string::npos);
}

}  // namespace qs
