// Statements and control flow (lowering.h): the markers the interpreter turns into lane masks.

#include <set>

#include "frontend/lowering.h"

namespace qs::frontend {

using glslang::TIntermAggregate;
using glslang::TIntermTyped;

using B = ir::Bank;

void StageLowering::statements(TIntermAggregate* sequence) {
    for (TIntermNode* n : sequence->getSequence()) statement(n);
}

void StageLowering::statement(TIntermNode* node) {
    if (!node) return;
    if (node->getLoc().line > 0) line_ = std::uint32_t(node->getLoc().line);
    const TempMark m = mark();
    if (auto* a = node->getAsAggregate(); a && a->getOp() == glslang::EOpSequence) {
        statements(a);
    } else if (auto* s = node->getAsSelectionNode(); s && s->getBasicType() == glslang::EbtVoid) {
        if_statement(s);
    } else if (auto* l = node->getAsLoopNode()) {
        loop(l);
    } else if (auto* b = node->getAsBranchNode()) {
        branch(b);
    } else if (auto* w = node->getAsSwitchNode()) {
        switch_statement(w);
    } else if (auto* t = node->getAsTyped()) {
        statement_value_ = t;
        (void)eval(t);
    } else {
        refuse(node, "this statement is not supported");
    }
    release(m);
}

void StageLowering::if_statement(glslang::TIntermSelection* node) {
    const Place c = eval(node->getCondition()->getAsTyped());
    const std::size_t at_if = stage_.code.size();
    emit(ir::Op::If).a = c[0].reg;
    statement(node->getTrueBlock());
    std::size_t at_else = 0;
    if (node->getFalseBlock()) {
        at_else = stage_.code.size();
        emit(ir::Op::Else);
        statement(node->getFalseBlock());
    }
    const std::size_t at_end = stage_.code.size();
    emit(ir::Op::EndIf);
    stage_.code[at_if].target = std::uint32_t(at_else ? at_else : at_end);
    if (at_else) stage_.code[at_else].target = std::uint32_t(at_end);
}

// A loop as llvmpipe runs one: its condition leaves lanes at the top (for, while) or at the
// bottom (do-while); lanes that continued rejoin before the increment; the interpreter returns
// to the top while any lane runs.
void StageLowering::loop(glslang::TIntermLoop* node) {
    stage_.loops = true;
    const std::size_t at_begin = stage_.code.size();
    emit(ir::Op::LoopBegin);
    ++loops_;
    const auto condition = [&] {
        if (!node->getTest()) return;
        const TempMark m = mark();
        const Place c = eval(node->getTest());
        emit(ir::Op::BreakUnless).a = c[0].reg;
        release(m);
    };
    if (node->testFirst()) condition();
    statement(node->getBody());
    emit(ir::Op::LoopContinue);
    if (node->getTerminal()) {
        const TempMark m = mark();
        statement_value_ = node->getTerminal();
        (void)eval(node->getTerminal());
        release(m);
    }
    if (!node->testFirst()) condition();
    --loops_;
    const std::size_t at_end = stage_.code.size();
    emit(ir::Op::LoopEnd).target = std::uint32_t(at_begin + 1);
    stage_.code[at_begin].target = std::uint32_t(at_end);
}

void StageLowering::branch(glslang::TIntermBranch* node) {
    switch (node->getFlowOp()) {
        case glslang::EOpKill: case glslang::EOpDemote:
            if (kind_ != StageKind::Fragment) refuse(node, "discard exists in fragment shaders only");
            stage_.discards = true;
            emit(ir::Op::Discard);
            return;
        case glslang::EOpBreak: emit(ir::Op::Break); return;
        case glslang::EOpContinue: emit(ir::Op::Continue); return;
        case glslang::EOpReturn:
            if (TIntermTyped* e = node->getExpression()) {
                auto* call = e->getAsAggregate();
                if (call && call->getOp() == glslang::EOpFunctionCall && call->isUserDefined()) {
                    // return f(...): f's returns write this function's result itself.
                    const Place result = frames_.back().result;
                    (void)eval_call(call, &result);
                } else {
                    // The value first: a call in it pushes a frame, which may move this one.
                    const Place value = eval(e);
                    assign(frames_.back().result, value, true);
                }
            }
            emit(ir::Op::Return);
            return;
        default: refuse(node, "this jump is not supported");
    }
}

// switch as a run of case groups, each entered by the lanes whose selector matched it or an
// earlier group they fell through from; break leaves the switch.
void StageLowering::switch_statement(glslang::TIntermSwitch* node) {
    const Place selector = eval(node->getCondition()->getAsTyped());
    const B bank = selector[0].bank;
    TIntermAggregate* body = node->getBody();
    // Which groups there are: the labels before each run of statements.
    struct Group {
        std::vector<std::uint32_t> labels;  // the values' registers
        bool is_default = false;
        std::vector<TIntermNode*> code;
    };
    std::vector<Group> groups;
    bool labels_open = false;
    for (TIntermNode* n : body->getSequence()) {
        auto* b = n->getAsBranchNode();
        if (b && (b->getFlowOp() == glslang::EOpCase || b->getFlowOp() == glslang::EOpDefault)) {
            if (!labels_open) groups.emplace_back();
            labels_open = true;
            if (b->getFlowOp() == glslang::EOpDefault) {
                groups.back().is_default = true;
            } else {
                groups.back().labels.push_back(eval(b->getExpression())[0].reg);
            }
            continue;
        }
        labels_open = false;
        if (groups.empty()) refuse(n, "a statement before the switch's first case");
        groups.back().code.push_back(n);
    }
    const ir::Op equal = ir::Op::IEqual;
    std::uint32_t any_case = bool_constant(false);
    for (const Group& g : groups) {
        for (std::uint32_t l : g.labels) any_case = emit1(ir::Op::BOr, B::Bool, any_case, emit1(equal, B::Bool, selector[0].reg, l, 0, bank));
    }
    const std::uint32_t no_case = emit1(ir::Op::BNot, B::Bool, any_case);
    const Slot falling{B::Bool, allocate(B::Bool, Space::Temp)};
    move(falling, {B::Bool, bool_constant(false)}, false);
    emit(ir::Op::SwitchBegin);
    ++loops_;
    for (const Group& g : groups) {
        std::uint32_t enter = falling.reg;
        for (std::uint32_t l : g.labels) enter = emit1(ir::Op::BOr, B::Bool, enter, emit1(equal, B::Bool, selector[0].reg, l, 0, bank));
        if (g.is_default) enter = emit1(ir::Op::BOr, B::Bool, enter, no_case);
        move(falling, {B::Bool, enter}, false);
        const std::size_t at_if = stage_.code.size();
        emit(ir::Op::If).a = falling.reg;
        for (TIntermNode* n : g.code) statement(n);
        const std::size_t at_end = stage_.code.size();
        emit(ir::Op::EndIf);
        stage_.code[at_if].target = std::uint32_t(at_end);
    }
    --loops_;
    emit(ir::Op::SwitchEnd);
}

// Every local of a function body gets its registers at the call, zeroed unless its first use
// is an assignment at the body's top level that does not read it (a declaration with an
// initialiser). GLSL leaves an uninitialised local undefined; zero makes every run give the
// same image, whatever the batch before left in the registers.
void StageLowering::initialise_locals(TIntermAggregate* body, const std::set<long long>& parameters) {
    class Uses : public glslang::TIntermTraverser {
    public:
        std::vector<glslang::TIntermSymbol*> order;
        std::set<long long> seen;
        bool visitBinary(glslang::TVisit visit, glslang::TIntermBinary* node) override {
            if (visit != glslang::EvPreVisit || node->getOp() != glslang::EOpAssign) return true;
            // the value before the target: `x = x + 1.0` reads x first
            node->getRight()->traverse(this);
            node->getLeft()->traverse(this);
            return false;
        }
        void visitSymbol(glslang::TIntermSymbol* s) override {
            if (seen.insert(s->getId()).second) order.push_back(s);
        }
    };
    std::set<long long> declared_first;  // first seen as an initialised declaration
    std::set<long long> seen;
    // The body's statements, a declaration of several variables (a sequence of assignments, as
    // glslang keeps `float a = x, b = y;`) opened into its assignments.
    std::vector<TIntermNode*> top;
    for (TIntermNode* n : body->getSequence()) {
        auto* a = n ? n->getAsAggregate() : nullptr;
        if (a && a->getOp() == glslang::EOpSequence) {
            for (TIntermNode* m : a->getSequence()) top.push_back(m);
        } else {
            top.push_back(n);
        }
    }
    for (TIntermNode* n : top) {
        if (!n) continue;
        if (auto* b = n->getAsBinaryNode(); b && b->getOp() == glslang::EOpAssign) {
            if (auto* s = b->getLeft()->getAsSymbolNode(); s && !seen.count(s->getId())) {
                Uses right;
                b->getRight()->traverse(&right);
                if (!right.seen.count(s->getId())) declared_first.insert(s->getId());
            }
        }
        Uses u;
        n->traverse(&u);
        seen.insert(u.seen.begin(), u.seen.end());
    }
    Uses all;
    body->traverse(&all);
    Frame& frame = frames_.back();
    for (glslang::TIntermSymbol* s : all.order) {
        const glslang::TStorageQualifier q = s->getQualifier().storage;
        if (q != glslang::EvqTemporary && !(q == glslang::EvqConst && s->getConstArray().size() == 0)) continue;
        if (parameters.count(s->getId()) || frame.locals.count(s->getId())) continue;
        if (s->getBasicType() == glslang::EbtSampler) continue;
        Place p = allocate(s->getType(), Space::Variable);
        if (!declared_first.count(s->getId())) {
            for (const Slot& r : p) move(r, {r.bank, constant(r.bank, 0)}, false);
        }
        frame.locals.emplace(s->getId(), std::move(p));
    }
}

}  // namespace qs::frontend
