#include "frontend/loop_bound.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glslang/Include/intermediate.h>

namespace qs::frontend {
namespace {

using glslang::TIntermAggregate;
using glslang::TIntermBinary;
using glslang::TIntermLoop;
using glslang::TIntermTyped;

constexpr long long kMany = 1LL << 40;  // past any limit; sums and products stop growing here

long long add(long long a, long long b) { return std::min(a + b, kMany); }
long long times(long long a, long long b) { return a == 0 || b == 0 ? 0 : a > kMany / b ? kMany : std::min(a * b, kMany); }

// Variables written once, by an assignment of a constant (`float k = 5.0;` that nothing changes),
// by symbol id: their value.
using Constants = std::map<long long, double>;

// A scalar constant's value, or nothing for anything else.
std::optional<double> constant(TIntermNode* n, const Constants& known = {}) {
    if (auto* s = n ? n->getAsSymbolNode() : nullptr) {
        const auto it = known.find(s->getId());
        if (it != known.end()) return it->second;
    }
    auto* c = n ? n->getAsConstantUnion() : nullptr;
    if (!c || !c->getType().isScalar()) return std::nullopt;
    const glslang::TConstUnion& v = c->getConstArray()[0];
    switch (v.getType()) {
        case glslang::EbtFloat:
        case glslang::EbtDouble: return v.getDConst();  // glslang keeps a float constant as a double
        case glslang::EbtInt: return double(v.getIConst());
        case glslang::EbtUint: return double(v.getUConst());
        default: return std::nullopt;
    }
}

long long symbol_id(TIntermNode* n) {
    auto* s = n ? n->getAsSymbolNode() : nullptr;
    return s ? s->getId() : -1;
}

// Every write in `n` (assignment, ++/--, an out or inout argument): the variable's symbol id and
// the writing node, the value's for a plain assignment.
template <class Write>
void for_each_write(TIntermNode* n, const Write& write) {
    struct Finder : glslang::TIntermTraverser {
        const Write* write;
        void target(TIntermTyped* t, TIntermTyped* value) {
            while (auto* b = t->getAsBinaryNode()) t = b->getLeft(), value = nullptr;  // a part of it
            if (const long long id = symbol_id(t); id >= 0) (*write)(id, value);
        }
        bool visitBinary(glslang::TVisit, TIntermBinary* b) override {
            if (b->getOp() == glslang::EOpAssign) target(b->getLeft(), b->getRight());
            else if (b->getOp() > glslang::EOpAssign && b->getOp() <= glslang::EOpRightShiftAssign) target(b->getLeft(), nullptr);
            return true;
        }
        bool visitUnary(glslang::TVisit, glslang::TIntermUnary* u) override {
            if (u->getOp() >= glslang::EOpPostIncrement && u->getOp() <= glslang::EOpPreDecrement) target(u->getOperand(), nullptr);
            return true;
        }
        bool visitAggregate(glslang::TVisit, TIntermAggregate* a) override {
            if (a->getOp() == glslang::EOpFunctionCall) {
                const glslang::TQualifierList& q = a->getQualifierList();
                for (std::size_t i = 0; i < a->getSequence().size() && i < q.size(); ++i) {
                    if (q[i] == glslang::EvqOut || q[i] == glslang::EvqInOut) target(a->getSequence()[i]->getAsTyped(), nullptr);
                }
            }
            return true;
        }
    } f;
    f.write = &write;
    if (n) n->traverse(&f);
}

bool assigns(TIntermNode* n, long long id) {
    bool found = false;
    for_each_write(n, [&](long long written, TIntermTyped*) { found = found || written == id; });
    return found;
}

Constants constants_of(TIntermNode* root) {
    std::map<long long, int> writes;
    Constants values;
    for_each_write(root, [&](long long id, TIntermTyped* value) {
        if (++writes[id] > 1) values.erase(id);
        else if (const std::optional<double> v = constant(value)) values[id] = *v;
    });
    return values;
}

// How many times `loop`, whose counter `init` sets (or null), goes round at most: its counter run
// in GLSL's arithmetic (float, or 32-bit integers), or nothing where the loop is not of that form
// or goes round kLoopLimit times.
std::optional<long long> trips(TIntermLoop* loop, TIntermBinary* init, const Constants& known) {
    auto* test = loop->getTest() ? loop->getTest()->getAsBinaryNode() : nullptr;
    if (!init || !test) return std::nullopt;
    const long long id = symbol_id(init->getLeft());
    const std::optional<double> start = constant(init->getRight());
    if (id < 0 || !start) return std::nullopt;
    glslang::TOperator compare = test->getOp();
    std::optional<double> bound = constant(test->getRight(), known);
    if (symbol_id(test->getLeft()) != id) {  // the constant on the left: 10 > i is i < 10
        if (symbol_id(test->getRight()) != id) return std::nullopt;
        bound = constant(test->getLeft(), known);
        switch (compare) {
            case glslang::EOpLessThan: compare = glslang::EOpGreaterThan; break;
            case glslang::EOpGreaterThan: compare = glslang::EOpLessThan; break;
            case glslang::EOpLessThanEqual: compare = glslang::EOpGreaterThanEqual; break;
            case glslang::EOpGreaterThanEqual: compare = glslang::EOpLessThanEqual; break;
            default: break;
        }
    } else if (symbol_id(test->getRight()) == id) {
        return std::nullopt;
    }
    if (!bound) return std::nullopt;

    glslang::TOperator step = glslang::EOpNull;
    double by = 1.0;
    TIntermTyped* terminal = loop->getTerminal();
    if (auto* u = terminal ? terminal->getAsUnaryNode() : nullptr) {
        if (symbol_id(u->getOperand()) != id) return std::nullopt;
        const bool up = u->getOp() == glslang::EOpPostIncrement || u->getOp() == glslang::EOpPreIncrement;
        const bool down = u->getOp() == glslang::EOpPostDecrement || u->getOp() == glslang::EOpPreDecrement;
        if (!up && !down) return std::nullopt;
        step = up ? glslang::EOpAddAssign : glslang::EOpSubAssign;
    } else if (auto* b = terminal ? terminal->getAsBinaryNode() : nullptr) {
        const std::optional<double> v = constant(b->getRight(), known);
        if (symbol_id(b->getLeft()) != id || !v) return std::nullopt;
        step = b->getOp();
        by = *v;
    } else {
        return std::nullopt;
    }
    if (assigns(loop->getBody(), id) || assigns(loop->getTest(), id)) return std::nullopt;

    const bool is_float = init->getLeft()->getType().getBasicType() == glslang::EbtFloat;
    const bool is_uint = init->getLeft()->getType().getBasicType() == glslang::EbtUint;
    // The counter's next value, as GLSL computes it; nothing where an integer would overflow or
    // divide by zero.
    auto next = [&](double x) -> std::optional<double> {
        if (is_float) {
            const float a = float(x), b = float(by);
            switch (step) {
                case glslang::EOpAddAssign: return double(a + b);
                case glslang::EOpSubAssign: return double(a - b);
                case glslang::EOpMulAssign: return double(a * b);
                case glslang::EOpDivAssign: return double(a / b);
                default: return std::nullopt;
            }
        }
        const auto a = std::int64_t(x), b = std::int64_t(by);
        std::int64_t r;
        switch (step) {
            case glslang::EOpAddAssign: r = a + b; break;
            case glslang::EOpSubAssign: r = a - b; break;
            case glslang::EOpMulAssign: r = a * b; break;
            case glslang::EOpDivAssign:
                if (b == 0) return std::nullopt;
                r = a / b;
                break;
            default: return std::nullopt;
        }
        if (is_uint ? (r < 0 || r > INT64_C(0xffffffff)) : (r < INT32_MIN || r > INT32_MAX)) return std::nullopt;
        return double(r);
    };
    auto holds = [&](double x) {
        const double y = is_float ? double(float(x)) : x, c = is_float ? double(float(*bound)) : *bound;
        switch (compare) {
            case glslang::EOpLessThan: return y < c;
            case glslang::EOpLessThanEqual: return y <= c;
            case glslang::EOpGreaterThan: return y > c;
            case glslang::EOpGreaterThanEqual: return y >= c;
            case glslang::EOpNotEqual: return y != c;
            case glslang::EOpEqual: return y == c;
            default: return true;  // not a comparison: unknown, so never ending here
        }
    };
    double x = is_float ? double(float(*start)) : *start;
    long long n = 0;
    if (!loop->testFirst()) ++n, x = next(x).value_or(NAN);  // a do loop goes round once first
    for (; !std::isnan(x) && holds(x); ++n) {
        if (n >= kLoopLimit) return std::nullopt;
        const std::optional<double> v = next(x);
        if (!v) return std::nullopt;
        x = *v;
    }
    if (std::isnan(x)) return std::nullopt;
    return n;
}

// The statements of a sequence, declarations' initialisers among them.
std::vector<TIntermNode*> flattened(TIntermAggregate* a) {
    std::vector<TIntermNode*> out;
    for (TIntermNode* c : a->getSequence()) {
        auto* d = c ? c->getAsAggregate() : nullptr;
        if (d && d->getOp() == glslang::EOpSequence) {
            const std::vector<TIntermNode*> inner = flattened(d);
            out.insert(out.end(), inner.begin(), inner.end());
        } else {
            out.push_back(c);
        }
    }
    return out;
}

class Counter {
public:
    explicit Counter(TIntermNode* root) : constants_(constants_of(root)) {
        auto* top = root ? root->getAsAggregate() : nullptr;
        if (!top) return;
        for (TIntermNode* n : top->getSequence()) {
            auto* f = n->getAsAggregate();
            if (f && f->getOp() == glslang::EOpFunction) functions_[std::string(f->getName().c_str())] = f;
        }
    }

