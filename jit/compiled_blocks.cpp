#include "jit/compiled_blocks.h"

#include <array>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "frontend/ir_operands.h"
#include "jit/llvm_api.h"

namespace qs::jit {

bool compilable(const ir::Instr& in) {
    using ir::Bank, ir::Op;
    switch (in.op) {
        case Op::Mov: case Op::Select: return in.bank != Bank::Uint;
        case Op::FNeg: case Op::FAdd: case Op::FSub: case Op::FMul: case Op::FDiv: case Op::FMod: case Op::FMin:
        case Op::FMax: case Op::FClamp: case Op::FMix: case Op::FStep: case Op::FSmoothStep: case Op::FAbs:
        case Op::FSign: case Op::FFloor: case Op::FCeil: case Op::FTrunc: case Op::FRoundEven: case Op::FFract:
        case Op::FSqrt: case Op::FInverseSqrt: case Op::FMixBool: case Op::Dot:
        case Op::FLess: case Op::FLessEqual: case Op::FGreater: case Op::FGreaterEqual: case Op::FEqual:
        case Op::FNotEqual: case Op::FIsNan: case Op::FIsInf:
        case Op::BNot: case Op::BAnd: case Op::BOr: case Op::BXor: case Op::BEqual: case Op::BNotEqual:
        case Op::FloatFromInt: case Op::FloatFromBool:
            return true;
        case Op::IAdd: case Op::ISub: case Op::IMul: case Op::ILess: case Op::ILessEqual: case Op::IGreater:
        case Op::IGreaterEqual: case Op::IEqual: case Op::INotEqual:
            return in.bank == Bank::Int;  // int's wrapping arithmetic and signed comparisons
        case Op::Length: return in.n > 1;  // a float's length is its absolute value, which geometric() takes
        default: return false;
    }
}

namespace {

// LLVM's error as a JitError, the error consumed.
[[noreturn]] void fail(LLVMErrorRef error, const std::string& what) {
    const LlvmApi& api = llvm();
    char* message = api.LLVMGetErrorMessage(error);
    const std::string text = what + ": " + message;
    api.LLVMDisposeErrorMessage(message);
    throw JitError(text);
}
void check(LLVMErrorRef error, const char* what) {
    if (error) fail(error, what);
}

// The alignment a block assumes of registers and masks: a lane's. A build for SSE aligns the
// interpreter's registers to 16 bytes, not a 64-byte vector, and unaligned vector moves cost
// nothing on data that happens to be aligned.
constexpr unsigned kAlignment = alignof(float);

// How far past a block its liveness is followed; what is still unsettled there is stored. It
// bounds the compile of a huge shader's many blocks.
constexpr std::size_t kLongestScan = 1u << 14;

// A register of one bank.
struct Register {
    ir::Bank bank;
    std::uint32_t index;
    auto operator<=>(const Register&) const = default;
};

// The registers of `written` that the stage may read after `block`: scanning on from the block's
// end, one is read before an unmasked write replaces it, or a loop around the block goes round
// first, or it is an output at the end. A write after a control-flow marker might not run, and
// an indexed store writes one element a lane, so neither replaces anything for sure.
std::set<Register> read_after(const ir::Stage& stage, const Block& block, std::set<Register> written) {
    std::set<Register> live;
    bool crossed = false;
    for (std::size_t j = block.end; j < stage.code.size() && !written.empty(); ++j) {
        const ir::Instr& in = stage.code[j];
        if ((in.op == ir::Op::LoopEnd && in.target <= block.first) || j - block.end == kLongestScan) {
            live.insert(written.begin(), written.end());
            return live;
        }
        if (in.op >= ir::Op::If) crossed = true;
        // An operation reads its operands before it writes its result: reads first.
        const ir::Operands operands = ir::operands(in);
        for (bool writes : {false, true}) {
            for (const ir::Operand& o : operands) {
                if (o.written != writes) continue;
                const std::uint32_t first = ir::field(in, o.field);
                for (auto it = written.lower_bound({o.bank, first});
                     it != written.end() && it->bank == o.bank && it->index < first + o.span;) {
                    if (!writes) {
                        live.insert(*it);
                        it = written.erase(it);
                    } else if (!crossed && !in.masked && in.op != ir::Op::StoreIndexed) {  // a whole write
                        it = written.erase(it);
                    } else {
                        ++it;
                    }
                }
            }
        }
    }
    for (const ir::Binding& b : stage.outputs) {
        if (written.count({b.bank, b.reg})) live.insert({b.bank, b.reg});
    }
    return live;
}

// The registers a block's instructions write.
std::set<Register> written_by(const ir::Stage& stage, const Block& block) {
    std::set<Register> written;
    for (std::uint32_t k = block.first; k < block.end; ++k) {
        const ir::Instr& in = stage.code[k];
        for (const ir::Operand& o : ir::operands(in)) {
            if (!o.written) continue;
            for (std::uint32_t r = ir::field(in, o.field); r < ir::field(in, o.field) + o.span; ++r) written.insert({o.bank, r});
        }
    }
    return written;
}

// This machine's target with every feature its processor has, code generated at LLVM's level
// "less": on the noises it compiles in 0.85 of the default level's time, and the code runs as
// fast (a block is arithmetic in one straight line, which the default level's passes do not
// speed up); level "none" runs Perlin noise 1.7 times as long.
LLVMTargetMachineRef host_machine() {
    const LlvmApi& api = llvm();
    char* triple = api.LLVMGetDefaultTargetTriple();
    char* cpu = api.LLVMGetHostCPUName();
    char* features = api.LLVMGetHostCPUFeatures();
    LLVMTargetRef target = nullptr;
    char* error = nullptr;
    LLVMTargetMachineRef machine = nullptr;
    if (api.LLVMGetTargetFromTriple(triple, &target, &error) == 0) {
        machine = api.LLVMCreateTargetMachine(target, triple, cpu, features, LLVMCodeGenLevelLess, LLVMRelocDefault,
                                          LLVMCodeModelJITDefault);
    }
    const std::string why = error ? error : "no target machine";
    api.LLVMDisposeMessage(triple), api.LLVMDisposeMessage(cpu), api.LLVMDisposeMessage(features);
    if (error) api.LLVMDisposeMessage(error);
    if (!machine) throw JitError("LLVM does not know this machine: " + why);
    return machine;
}

// One block's function for `lanes` lanes, written into `module`: its arguments are the float,
// int and bool banks of the register file and the running mask. An int is an i32 lane, a bool
// the interpreter's -1 or 0 in an i32 lane.
class BlockWriter {
public:
    BlockWriter(LLVMContextRef context, LLVMModuleRef module, int lanes)
        : api_(llvm()), c_(context), m_(module), lanes_(lanes), b_(api_.LLVMCreateBuilderInContext(context)) {
        f32_ = api_.LLVMFloatTypeInContext(c_);
        i32_ = api_.LLVMInt32TypeInContext(c_);
        i64_ = api_.LLVMInt64TypeInContext(c_);
        floats_ = api_.LLVMVectorType(f32_, unsigned(lanes));
        words_ = api_.LLVMVectorType(i32_, unsigned(lanes));
    }
    ~BlockWriter() { api_.LLVMDisposeBuilder(b_); }

