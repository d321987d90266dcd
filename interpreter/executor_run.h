#pragma once
// Executor<F>::run (executor.h): included by the one .cpp per number type that instantiates it.
// The hot loop dispatches the scalar operations inline; the composite ones (vectors, matrices,
// textures, indexing) and control flow are functions of their own, so that the loop keeps its
// values in registers.

#include "interpreter/executor.h"
#include "interpreter/native_blocks.h"
#include "shading/glsl/texture_cube.h"
#include "shading/glsl/texture_queries.h"
#include "shading/glsl/texture_shadow.h"

namespace qs::interpreter {

namespace executor_detail {

template <class T, class M>
T choose(const M& m, const T& a, const T& b) {
    if constexpr (std::is_same_v<T, M> && !std::is_same_v<M, bool>) {
        return (m && a) || (!m && b);
    } else {
        return select(m, a, b);
    }
}

// The registers of each component of a component-wise operation in turn (frontend/ir.h,
// Instr::broadcast): `for (Components k(in); k.more(); k.next())`.
struct Components {
    explicit Components(const ir::Instr& in)
        : d(in.d), a(in.a), b(in.b), c(in.c), step_a(~in.broadcast & 1u), step_b(~in.broadcast >> 1 & 1u),
          step_c(~in.broadcast >> 2 & 1u), left(in.n) {}
    bool more() const { return left > 0; }
    void next() { ++d, a += step_a, b += step_b, c += step_c, --left; }
    // The operation of this component alone.
    ir::Instr of(const ir::Instr& in) const {
        ir::Instr one = in;
        one.n = 1, one.d = d, one.a = a, one.b = b, one.c = c;
        return one;
    }

    std::uint32_t d, a, b, c;

private:
    std::uint32_t step_a, step_b, step_c;
    int left;
};

// f.template operator()<N>() for N = n in 2..4.
template <class Fn>
void with_size(int n, Fn f) {
    switch (n) {
        case 2: return f.template operator()<2>();
        case 3: return f.template operator()<3>();
        case 4: return f.template operator()<4>();
        default: throw std::logic_error("GLSL interpreter: a vector or matrix of " + std::to_string(n) + " components");
    }
}

// The machine state of one run: registers, the masks of divergent control flow (llvmpipe's
// lp_exec_mask), and the loop limiters.
template <class F>
class Machine {
public:
    using I = int_t<F>;
    using U = uint_t<F>;
    using M = Bool<F>;

    Machine(const ir::Stage& stage, Registers<F>& r, const TextureSlots& textures, std::span<const jit::BlockCode> native)
        : stage_(stage), f_(r.f.data()), i_(r.i.data()), u_(r.u.data()), b_(r.b.data()), textures_(textures),
          native_(native) {
        cond_ = brk_ = cnt_ = sw_ = ret_ = exec_ = M(true);
        killed_ = M(false);
        budget_.fill(kLoopLimit);
    }

    RunResult run();

private:
    static constexpr int kVectors = std::max(1, lanes_of<F>() / kVectorLanes);
    static_assert(kVectors <= kMaxVectors);

    // Writes value to dst, keeping the lanes outside the running mask for variables.
    template <class T, class V>
    [[gnu::always_inline]] void put(const ir::Instr& in, T& dst, const V& value) {
        if (!in.masked || all_) {
            dst = value;
        } else {
            dst = choose(exec_, T(value), dst);
        }
    }
    void update() {
        exec_ = cond_ && brk_ && cnt_ && sw_ && ret_;
        all_ = all_lanes(exec_);
    }
    template <int N>
    glsl::vec<F, N> vector_at(std::uint32_t first) const {
        glsl::vec<F, N> v;
        for (int i = 0; i < N; ++i) v[i] = f_[first + std::uint32_t(i)];
        return v;
    }
    template <int C, int R>
    glsl::mat<F, C, R> matrix_at(std::uint32_t first) const {
        glsl::mat<F, C, R> m;
        for (int c = 0; c < C; ++c) {
            for (int r = 0; r < R; ++r) m[c][r] = f_[first + std::uint32_t(c * R + r)];
        }
        return m;
    }

    [[gnu::noinline]] void derivative(const ir::Instr& in);
    [[gnu::noinline]] void geometric(const ir::Instr& in);
    [[gnu::noinline]] void matrix(const ir::Instr& in);
    [[gnu::noinline]] void texture(const ir::Instr& in);
    [[gnu::noinline]] void cube_texture(const ir::Instr& in, const glsl::samplerCube& cube);
    [[gnu::noinline]] F shadow_lookup(const ir::Instr& in, const glsl::sampler2D& depth);
    [[gnu::noinline]] void indexed(const ir::Instr& in);
    [[gnu::noinline]] void integer(const ir::Instr& in);
    [[gnu::noinline]] void rare_float(const ir::Instr& in);
    // Control flow: returns the next instruction's index.
    [[gnu::noinline]] std::size_t control(const ir::Instr& in, std::size_t pc);

    const ir::Stage& stage_;
    F* const f_;
    I* const i_;
    U* const u_;
    M* const b_;
    const TextureSlots& textures_;
    const std::span<const jit::BlockCode> native_;

