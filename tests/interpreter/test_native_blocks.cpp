// The compiled blocks (interpreter/native_blocks.h, jit/float_blocks.h) compute the bits the
// interpreter computes: every operation they take, on values that reach each rule's edge cases,
// in every lane, masked and not; loops that read a block's results when they go round; and every
// catalogue shader's GLSL, image against image, under each rule.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include "frontend/compile.h"
#include "frontend/ir_operands.h"
#include "interpreter/executor_run.h"
#include "interpreter/glsl_program.h"
#include "interpreter/native_blocks.h"
#include "render/scene_render.h"
#include "shading/catalogue.h"
#include "shading/glsl_export.h"
#include "tests/shading_modes.h"
#include "tests/test_paths.h"

using namespace qs;

namespace {

// Bit for bit, every NaN alike: x86 keeps the first operand's NaN of two, and either compiler
// may swap a sum's operands.
bool same_bits(float a, float b) {
    return (std::isnan(a) && std::isnan(b)) || std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
}

bool same(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), same_bits);
}

// Values at the edges of each operation: zeros of both signs, a denormal, the largest float,
// infinities, NaN, halves, exact integers and a value just under one.
const float kValues[] = {0.0f,   -0.0f,  1.0f,    -1.0f,  0.5f,  -2.5f,  1e-39f, 3.0e38f,  std::numeric_limits<float>::infinity(),
                         -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN(), 7.25f, 1e-7f,
                         289.0f, -1e20f, 0.99999994f, 2.0f,  -0.75f, 1.5f, 100.5f, -3.0f};
constexpr std::uint32_t kInputs = 8;  // float registers 0..7, each lane a value of kValues

ir::Instr op(ir::Op o, std::uint32_t d, std::uint32_t a = 0, std::uint32_t b = 0, std::uint32_t c = 0, std::uint8_t n = 1) {
    ir::Instr in{.op = o};
    in.d = d, in.a = a, in.b = b, in.c = c, in.n = n;
    return in;
}

// A stage that runs every compilable operation, on one component and on four, with operands
// that step and that stay, inside a branch that only some lanes take (their writes masked) and
// after it; each result is an output, so the blocks store it.
ir::Stage every_operation() {
    using ir::Op;
    ir::Stage s;
    s.serial = std::uint64_t{1} << 41;
    std::vector<ir::Instr> code;
    std::uint32_t next = kInputs;
    const auto result = [&](std::uint32_t n) {
        const std::uint32_t r = next;
        next += n;
        return r;
    };
    const Op unary[] = {Op::Mov, Op::FNeg, Op::FAbs, Op::FSign, Op::FFloor, Op::FCeil, Op::FTrunc, Op::FRoundEven,
                        Op::FFract, Op::FSqrt, Op::FInverseSqrt};
    const Op binary[] = {Op::FAdd, Op::FSub, Op::FMul, Op::FDiv, Op::FMod, Op::FMin, Op::FMax, Op::FStep};
    const Op ternary[] = {Op::FClamp, Op::FMix, Op::FSmoothStep};
    const auto operations = [&](bool masked) {
        for (std::uint8_t n : {std::uint8_t(1), std::uint8_t(4)}) {
            for (std::uint32_t shift = 0; shift < 3; ++shift) {
                const std::uint32_t a = shift, b = (shift + 3) % 4, c = (shift + 1) % 4;  // inputs 0..3 as vectors
                for (Op o : unary) code.push_back(op(o, result(n), a, 0, 0, n));
                for (Op o : binary) code.push_back(op(o, result(n), a, b + 4 * (shift == 2), 0, n));
                for (Op o : ternary) code.push_back(op(o, result(n), a, b, c, n));
                ir::Instr broadcast = op(Op::FMul, result(n), a, 7, 0, n);
                broadcast.broadcast = 2;  // v * s
                code.push_back(broadcast);
            }
        }
        code.push_back(op(Op::Dot, result(1), 0, 3, 0, 4));
        code.push_back(op(Op::Dot, result(1), 1, 2, 0, 3));
        code.push_back(op(Op::Length, result(1), 4, 0, 0, 2));
        // Results read again in the block, and a vector whose components read the ones before.
        const std::uint32_t t = result(4);
        code.push_back(op(Op::FMul, t, 0, 4, 0, 4));
        code.push_back(op(Op::FAdd, t + 1, t, 5, 0, 3));
        code.push_back(op(Op::FFloor, result(4), t, 0, 0, 4));
        if (masked) {
            for (std::size_t k = code.size() - 1; k > 0 && code[k].op != Op::If; --k) code[k].masked = true;
        }
    };
    code.push_back(op(Op::FLess, 0, 6, 2));  // the lanes whose input 6 is under input 2
    code.front().bank = ir::Bank::Bool;
    ir::Instr branch = op(Op::If, 0, 0);
    code.push_back(branch);
    operations(true);
    code.push_back(op(Op::EndIf, 0));
    code[1].target = std::uint32_t(code.size() - 1);
    operations(false);
    s.code = std::move(code);
    s.registers = {next, 0, 0, 1};
    for (std::uint32_t r = kInputs; r < next; ++r) s.outputs.push_back({ir::Source::Color, 0, 0, ir::Bank::Float, r});
    return s;
}

