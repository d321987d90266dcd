#include "frontend/loop_bound.h"
#include "frontend/variable_writes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
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

// Variables, by symbol id, that hold a constant (`float k = 5.0;` that nothing changes): their value.
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

bool assigns(TIntermNode* n, long long id) {
    bool found = false;
    for_each_write(n, [&](long long written, TIntermTyped*) { found = found || written == id; });
    return found;
}

// The variables `root` writes once, by assigning a constant: their value.
Constants written_once(TIntermNode* root) {
    std::map<long long, int> writes;
    Constants values;
    for_each_write(root, [&](long long id, TIntermTyped* value) {
        if (++writes[id] > 1) values.erase(id);
        else if (const std::optional<double> v = constant(value)) values[id] = *v;
    });
    return values;
}

// `n` as the assignment of a constant to a variable written nowhere else, or nothing.
std::optional<std::pair<long long, double>> constant_set(TIntermNode* n, const Constants& once) {
    auto* b = n ? n->getAsBinaryNode() : nullptr;
    if (!b || b->getOp() != glslang::EOpAssign) return std::nullopt;
    const auto it = once.find(symbol_id(b->getLeft()));
    if (it == once.end()) return std::nullopt;
    return *it;
}

// A loop of the counted form: its counter starts at `start`, moves by `step` `by` each time round,
// and the loop goes round while `counter compare bound`.
struct CountedLoop {
    double start = 0, bound = 0, by = 1;
    glslang::TOperator compare = glslang::EOpNull, step = glslang::EOpNull;
    glslang::TBasicType type = glslang::EbtInt;
    bool test_first = true;  // false: a do loop
};

// The comparison `c` with its sides swapped: 10 > i is i < 10.
glslang::TOperator swapped(glslang::TOperator c) {
    switch (c) {
        case glslang::EOpLessThan: return glslang::EOpGreaterThan;
        case glslang::EOpGreaterThan: return glslang::EOpLessThan;
        case glslang::EOpLessThanEqual: return glslang::EOpGreaterThanEqual;
        case glslang::EOpGreaterThanEqual: return glslang::EOpLessThanEqual;
        default: return c;
    }
}

// `loop`, whose counter `init` sets (or null), read as a counted loop, or nothing where it is not
// one: a test that is not the counter against a constant, a step that is not a constant one, or a
// body that changes the counter.
std::optional<CountedLoop> counted(TIntermLoop* loop, TIntermBinary* init, const Constants& known) {
    auto* test = loop->getTest() ? loop->getTest()->getAsBinaryNode() : nullptr;
    if (!init || !test) return std::nullopt;
    // A local: a global could be changed by a function the loop calls.
    auto* counter = init->getLeft()->getAsSymbolNode();
    if (!counter || counter->getQualifier().storage != glslang::EvqTemporary) return std::nullopt;
    const long long id = counter->getId();
    const std::optional<double> start = constant(init->getRight());
    if (!start) return std::nullopt;
    CountedLoop c{.start = *start, .type = init->getLeft()->getType().getBasicType(), .test_first = loop->testFirst()};
    std::optional<double> bound;
    if (symbol_id(test->getLeft()) == id && symbol_id(test->getRight()) != id) {
        c.compare = test->getOp(), bound = constant(test->getRight(), known);
    } else if (symbol_id(test->getRight()) == id && symbol_id(test->getLeft()) != id) {
        c.compare = swapped(test->getOp()), bound = constant(test->getLeft(), known);
    }
    if (!bound) return std::nullopt;
    c.bound = *bound;

    TIntermTyped* terminal = loop->getTerminal();
    if (auto* u = terminal ? terminal->getAsUnaryNode() : nullptr) {
        const glslang::TOperator op = u->getOp();
        const bool up = op == glslang::EOpPostIncrement || op == glslang::EOpPreIncrement;
        const bool down = op == glslang::EOpPostDecrement || op == glslang::EOpPreDecrement;
        if (symbol_id(u->getOperand()) != id || (!up && !down)) return std::nullopt;
        c.step = up ? glslang::EOpAddAssign : glslang::EOpSubAssign;
    } else if (auto* b = terminal ? terminal->getAsBinaryNode() : nullptr) {
        const std::optional<double> by = constant(b->getRight(), known);
        if (symbol_id(b->getLeft()) != id || !by) return std::nullopt;
        c.step = b->getOp(), c.by = *by;
    } else {
        return std::nullopt;
    }
    if (assigns(loop->getBody(), id) || assigns(loop->getTest(), id)) return std::nullopt;
    return c;
}

