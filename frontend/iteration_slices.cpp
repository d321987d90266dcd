#include "frontend/iteration_slices.h"

#include <algorithm>
#include <map>
#include <set>
#include <string>

#include "frontend/glsl_statements.h"
#include "frontend/variable_writes.h"

namespace qs::frontend {

namespace {

using glslang::TIntermAggregate;
using ::TIntermNode;
using glslang::TIntermBinary;
using glslang::TType;
using glslang::TIntermSymbol;
using glslang::TIntermTyped;
using glslang::TOperator;

bool is_constructor(TOperator op) { return op > glslang::EOpConstructGuardStart && op < glslang::EOpConstructGuardEnd; }

// An operation whose result is its operands' alone: not a derivative, an interpolation, a
// texture or image access, a barrier or an atomic; not a discard (a branch other than return,
// break and continue).
bool computes_only(TOperator op) {
    if (op >= glslang::EOpImageGuardBegin) return false;
    if (op >= glslang::EOpDPdx && op < glslang::EOpConstructGuardStart) {
        return op == glslang::EOpReturn || op == glslang::EOpBreak || op == glslang::EOpContinue;
    }
    return op != glslang::EOpSpirvInst;
}

// The values a stage's function may read and write where it computes only: its parameters,
// locals and constants.
bool own_storage(glslang::TStorageQualifier q) {
    return q == glslang::EvqTemporary || q == glslang::EvqIn || q == glslang::EvqConstReadOnly || q == glslang::EvqConst;
}

// Functions that compute only from their `in` parameters, with how many operations a call runs
// (each loop's body once: the part's cost is a lower bound).
class PureFunctions {
public:
    explicit PureFunctions(TIntermAggregate* root) {
        if (!root) return;
        for (TIntermNode* n : root->getSequence()) {
            TIntermAggregate* a = n->getAsAggregate();
            if (a && a->getOp() == glslang::EOpFunction) definitions_[a->getName().c_str()] = a;
        }
    }

