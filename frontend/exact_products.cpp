#include "frontend/exact_products.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "frontend/variable_writes.h"

namespace qs::frontend {

using glslang::TIntermAggregate;
using glslang::TIntermBinary;

using glslang::TIntermSymbol;
using glslang::TIntermTyped;
using glslang::TIntermUnary;
using glslang::TOperator;
using glslang::TType;

namespace {

using Num = KnownNumber;
using Value = std::vector<Num>;  // one per component; empty: a value the analysis does not follow

constexpr double kExactBelow = 16777216.0;  // 2^24: every whole number below it is a float
constexpr double kRealBound = 0x1p100;      // finite values kept far from overflow
constexpr long kBudget = 2'000'000;         // nodes visited before the analysis gives up

Num unknown() { return {}; }
Num integral() { return {Num::Integral, 0.0, 0.0, true}; }

bool is_whole(const Num& n) { return n.kind == Num::Whole; }
bool is_integral(const Num& n) { return n.kind == Num::Whole || n.kind == Num::Integral; }
bool is_bounded(const Num& n) { return n.kind == Num::Whole || n.kind == Num::Real; }

// Whole numbers in [lo, hi]: a float's rounding keeps a whole number whole, so beyond 2^24 they
// are still whole, only no longer exact.
Num whole(double lo, double hi, bool nan) {
    if (std::max(std::fabs(lo), std::fabs(hi)) < kExactBelow) return {Num::Whole, lo, hi, nan};
    return integral();
}

// Numbers in [lo, hi] as double arithmetic gives the bounds, widened to hold every rounding of
// them to float (rounding is monotonic, so a rounded result lies between its bounds' roundings).
Num real(double lo, double hi, bool nan, bool widen = true) {
    if (widen) {
        lo -= std::fabs(lo) * 0x1p-20 + 0x1p-126;
        hi += std::fabs(hi) * 0x1p-20 + 0x1p-126;
    }
    if (!(std::max(std::fabs(lo), std::fabs(hi)) < kRealBound)) return unknown();
    return {Num::Real, lo, hi, nan};
}

Num join(const Num& a, const Num& b) {
    if (a.kind == Num::Unknown || b.kind == Num::Unknown) return unknown();
    const bool nan = a.nan || b.nan;
    if (is_whole(a) && is_whole(b)) return {Num::Whole, std::min(a.lo, b.lo), std::max(a.hi, b.hi), nan};
    if (is_integral(a) && is_integral(b)) return integral();
    if (is_bounded(a) && is_bounded(b)) return {Num::Real, std::min(a.lo, b.lo), std::max(a.hi, b.hi), nan};
    return unknown();
}

Value join(const Value& a, const Value& b) {
    if (a.size() != b.size()) return {};
    Value r(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) r[i] = join(a[i], b[i]);
    return r;
}

Num negate(const Num& a) {
    if (is_bounded(a)) return {a.kind, -a.hi, -a.lo, a.nan};
    return a;
}

Num add(const Num& a, const Num& b) {
    const bool nan = a.nan || b.nan;
    if (is_whole(a) && is_whole(b)) return whole(a.lo + b.lo, a.hi + b.hi, nan);
    if (is_integral(a) && is_integral(b)) return integral();
    if (is_bounded(a) && is_bounded(b)) return real(a.lo + b.lo, a.hi + b.hi, nan);
    return unknown();
}

Num multiply(const Num& a, const Num& b) {
    const bool nan = a.nan || b.nan;
    const double p[] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    const double lo = *std::min_element(p, p + 4), hi = *std::max_element(p, p + 4);
    if (is_whole(a) && is_whole(b)) return whole(lo, hi, nan);
    if (is_integral(a) && is_integral(b)) return integral();  // 0 * inf is NaN, inf * inf inf
    if (is_bounded(a) && is_bounded(b)) return real(lo, hi, nan);
    return unknown();
}

Num divide(const Num& a, const Num& b) {
    if (!is_bounded(a) || !is_bounded(b) || (b.lo <= 0.0 && b.hi >= 0.0)) return unknown();
    const double p[] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
    return real(*std::min_element(p, p + 4), *std::max_element(p, p + 4), a.nan || b.nan);
}

// floor, ceil, trunc, round, roundEven: monotonic, whole, and an infinity or NaN where their
// operand is one.
Num rounded(const Num& a, TOperator op) {
    if (is_integral(a)) return a;
    if (a.kind != Num::Real) return integral();
    switch (op) {
        case glslang::EOpFloor:
            return whole(std::floor(a.lo), std::floor(a.hi), a.nan);
        case glslang::EOpCeil:
            return whole(std::ceil(a.lo), std::ceil(a.hi), a.nan);
        case glslang::EOpTrunc:
            return whole(std::trunc(a.lo), std::trunc(a.hi), a.nan);
        default:
            return whole(std::floor(a.lo), std::ceil(a.hi), a.nan);  // round, roundEven: a neighbour
    }
}

// min(a, b) or max(a, b): one of the two (which, where one is NaN, depends on the operation's
// form), so within both intervals' hull.
Num extremum(const Num& a, const Num& b, bool minimum) {
    if (is_whole(a) && is_whole(b) && !a.nan && !b.nan) {
        return minimum ? Num{Num::Whole, std::min(a.lo, b.lo), std::min(a.hi, b.hi), false}
                       : Num{Num::Whole, std::max(a.lo, b.lo), std::max(a.hi, b.hi), false};
    }
    return join(a, b);
}

// The largest half step between floats near |t| (t's own rounding error).
double half_float_step(double t) {
    int e = 0;
    std::frexp(std::fabs(t), &e);  // |t| < 2^e
    return std::ldexp(1.0, e - 25);
}

// x - floor(x * k) * c, or mod(x, c) = x - c * floor(x / c): for whole x with |x| <= X and whole
// c >= 1, the true quotient t = x / c is whole or at least 1/c from the whole numbers around it.
// Where the rounded quotient q (x / c, or x * k with k's own error k * c - 1) stays within 1/c
// of t, floor(q) is floor(t), or t - 1 where t is whole and q falls just below it: the result
// lies in [0, c]; every product floor(q) * c is below X + c < 2^24, exact, and so is the
// subtraction with it. `k_error` bounds |k * c - 1| (0 for a division).
std::optional<Num> mod_of_whole(const Num& x, double c, double k_error) {
    if (!is_whole(x) || !(c >= 1.0) || c != std::floor(c) || c >= kExactBelow) return std::nullopt;
    const double big = std::max(std::fabs(x.lo), std::fabs(x.hi));
    if (big + c >= kExactBelow) return std::nullopt;
    const double t = big / c;
    const double error = t * k_error + half_float_step(t * (1.0 + k_error)) + 0x1p-40;
    if (!(error * c < 1.0)) return std::nullopt;
    return Num{Num::Whole, 0.0, c, x.nan};
}

bool is_float(const TType& t) { return t.getBasicType() == glslang::EbtFloat; }
bool is_int(const TType& t) { return t.getBasicType() == glslang::EbtInt || t.getBasicType() == glslang::EbtUint; }
bool followed(const TType& t) { return !t.isArray() && !t.isStruct() && !t.isMatrix() && (is_float(t) || is_int(t)); }
int components(const TType& t) { return t.getVectorSize(); }

// A constant's components.
Value constant(const glslang::TConstUnionArray& a, const TType& t) {
    if (!followed(t)) return {};
    Value v;
    for (int i = 0; i < components(t); ++i) {
        const double d = is_float(t)                           ? a[i].getDConst()
                         : t.getBasicType() == glslang::EbtInt ? double(a[i].getIConst())
                                                               : double(a[i].getUConst());
        const double f = is_float(t) ? double(float(d)) : d;  // the translation writes float literals
        if (!std::isfinite(f))
            v.push_back(unknown());
        else if (f == std::floor(f) && std::fabs(f) < kExactBelow && f == d)
            v.push_back({Num::Whole, f, f, false});
        else if (is_float(t) && std::fabs(f) < kRealBound)
            v.push_back(real(std::min(f, d), std::max(f, d), false, false));
        else
            v.push_back(unknown());
    }
    return v;
}

// Local variables and parameters: what another function cannot write behind a call.
bool is_local(const TIntermSymbol* s) {
    switch (s->getQualifier().storage) {
        case glslang::EvqTemporary:
        case glslang::EvqIn:
        case glslang::EvqConstReadOnly:
        case glslang::EvqOut:
        case glslang::EvqInOut:
            return true;
        default:
            return false;
    }
}

using Env = std::map<long long, Value>;

Env join(const Env& a, const Env& b) {
    Env r;
    for (const auto& [id, v] : a) {
        if (auto it = b.find(id); it != b.end()) r[id] = join(v, it->second);
    }
    return r;
}

struct OutOfBudget {};

class Analysis {
public:
    std::unordered_map<const TIntermTyped*, Value>& seen;
    std::map<std::string, TIntermAggregate*> functions;

