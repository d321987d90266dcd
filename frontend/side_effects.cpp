#include "frontend/side_effects.h"

namespace qs::frontend {

namespace {

class SideEffects : public glslang::TIntermTraverser {
public:
    bool found = false;

    bool visitBinary(glslang::TVisit, glslang::TIntermBinary* node) override {
        switch (node->getOp()) {
            case glslang::EOpAssign: case glslang::EOpAddAssign: case glslang::EOpSubAssign: case glslang::EOpMulAssign:
            case glslang::EOpDivAssign: case glslang::EOpModAssign: case glslang::EOpAndAssign:
            case glslang::EOpInclusiveOrAssign: case glslang::EOpExclusiveOrAssign: case glslang::EOpLeftShiftAssign:
            case glslang::EOpRightShiftAssign: case glslang::EOpVectorTimesScalarAssign:
            case glslang::EOpMatrixTimesScalarAssign: case glslang::EOpVectorTimesMatrixAssign:
            case glslang::EOpMatrixTimesMatrixAssign:
                found = true;
                return false;
            default: return !found;
        }
    }
    bool visitUnary(glslang::TVisit, glslang::TIntermUnary* node) override {
        switch (node->getOp()) {
            case glslang::EOpPostIncrement: case glslang::EOpPostDecrement: case glslang::EOpPreIncrement:
            case glslang::EOpPreDecrement:
                found = true;
                return false;
            default: return !found;
        }
    }
    bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* node) override {
        // A user function, and the built-ins with out parameters.
        const glslang::TOperator op = node->getOp();
        if ((op == glslang::EOpFunctionCall && node->isUserDefined()) || op == glslang::EOpModf ||
            op == glslang::EOpFrexp || op == glslang::EOpAddCarry || op == glslang::EOpSubBorrow ||
            op == glslang::EOpUMulExtended || op == glslang::EOpIMulExtended) {
            found = true;
            return false;
        }
        return !found;
    }
    bool visitSelection(glslang::TVisit, glslang::TIntermSelection*) override { return !found; }
};

}  // namespace

bool has_side_effects(TIntermNode* node) {
    if (!node) return false;
    SideEffects v;
    node->traverse(&v);
    return v.found;
}

}  // namespace qs::frontend
