// The compiled blocks (interpreter/native_blocks.h, jit/compiled_blocks.h) compute the bits the
// interpreter computes: every operation they take, on values that reach each rule's edge cases,
// in every lane, masked and not; loops that read a block's results when they go round; and every
// catalogue shader's GLSL, image against image, under each rule.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <optional>
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
#include "tests/translate/same_pixels.h"

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
constexpr std::uint32_t kInputs = 8;     // float registers 0..7, each lane a value of kValues
constexpr std::uint32_t kIntInputs = 4;  // int registers 0..3, each lane a value of kInts

ir::Instr op(ir::Op o, std::uint32_t d, std::uint32_t a = 0, std::uint32_t b = 0, std::uint32_t c = 0, std::uint8_t n = 1) {
    ir::Instr in{.op = o};
    in.d = d, in.a = a, in.b = b, in.c = c, in.n = n;
    return in;
}

// Ints at the edges of wrapping arithmetic and of float's 24-bit significand.
const std::int32_t kInts[] = {0, 1, -1, 7, -8, 16777217, -16777219, 2147483647, -2147483647 - 1, 123456789, 65536, -3};

// A stage that runs every compilable operation, on one component and on four, with operands
// that step and that stay, inside a branch that only some lanes take (their writes masked) and
// after it; each result is an output, so the blocks store it. Float registers 0..7 and int
// registers 0..3 are its inputs.
ir::Stage every_operation() {
    using ir::Bank, ir::Op;
    ir::Stage s;
    s.serial = std::uint64_t{1} << 41;
    std::vector<ir::Instr> code;
    std::array<std::uint32_t, ir::kBanks> next{kInputs, kIntInputs, 0, 1};  // bool 0: the branch's condition
    const auto result = [&](Bank bank, std::uint32_t n) {
        const std::uint32_t r = next[std::size_t(bank)];
        next[std::size_t(bank)] += n;
        for (std::uint32_t k = 0; k < n; ++k) s.outputs.push_back({ir::Source::Color, 0, 0, bank, r + k});
        return r;
    };
    const auto in_bank = [](ir::Instr in, Bank bank) {
        in.bank = bank;
        return in;
    };
    const Op unary[] = {Op::Mov, Op::FNeg, Op::FAbs, Op::FSign, Op::FFloor, Op::FCeil, Op::FTrunc, Op::FRoundEven,
                        Op::FFract, Op::FSqrt, Op::FInverseSqrt};
    const Op binary[] = {Op::FAdd, Op::FSub, Op::FMul, Op::FDiv, Op::FMod, Op::FMin, Op::FMax, Op::FStep};
    const Op ternary[] = {Op::FClamp, Op::FMix, Op::FSmoothStep};
    const Op comparisons[] = {Op::FLess, Op::FLessEqual, Op::FGreater, Op::FGreaterEqual, Op::FEqual, Op::FNotEqual};
    const Op logic[] = {Op::BAnd, Op::BOr, Op::BXor, Op::BEqual, Op::BNotEqual};
    const Op integers[] = {Op::IAdd, Op::ISub, Op::IMul, Op::ILess, Op::ILessEqual, Op::IGreater, Op::IGreaterEqual,
                           Op::IEqual, Op::INotEqual};
    const auto operations = [&](bool masked) {
        const std::size_t start = code.size();
        for (std::uint8_t n : {std::uint8_t(1), std::uint8_t(4)}) {
            for (std::uint32_t shift = 0; shift < 3; ++shift) {
                const std::uint32_t a = shift, b = (shift + 3) % 4, c = (shift + 1) % 4;  // inputs 0..3 as vectors
                for (Op o : unary) code.push_back(op(o, result(Bank::Float, n), a, 0, 0, n));
                for (Op o : binary) code.push_back(op(o, result(Bank::Float, n), a, b + 4 * (shift == 2), 0, n));
                for (Op o : ternary) code.push_back(op(o, result(Bank::Float, n), a, b, c, n));
                ir::Instr broadcast = op(Op::FMul, result(Bank::Float, n), a, 7, 0, n);
                broadcast.broadcast = 2;  // v * s
                code.push_back(broadcast);
                // Comparisons into bools, the bools' logic, and selects by them.
                std::vector<std::uint32_t> truths;
                for (Op o : comparisons) {
                    truths.push_back(result(Bank::Bool, n));
                    code.push_back(op(o, truths.back(), a, b, 0, n));
                }
                for (Op o : {Op::FIsNan, Op::FIsInf}) {
                    truths.push_back(result(Bank::Bool, n));
                    code.push_back(op(o, truths.back(), b, 0, 0, n));
                }
                for (std::size_t t = 0; t + 1 < truths.size(); ++t) {
                    const Op o = logic[t % std::size(logic)];
                    code.push_back(in_bank(op(o, result(Bank::Bool, n), truths[t], truths[t + 1], 0, n), Bank::Bool));
                }
                code.push_back(in_bank(op(Op::BNot, result(Bank::Bool, n), truths[0], 0, 0, n), Bank::Bool));
                code.push_back(op(Op::Select, result(Bank::Float, n), truths[shift], a, c, n));
                code.push_back(op(Op::FMixBool, result(Bank::Float, n), a, b, truths[shift + 1], n));
                code.push_back(op(Op::FloatFromBool, result(Bank::Float, n), truths[shift + 2], 0, 0, n));
                code.push_back(in_bank(op(Op::Mov, result(Bank::Bool, n), truths[shift + 3], 0, 0, n), Bank::Bool));
                code.push_back(
                    in_bank(op(Op::Select, result(Bank::Bool, n), truths[0], truths[1], truths[2], n), Bank::Bool));
                if (n == 4) {  // ints 0..3 as a vector
                    for (Op o : integers) {  // over ints 0..3 and shift..shift+3 (inputs, and results past 3)
                        const bool compares = o >= Op::ILess;
                        code.push_back(in_bank(op(o, result(compares ? Bank::Bool : Bank::Int, n), 0, shift, 0, n), Bank::Int));
                    }
                    code.push_back(op(Op::FloatFromInt, result(Bank::Float, n), shift, 0, 0, n));
                    code.push_back(in_bank(op(Op::Mov, result(Bank::Int, n), shift, 0, 0, n), Bank::Int));
                    code.push_back(in_bank(op(Op::Select, result(Bank::Int, n), truths[0], 0, shift, n), Bank::Int));
                }
            }
        }
        code.push_back(op(Op::Dot, result(Bank::Float, 1), 0, 3, 0, 4));
        code.push_back(op(Op::Dot, result(Bank::Float, 1), 1, 2, 0, 3));
        code.push_back(op(Op::Length, result(Bank::Float, 1), 4, 0, 0, 2));
        // Results read again in the block, and a vector whose components read the ones before.
        const std::uint32_t t = result(Bank::Float, 4);
        code.push_back(op(Op::FMul, t, 0, 4, 0, 4));
        code.push_back(op(Op::FAdd, t + 1, t, 5, 0, 3));
        code.push_back(op(Op::FFloor, result(Bank::Float, 4), t, 0, 0, 4));
        if (masked) {
            for (std::size_t k = start; k < code.size(); ++k) code[k].masked = true;
        }
    };
    code.push_back(in_bank(op(Op::FLess, 0, 6, 2), Bank::Bool));  // the lanes whose input 6 is under input 2
    code.push_back(op(Op::If, 0, 0));
    operations(true);
    code.push_back(op(Op::EndIf, 0));
    code[1].target = std::uint32_t(code.size() - 1);
    operations(false);
    s.code = std::move(code);
    s.registers = next;
    return s;
}