    explicit Analysis(std::unordered_map<const TIntermTyped*, Value>& s) : seen(s) {}

    void run_function(TIntermAggregate* f, Env env, std::optional<Value>* returned) {
        if (!active_.insert(f).second) throw OutOfBudget{};  // recursion, which GLSL forbids
        Frame frame{returned};
        frames_.push_back(&frame);
        const glslang::TIntermSequence& parts = f->getSequence();
        if (parts.size() > 1) exec(parts[1], env);
        frames_.pop_back();
        active_.erase(f);
    }

    void exec(TIntermNode* n, Env& env) {
        if (!n) return;
        step();
        if (auto* a = n->getAsAggregate(); a && a->getOp() == glslang::EOpSequence) {
            const glslang::TIntermSequence& s = a->getSequence();
            for (std::size_t i = 0; i < s.size(); ++i) exec(s[i], env);
            return;
        }
        if (auto* l = n->getAsLoopNode()) return loop(l, env);
        if (auto* s = n->getAsSelectionNode();
            s && (s->getBasicType() == glslang::EbtVoid || !s->getTrueBlock() || !s->getTrueBlock()->getAsTyped())) {
            eval(s->getCondition(), env);
            Env t = env, e = env;
            exec(s->getTrueBlock(), t);
            exec(s->getFalseBlock(), e);
            env = join(t, e);
            return;
        }
        if (auto* s = n->getAsSwitchNode()) return switch_statement(s, env);
        if (auto* b = n->getAsBranchNode()) {
            if (b->getExpression()) {
                Value v = eval(b->getExpression(), env);
                if (b->getFlowOp() == glslang::EOpReturn && !frames_.empty() && frames_.back()->returned) {
                    std::optional<Value>& r = *frames_.back()->returned;
                    r = r ? join(*r, v) : v;
                }
            }
            return;
        }
        if (auto* t = n->getAsTyped()) eval(t, env);
    }

