// The lowering's registers, emission and the stage as a whole (lowering.h). Expressions are in
// lower_expressions.cpp, built-in functions in lower_builtins.cpp, statements in
// lower_statements.cpp, the stage's interface in lower_interface.cpp.

#include <algorithm>
#include <bit>
#include <cstring>

#include <cstdint>
#include <stdexcept>

#include "frontend/derivative_probe.h"
#include "frontend/glsl_types.h"
#include "frontend/ir_operands.h"
#include "frontend/ir_simplify.h"
#include "frontend/lowering.h"

namespace qs::frontend {

namespace {

// Limits that keep a hostile shader from exhausting memory: far above any real shader's (the
// catalogue's largest stage is a few thousand instructions and registers).
constexpr std::size_t kMaxInstructions = 1u << 20;
constexpr std::uint32_t kMaxRegisters = 1u << 18;  // per bank and space

}  // namespace

StageLowering::StageLowering(StageKind kind, const std::string& file, glslang::TIntermediate& ast,
                             ProgramInterface& interface)
    : kind_(kind), file_(file), ast_(ast), interface_(interface) {}

std::string StageLowering::position(const glslang::TSourceLoc& at) const {
    if (const auto& probe = interface_.options.derivative_probe; probe && at.string == kProbeString) {
        return probe->option + " \"" + probe->expression + "\": ";
    }
    return source_position(file_, at.line, at.column);
}

void StageLowering::refuse(const glslang::TSourceLoc& at, const std::string& what) const {
    throw GlslUnsupported(position(at) + what);
}

void StageLowering::refuse(const TIntermNode* at, const std::string& what) const {
    refuse(at->getLoc(), what);
}

void StageLowering::check_size() const {
    if (stage_.code.size() > kMaxInstructions) {
        throw GlslUnsupported(source_position(file_, int(line_)) + "the shader is too large to run: over " +
                              std::to_string(kMaxInstructions) + " operations after inlining its functions");
    }
}

// ---- registers ------------------------------------------------------------------------------

std::uint32_t StageLowering::allocate(ir::Bank bank, Space space) {
    const std::size_t b = std::size_t(bank);
    std::uint32_t* top = space == Space::Variable ? &variable_top_[b] : space == Space::Temp ? &temp_top_[b] : &constant_top_[b];
    if (*top >= kMaxRegisters) {
        throw GlslUnsupported(source_position(file_, int(line_)) + "the shader is too large to run: over " +
                              std::to_string(kMaxRegisters) + " values of one type");
    }
    const std::uint32_t r = (*top)++ | std::uint32_t(space);
    if (space == Space::Temp) temp_max_[b] = std::max(temp_max_[b], temp_top_[b]);
    if (space == Space::Variable) variable_max_[b] = std::max(variable_max_[b], variable_top_[b]);
    return r;
}

Place StageLowering::allocate(const glslang::TType& type, Space space) {
    std::vector<ir::Bank> banks;
    try {
        component_banks(type, banks);
    } catch (const GlslUnsupported& e) {
        throw GlslUnsupported(source_position(file_, int(line_)) + e.what());
    }
    Place p;
    p.reserve(banks.size());
    for (ir::Bank b : banks) p.push_back({b, allocate(b, space)});
    return p;
}

Place StageLowering::temps(ir::Bank bank, int n) {
    Place p;
    for (int i = 0; i < n; ++i) p.push_back({bank, allocate(bank, Space::Temp)});
    return p;
}

std::uint32_t StageLowering::constant(ir::Bank bank, std::uint32_t bits) {
    const auto key = std::make_pair(bank, bits);
    if (auto it = constants_.find(key); it != constants_.end()) return it->second;
    const std::uint32_t r = allocate(bank, Space::Constant);
    stage_.constants.push_back({bank, r, bits});
    constants_.emplace(key, r);
    return r;
}

std::uint32_t StageLowering::float_constant(float v) { return constant(ir::Bank::Float, std::bit_cast<std::uint32_t>(v)); }
std::uint32_t StageLowering::int_constant(std::int32_t v) { return constant(ir::Bank::Int, std::bit_cast<std::uint32_t>(v)); }
std::uint32_t StageLowering::bool_constant(bool v) { return constant(ir::Bank::Bool, v ? 1u : 0u); }

// ---- emitting -------------------------------------------------------------------------------

ir::Instr& StageLowering::emit(ir::Op op, ir::Bank bank) {
    ir::Instr in{};
    in.op = op;
    in.bank = bank;
    in.line = line_;
    stage_.code.push_back(in);
    if ((stage_.code.size() & 0xFFF) == 0) check_size();
    return stage_.code.back();
}

std::uint32_t StageLowering::emit1(ir::Op op, ir::Bank result, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                                   ir::Bank bank) {
    const std::uint32_t d = allocate(result, Space::Temp);
    ir::Instr& in = emit(op, bank);
    in.d = d, in.a = a, in.b = b, in.c = c;
    return d;
}

void StageLowering::move(const Slot& to, const Slot& from, bool masked) {
    if (to.bank != from.bank) throw std::logic_error("GLSL lowering: a move between banks");
    if (to.reg == from.reg) return;
    ir::Instr& in = emit(ir::Op::Mov, to.bank);
    in.d = to.reg, in.a = from.reg, in.masked = masked;
}

void StageLowering::assign(const Place& to, const Place& from, bool masked) {
    if (to.size() != from.size()) throw std::logic_error("GLSL lowering: an assignment between different types");
    // Through temporaries where the two overlap (v.xy = v.yx), so that every component is read
    // before any is written.
    bool overlap = false;
    for (const Slot& t : to) {
        for (const Slot& f : from) overlap = overlap || (t == f);
    }
    if (overlap) {
        Place copy;
        for (const Slot& f : from) {
            Slot t{f.bank, allocate(f.bank, Space::Temp)};
            move(t, f, false);
            copy.push_back(t);
        }
        for (std::size_t i = 0; i < to.size(); ++i) move(to[i], copy[i], masked);
        return;
    }
    for (std::size_t i = 0; i < to.size(); ++i) move(to[i], from[i], masked);
}

void StageLowering::store(const LValue& lv, const Place& value) {
    if (!lv.index) return assign(lv.place, value);
    for (std::size_t i = 0; i < lv.place.size(); ++i) {
        ir::Instr& in = emit(ir::Op::StoreIndexed, lv.place[i].bank);
        in.d = lv.place[i].reg, in.a = value[i].reg, in.b = *lv.index, in.c = lv.stride[i];
        in.count = std::uint16_t(lv.count);
        in.masked = true;
    }
}

std::uint32_t StageLowering::consecutive(const Place& p) {
    bool ok = !p.empty();
    for (std::size_t i = 1; i < p.size() && ok; ++i) ok = p[i].bank == p[0].bank && p[i].reg == p[0].reg + i;
    if (ok) return p[0].reg;
    const Place t = temps(p[0].bank, int(p.size()));
    for (std::size_t i = 0; i < p.size(); ++i) move(t[i], p[i], false);
    return t[0].reg;
}

Slot StageLowering::convert(const Slot& s, ir::Bank to) {
    using B = ir::Bank;
    if (s.bank == to) return s;
    ir::Op op{};
    switch (to) {
        case B::Float: op = s.bank == B::Int ? ir::Op::FloatFromInt : s.bank == B::Uint ? ir::Op::FloatFromUint : ir::Op::FloatFromBool; break;
        case B::Int: op = s.bank == B::Float ? ir::Op::IntFromFloat : s.bank == B::Uint ? ir::Op::IntFromUint : ir::Op::IntFromBool; break;
        case B::Uint: op = s.bank == B::Float ? ir::Op::UintFromFloat : s.bank == B::Int ? ir::Op::UintFromInt : ir::Op::UintFromBool; break;
        case B::Bool: op = s.bank == B::Float ? ir::Op::BoolFromFloat : s.bank == B::Int ? ir::Op::BoolFromInt : ir::Op::BoolFromUint; break;
    }
    return {to, emit1(op, to, s.reg)};
}

Place StageLowering::convert(const Place& p, ir::Bank to) {
    Place r;
    for (const Slot& s : p) r.push_back(convert(s, to));
    return r;
}

bool StageLowering::is_shared_variable(const Slot& s) const {
    return (s.reg & kSpaceMask) == std::uint32_t(Space::Variable) && s.reg < shared_variables_[std::size_t(s.bank)];
}

bool StageLowering::writes_symbol(glslang::TIntermAggregate* function, long long symbol) {
    // Keyed by the pair: glslang's symbol ids carry its symbol table's level in their high bits.
    const std::pair<const void*, long long> key{function, symbol};
    if (auto it = written_symbols_.find(key); it != written_symbols_.end()) return it->second;
    class Writes : public glslang::TIntermTraverser {
    public:
        Writes(long long id, const std::unordered_map<std::string, glslang::TIntermAggregate*>& functions) : id_(id), functions_(functions) {}
        bool found = false;
        // The variable an assignable expression names: through indices, members and swizzles.
        static const glslang::TIntermSymbol* base(TIntermNode* n) {
            while (n) {
                if (auto* s = n->getAsSymbolNode()) return s;
                auto* b = n->getAsBinaryNode();
                if (!b) return nullptr;
                n = b->getLeft();
            }
            return nullptr;
        }
        void target(TIntermNode* n) {
            const glslang::TIntermSymbol* s = base(n);
            if (s && s->getId() == id_) found = true;
        }
        bool visitBinary(glslang::TVisit, glslang::TIntermBinary* node) override {
            switch (node->getOp()) {
                case glslang::EOpAssign: case glslang::EOpAddAssign: case glslang::EOpSubAssign: case glslang::EOpMulAssign:
                case glslang::EOpDivAssign: case glslang::EOpModAssign: case glslang::EOpAndAssign:
                case glslang::EOpInclusiveOrAssign: case glslang::EOpExclusiveOrAssign: case glslang::EOpLeftShiftAssign:
                case glslang::EOpRightShiftAssign: case glslang::EOpVectorTimesScalarAssign:
                case glslang::EOpMatrixTimesScalarAssign: case glslang::EOpVectorTimesMatrixAssign:
                case glslang::EOpMatrixTimesMatrixAssign:
                    target(node->getLeft());
                    break;
                default: break;
            }
            return !found;
        }
        bool visitUnary(glslang::TVisit, glslang::TIntermUnary* node) override {
            switch (node->getOp()) {
                case glslang::EOpPostIncrement: case glslang::EOpPostDecrement: case glslang::EOpPreIncrement:
                case glslang::EOpPreDecrement:
                    target(node->getOperand());
                    break;
                default: break;
            }
            return !found;
        }
        bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* node) override {
            const glslang::TIntermSequence& args = node->getSequence();
            switch (node->getOp()) {
                case glslang::EOpFunctionCall: {
                    auto it = functions_.find(node->getName().c_str());
                    if (it == functions_.end()) break;
                    const glslang::TIntermSequence& params = it->second->getSequence()[0]->getAsAggregate()->getSequence();
                    for (std::size_t i = 0; i < params.size() && i < args.size(); ++i) {
                        const glslang::TStorageQualifier q = params[i]->getAsSymbolNode()->getQualifier().storage;
                        if (q == glslang::EvqOut || q == glslang::EvqInOut) target(args[i]);
                    }
                    break;
                }
                case glslang::EOpModf: case glslang::EOpFrexp: target(args[1]); break;
                case glslang::EOpAddCarry: case glslang::EOpSubBorrow: target(args[2]); break;
                case glslang::EOpUMulExtended: case glslang::EOpIMulExtended: target(args[2]), target(args[3]); break;
                default: break;
            }
            return !found;
        }

    private:
        long long id_;
        const std::unordered_map<std::string, glslang::TIntermAggregate*>& functions_;
    };
    Writes w(symbol, functions_);
    function->traverse(&w);
    written_symbols_.emplace(key, w.found);
    return w.found;
}

