// quadshade translate: every catalogue shader's GLSL written as C++ (or refused with a line and a
// reason), and translations compiled into this test (tests/CMakeLists.txt writes them at build
// time with `quadshade translate`) drawn beside the interpreter running the same GLSL: both call
// the vocabulary's functions in the same order, so the images are identical to the bit under
// every derivative rule, in double and with analytic derivatives.

#include <catch2/catch.hpp>

#include <bit>
#include <regex>

#include "frontend/cpp_writer.h"
#include "interpreter/glsl_program.h"
#include "render/scene_render.h"
#include "shading/catalogue.h"
#include "shading/glsl_export.h"
#include "shading/program_of.h"
#include "tests/test_paths.h"

#include "translated_lawlor_mandelbrot/translated_lawlor_mandelbrot.h"
#include "translated_bricks_aa/translated_bricks_aa.h"
#include "translated_lawlor_stained_glass/translated_lawlor_stained_glass.h"
#include "translated_texture_lookups/translated_texture_lookups.h"

namespace {

using namespace qs;

frontend::Translation translate(const Program& p, const std::string& name) {
    return frontend::translate_glsl({name + ".frag", glsl_source(p, false)}, frontend::GlslSource{name + ".vert", glsl_source(p, true)},
                                    name);
}

std::size_t differing_pixels(const Framebuffer& a, const Framebuffer& b) {
    std::size_t n = 0;
    for (std::size_t p = 0; p < a.rgba.size() / 4; ++p) {
        bool differs = false;
        for (std::size_t c = 0; c < 4; ++c) {
            differs = differs || std::bit_cast<std::uint32_t>(a.rgba[p * 4 + c]) != std::bit_cast<std::uint32_t>(b.rgba[p * 4 + c]);
        }
        n += differs;
    }
    return n;
}

}  // namespace

TEST_CASE("every catalogue shader's GLSL is translated, or refused with its line and why", "[translate]") {
    int translated = 0, refused = 0;
    const std::regex position(R"(^[^:]+\.(frag|vert)(:[0-9]+(:[0-9]+)?)?: error: .+)");
    for (const Program* p : catalogue()) {
        const std::string name(p->info().name);
        try {
            const frontend::Translation t = translate(*p, name);
            ++translated;
            // Every statement of main() carries its GLSL line; no GLSL text but names and numbers.
            CHECK(t.header.find("void main() {  // ") != std::string::npos);
            CHECK(t.source.find("QUADSHADE_SHADERS(") != std::string::npos);
        } catch (const frontend::GlslError& e) {
            // What the interpreter runs and the writer does not write is refused by position.
            INFO(name << ": " << e.what());
            CHECK(std::regex_match(std::string(e.what()), position));
            ++refused;
        }
    }
    INFO(translated << " translated, " << refused << " refused");
    CHECK(translated >= 97);
}

TEST_CASE("a translation names GLSL's identifiers safely and keeps file names out of code", "[translate]") {
    const frontend::GlslSource frag{"evil \"#include <x>\" */.frag",
                                    "varying vec2 st;\nfloat and_eq(float unix) { return unix * 2.0; }\n"
                                    "void main() { float delete = and_eq(st.x); gl_FragColor = vec4(delete); }\n"};
    const frontend::Translation t = frontend::translate_glsl(frag, std::nullopt, "evil");
    CHECK(t.header.find("\n#include <x>") == std::string::npos);
    CHECK(t.header.find("\"#include") == std::string::npos);  // the name reaches a comment only, its quotes replaced
    CHECK(t.header.find("and_eq_(F unix_)") != std::string::npos);
    CHECK(t.header.find("F delete_ = and_eq_(st.x);") != std::string::npos);
    CHECK_THROWS_AS(frontend::translate_glsl(frag, std::nullopt, "bad name"), frontend::GlslError);
}