    Value eval(TIntermTyped* n, Env& env) {
        step();
        Value v = evaluate(n, env);
        if (followed(n->getType()) && v.size() != std::size_t(components(n->getType()))) v = {};
        auto [it, fresh] = seen.try_emplace(n, v);
        if (!fresh) it->second = join(it->second, v);
        return v;
    }

private:
    struct Frame {
        std::optional<Value>* returned;
    };
    std::vector<Frame*> frames_;
    std::set<TIntermAggregate*> active_;
    long steps_ = 0;

    void step() {
        if (++steps_ > kBudget) throw OutOfBudget{};
    }

    static Value unknowns(const TType& t) {
        return followed(t) ? Value(std::size_t(components(t)), unknown()) : Value{};
    }

    // The variable a write lands in, forgotten.
    static void forget(TIntermTyped* target, Env& env) {
        while (auto* b = target->getAsBinaryNode()) target = b->getLeft();
        if (auto* s = target->getAsSymbolNode()) env.erase(s->getId());
    }

    static void forget_writes(TIntermNode* n, Env& env) {
        for_each_write(n, [&](long long id, TIntermTyped*) { env.erase(id); });
    }

    void assign(TIntermTyped* target, const Value& v, Env& env) {
        if (auto* s = target->getAsSymbolNode()) {
            if (is_local(s) && !v.empty())
                env[s->getId()] = v;
            else
                env.erase(s->getId());
            return;
        }
        // One component, or a swizzle, of a local vector.
        auto* b = target->getAsBinaryNode();
        auto* s = b ? b->getLeft()->getAsSymbolNode() : nullptr;
        if (s && is_local(s) && followed(s->getType()) && !v.empty() &&
            (b->getOp() == glslang::EOpIndexDirect || b->getOp() == glslang::EOpVectorSwizzle)) {
            auto it = env.find(s->getId());
            Value whole = it != env.end() ? it->second : unknowns(s->getType());
            const std::vector<int> picked = indices(b);
            if (picked.size() == v.size()) {
                for (std::size_t i = 0; i < picked.size(); ++i) {
                    if (picked[i] < 0 || std::size_t(picked[i]) >= whole.size()) return forget(target, env);
                    whole[std::size_t(picked[i])] = v[i];
                }
                env[s->getId()] = whole;
                return;
            }
        }
        forget(target, env);
    }