    // The block's function, which stores the registers of `stored` (read_after) it writes.
    void write(const ir::Stage& stage, const Block& block, const std::set<Register>& stored, const std::string& name) {
        LLVMTypeRef params[] = {api_.LLVMPointerType(f32_, 0), api_.LLVMPointerType(i32_, 0), api_.LLVMPointerType(i32_, 0),
                                api_.LLVMPointerType(i32_, 0)};
        LLVMTypeRef type = api_.LLVMFunctionType(api_.LLVMVoidTypeInContext(c_), params, 4, 0);
        LLVMValueRef fn = api_.LLVMAddFunction(m_, name.c_str(), type);
        // A block throws nothing: without unwind tables LLVM writes no .eh_frame for the JIT to
        // register with libgcc, whose frame lookup then deadlocks AddressSanitizer's slow unwinder
        // (fast_unwind_on_malloc=0, as the checking build runs).
        const unsigned nounwind = api_.LLVMGetEnumAttributeKindForName("nounwind", 8);
        api_.LLVMAddAttributeAtIndex(fn, LLVMAttributeFunctionIndex, api_.LLVMCreateEnumAttribute(c_, nounwind, 0));
        if (lanes_ * 32 >= 512) {  // whole 512-bit registers where the machine has them
            for (const char* key : {"prefer-vector-width", "min-legal-vector-width"}) {
                api_.LLVMAddAttributeAtIndex(fn, LLVMAttributeFunctionIndex,
                                        api_.LLVMCreateStringAttribute(c_, key, unsigned(std::strlen(key)), "512", 3));
            }
        }
        api_.LLVMPositionBuilderAtEnd(b_, api_.LLVMAppendBasicBlockInContext(c_, fn, "entry"));
        banks_[std::size_t(ir::Bank::Float)] = api_.LLVMGetParam(fn, 0);
        banks_[std::size_t(ir::Bank::Int)] = api_.LLVMGetParam(fn, 1);
        banks_[std::size_t(ir::Bank::Bool)] = api_.LLVMGetParam(fn, 2);
        running_words_ = api_.LLVMGetParam(fn, 3);
        running_ = nullptr;
        values_.clear();
        for (std::uint32_t k = block.first; k < block.end; ++k) instruction(stage.code[k]);
        for (const Register& r : stored) {
            LLVMValueRef store = api_.LLVMBuildStore(b_, values_.at(r), address(r));
            api_.LLVMSetAlignment(store, kAlignment);
        }
        api_.LLVMBuildRetVoid(b_);
    }

private:
    LLVMValueRef address(Register r) {
        LLVMValueRef index = api_.LLVMConstInt(i64_, std::uint64_t(r.index) * std::uint64_t(lanes_), 0);
        return api_.LLVMBuildGEP2(b_, r.bank == ir::Bank::Float ? f32_ : i32_, banks_[std::size_t(r.bank)], &index, 1, "");
    }
    // A register's value: computed in the block, or loaded once.
    LLVMValueRef read(ir::Bank bank, std::uint32_t index) {
        const Register r{bank, index};
        auto it = values_.find(r);
        if (it != values_.end()) return it->second;
        LLVMValueRef load = api_.LLVMBuildLoad2(b_, bank == ir::Bank::Float ? floats_ : words_, address(r), "");
        api_.LLVMSetAlignment(load, kAlignment);
        values_[r] = load;
        return load;
    }
    LLVMValueRef read(std::uint32_t index) { return read(ir::Bank::Float, index); }
    // The running lanes, loaded where the block first writes a variable.
    LLVMValueRef running() {
        if (!running_) {
            LLVMValueRef mask = api_.LLVMBuildLoad2(b_, words_, running_words_, "");
            api_.LLVMSetAlignment(mask, kAlignment);
            running_ = truth(mask);
        }
        return running_;
    }
    void write(const ir::Instr& in, ir::Bank bank, std::uint32_t index, LLVMValueRef v) {
        if (in.masked) v = select(running(), v, read(bank, index));
        values_[{bank, index}] = v;
    }
    void write(const ir::Instr& in, std::uint32_t index, LLVMValueRef v) { write(in, ir::Bank::Float, index, v); }