    // The operations a call of `mangled` runs, or nothing where it is not pure.
    std::optional<int> operations(const std::string& mangled) {
        if (auto it = known_.find(mangled); it != known_.end()) return it->second;
        known_[mangled] = std::nullopt;  // GLSL has no recursion; a cycle would not be pure
        auto def = definitions_.find(mangled);
        if (def == definitions_.end()) return std::nullopt;
        const glslang::TIntermSequence& parts = def->second->getSequence();
        if (!parts.empty() && parts[0]) {
            for (TIntermNode* p : parts[0]->getAsAggregate()->getSequence()) {
                TIntermSymbol* s = p->getAsSymbolNode();
                if (s && s->getQualifier().storage != glslang::EvqIn && s->getQualifier().storage != glslang::EvqConstReadOnly &&
                    s->getQualifier().storage != glslang::EvqTemporary) {
                    return std::nullopt;
                }
            }
        }
        struct Body : glslang::TIntermTraverser {
            PureFunctions* functions = nullptr;
            bool pure = true;
            int operations = 0;
            void visitSymbol(TIntermSymbol* s) override { pure = pure && own_storage(s->getQualifier().storage); }
            bool visitBinary(glslang::TVisit, TIntermBinary* b) override { return count(b->getOp()); }
            bool visitUnary(glslang::TVisit, glslang::TIntermUnary* u) override { return count(u->getOp()); }
            bool visitBranch(glslang::TVisit, glslang::TIntermBranch* b) override {
                pure = pure && computes_only(b->getFlowOp());
                return pure;
            }
            bool visitAggregate(glslang::TVisit, TIntermAggregate* a) override {
                const TOperator op = a->getOp();
                if (op == glslang::EOpFunctionCall) {
                    const std::optional<int> callee = functions->operations(a->getName().c_str());
                    pure = pure && callee.has_value();
                    operations += callee.value_or(0);
                    return pure;
                }
                if (op == glslang::EOpSequence || op == glslang::EOpParameters || op == glslang::EOpFunction) return true;
                return count(op);
            }
            bool visitSelection(glslang::TVisit, glslang::TIntermSelection*) override { return pure; }
            bool visitLoop(glslang::TVisit, glslang::TIntermLoop*) override { return pure; }
            bool visitSwitch(glslang::TVisit, glslang::TIntermSwitch*) override { return pure; }
            bool count(TOperator op) {
                pure = pure && computes_only(op);
                if (op != glslang::EOpVectorSwizzle && op != glslang::EOpIndexDirect && op != glslang::EOpIndexDirectStruct &&
                    !is_constructor(op)) {
                    ++operations;
                }
                return pure;
            }
        } body;
        body.functions = this;
        if (parts.size() > 1 && parts[1]) parts[1]->traverse(&body);
        if (!body.pure) return std::nullopt;
        known_[mangled] = body.operations;
        return body.operations;
    }

private:
    std::map<std::string, TIntermAggregate*> definitions_;
    std::map<std::string, std::optional<int>> known_;
};

// One loop of the nest: `for (int i = A; i < B; i++)` or `i <= B`, its counter a plain C++ int.
struct Level {
    TIntermSymbol* counter = nullptr;
    int first = 0, count = 0;
};

std::optional<Level> level_of(glslang::TIntermLoop* loop, TIntermBinary* init, const std::function<bool(long long)>& plain_counter) {
    if (!loop || !init || !loop->testFirst()) return std::nullopt;
    TIntermSymbol* counter = init->getLeft()->getAsSymbolNode();
    auto* from = init->getRight()->getAsConstantUnion();
    if (!counter || !from || !plain_counter(counter->getId()) || counter->getType().getBasicType() != glslang::EbtInt) return std::nullopt;
    auto* test = loop->getTest() ? loop->getTest()->getAsBinaryNode() : nullptr;
    if (!test || (test->getOp() != glslang::EOpLessThan && test->getOp() != glslang::EOpLessThanEqual)) return std::nullopt;
    auto* bound = test->getRight()->getAsConstantUnion();
    auto* tested = test->getLeft()->getAsSymbolNode();
    if (!bound || !tested || tested->getId() != counter->getId()) return std::nullopt;
    auto* step = loop->getTerminal() ? loop->getTerminal()->getAsUnaryNode() : nullptr;
    if (!step || (step->getOp() != glslang::EOpPostIncrement && step->getOp() != glslang::EOpPreIncrement)) return std::nullopt;
    const long long a = from->getConstArray()[0].getIConst();
    const long long b = bound->getConstArray()[0].getIConst() + (test->getOp() == glslang::EOpLessThanEqual ? 1 : 0);
    if (b <= a || b - a > kMostIterations) return std::nullopt;
    return Level{counter, int(a), int(b - a)};
}

// Whether a loop's body lets lanes leave or skip it: a break, continue, return or discard.
bool leaves(TIntermNode* body) {
    struct Finder : glslang::TIntermTraverser {
        bool found = false;
        bool visitBranch(glslang::TVisit, glslang::TIntermBranch*) override { return !(found = true); }
    } f;
    if (body) body->traverse(&f);
    return f.found;
}

// The statements of a loop's body (a block, or one statement).
std::vector<TIntermNode*> statements(TIntermNode* body) {
    TIntermAggregate* a = body ? body->getAsAggregate() : nullptr;
    if (!a || a->getOp() != glslang::EOpSequence || is_for_sequence(a)) return {body};
    return statements_of(a);
}

// What a declaration's value reads, and whether the part may hold it.
struct Reads {
    bool ok = true;
    int operations = 0;
    std::vector<long long> inputs;
};

class ValueReader {
public:
    ValueReader(PureFunctions& functions, const std::set<long long>& counters, const std::set<long long>& part,
                const std::set<long long>& written, const std::function<LocalAtNest(long long)>& local)
        : functions_(functions), counters_(counters), part_(part), written_(written), local_(local) {}

    void read(TIntermTyped* n, Reads& r) {
        if (!r.ok) return;
        if (n->getAsConstantUnion()) return;
        if (TIntermSymbol* s = n->getAsSymbolNode()) return symbol(s, r);
        if (TIntermBinary* b = n->getAsBinaryNode()) {
            const TOperator op = b->getOp();
            // An index the counters choose would be a per-lane index in the part: not taken.
            if (!computes_only(op) || op >= glslang::EOpAssign || op == glslang::EOpIndexIndirect) return void(r.ok = false);
            read(b->getLeft(), r);
            if (op == glslang::EOpVectorSwizzle || op == glslang::EOpIndexDirect || op == glslang::EOpIndexDirectStruct) return;
            ++r.operations;
            return read(b->getRight(), r);
        }
        if (glslang::TIntermUnary* u = n->getAsUnaryNode()) {
            const TOperator op = u->getOp();
            if (!computes_only(op) || (op >= glslang::EOpPostIncrement && op <= glslang::EOpPreDecrement)) return void(r.ok = false);
            ++r.operations;
            return read(u->getOperand(), r);
        }
        if (TIntermAggregate* a = n->getAsAggregate()) {
            const TOperator op = a->getOp();
            if (op == glslang::EOpFunctionCall) {
                const std::optional<int> callee = functions_.operations(a->getName().c_str());
                if (!callee) return void(r.ok = false);
                r.operations += *callee;
            } else if (op == glslang::EOpModf || op == glslang::EOpFrexp || !computes_only(op) || op >= glslang::EOpAssign) {
                return void(r.ok = false);
            } else if (!is_constructor(op)) {
                ++r.operations;
            }
            for (TIntermNode* arg : a->getSequence()) {
                if (TIntermTyped* t = arg->getAsTyped()) read(t, r);
                else r.ok = false;
            }
            return;
        }
        if (glslang::TIntermSelection* s = n->getAsSelectionNode()) {
            if (!s->getTrueBlock() || !s->getFalseBlock()) return void(r.ok = false);
            read(s->getCondition(), r);
            read(s->getTrueBlock()->getAsTyped(), r);
            read(s->getFalseBlock()->getAsTyped(), r);
            ++r.operations;
            return;
        }
        r.ok = false;
    }

private:
    PureFunctions& functions_;
    const std::set<long long>& counters_;
    const std::set<long long>& part_;
    const std::set<long long>& written_;
    const std::function<LocalAtNest(long long)>& local_;