    static std::vector<int> indices(TIntermBinary* b) {
        std::vector<int> out;
        if (b->getOp() == glslang::EOpIndexDirect) {
            if (auto* c = b->getRight()->getAsConstantUnion()) out.push_back(c->getConstArray()[0].getIConst());
        } else if (b->getOp() == glslang::EOpVectorSwizzle) {
            for (TIntermNode* k : b->getRight()->getAsAggregate()->getSequence()) {
                out.push_back(k->getAsConstantUnion()->getConstArray()[0].getIConst());
            }
        }
        return out;
    }

    // `for (int i = A; i < B; i++)` (or i <= B, ++i, i += 1) whose body leaves i alone: i's
    // values inside the body.
    std::optional<Num> counter(glslang::TIntermLoop* l, const Env& env, long long* id) {
        auto* test = l->getTest() ? l->getTest()->getAsBinaryNode() : nullptr;
        if (!test || (test->getOp() != glslang::EOpLessThan && test->getOp() != glslang::EOpLessThanEqual))
            return std::nullopt;
        auto* s = test->getLeft()->getAsSymbolNode();
        auto* bound = test->getRight()->getAsConstantUnion();
        if (!s || !bound || s->getBasicType() != glslang::EbtInt || !s->getType().isScalar() || !is_local(s))
            return std::nullopt;
        TIntermTyped* t = l->getTerminal();
        bool steps_by_one = false;
        if (auto* u = t ? t->getAsUnaryNode() : nullptr) {
            steps_by_one = (u->getOp() == glslang::EOpPostIncrement || u->getOp() == glslang::EOpPreIncrement) &&
                           u->getOperand()->getAsSymbolNode() &&
                           u->getOperand()->getAsSymbolNode()->getId() == s->getId();
        } else if (auto* b = t ? t->getAsBinaryNode() : nullptr) {
            auto* one = b->getRight()->getAsConstantUnion();
            steps_by_one = b->getOp() == glslang::EOpAddAssign && b->getLeft()->getAsSymbolNode() &&
                           b->getLeft()->getAsSymbolNode()->getId() == s->getId() && one &&
                           one->getConstArray()[0].getIConst() == 1;
        }
        if (!steps_by_one) return std::nullopt;
        bool written = false;
        for_each_write(l->getBody(), [&](long long w, TIntermTyped*) { written = written || w == s->getId(); });
        auto it = env.find(s->getId());
        if (written || it == env.end() || it->second.size() != 1 || !is_whole(it->second[0]) ||
            it->second[0].lo != it->second[0].hi) {
            return std::nullopt;
        }
        const double first = it->second[0].lo;
        const double last =
            double(bound->getConstArray()[0].getIConst()) - (test->getOp() == glslang::EOpLessThan ? 1.0 : 0.0);
        if (last < first || std::fabs(last) >= kExactBelow) return std::nullopt;
        *id = s->getId();
        return Num{Num::Whole, first, last, false};
    }

    void loop(glslang::TIntermLoop* l, Env& env) {
        long long id = 0;
        const std::optional<Num> i = counter(l, env, &id);
        forget_writes(l, env);
        Env body = env;
        if (i) body[id] = {*i};
        if (l->getTest()) eval(l->getTest(), body);
        exec(l->getBody(), body);
        if (l->getTerminal()) eval(l->getTerminal(), body);
    }

    void switch_statement(glslang::TIntermSwitch* s, Env& env) {
        if (auto* c = s->getCondition() ? s->getCondition()->getAsTyped() : nullptr) eval(c, env);
        forget_writes(s->getBody(), env);
        Env at = env;
        if (s->getBody()) {
            for (TIntermNode* n : s->getBody()->getSequence()) {
                auto* b = n->getAsBranchNode();
                if (b && (b->getFlowOp() == glslang::EOpCase || b->getFlowOp() == glslang::EOpDefault)) {
                    at = join(at, env);  // entered here, or fallen through
                    continue;
                }
                exec(n, at);
            }
        }
    }

    Value evaluate(TIntermTyped* n, Env& env) {
        const TType& type = n->getType();
        if (auto* c = n->getAsConstantUnion()) return constant(c->getConstArray(), type);
        if (auto* s = n->getAsSymbolNode()) {
            if (auto it = env.find(s->getId()); it != env.end()) return it->second;
            if (s->getQualifier().storage == glslang::EvqConst && s->getConstArray().size() > 0)
                return constant(s->getConstArray(), type);
            return unknowns(type);
        }
        if (auto* b = n->getAsBinaryNode()) return binary(b, env);
        if (auto* u = n->getAsUnaryNode()) return unary(u, env);
        if (auto* a = n->getAsAggregate()) return aggregate(a, env);
        if (auto* s = n->getAsSelectionNode()) {
            eval(s->getCondition(), env);
            Env te = env, fe = env;
            Value t = s->getTrueBlock() && s->getTrueBlock()->getAsTyped() ? eval(s->getTrueBlock()->getAsTyped(), te)
                                                                           : Value{};
            Value f = s->getFalseBlock() && s->getFalseBlock()->getAsTyped()
                          ? eval(s->getFalseBlock()->getAsTyped(), fe)
                          : Value{};
            env = join(te, fe);
            return join(t, f);
        }
        return unknowns(type);
    }