    // The iterations of one call of the function named `name` (glslang's mangled name).
    long long function(const std::string& name) {
        if (auto it = done_.find(name); it != done_.end()) return it->second;
        auto it = functions_.find(name);
        if (it == functions_.end()) return 0;
        done_[name] = kMany;  // GLSL has no recursion (the front end refuses it); this ends a cycle
        return done_[name] = of(it->second);
    }

    // The iterations of the loops in `n`, the loops of the functions it calls included.
    long long of(TIntermNode* n) {
        if (!n) return 0;
        struct Walker : glslang::TIntermTraverser {
            Counter* counter;
            long long total = 0;
            bool visitLoop(glslang::TVisit, TIntermLoop* l) override {
                total = add(total, counter->loop(l, nullptr));
                return false;
            }
            bool visitAggregate(glslang::TVisit, TIntermAggregate* a) override {
                if (a->getOp() == glslang::EOpFunctionCall && a->isUserDefined()) {
                    total = add(total, counter->function(std::string(a->getName().c_str())));
                    return true;  // and its arguments
                }
                if (a->getOp() != glslang::EOpSequence) return true;
                // A loop's counter is set by the statement before it (a for loop's initialiser).
                const std::vector<TIntermNode*> s = flattened(a);
                for (std::size_t i = 0; i < s.size(); ++i) {
                    TIntermLoop* l = s[i] ? s[i]->getAsLoopNode() : nullptr;
                    if (!l) {
                        total = add(total, counter->of(s[i]));
                        continue;
                    }
                    auto* init = i > 0 && s[i - 1] ? s[i - 1]->getAsBinaryNode() : nullptr;
                    total = add(total, counter->loop(l, init && init->getOp() == glslang::EOpAssign ? init : nullptr));
                }
                return false;
            }
        } w;
        w.counter = this;
        n->traverse(&w);
        return w.total;
    }

    // A loop's iterations, its inner loops' included: each time round counts once, as llvmpipe's
    // limiter counts.
    long long loop(TIntermLoop* l, TIntermBinary* init) {
        const std::optional<long long> n = trips(l, init, constants_);
        if (!n) {
            if (!unbounded_) unbounded_ = l;
            return kMany;
        }
        const long long inside = add(add(of(l->getBody()), of(l->getTerminal())), of(l->getTest()));
        return add(times(*n, add(1, inside)), of(l->getTest()));
    }

    const TIntermNode* unbounded() const { return unbounded_; }

private:
    Constants constants_;
    std::map<std::string, TIntermAggregate*> functions_;
    std::map<std::string, long long> done_;
    const TIntermNode* unbounded_ = nullptr;
};

}  // namespace

LoopBound loop_bound(glslang::TIntermediate& stage) {
    Counter c(stage.getTreeRoot());
    LoopBound b;
    b.iterations = c.function("main(");
    b.unbounded_loop = c.unbounded();
    return b;
}

}  // namespace qs::frontend
