#pragma once
// Statements as glslang's syntax tree holds them: a declaration is a sequence of its declarators'
// initialisations, a for loop a sequence of its initialiser and the loop. What the C++ writer
// and the analyses it runs read a block as.

#include <vector>

#include <glslang/Include/intermediate.h>

namespace qs::frontend {

// A declaration statement: a sequence of its declarators' initialisations.
inline bool is_declaration(TIntermNode* n) {
    auto* a = n ? n->getAsAggregate() : nullptr;
    if (!a || a->getOp() != glslang::EOpSequence || a->getSequence().empty()) return false;
    for (TIntermNode* c : a->getSequence()) {
        auto* b = c->getAsBinaryNode();
        if (!b || b->getOp() != glslang::EOpAssign || !b->getLeft()->getAsSymbolNode()) return false;
    }
    return true;
}

// The statements of a block, declarations' declarators as statements of their own.
inline std::vector<TIntermNode*> statements_of(glslang::TIntermAggregate* a) {
    std::vector<TIntermNode*> out;
    for (TIntermNode* c : a->getSequence()) {
        if (is_declaration(c)) {
            for (TIntermNode* d : c->getAsAggregate()->getSequence()) out.push_back(d);
        } else {
            out.push_back(c);
        }
    }
    return out;
}

// A for loop as glslang nests it: its initialiser (one declarator) and the loop.
inline bool is_for_sequence(glslang::TIntermAggregate* a) {
    if (!a || a->getOp() != glslang::EOpSequence) return false;
    const std::vector<TIntermNode*> s = statements_of(a);
    return s.size() == 2 && s[1]->getAsLoopNode() && s[0]->getAsBinaryNode() &&
           s[0]->getAsBinaryNode()->getOp() == glslang::EOpAssign;
}

}  // namespace qs::frontend