    LLVMValueRef splat(LLVMValueRef x) {
        std::vector<LLVMValueRef> lanes(std::size_t(lanes_), x);
        return api_.LLVMConstVector(lanes.data(), unsigned(lanes_));
    }
    LLVMValueRef splat(float x) { return splat(api_.LLVMConstReal(f32_, double(x))); }
    LLVMValueRef intrinsic(const char* name, LLVMValueRef x) {
        const unsigned id = api_.LLVMLookupIntrinsicID(name, std::strlen(name));
        LLVMTypeRef types[] = {floats_};
        LLVMValueRef fn = api_.LLVMGetIntrinsicDeclaration(m_, id, types, 1);
        return api_.LLVMBuildCall2(b_, api_.LLVMIntrinsicGetType(c_, id, types, 1), fn, &x, 1, "");
    }
    // A bool's lanes as LLVM's i1, and back as the interpreter's -1 or 0.
    LLVMValueRef truth(LLVMValueRef words) { return api_.LLVMBuildICmp(b_, LLVMIntNE, words, api_.LLVMConstNull(words_), ""); }
    LLVMValueRef words(LLVMValueRef truth) { return api_.LLVMBuildSExt(b_, truth, words_, ""); }
    LLVMValueRef compare(LLVMRealPredicate p, LLVMValueRef x, LLVMValueRef y) { return api_.LLVMBuildFCmp(b_, p, x, y, ""); }
    LLVMValueRef less(LLVMValueRef x, LLVMValueRef y) { return compare(LLVMRealOLT, x, y); }
    LLVMValueRef select(LLVMValueRef m, LLVMValueRef x, LLVMValueRef y) { return api_.LLVMBuildSelect(b_, m, x, y, ""); }
    LLVMValueRef add(LLVMValueRef x, LLVMValueRef y) { return api_.LLVMBuildFAdd(b_, x, y, ""); }
    LLVMValueRef sub(LLVMValueRef x, LLVMValueRef y) { return api_.LLVMBuildFSub(b_, x, y, ""); }
    LLVMValueRef mul(LLVMValueRef x, LLVMValueRef y) { return api_.LLVMBuildFMul(b_, x, y, ""); }
    LLVMValueRef div(LLVMValueRef x, LLVMValueRef y) { return api_.LLVMBuildFDiv(b_, x, y, ""); }
    LLVMValueRef floor(LLVMValueRef x) { return intrinsic("llvm.floor", x); }
    // GLSL min and max as the lanes compute them (number/lanes.h): a NaN b loses to a, and
    // otherwise a < b ? a : b, which is minps.
    LLVMValueRef min(LLVMValueRef a, LLVMValueRef b) { return select(compare(LLVMRealUNO, b, b), a, select(less(a, b), a, b)); }
    LLVMValueRef max(LLVMValueRef a, LLVMValueRef b) { return select(compare(LLVMRealUNO, b, b), a, select(less(b, a), a, b)); }
    LLVMValueRef clamp(LLVMValueRef x, LLVMValueRef lo, LLVMValueRef hi) { return min(max(x, lo), hi); }
    // dot(a, b) in glsl::dot's order: ((a0 b0 + a1 b1) + a2 b2) + a3 b3.
    LLVMValueRef dot(std::uint32_t a, std::uint32_t b, int n) {
        LLVMValueRef sum = mul(read(a), read(b));
        for (std::uint32_t i = 1; i < std::uint32_t(n); ++i) sum = add(sum, mul(read(a + i), read(b + i)));
        return sum;
    }