// A result computed into a temporary and then moved into a variable is computed into the
// variable: `x = a * b` is one multiply, not a multiply and a move, and `v = floor(w)` three
// floors. A move is fused into the operation that made its temporary where nothing reads the
// temporary but the move (temporaries live inside a statement, which writes each before it reads
// it), the operation writes that one register, and nothing between the two reads or writes the
// variable or crosses a control-flow marker.
void StageLowering::fuse_moves() {
    std::vector<ir::Instr>& code = stage_.code;
    const auto is_temp = [](std::uint32_t r) { return (r & kSpaceMask) == std::uint32_t(Space::Temp); };
    const auto control = [](ir::Op op) { return op >= ir::Op::If; };
    // Whether instruction j reads (or writes) register r of bank b.
    const auto touches = [&](const ir::Instr& in, ir::Bank b, std::uint32_t r, bool written) {
        for (const ir::Operand& o : ir::operands(in)) {
            if (o.bank != b || o.written != written) continue;
            const std::uint32_t first = ir::field(in, o.field);
            if (r >= first && r < first + o.span) return true;
        }
        return false;
    };
    std::vector<bool> removed(code.size(), false);
    constexpr std::size_t kWindow = 64;  // how far back a move looks for its operation
    for (std::size_t m = 1; m < code.size(); ++m) {
        const ir::Instr mov = code[m];
        if (mov.op != ir::Op::Mov || !is_temp(mov.a)) continue;
        const ir::Bank b = mov.bank;
        // The operation that wrote the temporary, with nothing in between that touches the
        // variable or is control flow.
        std::size_t p = m;
        bool found = false;
        while (p > 0 && m - p < kWindow) {
            --p;
            if (removed[p]) continue;
            const ir::Instr& in = code[p];
            if (control(in.op)) break;
            if (touches(in, b, mov.a, true)) {
                found = true;
                break;
            }
            if (touches(in, b, mov.d, false) || touches(in, b, mov.d, true)) break;
        }
        if (!found) continue;
        ir::Instr& op = code[p];
        if (op.masked) continue;
        int written = 0;
        bool single = false;
        for (const ir::Operand& o : ir::operands(op)) {
            if (!o.written) continue;
            ++written;
            single = o.field == ir::Field::D && o.span == 1 && o.bank == b && op.d == mov.a;
        }
        if (written != 1 || !single) continue;
        // The operation must not itself read the variable where it is a composite result.
        // Nothing but the move may read the temporary before it is written again.
        bool other_reader = false;
        for (std::size_t j = p + 1; j < code.size() && !other_reader; ++j) {
            if (j == m || removed[j]) continue;
            if (touches(code[j], b, mov.a, false)) other_reader = true;
            else if (touches(code[j], b, mov.a, true)) break;
        }
        if (other_reader) continue;
        op.d = mov.d;
        op.masked = mov.masked;
        removed[m] = true;
    }
    remove_instructions(stage_, removed);
}