    // `a` and `b` made the size of the result: a scalar operand stands for each component.
    static Num at(const Value& v, std::size_t i) { return v.size() == 1 ? v[0] : i < v.size() ? v[i] : unknown(); }

    Value componentwise(const TType& type, const Value& a, const Value& b, Num (*f)(const Num&, const Num&)) {
        if (!followed(type) || a.empty() || b.empty()) return unknowns(type);
        Value r(std::size_t(components(type)));
        for (std::size_t i = 0; i < r.size(); ++i) r[i] = f(at(a, i), at(b, i));
        return r;
    }

    static Num subtract(const Num& a, const Num& b) { return add(a, negate(b)); }
    // Integers wrap: only results that do not are kept (for uint, none below 0).
    static Num int_checked(const Num& n, const TType& t) {
        return is_whole(n) && (t.getBasicType() != glslang::EbtUint || n.lo >= 0.0) ? n : unknown();
    }

    Value binary(TIntermBinary* b, Env& env) {
        const TOperator op = b->getOp();
        const TType& type = b->getType();
        if (op >= glslang::EOpAssign && op <= glslang::EOpRightShiftAssign) {
            Value v = eval(b->getRight(), env);
            Value current = eval(b->getLeft(), env);
            Value r;
            switch (op) {
                case glslang::EOpAssign:
                    r = v;
                    break;
                case glslang::EOpAddAssign:
                    r = componentwise(b->getLeft()->getType(), current, v, add);
                    break;
                case glslang::EOpSubAssign:
                    r = componentwise(b->getLeft()->getType(), current, v, subtract);
                    break;
                case glslang::EOpMulAssign:
                case glslang::EOpVectorTimesScalarAssign:
                    r = componentwise(b->getLeft()->getType(), current, v, multiply);
                    break;
                default:
                    r = {};
                    break;
            }
            if (is_int(b->getLeft()->getType())) {
                for (Num& x : r) x = op == glslang::EOpAssign ? x : int_checked(x, b->getLeft()->getType());
            }
            assign(b->getLeft(), r, env);
            return r;
        }
        switch (op) {
            case glslang::EOpIndexDirect:
            case glslang::EOpVectorSwizzle: {
                Value base = eval(b->getLeft(), env);
                if (b->getLeft()->getType().isVector() ||
                    (op == glslang::EOpVectorSwizzle && b->getLeft()->getType().isScalar())) {
                    Value r;
                    for (int i : indices(b))
                        r.push_back(i >= 0 && std::size_t(i) < base.size() ? base[std::size_t(i)] : unknown());
                    return r;
                }
                return unknowns(type);
            }
            case glslang::EOpIndexDirectStruct:
                eval(b->getLeft(), env);
                return unknowns(type);
            default:
                break;
        }
        Value l = eval(b->getLeft(), env);
        Value r = eval(b->getRight(), env);
        if (!followed(type) || !followed(b->getLeft()->getType()) || !followed(b->getRight()->getType()))
            return unknowns(type);
        Value v;
        switch (op) {
            case glslang::EOpAdd:
                v = componentwise(type, l, r, add);
                break;
            case glslang::EOpSub:
                v = componentwise(type, l, r, subtract);
                break;
            case glslang::EOpMul:
            case glslang::EOpVectorTimesScalar:
                v = componentwise(type, l, r, multiply);
                break;
            case glslang::EOpDiv:
                if (!is_float(type)) return unknowns(type);
                v = componentwise(type, l, r, divide);
                break;
            default:
                return unknowns(type);
        }
        if (is_int(type)) {
            for (Num& x : v) x = int_checked(x, type);
        }
        if (op == glslang::EOpSub && is_float(type)) refine_mod(b, l, v);
        return v;
    }