// Float registers after one run of `stage` in F, the inputs set lane by lane.
template <class F>
std::vector<float> run(const ir::Stage& stage, std::span<const jit::BlockCode> native) {
    ir::validate(stage, 0);
    interpreter::Registers<F> r;
    r.prepare(stage);
    alignas(64) float lanes[F::size];
    for (std::uint32_t reg = 0; reg < kInputs; ++reg) {
        for (int l = 0; l < F::size; ++l) lanes[l] = kValues[(std::size_t(l) * 7 + reg * 5) % std::size(kValues)];
        r.f[reg] = F::load(lanes);
    }
    interpreter::Executor<F>::run(stage, r, interpreter::TextureSlots{}, native);
    std::vector<float> out;
    for (std::size_t reg = 0; reg < r.f.size(); ++reg) {
        r.f[reg].store(lanes);
        out.insert(out.end(), lanes, lanes + F::size);
    }
    return out;
}

template <class F>
void compare_operations() {
    const ir::Stage interpreted = every_operation();
    ir::Stage compiled = interpreted;
    const std::unique_ptr<jit::CompiledBlocks> blocks = interpreter::compile_blocks(compiled);
    REQUIRE(blocks);
    int markers = 0;
    for (const ir::Instr& in : compiled.code) markers += in.op == ir::Op::Native;
    CHECK(markers == 2);  // one block in the branch, one after it
    const std::vector<float> expected = run<F>(interpreted, {}), got = run<F>(compiled, blocks->code(F::size));
    REQUIRE(got.size() == expected.size());
    std::size_t differ = 0, first = 0;
    for (std::size_t i = 0; i < got.size(); ++i) {
        if (!same_bits(got[i], expected[i]) && differ++ == 0) first = i;
    }
    INFO(F::size << " lanes: " << differ << " values differ, the first in register " << first / F::size << ", lane "
                 << first % F::size << ": " << got[first] << " for " << expected[first]);
    CHECK(differ == 0);
    // The same stage run by a number type that has no compiled blocks runs the instructions.
    CHECK(same(run<F>(compiled, {}), expected));
}

// A GLSL pair as a program whose float arithmetic runs compiled or interpreted.
const Program& program_of(const std::string& name, const std::string& fragment, interpreter::GlslProgram::Blocks blocks) {
    frontend::CompiledProgram c = frontend::compile_glsl({name + ".frag", fragment}, std::nullopt);
    std::string vertex = c.vertex.text;
    auto program = std::make_unique<interpreter::GlslProgram>(name, std::move(c), blocks);
    return add_compiled_program(std::move(program), "blocks", vertex, fragment);
}

// How many pixels of two frames differ (any NaN alike).
std::size_t differing(const Framebuffer& a, const Framebuffer& b) {
    std::size_t n = 0;
    for (std::size_t p = 0; p < a.rgba.size() / 4; ++p) {
        bool differs = false;
        for (std::size_t c = 0; c < 4; ++c) differs = differs || !same_bits(a.rgba[p * 4 + c], b.rgba[p * 4 + c]);
        n += differs;
    }
    return n;
}

}  // namespace

TEST_CASE("a compiled block computes every operation it takes to the interpreter's bits, masked and not",
          "[interpreter][blocks]") {
    compare_operations<Pixels<float, jit::kWidths[0]>>();
    compare_operations<Pixels<float, jit::kWidths[1]>>();
}

