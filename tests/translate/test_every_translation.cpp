// Every catalogue shader's GLSL the C++ writer translates, compiled into a plugin as `--compile`
// compiles it (render/compiled_glsl.h) and drawn beside the interpreter running the same GLSL under
// every shading mode: the two call the vocabulary's functions in the same order, so the images are
// identical to the bit. About 115 plugins take about 14 CPU-minutes to compile, so this test is
// built only where it is asked for (tools/setup --translations); QUADSHADE_SHARD=k/n runs the
// shaders k, k + n, k + 2n ... of the catalogue, so that ctest runs shards side by side.

#include <catch2/catch.hpp>

#include <cstdlib>
#include <sstream>
#include <string>

#include "frontend/compile.h"
#include "frontend/cpp_writer.h"
#include "interpreter/glsl_program.h"
#include "render/compiled_glsl.h"
#include "render/scene_render.h"
#include "shading/catalogue.h"
#include "shading/glsl_export.h"
#include "shading/shade_choice.h"
#include "tests/test_paths.h"
#include "tests/translate/same_pixels.h"

namespace {

using namespace qs;

struct Shard {
    int index = 0, count = 1;
};

// QUADSHADE_SHARD=k/n, or the whole catalogue.
Shard shard_from_environment() {
    Shard s;
    if (const char* e = std::getenv("QUADSHADE_SHARD")) {
        std::istringstream in(e);
        char slash = 0;
        if (!(in >> s.index >> slash >> s.count) || slash != '/' || s.count < 1 || s.index < 0 || s.index >= s.count) {
            FAIL("QUADSHADE_SHARD is k/n with 0 <= k < n, not " << e);
        }
    }
    return s;
}

// Every mode the same-pixels check renders in, for a shader that needs `needs`.
ShadeModes modes_of_the_check(const Needs& needs) {
    ShadeModes modes{0};
    for (const test::ShadingMode& m : test::kShadingModes) {
        modes.bits |= modes_for(needs, ShadeRequest{.derivatives = m.derivatives, .precision = m.precision}).bits;
    }
    modes.bits |= modes_for(needs, ShadeRequest{.check_undefined = true}).bits;
    return modes;
}

}  // namespace

TEST_CASE("every catalogue shader's GLSL, compiled, draws what the interpreter draws, under each rule", "[translate]") {
    const Shard shard = shard_from_environment();
    int index = -1, compared = 0, refused = 0;
    const ProgramList shaders = catalogue();  // as it is before this test adds to it
    for (const Program* p : shaders) {
        if (++index % shard.count != shard.index) continue;
        const std::string name(p->info().name);
        if (!test::plane_binds_samplers(p->info())) continue;  // drawn only by the baked scenes
        const frontend::GlslSource frag{name + ".frag", glsl_source(*p, false)};
        const frontend::GlslSource vert{name + ".vert", glsl_source(*p, true)};
        try {
            // What the writer refuses (by its line, tests/translate/test_translate.cpp), and a
            // shader whose loops may reach llvmpipe's limit, the interpreter runs.
            const frontend::Translation t = frontend::translate_glsl(frag, vert, name);
            if (!t.unbounded_loop.empty()) {
                UNSCOPED_INFO(name << " not compiled: " << t.unbounded_loop);
                ++refused;
                continue;
            }
        } catch (const frontend::GlslError& e) {
            UNSCOPED_INFO(name << " not translated: " << e.what());
            ++refused;
            continue;
        }
        INFO(name);
        const Program* compiled = compiled_glsl_program(frag, vert, "generated " + name, GlslWay::Compile,
                                                        modes_of_the_check(p->info().needs));
        REQUIRE(compiled);
        frontend::CompiledProgram glsl = frontend::compile_glsl(frag, vert);
        const std::string vertex = glsl.vertex.text;
        auto program = std::make_unique<interpreter::GlslProgram>("interpreted " + name, std::move(glsl));
        const Program& interpreted = add_compiled_program(std::move(program), "interpreted", vertex, frag.text);
        Scene scene = load_scene(test::plane_for(name));
        test::check_same_pixels(scene, interpreted, *compiled, name, false);  // a constant colour too
        ++compared;
    }
    INFO(compared << " compared, " << refused << " not translated or not compiled");
    CHECK(compared > 0);
    CHECK(refused <= 2);  // builtins_probe's modf under a condition, loop_probe's while loop
}