    M cond_, brk_, cnt_, sw_, ret_, exec_, killed_;
    bool all_ = true;  // every lane runs: writes need no select
    std::array<std::int32_t, kMaxVectors> budget_{};
    // The lanes of each of F's 8-lane vectors, made once.
    static const std::array<M, kMaxVectors>& vectors() {
        static const std::array<M, kMaxVectors> lanes = [] {
            std::array<M, kMaxVectors> v{};
            for (int k = 0; k < kVectors; ++k) v[std::size_t(k)] = lane_range<F>(k * kVectorLanes, kVectorLanes);
            return v;
        }();
        return lanes;
    }
    struct Saved {
        M a, b;
    };
    // The masks saved by the constructs a run is inside. Kept by the thread across runs, emptied
    // at each start: a batch allocating them afresh spent 6% of a noise's time in malloc and free.
    struct Stacks {
        std::vector<Saved> cond, loop, switch_, call;
        std::vector<bool> breaks_loop;  // the innermost breakable construct at the back: loop or switch
    };
    static Stacks& emptied_stacks() {
        thread_local Stacks stacks;
        stacks.cond.clear(), stacks.loop.clear(), stacks.switch_.clear(), stacks.call.clear();
        stacks.breaks_loop.clear();
        return stacks;
    }
    Stacks& stacks_ = emptied_stacks();
    std::vector<Saved>& cond_stack_ = stacks_.cond;
    std::vector<Saved>& loop_stack_ = stacks_.loop;
    std::vector<Saved>& switch_stack_ = stacks_.switch_;
    std::vector<Saved>& call_stack_ = stacks_.call;
    std::vector<bool>& breaks_loop_ = stacks_.breaks_loop;
    RunResult result_;
};

template <class F>
RunResult Machine<F>::run() {
    const ir::Instr* const code = stage_.code.data();
    const std::size_t size = stage_.code.size();
    F* const f = f_;
    M* const b = b_;
    for (std::size_t pc = 0; pc < size; ++pc) {
        const ir::Instr& in = code[pc];
#define QS_EACH for (Components k(in); k.more(); k.next())
#define QS_F1(expr) QS_EACH { const F& x = f[k.a]; put(in, f[k.d], (expr)); } break
#define QS_F2(expr) QS_EACH { const F& x = f[k.a]; const F& y = f[k.b]; put(in, f[k.d], (expr)); } break
#define QS_F3(expr) \
    QS_EACH { const F& x = f[k.a]; const F& y = f[k.b]; const F& z = f[k.c]; put(in, f[k.d], (expr)); } break
#define QS_FCMP(op) QS_EACH put(in, b[k.d], M(f[k.a] op f[k.b])); break
#define QS_B2(expr) QS_EACH { const M& x = b[k.a]; const M& y = b[k.b]; put(in, b[k.d], M(expr)); } break
        switch (in.op) {
            case ir::Op::Mov:
                switch (in.bank) {
                    case ir::Bank::Float: QS_EACH put(in, f[k.d], f[k.a]); break;
                    case ir::Bank::Int: QS_EACH put(in, i_[k.d], i_[k.a]); break;
                    case ir::Bank::Uint: QS_EACH put(in, u_[k.d], u_[k.a]); break;
                    case ir::Bank::Bool: QS_EACH put(in, b[k.d], b[k.a]); break;
                }
                break;
            case ir::Op::Select:
                switch (in.bank) {
                    case ir::Bank::Float: QS_EACH put(in, f[k.d], choose(b[k.a], f[k.b], f[k.c])); break;
                    case ir::Bank::Int: QS_EACH put(in, i_[k.d], choose(b[k.a], i_[k.b], i_[k.c])); break;
                    case ir::Bank::Uint: QS_EACH put(in, u_[k.d], choose(b[k.a], u_[k.b], u_[k.c])); break;
                    case ir::Bank::Bool: QS_EACH put(in, b[k.d], choose(b[k.a], b[k.b], b[k.c])); break;
                }
                break;
            case ir::Op::FNeg: QS_F1(-x);
            case ir::Op::FAdd: QS_F2(x + y);
            case ir::Op::FSub: QS_F2(x - y);
            case ir::Op::FMul: QS_F2(x * y);
            case ir::Op::FDiv: QS_F2(x / y);
            case ir::Op::FMod: QS_F2(glsl::mod(x, y));
            case ir::Op::FMin: QS_F2(min(x, y));
            case ir::Op::FMax: QS_F2(max(x, y));
            case ir::Op::FClamp: QS_F3(glsl::clamp(x, y, z));
            case ir::Op::FMix: QS_F3(glsl::mix(x, y, z));
            case ir::Op::FStep: QS_F2(glsl::step(x, y));
            case ir::Op::FSmoothStep: QS_F3(glsl::smoothstep(x, y, z));
            case ir::Op::FAbs: QS_F1(abs(x));
            case ir::Op::FSign: QS_F1(glsl::sign(x));
            case ir::Op::FFloor: QS_F1(floor(x));
            case ir::Op::FCeil: QS_F1(ceil(x));
            case ir::Op::FTrunc: QS_F1(trunc(x));
            case ir::Op::FRoundEven: QS_F1(roundEven(x));
            case ir::Op::FFract: QS_F1(glsl::fract(x));
            case ir::Op::FSqrt: QS_F1(sqrt(x));
            case ir::Op::FInverseSqrt: QS_F1(glsl::inversesqrt(x));
            case ir::Op::FMixBool: QS_EACH put(in, f[k.d], choose(b[k.c], f[k.b], f[k.a])); break;
            case ir::Op::FLess: QS_FCMP(<);
            case ir::Op::FLessEqual: QS_FCMP(<=);
            case ir::Op::FGreater: QS_FCMP(>);
            case ir::Op::FGreaterEqual: QS_FCMP(>=);
            case ir::Op::FEqual: QS_FCMP(==);
            case ir::Op::FNotEqual: QS_FCMP(!=);
            case ir::Op::BNot: QS_EACH put(in, b[k.d], M(!b[k.a])); break;
            case ir::Op::BAnd: QS_B2(x && y);
            case ir::Op::BOr: QS_B2(x || y);
            case ir::Op::BXor: case ir::Op::BNotEqual: QS_B2(x != y);
            case ir::Op::BEqual: QS_B2(x == y);
            case ir::Op::FloatFromInt: QS_EACH put(in, f[k.d], F(i_[k.a])); break;
            case ir::Op::FloatFromBool: QS_EACH put(in, f[k.d], F(b[k.a])); break;
            case ir::Op::IntFromFloat: QS_EACH put(in, i_[k.d], I(f[k.a])); break;
            case ir::Op::FDdx: case ir::Op::FDdy: case ir::Op::FDdxFine: case ir::Op::FDdyFine: case ir::Op::FDdxCoarse:
            case ir::Op::FDdyCoarse: case ir::Op::FFwidth: case ir::Op::FFwidthFine: case ir::Op::FFwidthCoarse:
                QS_EACH derivative(k.of(in));
                break;
            case ir::Op::Dot: {  // glsl::dot's sum, in its order, without gathering the vectors
                F sum = f[in.a] * f[in.b];
                for (std::uint32_t i = 1; i < in.n; ++i) sum = sum + f[in.a + i] * f[in.b + i];
                put(in, f[in.d], sum);
                break;
            }
            case ir::Op::Length:
                if (in.n == 1) {
                    geometric(in);
                } else {  // glsl::length: the root of the vector's dot with itself
                    F sum = f[in.a] * f[in.a];
                    for (std::uint32_t i = 1; i < in.n; ++i) sum = sum + f[in.a + i] * f[in.a + i];
                    put(in, f[in.d], sqrt(sum));
                }
                break;
            case ir::Op::Distance: case ir::Op::Normalize: case ir::Op::Reflect:
            case ir::Op::Refract: case ir::Op::FaceForward: case ir::Op::Cross:
                geometric(in);
                break;
            case ir::Op::MatTimesVec: case ir::Op::VecTimesMat: case ir::Op::MatTimesMat: case ir::Op::Determinant:
            case ir::Op::Inverse:
                matrix(in);
                break;
            case ir::Op::Texture: case ir::Op::TextureBias: case ir::Op::TextureLod: case ir::Op::TextureGrad:
            case ir::Op::TextureOffset: case ir::Op::TextureBiasOffset: case ir::Op::TextureLodOffset:
            case ir::Op::TextureGradOffset: case ir::Op::TexelFetch: case ir::Op::TexelFetchOffset:
            case ir::Op::TextureSize: case ir::Op::TextureGather: case ir::Op::TextureGatherOffset:
            case ir::Op::TextureQueryLod: case ir::Op::TextureQueryLevels:
                texture(in);
                break;
            case ir::Op::LoadIndexed: case ir::Op::StoreIndexed: indexed(in); break;
            case ir::Op::If: case ir::Op::Else: case ir::Op::EndIf: case ir::Op::LoopBegin: case ir::Op::LoopContinue:
            case ir::Op::LoopEnd: case ir::Op::Break: case ir::Op::BreakUnless: case ir::Op::Continue:
            case ir::Op::SwitchBegin: case ir::Op::SwitchEnd: case ir::Op::CallBegin: case ir::Op::CallEnd:
            case ir::Op::Return: case ir::Op::Discard:
                pc = control(in, pc);
                break;
            case ir::Op::Native:
                if constexpr (native_lanes<F> > 0) {
                    if (!native_.empty()) {
                        native_[in.count](reinterpret_cast<float*>(f), reinterpret_cast<std::int32_t*>(i_),
                                          reinterpret_cast<std::int32_t*>(b), reinterpret_cast<const std::int32_t*>(&exec_));
                        pc = in.target - 1;  // the loop's ++pc lands on target
                    }
                }
                break;
            case ir::Op::INeg: case ir::Op::IAdd: case ir::Op::ISub: case ir::Op::IMul: case ir::Op::IDiv: case ir::Op::IMod:
            case ir::Op::IAnd: case ir::Op::IOr: case ir::Op::IXor: case ir::Op::INot: case ir::Op::IShl: case ir::Op::IShr:
            case ir::Op::IMin: case ir::Op::IMax: case ir::Op::IClamp: case ir::Op::IAbs: case ir::Op::ISign:
            case ir::Op::ILess: case ir::Op::ILessEqual: case ir::Op::IGreater: case ir::Op::IGreaterEqual:
            case ir::Op::IEqual: case ir::Op::INotEqual: case ir::Op::IBitfieldExtract: case ir::Op::IBitfieldInsert:
            case ir::Op::IBitfieldReverse: case ir::Op::IBitCount: case ir::Op::IFindLsb: case ir::Op::IFindMsb:
            case ir::Op::IAddCarry: case ir::Op::ISubBorrow: case ir::Op::IMulExtended: case ir::Op::FloatFromUint:
            case ir::Op::UintFromFloat: case ir::Op::IntFromUint: case ir::Op::UintFromInt: case ir::Op::IntFromBool:
            case ir::Op::UintFromBool: case ir::Op::BoolFromFloat: case ir::Op::BoolFromInt: case ir::Op::BoolFromUint:
            case ir::Op::FloatBitsToInt: case ir::Op::FloatBitsToUint: case ir::Op::IntBitsToFloat:
            case ir::Op::UintBitsToFloat:
                QS_EACH integer(k.of(in));
                break;
            default: QS_EACH rare_float(k.of(in)); break;
        }
#undef QS_EACH
#undef QS_B2
#undef QS_F1
#undef QS_F2
#undef QS_F3
#undef QS_FCMP
    }
    result_.discarded = bits_of(killed_);
    return result_;
}

template <class F>
void Machine<F>::rare_float(const ir::Instr& in) {
    F* const f = f_;
    const F& x = f[in.a];
    switch (in.op) {
        case ir::Op::FExp: return put(in, f[in.d], exp(x));
        case ir::Op::FLog: return put(in, f[in.d], log(x));
        case ir::Op::FExp2: return put(in, f[in.d], exp2(x));
        case ir::Op::FLog2: return put(in, f[in.d], log2(x));
        case ir::Op::FPow: return put(in, f[in.d], pow(x, f[in.b]));
        case ir::Op::FSin: return put(in, f[in.d], sin(x));
        case ir::Op::FCos: return put(in, f[in.d], cos(x));
        case ir::Op::FTan: return put(in, f[in.d], tan(x));
        case ir::Op::FAsin: return put(in, f[in.d], asin(x));
        case ir::Op::FAcos: return put(in, f[in.d], acos(x));
        case ir::Op::FAtan: return put(in, f[in.d], atan(x));
        case ir::Op::FAtan2: return put(in, f[in.d], atan(x, f[in.b]));
        case ir::Op::FSinh: return put(in, f[in.d], glsl::sinh(x));
        case ir::Op::FCosh: return put(in, f[in.d], glsl::cosh(x));
        case ir::Op::FTanh: return put(in, f[in.d], glsl::tanh(x));
        case ir::Op::FAsinh: return put(in, f[in.d], glsl::asinh(x));
        case ir::Op::FAcosh: return put(in, f[in.d], glsl::acosh(x));
        case ir::Op::FAtanh: return put(in, f[in.d], glsl::atanh(x));
        case ir::Op::FRadians: return put(in, f[in.d], glsl::radians(x));
        case ir::Op::FDegrees: return put(in, f[in.d], glsl::degrees(x));
        case ir::Op::FFma: return put(in, f[in.d], glsl::fma(x, f[in.b], f[in.c]));
        case ir::Op::FModf: {
            F whole;
            const F fraction = glsl::modf(x, whole);
            put(in, f[in.d], fraction);
            f[in.c] = whole;
            return;
        }
        case ir::Op::FFrexp: {
            I e;
            const F s = glsl::frexp(x, e);
            put(in, f[in.d], s);
            i_[in.c] = e;
            return;
        }
        case ir::Op::FLdexp: return put(in, f[in.d], glsl::ldexp(x, i_[in.b]));
        case ir::Op::FIsNan: return put(in, b_[in.d], M(isnan(x)));
        case ir::Op::FIsInf: return put(in, b_[in.d], M(isinf(x)));
        default: throw std::logic_error(std::string("GLSL interpreter: operation ") + ir::name(in.op) + " has no handler");
    }
}

template <class F>
void Machine<F>::derivative(const ir::Instr& in) {
    if constexpr (has_derivatives_v<F>) {
        const F& x = f_[in.a];
        F v;
        switch (in.op) {
            case ir::Op::FDdx: v = dFdx(x); break;
            case ir::Op::FDdy: v = dFdy(x); break;
            case ir::Op::FDdxFine: v = dFdxFine(x); break;
            case ir::Op::FDdyFine: v = dFdyFine(x); break;
            case ir::Op::FDdxCoarse: v = dFdxCoarse(x); break;
            case ir::Op::FDdyCoarse: v = dFdyCoarse(x); break;
            case ir::Op::FFwidth: v = fwidth(x); break;
            case ir::Op::FFwidthFine: v = fwidthFine(x); break;
            default: v = fwidthCoarse(x); break;
        }
        put(in, f_[in.d], v);
    } else {
        (void)in;
        throw std::logic_error("GLSL interpreter: a derivative on independent pixels");
    }
}

template <class F>
void Machine<F>::integer(const ir::Instr& in) {
    // In the instruction's bank (int or uint) where the operation takes either.
    const auto run = [&](auto* R) {
        using T = std::remove_pointer_t<decltype(R)>;
        T& d = R[in.d];
        const T& a = R[in.a];
        switch (in.op) {
            case ir::Op::INeg: return put(in, d, -a);
            case ir::Op::IAdd: return put(in, d, a + R[in.b]);
            case ir::Op::ISub: return put(in, d, a - R[in.b]);
            case ir::Op::IMul: return put(in, d, a * R[in.b]);
            case ir::Op::IDiv: return put(in, d, a / R[in.b]);
            case ir::Op::IMod: return put(in, d, a % R[in.b]);
            case ir::Op::IAnd: return put(in, d, a & R[in.b]);
            case ir::Op::IOr: return put(in, d, a | R[in.b]);
            case ir::Op::IXor: return put(in, d, a ^ R[in.b]);
            case ir::Op::INot: return put(in, d, ~a);
            case ir::Op::IShl: return put(in, d, a << R[in.b]);
            case ir::Op::IShr: return put(in, d, a >> R[in.b]);
            case ir::Op::IMin: return put(in, d, min(a, R[in.b]));
            case ir::Op::IMax: return put(in, d, max(a, R[in.b]));
            case ir::Op::IClamp: return put(in, d, glsl::clamp(a, R[in.b], R[in.c]));
            case ir::Op::ILess: return put(in, b_[in.d], M(a < R[in.b]));
            case ir::Op::ILessEqual: return put(in, b_[in.d], M(a <= R[in.b]));
            case ir::Op::IGreater: return put(in, b_[in.d], M(a > R[in.b]));
            case ir::Op::IGreaterEqual: return put(in, b_[in.d], M(a >= R[in.b]));
            case ir::Op::IEqual: return put(in, b_[in.d], M(a == R[in.b]));
            case ir::Op::INotEqual: return put(in, b_[in.d], M(a != R[in.b]));
            case ir::Op::IBitfieldExtract: return put(in, d, glsl::bitfieldExtract(a, i_[in.b], i_[in.c]));
            case ir::Op::IBitfieldInsert: return put(in, d, glsl::bitfieldInsert(a, R[in.b], i_[in.c], i_[in.c + 1]));
            case ir::Op::IBitfieldReverse: return put(in, d, glsl::bitfieldReverse(a));
            case ir::Op::IBitCount: return put(in, i_[in.d], glsl::bitCount(a));
            case ir::Op::IFindLsb: return put(in, i_[in.d], glsl::findLSB(a));
            case ir::Op::IFindMsb: return put(in, i_[in.d], glsl::findMSB(a));
            case ir::Op::IMulExtended: {
                T low;
                const T high = glsl::mulExtended(a, R[in.b], low);
                put(in, d, high);
                R[in.c] = low;
                return;
            }
            default: break;
        }
        throw std::logic_error(std::string("GLSL interpreter: operation ") + ir::name(in.op) + " has no handler");
    };
    switch (in.op) {
        case ir::Op::IAbs: return put(in, i_[in.d], abs(i_[in.a]));
        case ir::Op::ISign: return put(in, i_[in.d], glsl::sign(i_[in.a]));
        case ir::Op::IAddCarry: case ir::Op::ISubBorrow: {
            U second;
            const U first = in.op == ir::Op::IAddCarry ? glsl::uaddCarry(u_[in.a], u_[in.b], second)
                                                       : glsl::usubBorrow(u_[in.a], u_[in.b], second);
            put(in, u_[in.d], first);
            u_[in.c] = second;
            return;
        }
        case ir::Op::FloatFromUint: return put(in, f_[in.d], F(u_[in.a]));
        case ir::Op::UintFromFloat: return put(in, u_[in.d], U(f_[in.a]));
        case ir::Op::IntFromUint: return put(in, i_[in.d], I(u_[in.a]));
        case ir::Op::UintFromInt: return put(in, u_[in.d], U(i_[in.a]));
        case ir::Op::IntFromBool: return put(in, i_[in.d], I(b_[in.a]));
        case ir::Op::UintFromBool: return put(in, u_[in.d], U(b_[in.a]));
        case ir::Op::BoolFromFloat: return put(in, b_[in.d], M(f_[in.a] != F(0.0f)));
        case ir::Op::BoolFromInt: return put(in, b_[in.d], M(i_[in.a] != I(0)));
        case ir::Op::BoolFromUint: return put(in, b_[in.d], M(u_[in.a] != U(0u)));
        case ir::Op::FloatBitsToInt: return put(in, i_[in.d], glsl::floatBitsToInt(f_[in.a]));
        case ir::Op::FloatBitsToUint: return put(in, u_[in.d], glsl::floatBitsToUint(f_[in.a]));
        case ir::Op::IntBitsToFloat: return put(in, f_[in.d], F(glsl::intBitsToFloat(i_[in.a])));
        case ir::Op::UintBitsToFloat: return put(in, f_[in.d], F(glsl::uintBitsToFloat(u_[in.a])));
        default: break;
    }
    if (in.bank == ir::Bank::Int) return run(i_);
    return run(u_);
}

template <class F>
void Machine<F>::geometric(const ir::Instr& in) {
    F* const f = f_;
    if (in.op == ir::Op::Cross) {
        const glsl::vec<F, 3> v = glsl::cross(vector_at<3>(in.a), vector_at<3>(in.b));
        for (int i = 0; i < 3; ++i) put(in, f[in.d + std::uint32_t(i)], v[i]);
        return;
    }
    if (in.n == 1) {  // GLSL's geometric functions of one float
        const F& x = f[in.a];
        F v;
        switch (in.op) {
            case ir::Op::Dot: v = x * f[in.b]; break;
            case ir::Op::Length: v = glsl::length(x); break;
            case ir::Op::Distance: v = glsl::length(x - f[in.b]); break;
            case ir::Op::Normalize: v = x / glsl::length(x); break;
            case ir::Op::Reflect: v = x - F(2.0f) * (f[in.b] * x * f[in.b]); break;
            case ir::Op::FaceForward: v = select(f[in.c] * f[in.b] < F(0.0f), x, -x); break;
            default: {  // refract
                const F& n = f[in.b];
                const F& eta = f[in.c];
                const F d = n * x;
                const F k = F(1.0f) - eta * (eta * (F(1.0f) - d * d));
                v = select(k < F(0.0f), F(0.0f), eta * x - (eta * d + sqrt(k)) * n);
            }
        }
        return put(in, f[in.d], v);
    }
    with_size(in.n, [&]<int N>() {
        const glsl::vec<F, N> a = vector_at<N>(in.a);
        switch (in.op) {
            case ir::Op::Dot: return put(in, f[in.d], glsl::dot(a, vector_at<N>(in.b)));
            case ir::Op::Length: return put(in, f[in.d], glsl::length(a));
            case ir::Op::Distance: return put(in, f[in.d], glsl::distance(a, vector_at<N>(in.b)));
            default: break;
        }
        glsl::vec<F, N> v;
        switch (in.op) {
            case ir::Op::Normalize: v = glsl::normalize(a); break;
            case ir::Op::Reflect: v = glsl::reflect(a, vector_at<N>(in.b)); break;
            case ir::Op::Refract: v = glsl::refract(a, vector_at<N>(in.b), f[in.c]); break;
            default: v = glsl::faceforward(a, vector_at<N>(in.b), vector_at<N>(in.c)); break;
        }
        for (int i = 0; i < N; ++i) put(in, f[in.d + std::uint32_t(i)], v[i]);
    });
}

template <class F>
void Machine<F>::matrix(const ir::Instr& in) {
    F* const f = f_;
    switch (in.op) {
        case ir::Op::MatTimesVec: case ir::Op::VecTimesMat:
            return with_size(in.n, [&]<int C>() {
                with_size(in.m, [&]<int R>() {
                    if (in.op == ir::Op::MatTimesVec) {
                        const glsl::vec<F, R> v = matrix_at<C, R>(in.a) * vector_at<C>(in.b);
                        for (int i = 0; i < R; ++i) put(in, f[in.d + std::uint32_t(i)], v[i]);
                    } else {
                        const glsl::vec<F, C> v = vector_at<R>(in.a) * matrix_at<C, R>(in.b);
                        for (int i = 0; i < C; ++i) put(in, f[in.d + std::uint32_t(i)], v[i]);
                    }
                });
            });
        case ir::Op::MatTimesMat:
            return with_size(in.count, [&]<int Kc>() {
                with_size(in.m, [&]<int R>() {
                    with_size(in.n, [&]<int C>() {
                        const glsl::mat<F, C, R> p = matrix_at<Kc, R>(in.a) * matrix_at<C, Kc>(in.b);
                        for (int c = 0; c < C; ++c) {
                            for (int i = 0; i < R; ++i) put(in, f[in.d + std::uint32_t(c * R + i)], p[c][i]);
                        }
                    });
                });
            });
        default:
            return with_size(in.n, [&]<int N>() {
                const glsl::mat<F, N, N> m = matrix_at<N, N>(in.a);
                if (in.op == ir::Op::Determinant) return put(in, f[in.d], glsl::determinant(m));
                const glsl::mat<F, N, N> v = glsl::inverse(m);
                for (int c = 0; c < N; ++c) {
                    for (int i = 0; i < N; ++i) put(in, f[in.d + std::uint32_t(c * N + i)], v[c][i]);
                }
            });
    }
}

template <class F>
void Machine<F>::texture(const ir::Instr& in) {
    const glsl::Texture& t = *textures_[in.count];
    if (in.op == ir::Op::TextureQueryLevels) {
        put(in, i_[in.d], glsl::textureQueryLevels<F>(t));
        return;
    }
    if (t.dims == glsl::kCubeDims) return cube_texture(in, static_cast<const glsl::samplerCube&>(t));
    if (in.op == ir::Op::TextureGather && in.n != 2) throw std::logic_error("a cube map's gather on a texture that is not one");
    if (in.op == ir::Op::TextureSize) {
        if (in.n == 2) {
            const glsl::ivec2<F> s = glsl::textureSize<F>(static_cast<const glsl::sampler2D&>(t), i_[in.b]);
            for (int i = 0; i < 2; ++i) put(in, i_[in.d + std::uint32_t(i)], s[i]);
        } else {
            const glsl::ivec3<F> s = glsl::textureSize<F>(static_cast<const glsl::sampler3D&>(t), i_[in.b]);
            for (int i = 0; i < 3; ++i) put(in, i_[in.d + std::uint32_t(i)], s[i]);
        }
        return;
    }
    if (in.op == ir::Op::TextureQueryLod) {
        using glsl::sampler2D, glsl::sampler3D;
        const glsl::vec2<F> q = in.n == 2 ? glsl::textureQueryLod(static_cast<const sampler2D&>(t), vector_at<2>(in.a))
                                          : glsl::textureQueryLod(static_cast<const sampler3D&>(t), vector_at<3>(in.a));
        for (int i = 0; i < 2; ++i) put(in, f_[in.d + std::uint32_t(i)], q[i]);
        return;
    }
    if (in.m == 4 && in.op != ir::Op::TextureGather && in.op != ir::Op::TextureGatherOffset) {
        put(in, f_[in.d], shadow_lookup(in, static_cast<const glsl::sampler2D&>(t)));
        return;
    }
    glsl::vec<F, 4> c;
    // The lookup on a sampler of N coordinates: each operation calls the vocabulary's function
    // of its name.
    const auto lookup = [&]<int N>(const auto& s) {
        using IV = glsl::vec<I, N>;
        const auto ints_at = [&](std::uint32_t first) {
            IV v;
            for (int i = 0; i < N; ++i) v[i] = i_[first + std::uint32_t(i)];
            return v;
        };
        if (in.op == ir::Op::TexelFetch) return glsl::texelFetch<F>(s, ints_at(in.a), i_[in.b]);
        if (in.op == ir::Op::TexelFetchOffset) return glsl::texelFetchOffset<F>(s, ints_at(in.a), i_[in.b], ints_at(in.c));
        const glsl::vec<F, N> p = vector_at<N>(in.a);
        if constexpr (N == 2) {
            if (in.op == ir::Op::TextureGather) {
                return in.m == 4 ? glsl::textureGatherCompare(s, p, f_[in.b]) : glsl::textureGather(s, p, in.m);
            }
            if (in.op == ir::Op::TextureGatherOffset) {
                return in.m == 4 ? glsl::textureGatherOffsetCompare(s, p, f_[in.b], ints_at(in.c))
                                 : glsl::textureGatherOffset(s, p, ints_at(in.c), in.m);
            }
        }
        switch (in.op) {
            case ir::Op::Texture: return glsl::texture(s, p);
            case ir::Op::TextureBias: return glsl::texture(s, p, f_[in.b]);
            case ir::Op::TextureLod: return glsl::textureLod(s, p, f_[in.b]);
            case ir::Op::TextureGrad: return glsl::textureGrad(s, p, vector_at<N>(in.b), vector_at<N>(in.b + N));
            case ir::Op::TextureOffset: return glsl::textureOffset(s, p, ints_at(in.c));
            case ir::Op::TextureBiasOffset: return glsl::textureOffset(s, p, ints_at(in.c), f_[in.b]);
            case ir::Op::TextureLodOffset: return glsl::textureLodOffset(s, p, f_[in.b], ints_at(in.c));
            default: return glsl::textureGradOffset(s, p, vector_at<N>(in.b), vector_at<N>(in.b + N), ints_at(in.c));
        }
    };
    if (in.n == 2) {
        c = lookup.template operator()<2>(static_cast<const glsl::sampler2D&>(t));
    } else {
        c = lookup.template operator()<3>(static_cast<const glsl::sampler3D&>(t));
    }
    for (int i = 0; i < 4; ++i) put(in, f_[in.d + std::uint32_t(i)], c[i]);
}

// A sampler2DShadow's lookup (m = 4): P = (s, t, reference value) at A, the vocabulary's function
// of the operation's name.
template <class F>
F Machine<F>::shadow_lookup(const ir::Instr& in, const glsl::sampler2D& depth) {
    const glsl::vec3<F> p = vector_at<3>(in.a);
    const auto offset = [&] { return glsl::vec<I, 2>(i_[in.c], i_[in.c + 1]); };
    switch (in.op) {
        case ir::Op::Texture: return glsl::textureShadow(depth, p);
        case ir::Op::TextureBias: return glsl::textureShadow(depth, p, f_[in.b]);
        case ir::Op::TextureLod: return glsl::textureShadowLod(depth, p, f_[in.b]);
        case ir::Op::TextureGrad: return glsl::textureShadowGrad(depth, p, vector_at<2>(in.b), vector_at<2>(in.b + 2));
        case ir::Op::TextureOffset: return glsl::textureShadowOffset(depth, p, offset());
        case ir::Op::TextureBiasOffset: return glsl::textureShadowOffset(depth, p, offset(), f_[in.b]);
        case ir::Op::TextureLodOffset: return glsl::textureShadowLodOffset(depth, p, f_[in.b], offset());
        case ir::Op::TextureGradOffset:
            return glsl::textureShadowGradOffset(depth, p, vector_at<2>(in.b), vector_at<2>(in.b + 2), offset());
        default: throw std::logic_error(std::string("a sampler2DShadow's ") + ir::name(in.op));
    }
}

// A samplerCube's or samplerCubeShadow's operation (the renderer binds a cube map to those only).
template <class F>
void Machine<F>::cube_texture(const ir::Instr& in, const glsl::samplerCube& cube) {
    if (in.op == ir::Op::TextureSize) {
        const glsl::ivec2<F> s = glsl::textureSize<F>(cube, i_[in.b]);
        for (int i = 0; i < 2; ++i) put(in, i_[in.d + std::uint32_t(i)], s[i]);
        return;
    }
    if (in.m == 4 && in.op != ir::Op::TextureGather) {
        // a samplerCubeShadow's: P.w compared
        const glsl::vec4<F> p = vector_at<4>(in.a);
        F r;
        switch (in.op) {
            case ir::Op::Texture: r = glsl::textureCubeShadow(cube, p); break;
            case ir::Op::TextureBias: r = glsl::textureCubeShadow(cube, p, f_[in.b]); break;
            case ir::Op::TextureLod: r = glsl::textureCubeShadowLod(cube, p, f_[in.b]); break;
            case ir::Op::TextureGrad: r = glsl::textureCubeShadowGrad(cube, p, vector_at<3>(in.b), vector_at<3>(in.b + 3)); break;
            default: throw std::logic_error(std::string("a samplerCubeShadow's ") + ir::name(in.op));
        }
        put(in, f_[in.d], r);
        return;
    }
    const glsl::vec3<F> p = vector_at<3>(in.a);
    if (in.op == ir::Op::TextureQueryLod) {
        const glsl::vec2<F> q = glsl::textureQueryLod(cube, p);
        for (int i = 0; i < 2; ++i) put(in, f_[in.d + std::uint32_t(i)], q[i]);
        return;
    }
    glsl::vec<F, 4> c;
    switch (in.op) {
        case ir::Op::Texture: c = glsl::textureCube(cube, p); break;
        case ir::Op::TextureBias: c = glsl::textureCube(cube, p, f_[in.b]); break;
        case ir::Op::TextureLod: c = glsl::textureCubeLod(cube, p, f_[in.b]); break;
        case ir::Op::TextureGrad: c = glsl::textureGrad(cube, p, vector_at<3>(in.b), vector_at<3>(in.b + 3)); break;
        case ir::Op::TextureGather:
            c = in.m == 4 ? glsl::textureGatherCompare(cube, p, f_[in.b]) : glsl::textureGather(cube, p, in.m);
            break;
        default: throw std::logic_error(std::string("a cube map is bound to a sampler that ") + ir::name(in.op) + " reads");
    }
    for (int i = 0; i < 4; ++i) put(in, f_[in.d + std::uint32_t(i)], c[i]);
}

template <class F>
void Machine<F>::indexed(const ir::Instr& in) {
    const I index = i_[in.b];
    if (in.op == ir::Op::LoadIndexed) {
        // Element I[b] of the array at a (stride c): a select per element, which any lane
        // layout and number type takes alike; an index outside reads 0. GLSL leaves an index
        // outside the array undefined ("Behavior is undefined if a shader subscripts an array
        // with an index less than 0 or greater than or equal to the size the array was declared
        // with"): the checked run flags it, as a constant table's lookup (glsl/table.h).
        const auto load = [&](auto* bank, auto zero) {
            auto v = zero;
            for (std::uint32_t e = 0; e < in.count; ++e) v = choose(M(index == I(std::int32_t(e))), bank[in.a + e * in.c], v);
            if constexpr (requires { index.cases; }) {
                using L = decltype(index.v);
                const auto outside = !(index.v >= L(0) && index.v < L(std::int32_t(in.count)));
                v.cases |= LaneCases::on(lane_bits(outside), Undefined::Argument);
            }
            put(in, bank[in.d], v);
        };
        switch (in.bank) {
            case ir::Bank::Float: return load(f_, F(0.0f));
            case ir::Bank::Int: return load(i_, I(0));
            case ir::Bank::Uint: return load(u_, U(0u));
            case ir::Bank::Bool: return load(b_, M(false));
        }
        return;
    }
    const auto store = [&](auto* bank) {
        for (std::uint32_t e = 0; e < in.count; ++e) {
            auto& dst = bank[in.d + e * in.c];
            dst = choose(M(exec_ && M(index == I(std::int32_t(e)))), bank[in.a], dst);
        }
    };
    switch (in.bank) {
        case ir::Bank::Float: return store(f_);
        case ir::Bank::Int: return store(i_);
        case ir::Bank::Uint: return store(u_);
        case ir::Bank::Bool: return store(b_);
    }
}

template <class F>
std::size_t Machine<F>::control(const ir::Instr& in, std::size_t pc) {
    const auto jump = [&] { return std::size_t(in.target) - 1; };  // the loop's ++pc lands on target
    switch (in.op) {
        case ir::Op::If:
            cond_stack_.push_back({cond_, M(false)});
            cond_ = cond_ && b_[in.a];
            update();
            return any_lane(exec_) ? pc : jump();  // on to the Else or EndIf
        case ir::Op::Else:
            cond_ = !cond_ && cond_stack_.back().a;
            update();
            return any_lane(exec_) ? pc : jump();  // on to the EndIf
        case ir::Op::EndIf:
            cond_ = cond_stack_.back().a;
            cond_stack_.pop_back();
            update();
            return pc;
        case ir::Op::LoopBegin:
            loop_stack_.push_back({brk_, cnt_});
            breaks_loop_.push_back(true);
            return any_lane(exec_) ? pc : jump();  // one pass with no lane, as llvmpipe's
        case ir::Op::BreakUnless:
            brk_ = brk_ && !(exec_ && !b_[in.a]);
            update();
            return pc;
        case ir::Op::Break:
            if (breaks_loop_.back()) brk_ = brk_ && !exec_;
            else sw_ = sw_ && !exec_;
            update();
            return pc;
        case ir::Op::Continue:
            cnt_ = cnt_ && !exec_;
            update();
            return pc;
        case ir::Op::LoopContinue:
            cnt_ = loop_stack_.back().b;
            update();
            return pc;
        case ir::Op::LoopEnd: {
            cnt_ = loop_stack_.back().b;
            update();
            // Each 8-lane vector goes round while a lane of it that has not discarded runs and
            // its limiter lasts, as llvmpipe's does.
            const M alive = exec_ && !killed_;
            if constexpr (kVectors > 1) {
                for (int v = 0; v < kVectors; ++v) {
                    const M& lanes = vectors()[std::size_t(v)];
                    if (!any_lane(M(exec_ && lanes))) continue;  // left this loop already
                    const bool living = any_lane(M(alive && lanes));
                    const bool going = living && --budget_[std::size_t(v)] > 0;
                    if (!going) {
                        if (living) result_.loop_limit = true;
                        brk_ = brk_ && !lanes;
                    }
                }
            } else {
                const bool living = any_lane(alive);
                const bool going = living && --budget_[0] > 0;
                if (!going) {
                    if (living) result_.loop_limit = true;
                    brk_ = M(false);
                }
            }
            update();
            if (any_lane(exec_)) return jump();
            brk_ = loop_stack_.back().a;
            cnt_ = loop_stack_.back().b;
            loop_stack_.pop_back();
            breaks_loop_.pop_back();
            update();
            return pc;
        }
        case ir::Op::SwitchBegin:
            switch_stack_.push_back({sw_, M(false)});
            breaks_loop_.push_back(false);
            return pc;
        case ir::Op::SwitchEnd:
            sw_ = switch_stack_.back().a;
            switch_stack_.pop_back();
            breaks_loop_.pop_back();
            update();
            return pc;
        case ir::Op::CallBegin:
            call_stack_.push_back({ret_, M(false)});
            return pc;
        case ir::Op::CallEnd:
            ret_ = call_stack_.back().a;
            call_stack_.pop_back();
            update();
            return pc;
        case ir::Op::Return:
            ret_ = ret_ && !exec_;
            update();
            return pc;
        case ir::Op::Discard:
            killed_ = killed_ || exec_;
            return pc;
        default: break;
    }
    throw std::logic_error(std::string("GLSL interpreter: operation ") + ir::name(in.op) + " is not control flow");
}

}  // namespace executor_detail

template <class F>
RunResult Executor<F>::run(const ir::Stage& stage, Registers<F>& r, const TextureSlots& textures,
                           std::span<const jit::BlockCode> native) {
    executor_detail::Machine<F> machine(stage, r, textures, native);
    return machine.run();
}

}  // namespace qs::interpreter