    // A float operation's component as shading/glsl/builtins.h writes it.
    LLVMValueRef arithmetic(ir::Op op, LLVMValueRef x, LLVMValueRef y, LLVMValueRef z) {
        using ir::Op;
        switch (op) {
            case Op::FNeg: return api_.LLVMBuildFNeg(b_, x, "");
            case Op::FAdd: return add(x, y);
            case Op::FSub: return sub(x, y);
            case Op::FMul: return mul(x, y);
            case Op::FDiv: return div(x, y);
            case Op::FMod: return sub(x, mul(y, floor(div(x, y))));
            case Op::FMin: return min(x, y);
            case Op::FMax: return max(x, y);
            case Op::FClamp: return clamp(x, y, z);
            case Op::FMix: return add(mul(x, sub(splat(1.0f), z)), mul(y, z));
            case Op::FStep: return select(less(y, x), splat(0.0f), splat(1.0f));
            case Op::FSmoothStep: {
                LLVMValueRef t = clamp(div(sub(z, x), sub(y, x)), splat(0.0f), splat(1.0f));
                return mul(mul(t, t), sub(splat(3.0f), mul(splat(2.0f), t)));
            }
            case Op::FAbs: return intrinsic("llvm.fabs", x);
            case Op::FSign: {
                LLVMValueRef negative = select(less(x, splat(0.0f)), splat(-1.0f), splat(0.0f));
                return select(less(splat(0.0f), x), splat(1.0f), negative);
            }
            case Op::FFloor: return floor(x);
            case Op::FCeil: return intrinsic("llvm.ceil", x);
            case Op::FTrunc: return intrinsic("llvm.trunc", x);
            case Op::FRoundEven: return intrinsic("llvm.roundeven", x);
            case Op::FFract: return sub(x, floor(x));
            case Op::FSqrt: return intrinsic("llvm.sqrt", x);
            case Op::FInverseSqrt: return div(splat(1.0f), intrinsic("llvm.sqrt", x));
            default: throw std::logic_error(std::string("a compiled block cannot hold ") + ir::name(op));
        }
    }