TEST_CASE("compiled translations draw what the interpreter draws, to the bit, under each rule", "[translate]") {
    // A loop with a break that varies per fragment; a function of derivatives; nested loops
    // around an if and else that vary per fragment, with a texture.
    const std::pair<std::unique_ptr<Program> (*)(), std::string> cases[] = {
        {[] { return std::unique_ptr<Program>(new ProgramOf<translated_lawlor_mandelbrot::TranslatedLawlorMandelbrot>); }, "lawlor_mandelbrot"},
        {[] { return std::unique_ptr<Program>(new ProgramOf<translated_bricks_aa::TranslatedBricksAa>); }, "bricks_aa"},
        {[] { return std::unique_ptr<Program>(new ProgramOf<translated_lawlor_stained_glass::TranslatedLawlorStainedGlass>); },
         "lawlor_stained_glass"}};
    struct Mode {
        const char* what;
        Derivatives derivatives;
        Precision precision;
    };
    const Mode modes[] = {{"fine", Derivatives::Fine, Precision::Float},
                          {"coarse-lower", Derivatives::CoarseLower, Precision::Float},
                          {"coarse-upper", Derivatives::CoarseUpper, Precision::Float},
                          {"analytic", Derivatives::Analytic, Precision::Float},
                          {"double", Derivatives::Fine, Precision::Double}};
    for (const auto& [make, name] : cases) {
        const Program& catalogue_shader = *find_program(name);
        frontend::CompiledProgram c = frontend::compile_glsl({name + ".frag", glsl_source(catalogue_shader, false)},
                                                             frontend::GlslSource{name + ".vert", glsl_source(catalogue_shader, true)});
        const std::string vertex = c.vertex.text;
        const Program& interpreted = add_compiled_program(std::make_unique<interpreter::GlslProgram>("interpreted " + name, std::move(c)),
                                                          "interpreted", vertex, glsl_source(catalogue_shader, false));
        const Program& compiled = add_compiled_program(make(), "translated", vertex, glsl_source(catalogue_shader, false));
        Scene scene = load_scene(test::plane_for(name));
        for (const Mode& m : modes) {
            FrameRequest r;
            r.width = 64, r.height = 48;
            r.shading.derivatives = m.derivatives;
            r.shading.precision = m.precision;
            r.shader_override = interpreted.info().name;
            const Framebuffer expected = render_frame(scene, r);
            r.shader_override = compiled.info().name;
            const Framebuffer got = render_frame(scene, r);
            INFO(name << ", " << m.what);
            CHECK(differing_pixels(expected, got) == 0);
        }
    }
}

TEST_CASE("a translation's texture lookups, every form, draw what the interpreter draws, to the bit, under each rule",
          "[translate][textures]") {
    const frontend::GlslSource frag = frontend::read_glsl_file(test::kSource / "tests/glsl/textures/texture_lookups.frag");
    frontend::CompiledProgram c = frontend::compile_glsl(frag, std::nullopt);
    const std::string vertex = c.vertex.text;
    const Program& interpreted = add_compiled_program(
        std::make_unique<interpreter::GlslProgram>("interpreted texture_lookups", std::move(c)), "interpreted", vertex, frag.text);
    const Program& compiled = add_compiled_program(
        std::unique_ptr<Program>(new ProgramOf<translated_texture_lookups::TranslatedTextureLookups>), "translated", vertex,
        frag.text);
    // The plane's texture with trilinear mipmaps, and the shipped volume with them as `volume`.
    Scene scene = load_scene(test::kPlane);
    const Sampler trilinear{Filter::Linear, Filter::LinearMipmapLinear, Wrap::Repeat, Wrap::MirroredRepeat, Wrap::Repeat};
    scene.textures.at(0).sampler = trilinear;
    Texture volume;
    volume.image.file = test::kSource / "scenes/assets/textures/fast-noise-volume.png";
    volume.sampler = trilinear;
    volume.dims = 3, volume.depth = 32;
    volume.field = "volume";
    scene.textures.push_back(volume);
    scene.objects.at(0).samplers = {{"volume", int(scene.textures.size()) - 1}};
    const std::pair<Derivatives, Precision> modes[] = {{Derivatives::Fine, Precision::Float},
                                                       {Derivatives::CoarseLower, Precision::Float},
                                                       {Derivatives::CoarseUpper, Precision::Float},
                                                       {Derivatives::Analytic, Precision::Float},
                                                       {Derivatives::Fine, Precision::Double}};
    for (const auto& [derivatives, precision] : modes) {
        FrameRequest r;
        r.width = 64, r.height = 48;
        r.shading.derivatives = derivatives;
        r.shading.precision = precision;
        r.shader_override = interpreted.info().name;
        const Framebuffer expected = render_frame(scene, r);
        r.shader_override = compiled.info().name;
        const Framebuffer got = render_frame(scene, r);
        INFO("derivatives " << int(derivatives) << ", precision " << int(precision));
        CHECK(differing_pixels(expected, got) == 0);
    }
}