    // x - floor(x * k) * c (or c * floor(...), or floor(x / c)): GLSL's mod written out.
    void refine_mod(TIntermBinary* b, const Value& x, Value& v) {
        auto* product = b->getRight()->getAsBinaryNode();
        auto* xs = b->getLeft()->getAsSymbolNode();
        if (!product || !xs ||
            (product->getOp() != glslang::EOpMul && product->getOp() != glslang::EOpVectorTimesScalar))
            return;
        TIntermTyped* f = product->getLeft();
        TIntermTyped* c = product->getRight();
        if (!c->getAsConstantUnion()) std::swap(f, c);
        auto* floor = f->getAsUnaryNode();
        auto* cc = c->getAsConstantUnion();
        if (!floor || floor->getOp() != glslang::EOpFloor || !cc || !cc->getType().isScalar()) return;
        auto* q = floor->getOperand()->getAsBinaryNode();
        if (!q) return;
        auto* qx = q->getLeft()->getAsSymbolNode();
        auto* qk = q->getRight()->getAsConstantUnion();
        if (!qx || qx->getId() != xs->getId() || !qk || !qk->getType().isScalar()) return;
        const double cv = double(float(cc->getConstArray()[0].getDConst()));
        const double k = qk->getConstArray()[0].getDConst();
        if (q->getOp() == glslang::EOpDiv
                ? double(float(k)) != cv
                : q->getOp() != glslang::EOpMul && q->getOp() != glslang::EOpVectorTimesScalar)
            return;
        // k as the translation writes it (a float) and as double precision may keep it
        const double k_error = q->getOp() == glslang::EOpDiv
                                   ? 0.0
                                   : std::max(std::fabs(cv * double(float(k)) - 1.0), std::fabs(cv * k - 1.0));
        for (std::size_t i = 0; i < v.size(); ++i) {
            if (auto m = mod_of_whole(at(x, i), cv, k_error)) v[i] = refine(v[i], *m);
        }
    }

    static Num refine(const Num& general, const Num& mod) {
        if (!is_whole(general)) return mod;
        return {Num::Whole, std::max(general.lo, mod.lo), std::min(general.hi, mod.hi), general.nan || mod.nan};
    }

    Value unary(TIntermUnary* u, Env& env) {
        const TOperator op = u->getOp();
        const TType& type = u->getType();
        if (op >= glslang::EOpPostIncrement && op <= glslang::EOpPreDecrement) {
            eval(u->getOperand(), env);
            forget(u->getOperand(), env);
            return unknowns(type);
        }
        Value a = eval(u->getOperand(), env);
        if (!followed(type) || a.empty()) return unknowns(type);
        Value r(a.size());
        for (std::size_t i = 0; i < a.size(); ++i) {
            const Num& x = a[i];
            switch (op) {
                case glslang::EOpNegative:
                    r[i] = is_int(type) ? int_checked(negate(x), type) : negate(x);
                    break;
                case glslang::EOpConvIntToFloat:
                case glslang::EOpConvUintToFloat:
                    r[i] = is_whole(x) ? x : integral();  // an int is a whole number, and finite
                    break;
                case glslang::EOpFloor:
                case glslang::EOpCeil:
                case glslang::EOpTrunc:
                case glslang::EOpRound:
                case glslang::EOpRoundEven:
                    r[i] = rounded(x, op);
                    break;
                case glslang::EOpFract:
                    r[i] = {Num::Real, 0.0, 1.0, !is_bounded(x) || x.nan};
                    break;  // fract(inf) is NaN
                case glslang::EOpAbs:
                    if (is_bounded(x)) {
                        const double lo = x.lo <= 0.0 && x.hi >= 0.0 ? 0.0 : std::min(std::fabs(x.lo), std::fabs(x.hi));
                        r[i] = {x.kind, lo, std::max(std::fabs(x.lo), std::fabs(x.hi)), x.nan};
                    } else {
                        r[i] = is_float(type) && is_integral(x) ? integral() : unknown();
                    }
                    break;
                default:
                    r[i] = unknown();
                    break;
            }
        }
        return r;
    }

