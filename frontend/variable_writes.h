#pragma once
// Every write to a variable in a piece of glslang's syntax tree: what the translation writer
// registers with a Loop and the loop bound reads a counter's steps from, so that both see the
// same writes.

#include <cstddef>

#include <glslang/Include/intermediate.h>

namespace qs::frontend {

// Calls write(id, value) for each write in `n`: an assignment, plain or compound, ++ and --, a
// function's out and inout arguments, and the out arguments of the built-in functions that have
// them (modf, frexp, uaddCarry, usubBorrow, umulExtended, imulExtended). `id` is the written
// variable's symbol id; `value` is the value assigned where a plain assignment writes the whole
// variable, else null. A write to a part of a variable (a component, a member, an element) is a
// write to the variable.
template <class Write>
void for_each_write(TIntermNode* n, const Write& write) {
    struct Finder : glslang::TIntermTraverser {
        const Write* write = nullptr;
        void target(glslang::TIntermTyped* t, glslang::TIntermTyped* value) {
            if (!t) return;
            while (auto* b = t->getAsBinaryNode()) t = b->getLeft(), value = nullptr;
            if (auto* s = t->getAsSymbolNode()) (*write)(s->getId(), value);
        }
        void arguments_from(glslang::TIntermAggregate* a, std::size_t first) {
            for (std::size_t i = first; i < a->getSequence().size(); ++i) target(a->getSequence()[i]->getAsTyped(), nullptr);
        }
        bool visitBinary(glslang::TVisit, glslang::TIntermBinary* b) override {
            if (b->getOp() == glslang::EOpAssign) target(b->getLeft(), b->getRight());
            else if (b->getOp() > glslang::EOpAssign && b->getOp() <= glslang::EOpRightShiftAssign) target(b->getLeft(), nullptr);
            return true;
        }
        bool visitUnary(glslang::TVisit, glslang::TIntermUnary* u) override {
            if (u->getOp() >= glslang::EOpPostIncrement && u->getOp() <= glslang::EOpPreDecrement) target(u->getOperand(), nullptr);
            return true;
        }
        bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* a) override {
            switch (a->getOp()) {
                case glslang::EOpFunctionCall: {
                    const glslang::TQualifierList& q = a->getQualifierList();
                    for (std::size_t i = 0; i < a->getSequence().size() && i < q.size(); ++i) {
                        if (q[i] == glslang::EvqOut || q[i] == glslang::EvqInOut) target(a->getSequence()[i]->getAsTyped(), nullptr);
                    }
                    break;
                }
                case glslang::EOpModf: case glslang::EOpFrexp: arguments_from(a, 1); break;
                case glslang::EOpAddCarry: case glslang::EOpSubBorrow: arguments_from(a, 2); break;
                case glslang::EOpUMulExtended: case glslang::EOpIMulExtended: arguments_from(a, 2); break;
                default: break;
            }
            return true;
        }
    } f;
    f.write = &write;
    if (n) n->traverse(&f);
}

}  // namespace qs::frontend
