// quadshade translate: every catalogue shader's GLSL written as C++ (or refused with a line and a
// reason), and translations compiled into this test (tests/CMakeLists.txt writes them at build
// time with `quadshade translate`) drawn beside the interpreter running the same GLSL: both call
// the vocabulary's functions in the same order, so the images are identical to the bit under
// every derivative rule, in double and with analytic derivatives.

#include <catch2/catch.hpp>

#include <bit>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <regex>

#include "frontend/batch_width.h"
#include "frontend/cpp_writer.h"
#include "interpreter/glsl_program.h"
#include "render/compiled_glsl.h"
#include "render/scene_render.h"
#include "shading/catalogue.h"
#include "shading/glsl/iteration_lanes.h"
#include "shading/glsl_export.h"
#include "shading/program_of.h"
#include "tests/cube_map.h"
#include "tests/translate/same_pixels.h"
#include "tests/test_paths.h"

#include "translated_lawlor_mandelbrot/translated_lawlor_mandelbrot.h"
#include "translated_bricks_aa/translated_bricks_aa.h"
#include "translated_lawlor_stained_glass/translated_lawlor_stained_glass.h"
#include "translated_chained_assignment/translated_chained_assignment.h"
#include "translated_sampler_parameter/translated_sampler_parameter.h"
#include "translated_constant_vector_table/translated_constant_vector_table.h"
#include "translated_texture_lookups/translated_texture_lookups.h"
#include "translated_counted_loops/translated_counted_loops.h"
#include "translated_exact_products/translated_exact_products.h"
#include "translated_colour_unwritten/translated_colour_unwritten.h"
#include "translated_cell_searches/translated_cell_searches.h"
#include "translated_name_and_counter_edges/translated_name_and_counter_edges.h"
#include "translated_texture_queries/translated_texture_queries.h"
#include "translated_texture_shadow/translated_texture_shadow.h"
#include "translated_texture_cube/translated_texture_cube.h"