    Value aggregate(TIntermAggregate* a, Env& env) {
        const TOperator op = a->getOp();
        const TType& type = a->getType();
        const glslang::TIntermSequence& s = a->getSequence();
        if (op == glslang::EOpFunctionCall) return call(a, env);
        std::vector<Value> args;
        for (TIntermNode* n : s) args.push_back(n->getAsTyped() ? eval(n->getAsTyped(), env) : Value{});
        switch (op) {
            case glslang::EOpModf:
            case glslang::EOpFrexp:
            case glslang::EOpAddCarry:
            case glslang::EOpSubBorrow:
            case glslang::EOpUMulExtended:
            case glslang::EOpIMulExtended:
                forget_writes(a, env);
                return unknowns(type);
            default:
                break;
        }
        if (!followed(type)) return unknowns(type);
        if (op > glslang::EOpConstructGuardStart && op < glslang::EOpConstructGuardEnd) return construct(a, args);
        const auto each = [&](auto f) {
            Value r(std::size_t(components(type)));
            for (std::size_t i = 0; i < r.size(); ++i) r[i] = f(i);
            return r;
        };
        for (const Value& v : args) {
            if (v.empty()) return unknowns(type);
        }
        switch (op) {
            case glslang::EOpMin:
            case glslang::EOpMax:
                if (!is_float(type) || args.size() != 2) return unknowns(type);
                return each(
                    [&](std::size_t i) { return extremum(at(args[0], i), at(args[1], i), op == glslang::EOpMin); });
            case glslang::EOpClamp:
                if (!is_float(type) || args.size() != 3) return unknowns(type);
                return each([&](std::size_t i) {
                    // one of x (between the bounds), lo, hi, or NaN
                    const Num x = at(args[0], i), lo = at(args[1], i), hi = at(args[2], i);
                    if (!is_bounded(lo) || !is_bounded(hi)) return unknown();
                    Num r = join(lo, hi);
                    r.nan = r.nan || !is_bounded(x) || x.nan;
                    if (!is_integral(x)) r.kind = Num::Real;
                    return r;
                });
            case glslang::EOpStep:
                if (!is_float(type)) return unknowns(type);
                return each([&](std::size_t) { return Num{Num::Whole, 0.0, 1.0, false}; });
            case glslang::EOpMod: {
                if (!is_float(type) || args.size() != 2) return unknowns(type);
                auto* c = s[1]->getAsConstantUnion();
                return each([&](std::size_t i) {
                    const Num x = at(args[0], i), y = at(args[1], i);
                    if (c && is_whole(y) && y.lo == y.hi && !y.nan) {
                        if (auto m = mod_of_whole(x, y.lo, 0.0)) return *m;
                        if (is_integral(x)) return integral();  // x - c * floor(x / c): whole, or NaN
                    }
                    return unknown();
                });
            }
            default:
                return unknowns(type);
        }
    }

    Value construct(TIntermAggregate* a, const std::vector<Value>& args) {
        const TType& type = a->getType();
        Value all;
        for (std::size_t i = 0; i < args.size(); ++i) {
            const TType& at = a->getSequence()[i]->getAsTyped()->getType();
            if (!followed(at) || args[i].empty()) return unknowns(type);
            for (Num n : args[i]) {
                if (is_float(type) && is_int(at))
                    n = is_whole(n) ? n : integral();
                else if (is_int(type) && !is_int(at))
                    n = unknown();  // float to int: whole, but maybe out of range
                all.push_back(n);
            }
        }
        const std::size_t n = std::size_t(components(type));
        if (all.size() == 1) return Value(n, all[0]);
        if (all.size() < n) return unknowns(type);
        all.resize(n);
        return all;
    }