// Which value input register `reg` holds in lane l: every fourth lane the same in all registers,
// so that comparisons meet equal operands; the others different in each.
std::size_t value_index(int l, std::uint32_t reg, std::size_t values) {
    return l % 4 == 0 ? std::size_t(l / 4) % values : (std::size_t(l) * 7 + reg * 5) % values;
}

// Every register after one run of `stage` in F, the inputs set lane by lane.
struct Banks {
    std::vector<float> floats;
    std::vector<std::int32_t> words;  // ints, then bools
};
template <class F>
Banks run(const ir::Stage& stage, std::span<const jit::BlockCode> native) {
    ir::validate(stage, 0);
    interpreter::Registers<F> r;
    r.prepare(stage);
    alignas(64) float lanes[F::size];
    alignas(64) std::int32_t words[F::size];
    for (std::uint32_t reg = 0; reg < kInputs; ++reg) {
        for (int l = 0; l < F::size; ++l) lanes[l] = kValues[value_index(l, reg, std::size(kValues))];
        r.f[reg] = F::load(lanes);
    }
    for (std::uint32_t reg = 0; reg < kIntInputs; ++reg) {
        for (int l = 0; l < F::size; ++l) words[l] = kInts[value_index(l, reg, std::size(kInts))];
        static_assert(sizeof(r.i[reg]) == sizeof words);
        std::memcpy(&r.i[reg], words, sizeof words);
    }
    interpreter::Executor<F>::run(stage, r, interpreter::TextureSlots{}, native);
    Banks out;
    for (std::size_t reg = 0; reg < r.f.size(); ++reg) {
        r.f[reg].store(lanes);
        out.floats.insert(out.floats.end(), lanes, lanes + F::size);
    }
    const auto words_of = [&](const auto& bank) {
        static_assert(sizeof(bank[0]) == sizeof words);
        for (std::size_t reg = 0; reg < bank.size(); ++reg) {
            std::memcpy(words, &bank[reg], sizeof words);
            out.words.insert(out.words.end(), words, words + F::size);
        }
    };
    words_of(r.i);
    words_of(r.b);
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
    const Banks expected = run<F>(interpreted, {}), got = run<F>(compiled, blocks->code(F::size));
    REQUIRE(got.floats.size() == expected.floats.size());
    std::size_t differ = 0, first = 0;
    for (std::size_t i = 0; i < got.floats.size(); ++i) {
        if (!same_bits(got.floats[i], expected.floats[i]) && differ++ == 0) first = i;
    }
    INFO(F::size << " lanes: " << differ << " floats differ, the first in register " << first / F::size << ", lane "
                 << first % F::size << ": " << got.floats[first] << " for " << expected.floats[first]);
    CHECK(differ == 0);
    CHECK(got.words == expected.words);
    // The same stage run by a number type that has no compiled blocks runs the instructions.
    const Banks instructions = run<F>(compiled, {});
    CHECK(same(instructions.floats, expected.floats));
    CHECK(instructions.words == expected.words);
}