namespace {

using namespace qs;

frontend::Translation translate(const Program& p, const std::string& name) {
    return frontend::translate_glsl({name + ".frag", glsl_source(p, false)}, frontend::GlslSource{name + ".vert", glsl_source(p, true)},
                                    name);
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
    CHECK(translated >= 118);
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

namespace {

// A compiled translation and the GLSL it was written from: a catalogue shader's, or a file of
// tests/translate (with the default vertex stage) on the Table 1.1 plane.
struct TranslatedCase {
    std::unique_ptr<Program> (*make)();
    std::string name;
    bool catalogue = true;
};

std::string read_text(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Whether the C++ the writer makes of tests/translate/NAME.frag holds a line.
auto writes(const std::string& name) {
    const std::filesystem::path file = test::kSource / "tests/translate" / (name + ".frag");
    return [header = frontend::translate_glsl({file.string(), read_text(file)}, std::nullopt, name).header](
               const std::string& line) { return header.find(line) != std::string::npos; };
}

template <class Shader>
std::unique_ptr<Program> make_program() {
    return std::make_unique<ProgramOf<Shader>>();
}

}  // namespace

TEST_CASE("compiled translations draw what the interpreter draws, to the bit, under each rule", "[translate]") {
    // A loop with a break that varies per fragment; a function of derivatives; nested loops
    // around an if and else that vary per fragment, with a texture; chained assignments; functions
    // taking a sampler; constant arrays of vectors read per fragment; C++ loops beside and inside
    // Loop objects; multiply-adds rounded once beside ones a single rounding would change; a colour
    // that branches leave unwritten; loop nests whose heads run for all iterations at once; what C++
    // would read otherwise (names, shadowed locals, integer remainders, a counter per lane).
    const TranslatedCase cases[] = {
        {make_program<translated_lawlor_mandelbrot::TranslatedLawlorMandelbrot>, "lawlor_mandelbrot"},
        {make_program<translated_bricks_aa::TranslatedBricksAa>, "bricks_aa"},
        {make_program<translated_lawlor_stained_glass::TranslatedLawlorStainedGlass>, "lawlor_stained_glass"},
        {make_program<translated_chained_assignment::TranslatedChainedAssignment>, "chained_assignment", false},
        {make_program<translated_sampler_parameter::TranslatedSamplerParameter>, "sampler_parameter", false},
        {make_program<translated_constant_vector_table::TranslatedConstantVectorTable>, "constant_vector_table",
         false},
        {make_program<translated_counted_loops::TranslatedCountedLoops>, "counted_loops", false},
        {make_program<translated_exact_products::TranslatedExactProducts>, "exact_products", false},
        {make_program<translated_colour_unwritten::TranslatedColourUnwritten>, "colour_unwritten", false},
        {make_program<translated_cell_searches::TranslatedCellSearches>, "cell_searches", false},
        {make_program<translated_name_and_counter_edges::TranslatedNameAndCounterEdges>, "name_and_counter_edges", false}};
    for (const TranslatedCase& c : cases) {
        const std::string& name = c.name;
        std::optional<frontend::GlslSource> vert;
        frontend::GlslSource frag;
        if (c.catalogue) {
            const Program& catalogue_shader = *find_program(name);
            frag = {name + ".frag", glsl_source(catalogue_shader, false)};
            vert = frontend::GlslSource{name + ".vert", glsl_source(catalogue_shader, true)};
        } else {
            const std::filesystem::path file = test::kSource / "tests/translate" / (name + ".frag");
            frag = {file.string(), read_text(file)};
        }
        frontend::CompiledProgram compiled_glsl = frontend::compile_glsl(frag, vert);
        const std::string vertex = compiled_glsl.vertex.text;
        auto glsl_program = std::make_unique<interpreter::GlslProgram>("interpreted " + name, std::move(compiled_glsl));
        const Program& interpreted = add_compiled_program(std::move(glsl_program), "interpreted", vertex, frag.text);
        const Program& compiled = add_compiled_program(c.make(), "translated", vertex, frag.text);
        Scene scene = load_scene(c.catalogue ? test::plane_for(name) : test::kPlane);
        test::check_same_pixels(scene, interpreted, compiled, name);
    }
}

TEST_CASE("a loop nest's head that reads only its counters and values declared before it runs for all iterations "
          "at once, where those values are alike in every lane", "[translate]") {
    const auto has = writes("cell_searches");
    // The 3x3 search: the hash and the offsets, not the vector to the point (it reads Pf).
    CHECK(has("const IterationLanes<F, 3, 3> each({-1, -1}, lanes_alike(Pi));"));
    CHECK(has("F p = each.alike ? each.at(p_each, i, j) : permute(permute(Pi.x + float(i)) + Pi.y + float(j));  // 20"));
    CHECK(has("vec2<F> d = Pf - vec2<F>(float(i), float(j)) - o;  // 22"));
    // A Voronoi search: the offset, which reads no per-lane value, then the hash of the cell.
    CHECK(has("const IterationLanes<F, 3, 3> each2({-1, -1}, lanes_alike(n));"));
    CHECK(has("vec2<F> g_each2{}, o_each2{};"));
    CHECK(has("vec2<F> r = g + o - f;  // 40"));
    // Octaves around a 3x3x3 search: each loop's head its own, the inner one reading the outer counter.
    CHECK(has("const IterationLanes<F, 2> each3({0}, lanes_alike(P));"));
    CHECK(has("const IterationLanes<F, 3, 3, 3> each4({-1, -1, -1}, lanes_alike(Pi));"));
    // An int cell; a head under a condition that varies per fragment; a signed zero.
    CHECK(has("lanes_alike(cell)"));
    CHECK(has("lanes_alike(c)"));
    CHECK(has("lanes_alike(q)"));
    // Left as written: a head reading a varying, and one of two operations.
    CHECK(has("F vi = permute(permute(floor(st.x * 40.0f) + float(i)));"));
    CHECK(has("F ti = F_.x + float(i);"));
    CHECK_FALSE(has("vi_each"));
    CHECK_FALSE(has("ti_each"));
}

TEST_CASE("a translation says what GLSL says where C++ would read it otherwise", "[translate]") {
    const auto has = writes("name_and_counter_edges");
    // The writer's own names stay its own: GLSL's are renamed, and the new code's names step aside.
    CHECK(has("F IterationLanes_{};"));
    CHECK(has("F lanes_alike_ = F(0.5f);"));
    CHECK(has("const IterationLanes<F, 2> each2({0}, lanes_alike(c));"));
    // A nest whose counters share a name runs as written.
    CHECK(has("F a = each(c.x + float(i)) + h(c.y) * h(c.x + c.y) + lanes_alike_;  // 21"));
    // `vec2 c = c + ...` reads the outer c.
    CHECK(has("vec2<F> c_2 = c + vec2<F>(F(0.5f));  // 32"));
    // A remainder, quotient and float arithmetic of counters are F's; a counter per lane is held.
    CHECK(has("remainders += F(int_t<F>(i) % int_t<F>(2)) + F(int_t<F>(i) / int_t<F>(2));  // 37"));
    CHECK(has("acc += sin((F(float(i)) * 0.1f + 0.37f + st.x) * 1000.0f) * 0.01f;  // 41"));
    CHECK(has("int_t<F> k = int_t<F>(0);  // 44"));
    CHECK(has("Loop loop(left, k);"));
}

TEST_CASE("iteration lanes: each iteration's counters in its lane, read back in every lane; lanes alike to the bit",
          "[translate]") {
    using P = Pixels<float, 16>;
    using glsl::IterationLanes;
    const IterationLanes<P, 3, 2> each({-1, 4}, true);
    REQUIRE(each.alike);
    const int_t<P> i = each.counter(0), j = each.counter(1);
    for (int k = 0; k < 16; ++k) {
        const int it = std::min(k, 5);  // lanes past the last iteration repeat it
        CHECK(lane(i, k) == -1 + it / 2);
        CHECK(lane(j, k) == 4 + it % 2);
    }
    const P value = P(i) * 10.0f + P(j);
    CHECK(lane(each.at(value, 0, 5), 7) == 5.0f);
    CHECK(lane(each.at(glsl::vec2<P>(value, -value), 1, 4).y, 3) == -14.0f);
    // Too many iterations for the lanes, or not plain lanes: never alike, the loop runs as written.
    CHECK_FALSE((IterationLanes<P, 17>({0}, true).alike));
    CHECK_FALSE((IterationLanes<float, 1>({0}, true).alike));
    CHECK_FALSE((IterationLanes<Dual2<P>, 2>({0}, true).alike));

    float v[16];
    for (float& x : v) x = 3.5f;
    CHECK(glsl::lanes_alike(P::load(v), int_t<P>(7)));
    v[9] = -0.0f;
    P zeros = P::load(v);
    for (float& x : v) x = 0.0f;
    CHECK(glsl::lanes_alike(P::load(v)));
    v[9] = -0.0f;
    CHECK_FALSE(glsl::lanes_alike(P::load(v)));  // -0 and +0 compare equal but divide apart
    CHECK_FALSE(glsl::lanes_alike(zeros));
    for (float& x : v) x = std::numeric_limits<float>::quiet_NaN();
    CHECK(glsl::lanes_alike(P::load(v)));  // the same NaN: the same results
    CHECK_FALSE(glsl::lanes_alike(glsl::vec2<P>(P(1.0f), P::load(v)), P(1.0f) + P(i)));
}

TEST_CASE("a translation rounds a multiply-add once only where its product is exact for every input", "[translate]") {
    const std::filesystem::path file = test::kSource / "tests/translate/exact_products.frag";
    const std::string shader = frontend::translate_glsl({file.string(), read_text(file)}, std::nullopt, "exact_products").header;
    const auto has = [&](const std::string& text, const std::string& line) {
        INFO(line);
        return text.find(line) != std::string::npos;
    };
    // The permutation's inputs after mod289 of a bounded floor, through three calls; mod289
    // itself, its argument a whole number it proves below 2^24.
    CHECK(has(shader, "return mod289(exact_product_add(x, vec4<F>(34.0f), vec4<F>(1.0f)) * x);"));
    CHECK(has(shader, "return exact_sub_product(x, floor(x * 0.0034602077f), vec4<F>(289.0f));"));
    CHECK(has(shader, "return exact_sub_product(x, floor(x * 0.0034602077f), vec3<F>(289.0f));"));
    // Worley's chain: mod() of a bounded floor, plus a loop counter.
    CHECK(has(shader, "return mod(exact_product_add(F(34.0f), x, F(1.0f)) * x, F(289.0f));"));
    // A product of floors of anything, of a varying, of whole numbers past 2^24: GLSL's form.
    CHECK(has(shader, "F odd = floor(st.x * 1.0e+06f) * floor(st.y * 1.0e+06f) + 1.0f;"));
    CHECK(has(shader, "F line = st.x * 34.0f + 1.0f;"));
    CHECK(has(shader, "F past = w * 3.0f + 1.0f;"));
    // A floor of anything times a power of two: exact, or infinite both ways.
    CHECK(has(shader, "exact_sub_product(-floor(fract(st.x) * 4.0f), floor(st.y * 4.0f) - 8.0f, F(2.0f))"));

    const auto translate = [](const std::string& body) {
        const std::string glsl = "varying vec2 st;\n"
                                 "vec4 mod289(vec4 x) { return x - floor(x * (1.0 / 289.0)) * 289.0; }\n"
                                 "vec4 permute(vec4 x) { return mod289(((x * 34.0) + 1.0) * x); }\n"
                                 "void main() {\n" + body + "\n}\n";
        return frontend::translate_glsl({"snippet.frag", glsl}, std::nullopt, "snippet").header;
    };
    // The noises' own: mod289 of floor(P) of a varying can be any size, so nothing is exact.
    CHECK_FALSE(has(translate("gl_FragColor = permute(mod289(floor(st.xyxy * 10.0)));"), "exact_"));
    // A function analysed over all its calls: one unbounded call keeps GLSL's form for all.
    CHECK_FALSE(has(translate("gl_FragColor = permute(floor(fract(st.xyxy) * 9.0)) + permute(floor(st.xyxy));"),
                    "exact_"));
    CHECK(has(translate("gl_FragColor = permute(floor(fract(st.xyxy) * 9.0));"), "exact_"));
    // Whole numbers up to 3 * 5592405 = 2^24 - 1 are exact, from 3 * 5592406 = 2^24 + 2 not.
    CHECK(has(translate("float w = floor(fract(st.x) * 5.0) + 5592400.0; gl_FragColor = vec4(w * 3.0 - 1.0);"),
              "vec4<F>(exact_product_sub(w, F(3.0f), F(1.0f)))"));
    CHECK_FALSE(has(translate("float w = floor(fract(st.x) * 6.0) + 5592400.0; gl_FragColor = vec4(w * 3.0 - 1.0);"),
                    "exact_"));
    // A difference negates an operand in the fused form: never one that may be NaN (fract of a
    // varying is NaN where the varying is infinite).
    CHECK_FALSE(has(translate("gl_FragColor = vec4(floor(fract(st.y) * 4.0) * 2.0 - fract(st.x));"), "exact_"));
    CHECK(has(translate("gl_FragColor = vec4(fract(st.x) - floor(fract(st.y) * 4.0) * 2.0);"),
              "exact_sub_product(fract(st.x), floor(fract(st.y) * 4.0f), F(2.0f))"));
    // A loop counter's float, a plain C++ float, stays one.
    CHECK(has(translate("for (int k = 0; k < 4; k++) { gl_FragColor += vec4(float(k) * 2.0 + 1.0); }"),
              "float(k) * 2.0f + 1.0f"));
    // A variable a loop writes is not followed round the loop.
    CHECK_FALSE(has(translate("vec4 x = floor(fract(st.xyxy) * 9.0);\n"
                              "for (int k = 0; k < 3; k++) { x = mod289(x * 34.0 + 1.0); }\n"
                              "gl_FragColor = x;"),
                    "exact_"));
}

namespace {

// bricks_aa compiled for llvmpipe's rule in float only, as a plugin compiled for one render is.
struct BricksAaFineOnly : translated_bricks_aa::TranslatedBricksAa {
    static constexpr ShadeModes compiled_modes{1u << ShadeModes::bit({Derivatives::Fine, Precision::Float, false})};
};

}  // namespace

TEST_CASE("a translation zeroes the colour first only where main() could leave it unwritten", "[translate]") {
    const auto written = [](const std::string& main_body) {
        const std::string glsl = "varying vec2 st;\nvoid main() {\n" + main_body + "\n}\n";
        const std::string h = frontend::translate_glsl({"colour.frag", glsl}, std::nullopt, "colour").header;
        return h.find("out{vec4<F>(F(0.0f))}") == std::string::npos;
    };
    CHECK(written("float a = st.x * 2.0;\ngl_FragColor = vec4(a);"));
    CHECK_FALSE(written("if (st.x > 0.5) gl_FragColor = vec4(1.0);"));                      // in a branch
    CHECK_FALSE(written("gl_FragColor = vec4(1.0);\ngl_FragColor.x = gl_FragColor.y;"));  // read after
    CHECK_FALSE(written("gl_FragColor.xy = st;\ngl_FragColor.zw = st;"));                 // in parts
}

TEST_CASE("a translation compiled for some ways of shading shades them as the whole one does, refuses others",
          "[translate]") {
    const ProgramOf<translated_bricks_aa::TranslatedBricksAa> whole;
    const ProgramOf<BricksAaFineOnly> fine_only;
    FragmentBatch in{};
    for (int i = 0; i < kBatchLanes; ++i) {
        in.frag_coord[0][i] = float(i % 2 + 2 * (i / 4)), in.frag_coord[1][i] = float(i / 2 % 2);
        in.frag_coord[2][i] = 0.5f, in.frag_coord[3][i] = 1.0f;
        for (int v = 0; v < whole.info().needs.varyings; ++v) in.varying[v][i] = 0.37f * float(i) + 0.11f * float(v);
    }
    ColorBatch expected{}, got{};
    whole.shade({Derivatives::Fine, Precision::Float, false}, in, Uniforms{}, expected);
    fine_only.shade({Derivatives::Fine, Precision::Float, false}, in, Uniforms{}, got);
    for (int c = 0; c < 4; ++c) {
        for (int i = 0; i < kBatchLanes; ++i) {
            CHECK(std::bit_cast<std::uint32_t>(got.rgba[c][i]) == std::bit_cast<std::uint32_t>(expected.rgba[c][i]));
        }
    }
    // Its wide batches too (bricks_aa asks for them: frontend/batch_width.h): a pair of batches
    // shaded as one number of twice the width on AVX-512, each batch's bits as shaded alone.
    static_assert(translated_bricks_aa::TranslatedBricksAa::info.wide_batches);
    FragmentBatch next = in;
    for (int i = 0; i < kBatchLanes; ++i) next.frag_coord[0][i] += 4.0f;
    ColorBatch expected_next{}, got_next{};
    whole.shade({Derivatives::Fine, Precision::Float, false}, next, Uniforms{}, expected_next);
    fine_only.shade_pair({Derivatives::Fine, Precision::Float, false}, in, next, Uniforms{}, got, got_next);
    for (int c = 0; c < 4; ++c) {
        for (int i = 0; i < kBatchLanes; ++i) {
            CHECK(std::bit_cast<std::uint32_t>(got.rgba[c][i]) == std::bit_cast<std::uint32_t>(expected.rgba[c][i]));
            CHECK(std::bit_cast<std::uint32_t>(got_next.rgba[c][i]) == std::bit_cast<std::uint32_t>(expected_next.rgba[c][i]));
        }
    }
    for (const ShadeMode other : {ShadeMode{Derivatives::CoarseLower, Precision::Float, false},
                                  ShadeMode{Derivatives::Fine, Precision::Double, false},
                                  ShadeMode{Derivatives::Fine, Precision::Float, true}}) {
        CHECK_THROWS_AS(fine_only.shade(other, in, Uniforms{}, got), std::logic_error);
    }
}

TEST_CASE("a translation asks for wide batches unless its values outgrow the registers, it reads tables by index "
          "or a loop waits on texture lookups", "[translate]") {
    const auto traits = [](const std::string& name) {
        const Program& p = *find_program(name);
        const frontend::CompiledProgram c = frontend::compile_glsl({name + ".frag", glsl_source(p, false)},
                                                                   frontend::GlslSource{name + ".vert", glsl_source(p, true)});
        return frontend::batch_width_traits(c.program.fragment);
    };
    const frontend::BatchWidthTraits perlin = traits("perlin"), perlin5 = traits("perlin5"),
                                     improved = traits("improved_noise"), stained = traits("lawlor_stained_glass");
    CHECK(frontend::wide_batches_pay(perlin));
    CHECK(perlin5.peak_live_floats > perlin.peak_live_floats);  // five octaves' gradients at once
    CHECK_FALSE(frontend::wide_batches_pay(perlin5));
    CHECK(improved.largest_table == 256);  // its permutation
    CHECK_FALSE(frontend::wide_batches_pay(improved));
    CHECK(stained.texture_in_loop);
    CHECK_FALSE(frontend::wide_batches_pay(stained));
    // What the writer writes: the translations this test compiles.
    CHECK(translated_bricks_aa::TranslatedBricksAa::info.wide_batches);
    CHECK_FALSE(translated_lawlor_stained_glass::TranslatedLawlorStainedGlass::info.wide_batches);
}

TEST_CASE("a render's modes: those of a draw with and without a texture's level of detail", "[translate]") {
    const auto bit = [](Derivatives d, Precision p = Precision::Float, bool checked = false) {
        return 1u << ShadeModes::bit({d, p, checked});
    };
    CHECK(modes_for(Needs{.derivatives = true}, ShadeRequest{}).bits == bit(Derivatives::Fine));
    CHECK(modes_for(Needs{}, ShadeRequest{}).bits == (bit(Derivatives::None) | bit(Derivatives::Fine)));
    CHECK(modes_for(Needs{}, ShadeRequest{.derivatives = Derivatives::Analytic, .precision = Precision::Double}).bits ==
          (bit(Derivatives::None, Precision::Double) | bit(Derivatives::Analytic, Precision::Double)));
    CHECK(modes_for(Needs{.derivatives = true}, ShadeRequest{.check_undefined = true}).bits ==
          bit(Derivatives::Fine, Precision::Float, true));
    CHECK(ShadeModes{}.covers(modes_for(Needs{}, ShadeRequest{})));
    CHECK_FALSE(ShadeModes{bit(Derivatives::Fine)}.covers(ShadeModes{bit(Derivatives::Fine) | bit(Derivatives::None)}));
}

namespace {

// A file of tests/translate drawn on `scene` by the interpreter and by its translation compiled
// into this test (with the vertex stage the front end writes for it), to the bit under each rule;
// the translated program's name, to draw it again.
std::string check_file_on(const std::string& name, std::unique_ptr<Program> (*translated)(), Scene& scene) {
    const frontend::GlslSource frag = frontend::read_glsl_file(test::kSource / "tests/translate" / (name + ".frag"));
    frontend::CompiledProgram compiled_glsl = frontend::compile_glsl(frag, std::nullopt);
    const std::string vertex = compiled_glsl.vertex.text;
    const Program& interpreted = add_compiled_program(
        std::make_unique<interpreter::GlslProgram>("interpreted " + name, std::move(compiled_glsl)), "interpreted",
        vertex, frag.text);
    const Program& compiled = add_compiled_program(translated(), "translated", vertex, frag.text);
    test::check_same_pixels(scene, interpreted, compiled, name);
    return std::string(compiled.info().name);
}

// The shipped noise volume bound to the plane as `volume`.
void bind_volume(Scene& scene, const Sampler& sampler) {
    Texture volume;
    volume.image.file = test::kSource / "scenes/assets/textures/fast-noise-volume.png";
    volume.sampler = sampler;
    volume.dims = 3, volume.depth = 32;
    volume.field = "volume";
    scene.textures.push_back(volume);
    scene.objects.at(0).samplers = {{"volume", int(scene.textures.size()) - 1}};
}

}  // namespace

TEST_CASE("a translation's texture lookups, every form, draw what the interpreter draws, to the bit, under each rule",
          "[translate][textures]") {
    // The plane's texture and the shipped volume, both with trilinear mipmaps and a mirrored wrap,
    // so that offsets and explicit levels reach every filter's path.
    Scene scene = load_scene(test::kPlane);
    const Sampler trilinear{Filter::Linear, Filter::LinearMipmapLinear, Wrap::Repeat, Wrap::MirroredRepeat,
                            Wrap::Repeat};
    scene.textures.at(0).sampler = trilinear;
    bind_volume(scene, trilinear);
    check_file_on("texture_lookups", make_program<translated_texture_lookups::TranslatedTextureLookups>, scene);
}

TEST_CASE("a shader whose loops may reach llvmpipe's limit is not compiled: the interpreter keeps the limit", "[translate]") {
    // The iterations of main() and what it calls, each loop's counter run as GLSL runs it.
    const auto unbounded = [](const std::string& body, const std::string& version = "") {
        const std::string text = version + "varying vec2 st;\nuniform int n;\n" + body;
        return frontend::translate_glsl({"loops.frag", text}, std::nullopt, "loops").unbounded_loop;
    };
    const std::string sum = "float f(float x) { float s = 0.0; for (int i = 0; i < 250; i++) s += x; return s; }\n";
    CHECK(unbounded("void main() { float s = 0.0;\n"
                    "  for (float f = 8.0; f >= 0.25; f *= 0.5) s += f;\n"     // 6 times
                    "  float k = 5.0; for (float i = 0.; i < k; i++) s += i;\n"  // k is never changed
                    "  for (int i = 10; 0 < i; i -= 3) s += 1.0;\n"              // 4 times
                    "  gl_FragColor = vec4(s); }\n")
              .empty());
    CHECK(unbounded(sum + "void main() { float s = 0.0; for (int j = 0; j < 261; j++) s += f(st.x);\n"
                          "  gl_FragColor = vec4(s); }\n")  // 261 * 251 = 65,511 of 65,535
              .empty());
    CHECK(unbounded(sum + "void main() { float s = 0.0; for (int j = 0; j < 262; j++) s += f(st.x);\n"
                          "  gl_FragColor = vec4(s); }\n") == "loops.frag: the loops may go round 65,535 times");
    CHECK(unbounded("void main() { float s = 0.0;\n"
                    "  for (int i = 0; i < n; i++) s += 1.0;\n"  // a uniform bound
                    "  gl_FragColor = vec4(s); }\n") == "loops.frag:4:3: this loop may go round 65,535 times");
    CHECK(unbounded("void main() { float x = st.x;\n"
                    "  while (x < 1e30) x *= 2.0;\n"  // a value the body computes
                    "  gl_FragColor = vec4(x); }\n") == "loops.frag:4:3: this loop may go round 65,535 times");
    CHECK(unbounded("void main() { float s = 0.0;\n"
                    "  for (int i = 0; i < 4; i++) { s += 1.0; i += int(st.x); }\n"  // the body moves the counter
                    "  gl_FragColor = vec4(s); }\n") == "loops.frag:4:3: this loop may go round 65,535 times");
    CHECK(unbounded("int i;\nvoid restart() { i = 0; }\nvoid main() {\n"
                    "  for (i = 0; i < 10; i++) restart();\n"  // a global counter a called function changes
                    "  gl_FragColor = vec4(st, 0.0, 1.0); }\n") == "loops.frag:6:3: this loop may go round 65,535 times");
    CHECK(unbounded("void main() { float s = 0.0; int m;\n"
                    "  for (int i = 1; i != m; i++) s += 1.0;\n"  // read before it is set
                    "  m = 3;\n"
                    "  gl_FragColor = vec4(s); }\n") == "loops.frag:4:3: this loop may go round 65,535 times");
    CHECK(unbounded("void main() { float s = 0.0;\n"
                    "  for (int i = 0; i < 4; i++) s += frexp(st.x, i);\n"  // a built-in's out argument
                    "  gl_FragColor = vec4(s); }\n",
                    "#version 400\n") == "loops.frag:5:3: this loop may go round 65,535 times");
    // Not compiled, so that the interpreter runs it: nothing to compile, no plugin cache needed.
    const frontend::GlslSource never_ending{"never.frag", "varying vec2 st;\nvoid main() { float x = st.x;\n"
                                                          "  while (true) { x += 1.0; if (x < -1.0) break; }\n"
                                                          "  gl_FragColor = vec4(x); }\n"};
    CHECK(compiled_glsl_program(never_ending, std::nullopt, "never", GlslWay::Compile) == nullptr);
}

TEST_CASE("a translation's gathers and textureQueryLod draw what the interpreter draws, to the bit, under each rule",
          "[translate][textures]") {
    // GLSL 4.00, whose vertex stage the front end writes in GLSL 1.50 or later (gl_Position is
    // gl_PerVertex's). Mipmaps and a mirrored wrap, so that the gathers reach each wrap's code and
    // the query each level.
    Scene scene = load_scene(test::kPlane);
    scene.textures.at(0).sampler = {Filter::Linear, Filter::NearestMipmapNearest, Wrap::MirroredRepeat,
                                    Wrap::ClampToEdge, Wrap::Repeat};
    bind_volume(scene, {Filter::Linear, Filter::LinearMipmapLinear, Wrap::Repeat, Wrap::Repeat, Wrap::Repeat});
    check_file_on("texture_queries", make_program<translated_texture_queries::TranslatedTextureQueries>, scene);
}

TEST_CASE("a translation's sampler2DShadow lookups draw what the interpreter draws, to the bit, under each rule",
          "[translate][textures]") {
    // A trilinear depth texture of a size that is no power of two, mirrored, so that the blend of
    // the comparisons, of its float mipmaps and the offsets reach each wrap's code.
    Scene scene = load_scene(test::kPlane);
    Texture depth;
    depth.image.file = test::kSource / "scenes/assets/conformance/images/texture-37x19.png";
    depth.sampler = {Filter::Linear, Filter::LinearMipmapLinear, Wrap::MirroredRepeat, Wrap::Repeat, Wrap::Repeat};
    depth.compare = CompareFunc::Greater;  // a function other than GL's default reaches the translation
    depth.field = "depth";
    scene.textures.push_back(depth);
    scene.objects.at(0).samplers = {{"depth", int(scene.textures.size()) - 1}};
    const std::string translated =
        check_file_on("texture_shadow", make_program<translated_texture_shadow::TranslatedTextureShadow>, scene);
    // The translation says its sampler is a shadow sampler, so a plain texture bound to it is
    // refused by name, as it is under the interpreter.
    scene.textures.back().compare.reset();
    FrameRequest r;
    r.width = r.height = 16;
    r.shader_override = translated;
    CHECK_THROWS_WITH(render_frame(scene, r), Catch::Contains("sampler2DShadow 'depth'") &&
                                                  Catch::Contains("not a depth comparison texture"));
}

TEST_CASE("a translation's samplerCube and samplerCubeShadow lookups draw what the interpreter draws, to the bit, under "
          "each rule",
          "[translate][textures]") {
    // A trilinear cube map, whose implicit lookups take a level per pixel, and a depth comparison
    // cube map with float mipmaps and a nearest magnification filter.
    const std::filesystem::path dir = test::temp_dir("translate-cube");
    Scene scene = load_scene(test::kPlane);
    scene.textures.push_back(test::cube_map(
        dir, 32, {Filter::Linear, Filter::LinearMipmapLinear, Wrap::Repeat, Wrap::Repeat, Wrap::Repeat}, std::nullopt, "env"));
    scene.textures.push_back(
        test::cube_map(dir, 16, {Filter::Nearest, Filter::LinearMipmapLinear, Wrap::Repeat, Wrap::Repeat, Wrap::Repeat},
                       CompareFunc::NotEqual, "depth"));
    const int n = int(scene.textures.size());
    scene.objects.at(0).samplers = {{"env", n - 2}, {"depth", n - 1}};
    check_file_on("texture_cube", make_program<translated_texture_cube::TranslatedTextureCube>, scene);
}