    Value call(TIntermAggregate* a, Env& env) {
        const glslang::TIntermSequence& s = a->getSequence();
        const glslang::TQualifierList& q = a->getQualifierList();
        std::vector<Value> args;
        for (TIntermNode* n : s) args.push_back(n->getAsTyped() ? eval(n->getAsTyped(), env) : Value{});
        Value result = unknowns(a->getType());
        auto it = functions.find(a->getName().c_str());
        if (it != functions.end()) {
            Env inner;
            const glslang::TIntermSequence& parts = it->second->getSequence();
            if (!parts.empty() && parts[0] && parts[0]->getAsAggregate()) {
                const glslang::TIntermSequence& params = parts[0]->getAsAggregate()->getSequence();
                for (std::size_t i = 0; i < params.size() && i < args.size(); ++i) {
                    TIntermSymbol* p = params[i] ? params[i]->getAsSymbolNode() : nullptr;
                    const bool out = i < q.size() && q[i] == glslang::EvqOut;
                    if (p && !out && !args[i].empty()) inner[p->getId()] = args[i];
                }
            }
            std::optional<Value> returned;
            run_function(it->second, inner, &returned);
            if (returned && !returned->empty()) result = *returned;
        }
        for (std::size_t i = 0; i < s.size() && i < q.size(); ++i) {
            if ((q[i] == glslang::EvqOut || q[i] == glslang::EvqInOut) && s[i]->getAsTyped())
                forget(s[i]->getAsTyped(), env);
        }
        return result;
    }
};

bool power_of_two_constant(const Num& n) {
    if (!is_bounded(n) || n.lo != n.hi || n.nan || n.lo <= 0.0) return false;
    int e = 0;
    const double m = std::frexp(n.lo, &e);
    return m == 0.5 && e - 1 >= -24 && e - 1 <= 24;
}

// Whether a * b is exact for every value of the components (a * b + c, or a * b - c where
// `difference`, then rounds once whichever way it is written).
bool exact_component(const Num& a, const Num& b, const Num& c, bool difference) {
    if (is_whole(a) && is_whole(b) && is_whole(c)) {
        const Num p = multiply(a, b);
        return is_whole(p) && is_whole(add(p, difference ? negate(c) : c));
    }
    // A power of two times a whole number, an infinity or NaN: exact, or an overflow that a
    // bounded c cannot bring back below the largest float.
    const bool scaled = (power_of_two_constant(a) && is_integral(b)) || (power_of_two_constant(b) && is_integral(a));
    return scaled && is_bounded(c);
}

}  // namespace

ExactProducts::ExactProducts(TIntermAggregate* root) {
    if (!root) return;
    std::unordered_map<const TIntermTyped*, Value> seen;
    Analysis analysis(seen);
    TIntermAggregate* main = nullptr;
    std::vector<TIntermNode*> globals;
    for (TIntermNode* n : root->getSequence()) {
        TIntermAggregate* a = n->getAsAggregate();
        if (a && a->getOp() == glslang::EOpFunction) {
            analysis.functions[a->getName().c_str()] = a;
            if (std::string(a->getName().c_str()) == "main(") main = a;
        } else if (!(a && a->getOp() == glslang::EOpLinkerObjects)) {
            globals.push_back(n);
        }
    }
    if (!main) return;
    try {
        Env env;
        for (TIntermNode* g : globals) analysis.exec(g, env);
        analysis.run_function(main, {}, nullptr);
    } catch (const OutOfBudget&) {
        return;  // nothing known: nothing fused
    }
    seen_ = std::move(seen);
}

std::vector<KnownNumber> ExactProducts::known(const TIntermTyped* n) const {
    auto it = seen_.find(n);
    return it == seen_.end() ? std::vector<KnownNumber>{} : it->second;
}

std::optional<FusibleProduct> ExactProducts::fusible(TIntermBinary* b) const {
    const TType& type = b->getType();
    if ((b->getOp() != glslang::EOpAdd && b->getOp() != glslang::EOpSub) || !is_float(type) || !followed(type))
        return std::nullopt;
    const auto product_of = [](TIntermTyped* n) -> TIntermBinary* {
        auto* p = n->getAsBinaryNode();
        if (!p || (p->getOp() != glslang::EOpMul && p->getOp() != glslang::EOpVectorTimesScalar)) return nullptr;
        if (!followed(p->getLeft()->getType()) || !followed(p->getRight()->getType())) return nullptr;
        return p;
    };
    const bool subtract = b->getOp() == glslang::EOpSub;
    // `negated`: the operand the fused form negates, which must not be NaN (a negation turns a
    // NaN's sign, a subtraction keeps it).
    const auto exact = [&](TIntermBinary* p, TIntermTyped* c, TIntermTyped* negated) {
        const Value a = known(p->getLeft()), bb = known(p->getRight()), cc = known(c);
        const Value n = negated ? known(negated) : Value{};
        if (a.empty() || bb.empty() || cc.empty() || (negated && n.empty())) return false;
        for (std::size_t i = 0; i < std::size_t(components(type)); ++i) {
            const auto at = [&](const Value& v) { return v.size() == 1 ? v[0] : i < v.size() ? v[i] : unknown(); };
            if (!exact_component(at(a), at(bb), at(cc), subtract)) return false;
            if (negated && (!is_bounded(at(n)) || at(n).nan)) return false;
        }
        return true;
    };
    if (TIntermBinary* p = product_of(b->getLeft()); p && exact(p, b->getRight(), subtract ? b->getRight() : nullptr)) {
        return FusibleProduct{p->getLeft(), p->getRight(), b->getRight(), false, subtract};
    }
    if (TIntermBinary* p = product_of(b->getRight()); p && exact(p, b->getLeft(), subtract ? p->getRight() : nullptr)) {
        return FusibleProduct{p->getLeft(), p->getRight(), b->getLeft(), subtract, false};
    }
    return std::nullopt;
}

}  // namespace qs::frontend