TEST_CASE("blocks in loops keep what the loop reads when it goes round, and break and discard mask their writes",
          "[interpreter][blocks]") {
    const char* const fragment = R"(#version 120
varying vec2 st;
void main() {
    vec2 p = st * 3.0 - 1.5;
    vec2 z = vec2(0.0);
    float t = 0.0;
    for (int i = 0; i < 24; ++i) {
        t = t * 0.5 + p.x * p.y;
        z = vec2(z.x * z.x - z.y * z.y, 2.0 * z.x * z.y) + p;
        if (dot(z, z) > 4.0) break;
        p = p * 1.01 + vec2(t, 0.25) * 0.001;
    }
    if (fract(t * 7.0) < 0.1) discard;
    gl_FragColor = vec4(fract(z * 0.5), fract(t), 1.0);
}
)";
    using Blocks = interpreter::GlslProgram::Blocks;
    const Program& compiled = program_of("loop blocks", fragment, Blocks::Compiled);
    const Program& interpreted = program_of("loop instructions", fragment, Blocks::Interpreted);
    CHECK(static_cast<const interpreter::GlslProgram&>(compiled).runs_compiled_blocks());
    CHECK_FALSE(static_cast<const interpreter::GlslProgram&>(interpreted).runs_compiled_blocks());
    Scene scene = load_scene(test::kPlane);
    for (const test::ShadingMode& m : test::kShadingModes) {
        FrameRequest r;
        r.width = 64, r.height = 48;
        r.shading.derivatives = m.derivatives;
        r.shading.precision = m.precision;
        r.shader_override = compiled.info().name;
        const Framebuffer got = render_frame(scene, r);
        r.shader_override = interpreted.info().name;
        const Framebuffer expected = render_frame(scene, r);
        INFO(m.what);
        CHECK(differing(got, expected) == 0);
    }
}

TEST_CASE("every catalogue shader's GLSL renders the same with its float arithmetic compiled or interpreted",
          "[interpreter][blocks]") {
    std::vector<Scene> scenes;
    for (const auto& f : {test::kPlane, test::kLawlorPlane, test::kSphere, test::kProcTexGenSpheres}) scenes.push_back(load_scene(f));
    using Blocks = interpreter::GlslProgram::Blocks;
    int compared = 0, with_blocks = 0;
    const ProgramList translations = catalogue();  // before this test adds its own
    for (const Program* translation : translations) {
        const std::string name(translation->info().name);
        const Scene* scene = nullptr;
        for (const Scene& s : scenes) {
            if (!scene && binds_samplers(s, translation->info())) scene = &s;
        }
        if (!scene) continue;
        const std::string fragment = glsl_source(*translation, false), vertex = glsl_source(*translation, true);
        const auto make = [&](Blocks blocks, const char* how) -> const Program& {
            frontend::CompiledProgram c = frontend::compile_glsl({name + ".frag", fragment}, frontend::GlslSource{name + ".vert", vertex});
            auto p = std::make_unique<interpreter::GlslProgram>(std::string(how) + " " + name, std::move(c), blocks);
            return add_compiled_program(std::move(p), "blocks", vertex, fragment);
        };
        const Program& compiled = make(Blocks::Compiled, "blocks compiled");
        const Program& interpreted = make(Blocks::Interpreted, "blocks interpreted");
        with_blocks += static_cast<const interpreter::GlslProgram&>(compiled).runs_compiled_blocks();
        for (const test::ShadingMode& m : test::kShadingModes) {
            if (m.precision == Precision::Double || m.derivatives == Derivatives::Analytic) continue;  // no blocks there
            FrameRequest r;
            r.width = 48, r.height = 32;
            r.shading.derivatives = m.derivatives;
            r.shading.precision = m.precision;
            Scene s = *scene;
            r.shader_override = compiled.info().name;
            const Framebuffer got = render_frame(s, r);
            r.shader_override = interpreted.info().name;
            const Framebuffer expected = render_frame(s, r);
            const std::size_t d = differing(got, expected);
            INFO(name << " on " << scene->file.filename().string() << ", " << m.what << ": " << d << " pixels differ");
            CHECK(d == 0);
            ++compared;
        }
    }
    CHECK(compared > 300);
    CHECK(with_blocks > 100);  // nearly every shader has a straight run of float arithmetic
}
