#include "frontend/derivative_control.h"

#include <set>
#include <string>

namespace qs::frontend {

namespace {

struct Function {
    const char* name;
    glslang::TOperator op;
};

constexpr Function kFunctions[] = {
    {"dFdxFine", glslang::EOpDPdxFine},     {"dFdyFine", glslang::EOpDPdyFine},
    {"fwidthFine", glslang::EOpFwidthFine}, {"dFdxCoarse", glslang::EOpDPdxCoarse},
    {"dFdyCoarse", glslang::EOpDPdyCoarse}, {"fwidthCoarse", glslang::EOpFwidthCoarse},
};

}  // namespace

const char* derivative_control_declarations() {
    static const std::string text = [] {
        std::string t;
        for (const Function& f : kFunctions) {
            for (const char* type : {"float", "vec2", "vec3", "vec4"}) t += std::string(type) + " " + f.name + "(" + type + " p);\n";
        }
        return t;
    }();
    return text.c_str();
}

bool wants_derivative_control(const glslang::TIntermediate& stage) {
    return stage.getStage() == EShLangFragment && stage.getProfile() != EEsProfile && stage.getVersion() < 400 &&
           stage.getRequestedExtensions().count("GL_ARB_derivative_control") > 0;
}

void call_derivative_control_builtins(glslang::TIntermediate& stage) {
    glslang::TIntermAggregate* root = stage.getTreeRoot() ? stage.getTreeRoot()->getAsAggregate() : nullptr;
    if (!root) return;
    // The shader's own definitions keep their calls (a function it defines is its own).
    std::set<std::string> defined;
    for (TIntermNode* n : root->getSequence()) {
        glslang::TIntermAggregate* a = n->getAsAggregate();
        if (a && a->getOp() == glslang::EOpFunction) defined.insert(a->getName().c_str());
    }
    class Calls : public glslang::TIntermTraverser {
    public:
        explicit Calls(const std::set<std::string>& defined) : defined_(defined) {}
        bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* call) override {
            if (call->getOp() != glslang::EOpFunctionCall || defined_.count(call->getName().c_str()) > 0) return true;
            const std::string name = call->getName().c_str();
            for (const Function& f : kFunctions) {
                if (name.compare(0, name.find('('), f.name) == 0 && call->getSequence().size() == 1) call->setOperator(f.op);
            }
            return true;
        }

    private:
        const std::set<std::string>& defined_;
    };
    Calls calls(defined);
    root->traverse(&calls);
}

}  // namespace qs::frontend