// A GLSL pair (the vertex shader written for the fragment one where none is given) as a program
// whose float arithmetic runs compiled or interpreted.
const Program& program_of(const std::string& name, const std::string& fragment, interpreter::GlslProgram::Blocks blocks,
                          const std::optional<std::string>& vertex = std::nullopt) {
    std::optional<frontend::GlslSource> vert;
    if (vertex) vert = frontend::GlslSource{name + ".vert", *vertex};
    frontend::CompiledProgram c = frontend::compile_glsl({name + ".frag", fragment}, vert);
    std::string vertex_text = c.vertex.text;
    auto program = std::make_unique<interpreter::GlslProgram>(name, std::move(c), blocks);
    return add_compiled_program(std::move(program), "blocks", vertex_text, fragment);
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
    test::check_same_pixels(scene, interpreted, compiled, "a loop with break and discard");
}

TEST_CASE("every catalogue shader's GLSL renders the same with its float arithmetic compiled or interpreted",
          "[interpreter][blocks]") {
    std::vector<Scene> scenes;
    for (const auto& f : {test::kPlane, test::kLawlorPlane, test::kSphere, test::kProcTexGenSpheres}) scenes.push_back(load_scene(f));
    using Blocks = interpreter::GlslProgram::Blocks;
    int compared = 0, with_blocks = 0;
    const ProgramList translations = catalogue();  // before this test adds its own
    for (const Program* translation : translations) {
        if (dynamic_cast<const interpreter::GlslProgram*>(translation)) continue;  // another test's, run from GLSL
        const std::string name(translation->info().name);
        const Scene* scene = nullptr;
        for (const Scene& s : scenes) {
            if (!scene && binds_samplers(s, translation->info())) scene = &s;
        }
        if (!scene) continue;
        const std::string fragment = glsl_source(*translation, false), vertex = glsl_source(*translation, true);
        const Program& compiled = program_of("blocks compiled " + name, fragment, Blocks::Compiled, vertex);
        const Program& interpreted = program_of("blocks interpreted " + name, fragment, Blocks::Interpreted, vertex);
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
            const std::size_t d = test::differing_pixels(got, expected);
            INFO(name << " on " << scene->file.filename().string() << ", " << m.what << ": " << d << " pixels differ");
            CHECK(d == 0);
            ++compared;
        }
    }
    CHECK(compared > 300);
    CHECK(with_blocks > 100);  // nearly every shader has a straight run of float arithmetic
}