// ---- a derivative probe (compile_options.h) -------------------------------------------------

glslang::TIntermTyped* StageLowering::take_probe(glslang::TIntermAggregate* main) {
    if (kind_ != StageKind::Fragment || !interface_.options.derivative_probe) return nullptr;
    // derivative_probe.h put it last in main's body, as an expression statement of its own string.
    const glslang::TIntermSequence& parts = main->getSequence();
    glslang::TIntermAggregate* body = parts.size() > 1 && parts[1] ? parts[1]->getAsAggregate() : nullptr;
    glslang::TIntermTyped* probe = nullptr;
    if (body && body->getOp() == glslang::EOpSequence && !body->getSequence().empty()) {
        probe = body->getSequence().back()->getAsTyped();
    }
    if (!probe || probe->getLoc().string != kProbeString) {
        throw std::logic_error("GLSL front end: the derivative probe is not main's last statement");
    }
    body->getSequence().pop_back();
    return probe;
}

void StageLowering::write_probe(glslang::TIntermTyped* e) {
    const DerivativeProbe& probe = *interface_.options.derivative_probe;
    const glslang::TType& type = e->getType();
    if (type.getBasicType() != glslang::EbtFloat || type.isArray() || type.isMatrix() || type.isStruct()) {
        throw GlslError(position(e->getLoc()) + "error: the expression is " + type_name(type) +
                        "; dFdx and dFdy take a float or a float vector");
    }
    const int n = type.isVector() ? type.getVectorSize() : 1;
    interface_.probe_components = n;
    if (probe.component < 0 || probe.component >= n) {
        throw GlslError(position(e->getLoc()) + "error: no component " + std::to_string(probe.component) + " in " +
                        type_name(type));
    }
    line_ = std::uint32_t(e->getLoc().line);
    const std::uint32_t value = eval(e)[std::size_t(probe.component)].reg;
    stage_.derivatives = true;
    using B = ir::Bank;
    const std::uint32_t colour[4] = {emit1(ir::Op::FDdx, B::Float, value), emit1(ir::Op::FDdy, B::Float, value), value,
                                     float_constant(1.0f)};
    std::erase_if(stage_.outputs, [](const ir::Binding& b) { return b.source == ir::Source::Color; });
    for (std::uint16_t i = 0; i < 4; ++i) {
        const std::uint32_t r = allocate(B::Float, Space::Variable);
        move({B::Float, r}, {B::Float, colour[i]}, false);
        stage_.outputs.push_back({ir::Source::Color, 0, i, B::Float, r});
    }
}