// The counter's next value, as GLSL computes it (float, or 32-bit integers); nothing where an
// integer would overflow or divide by zero, or for another step.
std::optional<double> next(const CountedLoop& c, double x) {
    if (c.type == glslang::EbtFloat) {
        const float a = float(x), b = float(c.by);
        switch (c.step) {
            case glslang::EOpAddAssign: return double(a + b);
            case glslang::EOpSubAssign: return double(a - b);
            case glslang::EOpMulAssign: return double(a * b);
            case glslang::EOpDivAssign: return double(a / b);
            default: return std::nullopt;
        }
    }
    const auto a = std::int64_t(x), b = std::int64_t(c.by);
    std::int64_t r;
    switch (c.step) {
        case glslang::EOpAddAssign: r = a + b; break;
        case glslang::EOpSubAssign: r = a - b; break;
        case glslang::EOpMulAssign: r = a * b; break;
        case glslang::EOpDivAssign:
            if (b == 0) return std::nullopt;
            r = a / b;
            break;
        default: return std::nullopt;
    }
    const bool fits = c.type == glslang::EbtUint ? r >= 0 && r <= INT64_C(0xffffffff) : r >= INT32_MIN && r <= INT32_MAX;
    return fits ? std::optional<double>(double(r)) : std::nullopt;
}

// Whether a loop goes round again with its counter at x.
bool holds(const CountedLoop& c, double x) {
    const bool f = c.type == glslang::EbtFloat;
    const double y = f ? double(float(x)) : x, bound = f ? double(float(c.bound)) : c.bound;
    switch (c.compare) {
        case glslang::EOpLessThan: return y < bound;
        case glslang::EOpLessThanEqual: return y <= bound;
        case glslang::EOpGreaterThan: return y > bound;
        case glslang::EOpGreaterThanEqual: return y >= bound;
        case glslang::EOpNotEqual: return y != bound;
        case glslang::EOpEqual: return y == bound;
        default: return true;  // not a comparison: unknown, so never ending here
    }
}

// How many times a counted loop goes round, its counter run; nothing where it reaches kLoopLimit.
std::optional<long long> trips(const CountedLoop& c) {
    double x = c.type == glslang::EbtFloat ? double(float(c.start)) : c.start;
    long long n = 0;
    for (bool first = true; (!c.test_first && first) || holds(c, x); first = false, ++n) {
        if (n >= kLoopLimit) return std::nullopt;
        const std::optional<double> v = next(c, x);
        if (!v || std::isnan(*v)) return std::nullopt;
        x = *v;
    }
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
    explicit Counter(TIntermNode* root) : once_(written_once(root)) {
        auto* top = root ? root->getAsAggregate() : nullptr;
        if (!top) return;
        for (TIntermNode* n : top->getSequence()) {
            auto* f = n->getAsAggregate();
            if (f && f->getOp() == glslang::EOpFunction) {
                functions_[std::string(f->getName().c_str())] = f;
            } else if (f && f->getOp() == glslang::EOpSequence) {  // globals' initialisers, run before main()
                for (TIntermNode* g : flattened(f)) {
                    if (const auto set = constant_set(g, once_)) globals_.insert(*set);
                }
            }
        }
    }

    // The iterations of one call of the function named `name` (glslang's mangled name).
    long long function(const std::string& name) {
        if (auto it = done_.find(name); it != done_.end()) return it->second;
        auto it = functions_.find(name);
        if (it == functions_.end()) return 0;
        done_[name] = kMany;  // GLSL has no recursion (the front end refuses it); this ends a cycle
        Constants caller = std::exchange(known_, globals_);  // what it knows is its own and the globals'
        const long long n = of(it->second);
        known_ = std::move(caller);
        return done_[name] = n;
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
                // In order: a loop's counter is set by the statement before it (a for loop's
                // initialiser), and a constant set once is known from there to the sequence's end.
                const std::vector<TIntermNode*> s = flattened(a);
                std::vector<long long> set_here;
                for (std::size_t i = 0; i < s.size(); ++i) {
                    if (const auto set = constant_set(s[i], counter->once_); set && counter->known_.insert(*set).second) {
                        set_here.push_back(set->first);
                    }
                    TIntermLoop* l = s[i] ? s[i]->getAsLoopNode() : nullptr;
                    if (!l) {
                        total = add(total, counter->of(s[i]));
                        continue;
                    }
                    auto* init = i > 0 && s[i - 1] ? s[i - 1]->getAsBinaryNode() : nullptr;
                    total = add(total, counter->loop(l, init && init->getOp() == glslang::EOpAssign ? init : nullptr));
                }
                for (long long id : set_here) counter->known_.erase(id);
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
        const std::optional<CountedLoop> c = counted(l, init, known_);
        const std::optional<long long> n = c ? trips(*c) : std::nullopt;
        if (!n) {
            if (!unbounded_) unbounded_ = l;
            return kMany;
        }
        const long long inside = add(add(of(l->getBody()), of(l->getTerminal())), of(l->getTest()));
        return add(times(*n, add(1, inside)), of(l->getTest()));
    }

    const TIntermNode* unbounded() const { return unbounded_; }

private:
    Constants once_;     // variables written once, by assigning a constant
    Constants globals_;  // of those, the globals set before main() runs
    Constants known_;    // of those, the ones set where the walk is
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