TEST_CASE("a block stores what the operations after it read: one that then writes it, an indexed store's other elements",
          "[interpreter][blocks]") {
    using ir::Op;
    ir::Stage interpreted;
    interpreted.serial = std::uint64_t{1} << 43;
    interpreted.registers = {kInputs + 2, kIntInputs, 0, 0};
    const std::uint32_t x = kInputs, y = kInputs + 1;
    interpreted.code = {op(Op::FMul, x, 0, 1), op(Op::FAdd, x, x, 2), op(Op::FExp, y, 3), op(Op::FMul, x, x, 4)};
    for (std::uint32_t r : {x, y}) interpreted.outputs.push_back({ir::Source::Color, 0, 0, ir::Bank::Float, r});
    // An array whose elements a block writes, then an indexed store writes one of in each lane.
    ir::Stage array = interpreted;
    const std::uint32_t elements = kInputs;
    ir::Instr store = op(Op::StoreIndexed, elements, 5, 0);
    store.count = 4, store.c = 1;
    array.registers = {kInputs + 5, kIntInputs, 0, 0};
    array.code = {op(Op::FMul, elements, 0, 4, 0, 4), op(Op::FAdd, elements + 4, elements, 1), store};
    array.outputs.clear();
    for (std::uint32_t r = elements; r < elements + 5; ++r) array.outputs.push_back({ir::Source::Color, 0, 0, ir::Bank::Float, r});
    for (const ir::Stage& given : {interpreted, array}) {
        ir::Stage compiled = given;
        const std::unique_ptr<jit::CompiledBlocks> blocks = interpreter::compile_blocks(compiled);
        REQUIRE(blocks);
        REQUIRE(compiled.code.front().op == Op::Native);
        using F = Pixels<float, jit::kWidths[0]>;
        CHECK(same(run<F>(compiled, blocks->code(F::size)).floats, run<F>(given, {}).floats));
    }
}

TEST_CASE("a long run is cut into blocks, and a huge stage compiles only its first instructions",
          "[interpreter][blocks]") {
    ir::Stage interpreted;
    interpreted.serial = std::uint64_t{1} << 42;
    interpreted.registers = {kInputs + 2, kIntInputs, 0, 0};
    const std::uint32_t sum = kInputs, other = kInputs + 1;
    interpreted.code.push_back(op(ir::Op::Mov, sum, 0));
    for (std::uint32_t k = 0; k < interpreter::kMostCompiled + 900; ++k) {
        interpreted.code.push_back(op(k % 3 ? ir::Op::FAdd : ir::Op::FMul, k % 2 ? sum : other, sum, 1 + k % 6));
    }
    for (std::uint32_t r : {sum, other}) interpreted.outputs.push_back({ir::Source::Color, 0, 0, ir::Bank::Float, r});
    ir::Stage compiled = interpreted;
    const std::unique_ptr<jit::CompiledBlocks> blocks = interpreter::compile_blocks(compiled);
    REQUIRE(blocks);
    std::vector<std::uint32_t> lengths;
    for (std::size_t k = 0; k < compiled.code.size(); ++k) {
        if (compiled.code[k].op == ir::Op::Native) lengths.push_back(compiled.code[k].target - std::uint32_t(k) - 1);
    }
    CHECK(lengths == std::vector<std::uint32_t>(interpreter::kMostCompiled / interpreter::kLongestBlock, interpreter::kLongestBlock));
    using F = Pixels<float, jit::kWidths[1]>;
    const Banks expected = run<F>(interpreted, {}), got = run<F>(compiled, blocks->code(F::size));
    CHECK(same(got.floats, expected.floats));
}