    // Component k of every other operation: its result's bank and value.
    std::pair<ir::Bank, LLVMValueRef> other(const ir::Instr& in, std::uint32_t k) {
        using ir::Bank, ir::Op;
        const auto at = [&](std::uint32_t first, int bit) { return first + ((in.broadcast >> bit & 1u) ? 0u : k); };
        const auto f = [&](std::uint32_t first, int bit) { return read(Bank::Float, at(first, bit)); };
        const auto b = [&](std::uint32_t first, int bit) { return read(Bank::Bool, at(first, bit)); };
        const auto i = [&](std::uint32_t first, int bit) { return read(Bank::Int, at(first, bit)); };
        const auto compared = [&](LLVMRealPredicate p) { return std::pair{Bank::Bool, words(compare(p, f(in.a, 0), f(in.b, 1)))}; };
        const auto integers = [&](LLVMIntPredicate p) {
            return std::pair{Bank::Bool, words(api_.LLVMBuildICmp(b_, p, i(in.a, 0), i(in.b, 1), ""))};
        };
        switch (in.op) {
            case Op::Mov: return {in.bank, read(in.bank, at(in.a, 0))};
            case Op::Select: return {in.bank, select(truth(b(in.a, 0)), read(in.bank, at(in.b, 1)), read(in.bank, at(in.c, 2)))};
            case Op::FMixBool: return {Bank::Float, select(truth(b(in.c, 2)), f(in.b, 1), f(in.a, 0))};
            case Op::FLess: return compared(LLVMRealOLT);
            case Op::FLessEqual: return compared(LLVMRealOLE);
            case Op::FGreater: return compared(LLVMRealOGT);
            case Op::FGreaterEqual: return compared(LLVMRealOGE);
            case Op::FEqual: return compared(LLVMRealOEQ);
            case Op::FNotEqual: return compared(LLVMRealUNE);
            case Op::FIsNan: return {Bank::Bool, words(compare(LLVMRealUNE, f(in.a, 0), f(in.a, 0)))};
            case Op::FIsInf: {
                LLVMValueRef magnitude = intrinsic("llvm.fabs", f(in.a, 0));
                return {Bank::Bool, words(compare(LLVMRealOEQ, magnitude, splat(std::numeric_limits<float>::infinity())))};
            }
            case Op::BNot: return {Bank::Bool, api_.LLVMBuildNot(b_, b(in.a, 0), "")};
            case Op::BAnd: return {Bank::Bool, api_.LLVMBuildAnd(b_, b(in.a, 0), b(in.b, 1), "")};
            case Op::BOr: return {Bank::Bool, api_.LLVMBuildOr(b_, b(in.a, 0), b(in.b, 1), "")};
            case Op::BXor: case Op::BNotEqual: return {Bank::Bool, api_.LLVMBuildXor(b_, b(in.a, 0), b(in.b, 1), "")};
            case Op::BEqual: return {Bank::Bool, api_.LLVMBuildNot(b_, api_.LLVMBuildXor(b_, b(in.a, 0), b(in.b, 1), ""), "")};
            case Op::FloatFromInt: return {Bank::Float, api_.LLVMBuildSIToFP(b_, i(in.a, 0), floats_, "")};
            case Op::FloatFromBool: return {Bank::Float, select(truth(b(in.a, 0)), splat(1.0f), splat(0.0f))};
            case Op::IAdd: return {Bank::Int, api_.LLVMBuildAdd(b_, i(in.a, 0), i(in.b, 1), "")};
            case Op::ISub: return {Bank::Int, api_.LLVMBuildSub(b_, i(in.a, 0), i(in.b, 1), "")};
            case Op::IMul: return {Bank::Int, api_.LLVMBuildMul(b_, i(in.a, 0), i(in.b, 1), "")};
            case Op::ILess: return integers(LLVMIntSLT);
            case Op::ILessEqual: return integers(LLVMIntSLE);
            case Op::IGreater: return integers(LLVMIntSGT);
            case Op::IGreaterEqual: return integers(LLVMIntSGE);
            case Op::IEqual: return integers(LLVMIntEQ);
            case Op::INotEqual: return integers(LLVMIntNE);
            default: {
                int n = 0;  // operands read
                for (const ir::Operand& o : ir::operands(in)) n += !o.written;
                return {Bank::Float, arithmetic(in.op, f(in.a, 0), n > 1 ? f(in.b, 1) : nullptr, n > 2 ? f(in.c, 2) : nullptr)};
            }
        }
    }

    void instruction(const ir::Instr& in) {
        if (in.op == ir::Op::Dot) return write(in, in.d, dot(in.a, in.b, in.n));
        if (in.op == ir::Op::Length) return write(in, in.d, intrinsic("llvm.sqrt", dot(in.a, in.a, in.n)));
        // Component by component, in order: a later component may read an earlier one's result.
        for (std::uint32_t k = 0; k < in.n; ++k) {
            const auto [bank, value] = other(in, k);
            write(in, bank, in.d + k, value);
        }
    }