// ---- the stage ------------------------------------------------------------------------------

ir::Stage StageLowering::run() {
    glslang::TIntermAggregate* root = ast_.getTreeRoot() ? ast_.getTreeRoot()->getAsAggregate() : nullptr;
    if (!root) throw GlslError(source_position(file_, 0) + "the shader has no code");
    glslang::TIntermAggregate* main = nullptr;
    std::vector<TIntermNode*> global_code;
    for (TIntermNode* n : root->getSequence()) {
        glslang::TIntermAggregate* a = n->getAsAggregate();
        if (a && a->getOp() == glslang::EOpFunction) {
            const std::string name = a->getName().c_str();
            functions_[name] = a;
            if (name == "main(") main = a;
        } else if (a && a->getOp() == glslang::EOpLinkerObjects) {
            continue;
        } else {
            global_code.push_back(n);
        }
    }
    if (!main) throw GlslLinkError(source_position(file_, 0) + "the shader has no main()");

    frames_.push_back(Frame{"main", {}, {}, {}});
    declare_globals(root);
    shared_variables_ = variable_top_;
    // Globals' initialisers run first, in the order they are written (GLSL's).
    for (TIntermNode* n : global_code) {
        line_ = std::uint32_t(n->getLoc().line);
        statement(n);
    }
    const glslang::TIntermSequence& parts = main->getSequence();
    glslang::TIntermTyped* probe = take_probe(main);
    // With a probe, main runs as a call does: the lanes its returns set aside rejoin at its end.
    if (probe) emit(ir::Op::CallBegin);
    if (parts.size() > 1 && parts[1]) {
        glslang::TIntermAggregate* body = parts[1]->getAsAggregate();
        if (body) {
            initialise_locals(body, {});
            statements(body);
        } else {
            statement(parts[1]);
        }
    }
    if (probe) {
        emit(ir::Op::CallEnd);
        write_probe(probe);
    }
    frames_.pop_back();
    if (kind_ == StageKind::Vertex) supply_unwritten_colors();
    fuse_moves();

    // Lay the spaces out: variables, temporaries, constants.
    for (int b = 0; b < ir::kBanks; ++b) {
        stage_.registers[std::size_t(b)] = variable_max_[std::size_t(b)] + temp_max_[std::size_t(b)] + constant_top_[std::size_t(b)];
    }
    const auto place = [&](ir::Bank bank, std::uint32_t r) {
        const std::size_t b = std::size_t(bank);
        const std::uint32_t index = r & ~kSpaceMask;
        switch (r & kSpaceMask) {
            case std::uint32_t(Space::Variable): return index;
            case std::uint32_t(Space::Temp): return variable_max_[b] + index;
            default: return variable_max_[b] + temp_max_[b] + index;
        }
    };
    for (ir::Instr& in : stage_.code) {
        for (const ir::Operand& op : ir::operands(in)) {
            std::uint32_t& r = ir::field(in, op.field);
            r = place(op.bank, r);
        }
    }
    for (ir::Constant& c : stage_.constants) c.reg = place(c.bank, c.reg);
    for (ir::Binding& b : stage_.inputs) b.reg = place(b.bank, b.reg);
    for (ir::Binding& b : stage_.outputs) b.reg = place(b.bank, b.reg);
    drop_idle_calls(stage_);
    join_component_runs(stage_);
    return std::move(stage_);
}

}  // namespace qs::frontend
