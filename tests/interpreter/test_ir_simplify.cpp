// The rewrites that leave the interpreter fewer operations to dispatch (frontend/ir_simplify.h)
// change no value a stage computes: each stage here runs before and after them.

#include <catch2/catch.hpp>

#include <vector>

#include "frontend/compile.h"
#include "frontend/ir_operands.h"
#include "frontend/ir_simplify.h"
#include "interpreter/executor_run.h"

using namespace qs;

namespace {

ir::Instr op(ir::Op o, std::uint32_t d = 0, std::uint32_t a = 0, std::uint32_t b = 0) {
    ir::Instr in{.op = o};
    in.d = d, in.a = a, in.b = b;
    return in;
}

// The float registers of `stage` after one run in float.
std::vector<float> run(const ir::Stage& stage) {
    ir::validate(stage, 0);
    interpreter::Registers<float> r;
    r.prepare(stage);
    interpreter::Executor<float>::run(stage, r, interpreter::TextureSlots{});
    return std::vector<float>(r.f.data(), r.f.data() + r.f.size());
}

ir::Stage stage_of(std::vector<ir::Instr> code) {
    static std::uint64_t serial = std::uint64_t{1} << 40;
    ir::Stage s;
    s.serial = ++serial;
    s.registers = {16, 0, 0, 1};
    const float values[] = {1.0f, 2.0f, 3.0f, 10.0f};
    for (std::uint32_t k = 0; k < 4; ++k)
        s.constants.push_back({ir::Bank::Float, k, std::bit_cast<std::uint32_t>(values[k])});
    s.constants.push_back({ir::Bank::Bool, 0, 1u});
    s.code = std::move(code);
    return s;
}

}  // namespace

TEST_CASE("runs of a component-wise operation join into one, computing what the operations computed one by one",
          "[interpreter][ir]") {
    using ir::Op;
    const ir::Stage given = stage_of({
        op(Op::FAdd, 4, 0, 3), op(Op::FAdd, 5, 1, 3), op(Op::FAdd, 6, 2, 3),  // vec3 + float
        op(Op::Mov, 7, 3),
        // each component reads the one before it: in order, as one by one
        op(Op::FAdd, 8, 7, 0), op(Op::FAdd, 9, 8, 0), op(Op::FAdd, 10, 9, 0), op(Op::FMul, 11, 0, 1),
        op(Op::FMul, 12, 2, 1),  // a steps by 2: not a run
    });
    ir::Stage joined = given;
    frontend::join_component_runs(joined);
    REQUIRE(joined.code.size() == 5);
    CHECK(joined.code[0].n == 3);
    CHECK(joined.code[0].broadcast == 0b110);  // b and c stay (c is not read)
    CHECK(joined.code[2].n == 3);
    CHECK(joined.code[3].n == 1);
    CHECK(joined.code[4].n == 1);
    const std::vector<float> expected = run(given), got = run(joined);
    CHECK(got == expected);
    CHECK(got[10] == 13.0f);
}

TEST_CASE("the markers of a function that sets no lanes aside are dropped, the others kept", "[interpreter][ir]") {
    using ir::Op;
    ir::Instr branch = op(Op::If, 0, 0);
    branch.target = 7;  // its EndIf
    ir::Instr variable = op(Op::FAdd, 5, 0, 1);
    variable.masked = true;
    const ir::Stage given = stage_of({
        op(Op::CallBegin), op(Op::FAdd, 4, 0, 1), op(Op::Return), op(Op::CallEnd),  // returns at its end only
        op(Op::CallBegin), branch, op(Op::Return), op(Op::EndIf), variable, op(Op::Return), op(Op::CallEnd),
        op(Op::FAdd, 6, 4, 5), op(Op::Return),  // main's last
    });
    ir::Stage simpler = given;
    frontend::drop_idle_calls(simpler);
    std::vector<Op> ops;
    for (const ir::Instr& in : simpler.code) ops.push_back(in.op);
    CHECK(ops ==
          std::vector<Op>{Op::FAdd, Op::CallBegin, Op::If, Op::Return, Op::EndIf, Op::FAdd, Op::CallEnd, Op::FAdd});
    CHECK(simpler.code[2].target == 4);
    const std::vector<float> expected = run(given), got = run(simpler);
    CHECK(got == expected);
    CHECK(got[4] == 3.0f);
    CHECK(got[5] == 0.0f);  // its lanes returned before it
}

TEST_CASE("a run does not reach past a jump's target, and GLSL's vector arithmetic is one operation per vector",
          "[interpreter][ir]") {
    using ir::Op;
    ir::Instr begin = op(Op::LoopBegin), end = op(Op::LoopEnd);
    begin.target = 3;
    end.target = 2;  // a jump into what would be a run
    ir::Stage split = stage_of({begin, op(Op::FAdd, 4, 0, 3), op(Op::FAdd, 5, 1, 3), end});
    frontend::join_component_runs(split);
    CHECK(split.code.size() == 4);
    CHECK(split.code[3].target == 2);
    const char* const fragment = R"(#version 120
varying vec2 st;
void main() {
    vec4 v = vec4(st, 0.25, 1.0);
    gl_FragColor = v * v.x + vec4(0.5);
}
)";
    const frontend::CompiledProgram c = frontend::compile_glsl({"vector.frag", fragment}, std::nullopt);
    int four = 0;
    for (const ir::Instr& in : c.program.fragment.code) four += in.n == 4 && (in.op == Op::FMul || in.op == Op::FAdd);
    CHECK(four == 2);  // the multiply and the add, each over the vec4
}