    const LlvmApi& api_;
    LLVMContextRef c_;
    LLVMModuleRef m_;
    int lanes_;
    LLVMBuilderRef b_;
    LLVMTypeRef f32_, i32_, i64_, floats_, words_;
    std::array<LLVMValueRef, ir::kBanks> banks_{};
    LLVMValueRef running_words_ = nullptr, running_ = nullptr;
    std::map<Register, LLVMValueRef> values_;
};

}  // namespace

// The JIT that holds the blocks' code, freed with them.
// The JIT that holds the blocks' code, freed with them, and what compiling a width takes.
struct CompiledBlocks::Session {
    const LlvmApi& api = llvm();
    LLVMOrcLLJITRef jit = nullptr;
    ir::Stage stage;                         // unmarked
    std::vector<Block> blocks;
    std::vector<std::set<Register>> stored;  // per block: what it stores
    std::mutex compiling;                    // one width at a time into the JIT
    ~Session() {
        if (jit) api.LLVMConsumeError(api.LLVMOrcDisposeLLJIT(jit));
    }
};

CompiledBlocks::CompiledBlocks(const ir::Stage& stage, std::span<const Block> blocks) : session_(std::make_unique<Session>()) {
    Session& s = *session_;
    const LlvmApi& api = s.api;
    LLVMTargetMachineRef host = host_machine();
    LLVMOrcLLJITBuilderRef builder = api.LLVMOrcCreateLLJITBuilder();
    api.LLVMOrcLLJITBuilderSetJITTargetMachineBuilder(builder, api.LLVMOrcJITTargetMachineBuilderCreateFromTargetMachine(host));
    check(api.LLVMOrcCreateLLJIT(&s.jit, builder), "LLVM's compiler did not start");
    s.stage = stage;
    s.blocks.assign(blocks.begin(), blocks.end());
    for (const Block& block : blocks) s.stored.push_back(read_after(stage, block, written_by(stage, block)));
}

std::span<const BlockCode> CompiledBlocks::code(int lanes) const {
    const std::size_t width = lanes == kWidths[0] ? 0 : 1;
    std::call_once(compiled_[width], [&] {
        try {
            compile(width);
        } catch (const JitError&) {
            code_[width].clear();
            failed_.store(true, std::memory_order_relaxed);
        }
    });
    return code_[width];
}

void CompiledBlocks::compile(std::size_t width) const {
    Session& s = *session_;
    const LlvmApi& api = s.api;
    const std::lock_guard<std::mutex> lock(s.compiling);
    const int lanes = kWidths[width];
    // The module's functions: every block for this width.
    struct Module {
        const LlvmApi& api;
        LLVMOrcThreadSafeContextRef context = api.LLVMOrcCreateNewThreadSafeContext();
        LLVMModuleRef module = api.LLVMModuleCreateWithNameInContext("quadshade blocks", api.LLVMOrcThreadSafeContextGetContext(context));
        ~Module() {
            if (module) api.LLVMDisposeModule(module);
            api.LLVMOrcDisposeThreadSafeContext(context);
        }
    } m{api};
    std::vector<std::string> names;
    BlockWriter writer(api.LLVMOrcThreadSafeContextGetContext(m.context), m.module, lanes);
    for (std::size_t i = 0; i < s.blocks.size(); ++i) {
        names.push_back("block" + std::to_string(i) + "_" + std::to_string(lanes));
        writer.write(s.stage, s.blocks[i], s.stored[i], names.back());
    }
    LLVMOrcThreadSafeModuleRef owned = api.LLVMOrcCreateNewThreadSafeModule(m.module, m.context);
    m.module = nullptr;  // the thread-safe module owns it, and shares the context
    check(api.LLVMOrcLLJITAddLLVMIRModule(s.jit, api.LLVMOrcLLJITGetMainJITDylib(s.jit), owned),  // takes it
          "LLVM did not take the compiled blocks");
    std::vector<BlockCode> code;
    for (const std::string& name : names) {
        LLVMOrcExecutorAddress address = 0;
        check(api.LLVMOrcLLJITLookup(s.jit, &address, name.c_str()), "LLVM did not compile a block");
        code.push_back(reinterpret_cast<BlockCode>(address));
    }
    code_[width] = std::move(code);
}

CompiledBlocks::~CompiledBlocks() = default;

}  // namespace qs::jit
