// Every catalogue shader's GLSL, run by the interpreter, against its hand translation: the same
// scene, size and settings, image against image. Both call the same vocabulary functions in the
// same order, so the images are identical to the bit; a difference is a bug of the front end or
// the interpreter (or a translation that does not read like its GLSL).

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "frontend/compile.h"
#include "interpreter/glsl_program.h"
#include "render/scene_render.h"
#include "shading/catalogue.h"
#include "shading/glsl_export.h"
#include "tests/shading_modes.h"
#include "tests/test_paths.h"

namespace {

using namespace qs;

struct Difference {
    double max = 0.0;
    std::size_t pixels = 0;  // differing at all
};

Difference compare(const Framebuffer& a, const Framebuffer& b) {
    Difference d;
    for (std::size_t p = 0; p < a.rgba.size() / 4; ++p) {
        bool differs = false;
        for (int c = 0; c < 4; ++c) {
            const float x = a.rgba[p * 4 + std::size_t(c)], y = b.rgba[p * 4 + std::size_t(c)];
            if (std::isnan(x) && std::isnan(y)) continue;
            const double e = std::isnan(x) || std::isnan(y) ? 1.0 : std::abs(double(x) - double(y));
            if (std::bit_cast<std::uint32_t>(x) != std::bit_cast<std::uint32_t>(y)) differs = true;
            d.max = std::max(d.max, e);
        }
        if (differs) ++d.pixels;
    }
    return d;
}

// The scene a shader is drawn on: the first that binds its textures, the solids' sphere first
// for a solid texture.
const Scene* scene_for(const ShaderInfo& info, const std::vector<Scene>& scenes) {
    for (const Scene& s : scenes) {
        if (binds_samplers(s, info)) return &s;
    }
    return nullptr;
}

// The shaders compiled from the catalogue's GLSL, once for the whole run, by catalogue name.
const std::map<std::string, const Program*>& interpreted() {
    static const std::map<std::string, const Program*> programs = [] {
        std::map<std::string, const Program*> m;
        const ProgramList translations = catalogue();
        for (const Program* p : translations) {
            const std::string name(p->info().name);
            try {
                frontend::CompiledProgram c = frontend::compile_glsl({name + ".frag", glsl_source(*p, false)},
                                                                     frontend::GlslSource{name + ".vert", glsl_source(*p, true)});
                std::string vertex = c.vertex.text;
                auto program = std::make_unique<interpreter::GlslProgram>("interpreted " + name, std::move(c));
                m[name] = &add_compiled_program(std::move(program), "interpreted", vertex, glsl_source(*p, false));
            } catch (const std::exception& e) {
                UNSCOPED_INFO(name << ": " << e.what());
                m[name] = nullptr;
            }
        }
        return m;
    }();
    return programs;
}

}  // namespace

TEST_CASE("every catalogue shader's GLSL compiles for the interpreter", "[interpreter]") {
    std::ostringstream failed;
    for (const auto& [name, program] : interpreted()) {
        if (!program) failed << name << " ";
    }
    INFO("not compiled: " << failed.str());
    CHECK(failed.str().empty());
}

TEST_CASE("every catalogue shader's GLSL renders as its translation does, under each rule", "[interpreter]") {
    std::vector<Scene> scenes;
    for (const auto& f : {test::kPlane, test::kLawlorPlane, test::kSphere, test::kProcTexGenSpheres}) scenes.push_back(load_scene(f));
    int compared = 0;
    for (const auto& [name, program] : interpreted()) {
        if (!program) continue;
        const Program* translation = find_program(name);
        const ShaderInfo& info = translation->info();
        std::vector<Scene> candidates;
        const Scene* scene = scene_for(info, scenes);
        if (!scene) continue;  // a shader no shipped scene binds (the baked scenes' own)
        for (const test::ShadingMode& m : test::kShadingModes) {
            FrameRequest r;
            r.width = 48, r.height = 32;
            r.shading.derivatives = m.derivatives;
            r.shading.precision = m.precision;
            r.shader_override = name;
            Scene s = *scene;
            const Framebuffer expected = render_frame(s, r);
            r.shader_override = program->info().name;
            const Framebuffer got = render_frame(s, r);
            const Difference d = compare(expected, got);
            INFO(name << " on " << scene->file.filename().string() << ", " << m.what << ": " << d.pixels
                      << " pixels differ, by at most " << d.max);
            if (test::kReassociatedByMesa.contains(name)) {
                // An ulp apart in float, which these shaders' hash and escape time magnify (double
                // absorbs it); the day the two agree, the list is wrong.
                CHECK((m.precision == Precision::Double || d.pixels > 0));
            } else if (m.precision == Precision::Double) {
                // glslang folds a constant expression such as 3.0 * C.xxx (C const) to GLSL's float,
                // which the interpreter keeps; a translation computes it in double at run time, so the
                // 3D simplex noises end an ulp of the float output apart (a contour's 1 / fwidth
                // magnifies it to a few).
                CHECK(d.max <= 0x1p-16f);
            } else {
                CHECK(d.pixels == 0);
            }
            ++compared;
        }
    }
    CHECK(compared > 400);
}
