#include "frontend/ir_operands.h"

#include <vector>

namespace qs::ir {

const char* name(Op op) {
    static constexpr const char* names[] = {
#define QS_IR_NAME(n) #n,
        QS_IR_OPERATIONS(QS_IR_NAME)
#undef QS_IR_NAME
    };
    return names[std::size_t(op)];
}

bool component_wise(Op op) {
    switch (op) {
        case Op::Mov: case Op::Select: case Op::FMixBool: case Op::FLdexp: case Op::FIsNan: case Op::FIsInf:
            return true;
        case Op::FModf: case Op::FFrexp: case Op::IAddCarry: case Op::ISubBorrow: case Op::IMulExtended:
            return false;  // two results
        case Op::IBitfieldInsert: return false;  // c spans two registers
        case Op::IBitfieldExtract: case Op::IBitfieldReverse: case Op::IBitCount: case Op::IFindLsb: case Op::IFindMsb:
            return true;
        default:
            return (op >= Op::FNeg && op <= Op::FNotEqual) || (op >= Op::INeg && op <= Op::INotEqual) ||
                   (op >= Op::BNot && op <= Op::UintBitsToFloat);
    }
}

namespace {

// The operands of `in`, a component-wise operation's for one component.
Operands single_component_operands(const Instr& in) {
    Operands o;
    const Bank F = Bank::Float, I = Bank::Int, U = Bank::Uint, B = Bank::Bool;
    const Bank X = in.bank;  // the instruction's own bank
    const auto unary = [&](Bank d, Bank a) { o.add(Field::D, d, 1, true), o.add(Field::A, a); };
    const auto binary = [&](Bank d, Bank a) { unary(d, a), o.add(Field::B, a); };
    const auto ternary = [&](Bank d, Bank a) { binary(d, a), o.add(Field::C, a); };
    switch (in.op) {
        case Op::Mov: unary(X, X); break;
        case Op::Select: o.add(Field::D, X, 1, true), o.add(Field::A, B), o.add(Field::B, X), o.add(Field::C, X); break;
        case Op::LoadIndexed:
            // a spans the elements: (count - 1) * stride + 1 registers; c is the stride, no register.
            o.add(Field::D, X, 1, true), o.add(Field::A, X, (in.count - 1u) * in.c + 1u), o.add(Field::B, I);
            break;
        case Op::StoreIndexed:
            o.add(Field::D, X, (in.count - 1u) * in.c + 1u, true), o.add(Field::A, X), o.add(Field::B, I);
            break;
        case Op::FNeg: case Op::FAbs: case Op::FSign: case Op::FFloor: case Op::FCeil: case Op::FTrunc:
        case Op::FRoundEven: case Op::FFract: case Op::FSqrt: case Op::FInverseSqrt: case Op::FExp: case Op::FLog:
        case Op::FExp2: case Op::FLog2: case Op::FSin: case Op::FCos: case Op::FTan: case Op::FAsin: case Op::FAcos:
        case Op::FAtan: case Op::FSinh: case Op::FCosh: case Op::FTanh: case Op::FAsinh: case Op::FAcosh:
        case Op::FAtanh: case Op::FRadians: case Op::FDegrees: case Op::FDdx: case Op::FDdy: case Op::FDdxFine:
        case Op::FDdyFine: case Op::FDdxCoarse: case Op::FDdyCoarse: case Op::FFwidth: case Op::FFwidthFine:
        case Op::FFwidthCoarse:
            unary(F, F);
            break;
        case Op::FAdd: case Op::FSub: case Op::FMul: case Op::FDiv: case Op::FMod: case Op::FMin: case Op::FMax:
        case Op::FStep: case Op::FPow: case Op::FAtan2:
            binary(F, F);
            break;
        case Op::FClamp: case Op::FMix: case Op::FSmoothStep: case Op::FFma: ternary(F, F); break;
        case Op::FModf: unary(F, F), o.add(Field::C, F, 1, true); break;
        case Op::FFrexp: unary(F, F), o.add(Field::C, I, 1, true); break;
        case Op::FLdexp: unary(F, F), o.add(Field::B, I); break;
        case Op::FMixBool: binary(F, F), o.add(Field::C, B); break;
        case Op::FLess: case Op::FLessEqual: case Op::FGreater: case Op::FGreaterEqual: case Op::FEqual:
        case Op::FNotEqual:
            binary(B, F);
            break;
        case Op::FIsNan: case Op::FIsInf: unary(B, F); break;
        case Op::INeg: case Op::INot: case Op::IAbs: case Op::ISign: case Op::IBitfieldReverse: unary(X, X); break;
        case Op::IBitCount: case Op::IFindLsb: case Op::IFindMsb: unary(I, X); break;
        case Op::IAdd: case Op::ISub: case Op::IMul: case Op::IDiv: case Op::IMod: case Op::IAnd: case Op::IOr:
        case Op::IXor: case Op::IMin: case Op::IMax: case Op::IShl: case Op::IShr:
            binary(X, X);
            break;
        case Op::IClamp: ternary(X, X); break;
        case Op::ILess: case Op::ILessEqual: case Op::IGreater: case Op::IGreaterEqual: case Op::IEqual:
        case Op::INotEqual:
            binary(B, X);
            break;
        case Op::IBitfieldExtract: unary(X, X), o.add(Field::B, I), o.add(Field::C, I); break;
        case Op::IBitfieldInsert:
            // d = insert(a, b) at offset I[c], bits I[c + 1]
            binary(X, X), o.add(Field::C, I, 2);
            break;
        case Op::IAddCarry: case Op::ISubBorrow: binary(U, U), o.add(Field::C, U, 1, true); break;
        case Op::IMulExtended: binary(X, X), o.add(Field::C, X, 1, true); break;
        case Op::BNot: unary(B, B); break;
        case Op::BAnd: case Op::BOr: case Op::BXor: case Op::BEqual: case Op::BNotEqual: binary(B, B); break;
        case Op::FloatFromInt: unary(F, I); break;
        case Op::FloatFromUint: unary(F, U); break;
        case Op::FloatFromBool: unary(F, B); break;
        case Op::IntFromFloat: unary(I, F); break;
        case Op::UintFromFloat: unary(U, F); break;
        case Op::IntFromUint: unary(I, U); break;
        case Op::UintFromInt: unary(U, I); break;
        case Op::IntFromBool: unary(I, B); break;
        case Op::UintFromBool: unary(U, B); break;
        case Op::BoolFromFloat: unary(B, F); break;
        case Op::BoolFromInt: unary(B, I); break;
        case Op::BoolFromUint: unary(B, U); break;
        case Op::FloatBitsToInt: unary(I, F); break;
        case Op::FloatBitsToUint: unary(U, F); break;
        case Op::IntBitsToFloat: unary(F, I); break;
        case Op::UintBitsToFloat: unary(F, U); break;
        case Op::Dot: case Op::Distance: o.add(Field::D, F, 1, true), o.add(Field::A, F, in.n), o.add(Field::B, F, in.n); break;
        case Op::Length: o.add(Field::D, F, 1, true), o.add(Field::A, F, in.n); break;
        case Op::Normalize: o.add(Field::D, F, in.n, true), o.add(Field::A, F, in.n); break;
        case Op::Cross: o.add(Field::D, F, 3, true), o.add(Field::A, F, 3), o.add(Field::B, F, 3); break;
        case Op::Reflect: o.add(Field::D, F, in.n, true), o.add(Field::A, F, in.n), o.add(Field::B, F, in.n); break;
        case Op::Refract:
            o.add(Field::D, F, in.n, true), o.add(Field::A, F, in.n), o.add(Field::B, F, in.n), o.add(Field::C, F);
            break;
        case Op::FaceForward:
            o.add(Field::D, F, in.n, true), o.add(Field::A, F, in.n), o.add(Field::B, F, in.n), o.add(Field::C, F, in.n);
            break;
        case Op::MatTimesVec:
            o.add(Field::D, F, in.m, true), o.add(Field::A, F, std::uint32_t(in.n) * in.m), o.add(Field::B, F, in.n);
            break;
        case Op::VecTimesMat:
            o.add(Field::D, F, in.n, true), o.add(Field::A, F, in.m), o.add(Field::B, F, std::uint32_t(in.n) * in.m);
            break;
        case Op::MatTimesMat:
            o.add(Field::D, F, std::uint32_t(in.n) * in.m, true), o.add(Field::A, F, std::uint32_t(in.count) * in.m),
                o.add(Field::B, F, std::uint32_t(in.n) * in.count);
            break;
        case Op::Determinant: o.add(Field::D, F, 1, true), o.add(Field::A, F, std::uint32_t(in.n) * in.n); break;
        case Op::Inverse: o.add(Field::D, F, std::uint32_t(in.n) * in.n, true), o.add(Field::A, F, std::uint32_t(in.n) * in.n); break;
        case Op::Texture: case Op::TextureBias: case Op::TextureLod: case Op::TextureGrad: case Op::TextureOffset:
        case Op::TextureBiasOffset: case Op::TextureLodOffset: case Op::TextureGradOffset: {
            // a shadow sampler's (m = 4): the reference value after the coordinates, one result
            const bool shadow = in.m == 4;
            o.add(Field::D, F, shadow ? 1 : 4, true), o.add(Field::A, F, in.n + (shadow ? 1u : 0u));
            if (in.op == Op::TextureBias || in.op == Op::TextureLod || in.op == Op::TextureBiasOffset ||
                in.op == Op::TextureLodOffset) {
                o.add(Field::B, F);
            }
            if (in.op == Op::TextureGrad || in.op == Op::TextureGradOffset) o.add(Field::B, F, 2u * in.n);
            if (in.op == Op::TextureOffset || in.op == Op::TextureBiasOffset || in.op == Op::TextureLodOffset ||
                in.op == Op::TextureGradOffset) {
                o.add(Field::C, I, in.n);
            }
            break;
        }
        case Op::TexelFetch: o.add(Field::D, F, 4, true), o.add(Field::A, I, in.n), o.add(Field::B, I); break;
        case Op::TexelFetchOffset:
            o.add(Field::D, F, 4, true), o.add(Field::A, I, in.n), o.add(Field::B, I), o.add(Field::C, I, in.n);
            break;
        case Op::TextureSize: o.add(Field::D, I, in.n, true), o.add(Field::B, I); break;
        case Op::TextureGather:
            o.add(Field::D, F, 4, true), o.add(Field::A, F, in.n);
            if (in.m == 4) o.add(Field::B, F);
            break;
        case Op::TextureGatherOffset:
            o.add(Field::D, F, 4, true), o.add(Field::A, F, 2), o.add(Field::C, I, 2);
            if (in.m == 4) o.add(Field::B, F);
            break;
        case Op::TextureQueryLod: o.add(Field::D, F, 2, true), o.add(Field::A, F, in.n); break;
        case Op::TextureQueryLevels: o.add(Field::D, I, 1, true); break;
        case Op::If: case Op::BreakUnless: o.add(Field::A, B); break;
        case Op::Else: case Op::EndIf: case Op::LoopBegin: case Op::LoopContinue: case Op::LoopEnd: case Op::Break:
        case Op::Continue: case Op::SwitchBegin: case Op::SwitchEnd: case Op::CallBegin: case Op::CallEnd:
        case Op::Return: case Op::Discard: case Op::Native:
            break;
    }
    return o;
}

bool is_texture(Op op) {
    switch (op) {
        case Op::Texture: case Op::TextureBias: case Op::TextureLod: case Op::TextureGrad: case Op::TextureOffset:
        case Op::TextureBiasOffset: case Op::TextureLodOffset: case Op::TextureGradOffset: case Op::TexelFetch:
        case Op::TexelFetchOffset: case Op::TextureSize: case Op::TextureGather: case Op::TextureGatherOffset:
        case Op::TextureQueryLod: case Op::TextureQueryLevels:
            return true;
        default: return false;
    }
}

}  // namespace

Operands operands(const Instr& in) {
    Operands o = single_component_operands(in);
    if (in.n > 1 && component_wise(in.op)) {
        for (int k = 0; k < o.size; ++k) {
            Operand& x = o.list[std::size_t(k)];
            const bool one = !x.written && (in.broadcast >> (int(x.field) - int(Field::A)) & 1);
            x.span = one ? 1 : in.n;
        }
    }
    return o;
}

void validate(const Stage& stage, int samplers) {
    const auto fail = [&](std::size_t at, const std::string& why) {
        const Instr& in = stage.code[at];
        throw std::logic_error("GLSL interpreter: instruction " + std::to_string(at) + " (" + name(in.op) + ", GLSL line " +
                               std::to_string(in.line) + "): " + why);
    };
    std::vector<Op> open;  // the control flow markers not yet closed
    for (std::size_t at = 0; at < stage.code.size(); ++at) {
        const Instr& in = stage.code[at];
        if (std::size_t(in.op) > std::size_t(Op::Native)) fail(at, "unknown operation");
        if (in.op == Op::Native) {
            if (in.target <= at || in.target > stage.code.size()) fail(at, "a compiled block outside the code");
            for (std::size_t k = at + 1; k < in.target; ++k) {
                if (stage.code[k].op >= Op::If) fail(at, "control flow in a compiled block");
            }
        }
        if ((in.op == Op::LoadIndexed || in.op == Op::StoreIndexed) && (in.count == 0 || in.c == 0)) {
            fail(at, "an indexed access of no elements");
        }
        for (const Operand& op : operands(in)) {
            const std::uint64_t first = field(in, op.field), last = first + op.span;
            if (op.span == 0 || last > stage.registers[std::size_t(op.bank)]) fail(at, "a register outside the stage's");
        }
        if (in.broadcast != 0 && !component_wise(in.op)) {
            fail(at, "a broadcast operand of an operation that is not component-wise");
        }
        if (is_texture(in.op) && (int(in.count) >= samplers || in.n < 1 || in.n > 3)) fail(at, "no such sampler");
        // a cube map's gather takes a direction; a shadow sampler's compares (channel 4)
        if (in.op == Op::TextureGather && ((in.n != 2 && in.n != 3) || in.m > 4)) {
            fail(at, "a gather of no such channel");
        }
        if (in.op == Op::TextureGatherOffset && (in.n != 2 || in.m > 4)) fail(at, "a gather of no such channel");
        switch (in.op) {
            case Op::If: case Op::LoopBegin: case Op::SwitchBegin: case Op::CallBegin: open.push_back(in.op); break;
            case Op::Else:
                if (open.empty() || open.back() != Op::If) fail(at, "else without if");
                open.back() = Op::Else;
                break;
            case Op::EndIf:
                if (open.empty() || (open.back() != Op::If && open.back() != Op::Else)) fail(at, "endif without if");
                open.pop_back();
                break;
            case Op::LoopEnd:
                if (open.empty() || open.back() != Op::LoopBegin) fail(at, "loop end without loop");
                open.pop_back();
                break;
            case Op::SwitchEnd:
                if (open.empty() || open.back() != Op::SwitchBegin) fail(at, "switch end without switch");
                open.pop_back();
                break;
            case Op::CallEnd:
                if (open.empty() || open.back() != Op::CallBegin) fail(at, "call end without call");
                open.pop_back();
                break;
            case Op::LoopContinue: case Op::BreakUnless: case Op::Continue: {
                bool in_loop = false;
                for (Op o : open) in_loop = in_loop || o == Op::LoopBegin;
                if (!in_loop) fail(at, "continue or loop condition outside a loop");
                break;
            }
            case Op::Break: {
                bool in_loop = false;
                for (Op o : open) in_loop = in_loop || o == Op::LoopBegin || o == Op::SwitchBegin;
                if (!in_loop) fail(at, "break outside a loop or switch");
                break;
            }
            default: break;
        }
        if (jumps(in.op) && in.target >= stage.code.size()) fail(at, "a jump outside the code");
    }
    if (!open.empty()) throw std::logic_error("GLSL interpreter: control flow left open at the end of the stage");
    for (const Binding& b : stage.inputs) {
        if (b.reg >= stage.registers[std::size_t(b.bank)]) throw std::logic_error("GLSL interpreter: an input outside the registers");
    }
    for (const Binding& b : stage.outputs) {
        if (b.reg >= stage.registers[std::size_t(b.bank)]) throw std::logic_error("GLSL interpreter: an output outside the registers");
    }
    for (const Constant& c : stage.constants) {
        if (c.reg >= stage.registers[std::size_t(c.bank)]) throw std::logic_error("GLSL interpreter: a constant outside the registers");
    }
}

}  // namespace qs::ir