    void symbol(TIntermSymbol* s, Reads& r) {
        const long long id = s->getId();
        const TType& t = s->getType();
        if (t.getQualifier().storage == glslang::EvqConst && s->getConstArray().size() > 0 && !t.isArray()) return;
        if (counters_.contains(id) || part_.contains(id)) return;
        if (t.getQualifier().storage != glslang::EvqTemporary && t.getQualifier().storage != glslang::EvqIn &&
            t.getQualifier().storage != glslang::EvqConstReadOnly) {
            r.ok = false;  // a global: an input, uniform or variable of the stage
            return;
        }
        const LocalAtNest at = local_(id);
        if (at == LocalAtNest::PlainCounter) return;
        const glslang::TBasicType b = t.getBasicType();
        if (at != LocalAtNest::DeclaredBefore || written_.contains(id) || t.isArray() || t.isMatrix() || t.isStruct() ||
            (b != glslang::EbtFloat && b != glslang::EbtInt)) {
            r.ok = false;
            return;
        }
        if (std::find(r.inputs.begin(), r.inputs.end(), id) == r.inputs.end()) r.inputs.push_back(id);
    }
};

}  // namespace

std::optional<IterationSlice> iteration_slice(glslang::TIntermLoop* loop, TIntermBinary* init, TIntermAggregate* root,
                                              const std::function<bool(long long)>& plain_counter,
                                              const std::function<LocalAtNest(long long)>& local) {
    IterationSlice slice;
    glslang::TIntermLoop* outer = loop;
    int iterations = 1;
    TIntermNode* body = nullptr;
    for (;;) {
        const std::optional<Level> level = level_of(loop, init, plain_counter);
        if (!level || leaves(loop->getBody()) || iterations * level->count > kMostIterations) return std::nullopt;
        iterations *= level->count;
        slice.loops.push_back(loop);
        slice.counters.push_back(level->counter);
        slice.first.push_back(level->first);
        slice.count.push_back(level->count);
        body = loop->getBody();
        const std::vector<TIntermNode*> s = statements(body);
        TIntermAggregate* inner = s.size() == 1 && s[0] ? s[0]->getAsAggregate() : nullptr;
        if (!is_for_sequence(inner)) break;
        const std::vector<TIntermNode*> parts = statements_of(inner);
        init = parts[0]->getAsBinaryNode();
        loop = parts[1]->getAsLoopNode();
    }

    std::set<long long> written, counters, part;
    for_each_write(outer, [&](long long id, TIntermTyped*) { written.insert(id); });
    for (TIntermSymbol* c : slice.counters) counters.insert(c->getId());
    PureFunctions functions(root);
    ValueReader reader(functions, counters, part, written, local);
    for (TIntermNode* n : statements(body)) {
        auto* d = n ? n->getAsBinaryNode() : nullptr;
        TIntermSymbol* target = d && d->getOp() == glslang::EOpAssign ? d->getLeft()->getAsSymbolNode() : nullptr;
        // Not a declaration: an assignment to a variable declared before, or one the part declared.
        if (!target || local(target->getId()) == LocalAtNest::DeclaredBefore || part.contains(target->getId())) break;
        const TType& t = target->getType();
        if (t.getBasicType() != glslang::EbtFloat || t.isArray() || t.isMatrix() || t.isStruct()) break;
        Reads r;
        reader.read(d->getRight(), r);
        const bool same_inputs =
            slice.inputs.empty() || std::all_of(r.inputs.begin(), r.inputs.end(), [&](long long id) {
                return std::find(slice.inputs.begin(), slice.inputs.end(), id) != slice.inputs.end();
            });
        if (!r.ok || !same_inputs) break;
        if (slice.inputs.empty()) slice.inputs = r.inputs;
        slice.declarations.push_back(d);
        slice.operations += r.operations;
        part.insert(target->getId());
    }
    if (slice.declarations.empty() || slice.operations < kLeastOperations) return std::nullopt;
    return slice;
}

}  // namespace qs::frontend
