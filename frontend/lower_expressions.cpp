// Expressions: constants, variables, operators, indexing, assignments and calls (lowering.h).

#include <bit>

#include "frontend/glsl_types.h"
#include "frontend/lowering.h"
#include "frontend/side_effects.h"

namespace qs::frontend {

using glslang::TIntermAggregate;
using glslang::TIntermBinary;
using glslang::TIntermTyped;
using glslang::TIntermUnary;
using B = ir::Bank;

namespace {

std::uint32_t constant_bits(const glslang::TConstUnion& c, B bank) {
    switch (bank) {
        case B::Float: return std::bit_cast<std::uint32_t>(float(c.getDConst()));
        case B::Int: return std::bit_cast<std::uint32_t>(c.getIConst());
        case B::Uint: return c.getUConst();
        case B::Bool: return c.getBConst() ? 1u : 0u;
    }
    return 0;
}

// The element registers of `p` (count elements of `size` components each) as bases and strides:
// false where some component's registers are not evenly spaced.
bool evenly_spaced(const Place& p, int count, int size, std::vector<std::uint32_t>& stride) {
    stride.assign(std::size_t(size), 1);
    for (int k = 0; k < size; ++k) {
        const Slot first = p[std::size_t(k)];
        if (count > 1) {
            const Slot second = p[std::size_t(size + k)];
            if (second.bank != first.bank || second.reg <= first.reg) return false;
            stride[std::size_t(k)] = second.reg - first.reg;
        }
        for (int j = 2; j < count; ++j) {
            const Slot s = p[std::size_t(j * size + k)];
            if (s.bank != first.bank || s.reg != first.reg + std::uint32_t(j) * stride[std::size_t(k)]) return false;
        }
    }
    return true;
}

int element_count(const glslang::TType& t) {
    if (t.isArray()) return t.getOuterArraySize();
    if (t.isMatrix()) return t.getMatrixCols();
    return t.getVectorSize();
}

}  // namespace

Place StageLowering::eval(TIntermTyped* node) {
    if (auto* c = node->getAsConstantUnion()) return eval_constant(c);
    if (auto* s = node->getAsSymbolNode()) return eval_symbol(s);
    if (auto* b = node->getAsBinaryNode()) return eval_binary(b);
    if (auto* u = node->getAsUnaryNode()) return eval_unary(u);
    if (auto* a = node->getAsAggregate()) return eval_aggregate(a);
    if (auto* s = node->getAsSelectionNode()) return eval_selection(s);
    refuse(node, "this kind of expression is not supported");
}

Place StageLowering::eval_constant(glslang::TIntermConstantUnion* node) {
    const glslang::TConstUnionArray& values = node->getConstArray();
    std::vector<B> banks;
    try {
        component_banks(node->getType(), banks);
    } catch (const GlslError& e) {
        refuse(node, e.what());
    }
    if (values.size() < int(banks.size())) refuse(node, "a constant without its values");
    Place p;
    if (node->getType().isArray()) {
        // An array keeps its elements evenly spaced (a run-time index reads them so), so its
        // constants are its own, not shared with equal values elsewhere.
        for (std::size_t i = 0; i < banks.size(); ++i) {
            const std::uint32_t r = allocate(banks[i], Space::Constant);
            stage_.constants.push_back({banks[i], r, constant_bits(values[int(i)], banks[i])});
            p.push_back({banks[i], r});
        }
        return p;
    }
    for (std::size_t i = 0; i < banks.size(); ++i) p.push_back({banks[i], constant(banks[i], constant_bits(values[int(i)], banks[i]))});
    return p;
}

Place StageLowering::eval_symbol(glslang::TIntermSymbol* node) {
    const long long id = node->getId();
    if (node->getBasicType() == glslang::EbtSampler) refuse(node, "a sampler is only read by texture functions");
    if (!frames_.empty()) {
        auto& locals = frames_.back().locals;
        if (auto it = locals.find(id); it != locals.end()) return it->second;
    }
    if (auto it = globals_.find(id); it != globals_.end()) return it->second;
    if (auto it = const_arrays_.find(id); it != const_arrays_.end()) return it->second;
    if (node->getConstArray().size() > 0) {
        // A const variable glslang folded: its values, once.
        const glslang::TConstUnionArray& values = node->getConstArray();
        const std::vector<B> banks = component_banks(node->getType());
        Place p;
        for (std::size_t i = 0; i < banks.size(); ++i) {
            const std::uint32_t r = allocate(banks[i], Space::Constant);
            stage_.constants.push_back({banks[i], r, constant_bits(values[int(i)], banks[i])});
            p.push_back({banks[i], r});
        }
        const_arrays_.emplace(id, p);
        return p;
    }
    const glslang::TStorageQualifier q = node->getQualifier().storage;
    if (q == glslang::EvqTemporary || q == glslang::EvqConst || q == glslang::EvqConstReadOnly || q == glslang::EvqIn ||
        q == glslang::EvqOut || q == glslang::EvqInOut) {
        if (frames_.size() > 1 || q == glslang::EvqTemporary || q == glslang::EvqConst) {
            // A local the scan before the function did not see (a declaration glslang keeps
            // only as its first use): zero, as every other local.
            Place p = allocate(node->getType(), Space::Variable);
            for (const Slot& s : p) {
                const Slot zero{s.bank, constant(s.bank, 0)};
                move(s, zero, false);
            }
            frames_.back().locals.emplace(id, p);
            return p;
        }
    }
    refuse(node, "'" + std::string(node->getName().c_str()) + "' is not a variable this shader can read here");
}

Place StageLowering::componentwise(ir::Op op, B result, const Place& a, const Place& b, B bank) {
    const std::size_t n = std::max(a.size(), b.size());
    Place r;
    for (std::size_t i = 0; i < n; ++i) {
        const Slot& x = a.size() == 1 ? a[0] : a[i];
        const Slot& y = b.size() == 1 ? b[0] : b[i];
        r.push_back({result, emit1(op, result, x.reg, y.reg, 0, bank)});
    }
    return r;
}

Place StageLowering::arithmetic(glslang::TOperator op, const glslang::TType& type, const Place& a, const Place& b) {
    B bank;
    if (!bank_of(type.getBasicType(), bank)) throw std::logic_error("GLSL lowering: arithmetic on a non-scalar type");
    const bool f = bank == B::Float;
    ir::Op o{};
    switch (op) {
        case glslang::EOpAdd: case glslang::EOpAddAssign: o = f ? ir::Op::FAdd : ir::Op::IAdd; break;
        case glslang::EOpSub: case glslang::EOpSubAssign: o = f ? ir::Op::FSub : ir::Op::ISub; break;
        case glslang::EOpMul: case glslang::EOpMulAssign: case glslang::EOpVectorTimesScalar:
        case glslang::EOpVectorTimesScalarAssign: case glslang::EOpMatrixTimesScalar:
        case glslang::EOpMatrixTimesScalarAssign:
            o = f ? ir::Op::FMul : ir::Op::IMul;
            break;
        case glslang::EOpDiv: case glslang::EOpDivAssign: o = f ? ir::Op::FDiv : ir::Op::IDiv; break;
        case glslang::EOpMod: case glslang::EOpModAssign: o = f ? ir::Op::FMod : ir::Op::IMod; break;
        case glslang::EOpAnd: case glslang::EOpAndAssign: o = ir::Op::IAnd; break;
        case glslang::EOpInclusiveOr: case glslang::EOpInclusiveOrAssign: o = ir::Op::IOr; break;
        case glslang::EOpExclusiveOr: case glslang::EOpExclusiveOrAssign: o = ir::Op::IXor; break;
        case glslang::EOpLeftShift: case glslang::EOpLeftShiftAssign: o = ir::Op::IShl; break;
        case glslang::EOpRightShift: case glslang::EOpRightShiftAssign: o = ir::Op::IShr; break;
        default: throw std::logic_error("GLSL lowering: not an arithmetic operator");
    }
    if (o == ir::Op::IShl || o == ir::Op::IShr) {
        // The count may be int or uint whatever the value is: the same bits.
        return componentwise(o, bank, a, convert_bits(b, bank), bank);
    }
    return componentwise(o, bank, a, b, bank);
}

Place StageLowering::convert_bits(const Place& p, B to) {
    Place r;
    for (const Slot& s : p) {
        if (s.bank == to) {
            r.push_back(s);
        } else if (s.bank == B::Int && to == B::Uint) {
            r.push_back({to, emit1(ir::Op::UintFromInt, to, s.reg)});
        } else if (s.bank == B::Uint && to == B::Int) {
            r.push_back({to, emit1(ir::Op::IntFromUint, to, s.reg)});
        } else {
            r.push_back(convert(s, to));
        }
    }
    return r;
}

Place StageLowering::compare(glslang::TOperator op, const Place& a, const Place& b) {
    const B bank = a[0].bank;
    const bool f = bank == B::Float;
    ir::Op o{};
    switch (op) {
        case glslang::EOpLessThan: o = f ? ir::Op::FLess : ir::Op::ILess; break;
        case glslang::EOpLessThanEqual: o = f ? ir::Op::FLessEqual : ir::Op::ILessEqual; break;
        case glslang::EOpGreaterThan: o = f ? ir::Op::FGreater : ir::Op::IGreater; break;
        case glslang::EOpGreaterThanEqual: o = f ? ir::Op::FGreaterEqual : ir::Op::IGreaterEqual; break;
        case glslang::EOpVectorEqual: case glslang::EOpEqual:
            o = f ? ir::Op::FEqual : bank == B::Bool ? ir::Op::BEqual : ir::Op::IEqual;
            break;
        case glslang::EOpVectorNotEqual: case glslang::EOpNotEqual:
            o = f ? ir::Op::FNotEqual : bank == B::Bool ? ir::Op::BNotEqual : ir::Op::INotEqual;
            break;
        default: throw std::logic_error("GLSL lowering: not a comparison");
    }
    if (op != glslang::EOpEqual && op != glslang::EOpNotEqual) return componentwise(o, B::Bool, a, b, bank);
    // == and != compare whole values (of mixed banks, for structs) into one bool: != is
    // !(a == b) on every component, as GLSL defines it.
    std::uint32_t all = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const B k = a[i].bank;
        const ir::Op eq = k == B::Float ? ir::Op::FEqual : k == B::Bool ? ir::Op::BEqual : ir::Op::IEqual;
        const std::uint32_t e = emit1(eq, B::Bool, a[i].reg, b[i].reg, 0, k);
        all = i == 0 ? e : emit1(ir::Op::BAnd, B::Bool, all, e);
    }
    if (op == glslang::EOpNotEqual) all = emit1(ir::Op::BNot, B::Bool, all);
    return {{B::Bool, all}};
}

Place StageLowering::logical(TIntermBinary* node) {
    const glslang::TOperator op = node->getOp();
    const Place a = eval(node->getLeft());
    if (op == glslang::EOpLogicalXor) {
        const Place b = eval(node->getRight());
        return {{B::Bool, emit1(ir::Op::BXor, B::Bool, a[0].reg, b[0].reg)}};
    }
    const ir::Op combine = op == glslang::EOpLogicalAnd ? ir::Op::BAnd : ir::Op::BOr;
    if (!has_side_effects(node->getRight())) {
        const Place b = eval(node->getRight());
        return {{B::Bool, emit1(combine, B::Bool, a[0].reg, b[0].reg)}};
    }
    // The right operand runs only where it decides the value: a && b as if (a) r = b.
    const Slot r{B::Bool, allocate(B::Bool, Space::Temp)};
    move(r, a[0], false);
    std::uint32_t condition = a[0].reg;
    if (op == glslang::EOpLogicalOr) condition = emit1(ir::Op::BNot, B::Bool, a[0].reg);
    const std::size_t at_if = stage_.code.size();
    emit(ir::Op::If).a = condition;
    {
        const TempMark m = mark();
        const Place b = eval(node->getRight());
        move(r, b[0], true);
        release(m);
    }
    const std::size_t at_end = stage_.code.size();
    emit(ir::Op::EndIf);
    stage_.code[at_if].target = std::uint32_t(at_end);
    return {r};
}

Place StageLowering::eval_binary(TIntermBinary* node) {
    const glslang::TOperator op = node->getOp();
    switch (op) {
        case glslang::EOpAssign: case glslang::EOpAddAssign: case glslang::EOpSubAssign: case glslang::EOpMulAssign:
        case glslang::EOpDivAssign: case glslang::EOpModAssign: case glslang::EOpAndAssign:
        case glslang::EOpInclusiveOrAssign: case glslang::EOpExclusiveOrAssign: case glslang::EOpLeftShiftAssign:
        case glslang::EOpRightShiftAssign: case glslang::EOpVectorTimesScalarAssign:
        case glslang::EOpMatrixTimesScalarAssign: case glslang::EOpVectorTimesMatrixAssign:
        case glslang::EOpMatrixTimesMatrixAssign:
            return eval_assignment(node);
        case glslang::EOpIndexDirect: case glslang::EOpIndexIndirect: case glslang::EOpIndexDirectStruct:
        case glslang::EOpVectorSwizzle:
            return eval_index(node);
        case glslang::EOpLogicalAnd: case glslang::EOpLogicalOr: case glslang::EOpLogicalXor: return logical(node);
        case glslang::EOpComma: {
            (void)eval(node->getLeft());
            return eval(node->getRight());
        }
        default: break;
    }
    // Left to right, as GLSL evaluates operands: a variable read on the left is copied first
    // where the right operand may change it.
    Place a = eval(node->getLeft());
    if (has_side_effects(node->getRight())) {
        Place copy = temps_like(a);
        assign(copy, a, false);
        a = copy;
    }
    const Place b = eval(node->getRight());
    switch (op) {
        case glslang::EOpAdd: case glslang::EOpSub: case glslang::EOpMul: case glslang::EOpDiv: case glslang::EOpMod:
        case glslang::EOpAnd: case glslang::EOpInclusiveOr: case glslang::EOpExclusiveOr: case glslang::EOpLeftShift:
        case glslang::EOpRightShift: case glslang::EOpVectorTimesScalar: case glslang::EOpMatrixTimesScalar:
            return arithmetic(op, node->getType(), a, b);
        case glslang::EOpLessThan: case glslang::EOpLessThanEqual: case glslang::EOpGreaterThan:
        case glslang::EOpGreaterThanEqual: case glslang::EOpEqual: case glslang::EOpNotEqual:
        case glslang::EOpVectorEqual: case glslang::EOpVectorNotEqual:
            return compare(op, a, b);
        case glslang::EOpMatrixTimesVector: case glslang::EOpVectorTimesMatrix: case glslang::EOpMatrixTimesMatrix:
            return matrix_product(op, shape(node->getLeft()->getType()), shape(node->getRight()->getType()), a, b);
        default: break;
    }
    refuse(node, "this operator is not supported");
}

Place StageLowering::temps_like(const Place& p) {
    Place r;
    for (const Slot& s : p) r.push_back({s.bank, allocate(s.bank, Space::Temp)});
    return r;
}

StageLowering::Shape StageLowering::shape(const glslang::TType& t) {
    return t.isMatrix() ? Shape{t.getMatrixCols(), t.getMatrixRows()} : Shape{1, t.getVectorSize()};
}

Place StageLowering::matrix_product(glslang::TOperator op, Shape left, Shape right, const Place& a, const Place& b) {
    Place result;
    const std::uint32_t ra = consecutive(a), rb = consecutive(b);
    if (op == glslang::EOpMatrixTimesVector) {
        const int cols = left.columns, rows = left.rows;
        result = temps(B::Float, rows);
        ir::Instr& e = emit(ir::Op::MatTimesVec);
        e.d = result[0].reg, e.a = ra, e.b = rb, e.n = std::uint8_t(cols), e.m = std::uint8_t(rows);
    } else if (op == glslang::EOpVectorTimesMatrix) {
        const int cols = right.columns, rows = right.rows;
        result = temps(B::Float, cols);
        ir::Instr& e = emit(ir::Op::VecTimesMat);
        e.d = result[0].reg, e.a = ra, e.b = rb, e.n = std::uint8_t(cols), e.m = std::uint8_t(rows);
    } else {
        // a: K columns of R rows; b: C columns of K rows; the product C columns of R rows.
        const int k = left.columns, rows = left.rows, cols = right.columns;
        result = temps(B::Float, cols * rows);
        ir::Instr& e = emit(ir::Op::MatTimesMat);
        e.d = result[0].reg, e.a = ra, e.b = rb, e.n = std::uint8_t(cols), e.m = std::uint8_t(rows);
        e.count = std::uint16_t(k);
    }
    return result;
}

Place StageLowering::eval_index(TIntermBinary* node) {
    const glslang::TOperator op = node->getOp();
    const glslang::TType& type = node->getLeft()->getType();
    if (op == glslang::EOpIndexIndirect) {
        Place base = eval(node->getLeft());
        Place index = eval(node->getRight());
        const std::uint32_t i = convert_bits(index, B::Int)[0].reg;
        const int count = element_count(type);
        const int size = int(base.size()) / count;
        std::vector<std::uint32_t> stride;
        if (!evenly_spaced(base, count, size, stride)) {
            Place copy = allocate(type, Space::Temp);
            assign(copy, base, false);
            base = copy;
            evenly_spaced(base, count, size, stride);
        }
        Place r;
        for (int k = 0; k < size; ++k) {
            const Slot first = base[std::size_t(k)];
            const std::uint32_t d = allocate(first.bank, Space::Temp);
            ir::Instr& e = emit(ir::Op::LoadIndexed, first.bank);
            e.d = d, e.a = first.reg, e.b = i, e.c = stride[std::size_t(k)], e.count = std::uint16_t(count);
            r.push_back({first.bank, d});
        }
        return r;
    }
    const Place base = eval(node->getLeft());
    return select_part(node, base);
}

// The registers of the part of `base` that a constant index, struct member or swizzle names.
Place StageLowering::select_part(TIntermBinary* node, const Place& base) {
    const glslang::TOperator op = node->getOp();
    const glslang::TType& type = node->getLeft()->getType();
    if (op == glslang::EOpVectorSwizzle) {
        Place r;
        for (TIntermNode* c : node->getRight()->getAsAggregate()->getSequence()) {
            const int k = c->getAsConstantUnion()->getConstArray()[0].getIConst();
            r.push_back(base[std::size_t(k)]);
        }
        return r;
    }
    const int k = node->getRight()->getAsConstantUnion()->getConstArray()[0].getIConst();
    if (op == glslang::EOpIndexDirectStruct) {
        const int first = member_offset(type, k), n = component_count(member_type(type, k));
        return Place(base.begin() + first, base.begin() + first + n);
    }
    const int count = element_count(type);
    if (k < 0 || k >= count) refuse(node, "index " + std::to_string(k) + " is outside '" + type_name(type) + "'");
    const int size = int(base.size()) / count;
    return Place(base.begin() + k * size, base.begin() + (k + 1) * size);
}

LValue StageLowering::lvalue(TIntermTyped* node) {
    if (auto* s = node->getAsSymbolNode()) {
        const glslang::TStorageQualifier q = s->getQualifier().storage;
        if (q == glslang::EvqUniform || q == glslang::EvqConst) refuse(node, "a uniform or constant cannot be assigned");
        LValue lv;
        lv.place = eval_symbol(s);
        return lv;
    }
    TIntermBinary* b = node->getAsBinaryNode();
    if (!b) refuse(node, "this expression cannot be assigned");
    const glslang::TOperator op = b->getOp();
    if (op == glslang::EOpIndexIndirect) {
        LValue base = lvalue(b->getLeft());
        if (base.index) refuse(node, "an assignment through two run-time indices is not supported");
        const glslang::TType& type = b->getLeft()->getType();
        const Place index = eval(b->getRight());
        const int count = element_count(type);
        const int size = int(base.place.size()) / count;
        LValue lv;
        if (!evenly_spaced(base.place, count, size, lv.stride)) refuse(node, "this indexed assignment is not supported");
        lv.place = Place(base.place.begin(), base.place.begin() + size);
        lv.index = convert_bits(index, B::Int)[0].reg;
        lv.count = std::uint32_t(count);
        lv.whole = base.place;
        return lv;
    }
    if (op != glslang::EOpIndexDirect && op != glslang::EOpIndexDirectStruct && op != glslang::EOpVectorSwizzle) {
        refuse(node, "this expression cannot be assigned");
    }
    LValue base = lvalue(b->getLeft());
    if (!base.index) {
        base.place = select_part(b, base.place);
        return base;
    }
    // A part of each element of an indexed target: pick the same part of element 0 and its strides.
    Place positions;
    for (std::size_t i = 0; i < base.place.size(); ++i) positions.push_back({base.place[i].bank, std::uint32_t(i)});
    const Place picked = select_part(b, positions);
    LValue lv = base;
    lv.place.clear();
    lv.stride.clear();
    for (const Slot& s : picked) {
        lv.place.push_back(base.place[s.reg]);
        lv.stride.push_back(base.stride[s.reg]);
    }
    return lv;
}

LValue StageLowering::argument_lvalue(TIntermTyped* node, std::optional<std::uint32_t> index_register) {
    LValue lv = lvalue(node);
    if (lv.index) {
        // In a variable register: the function's statements reuse temporaries.
        const Slot index{B::Int, index_register ? *index_register : allocate(B::Int, Space::Variable)};
        move(index, {B::Int, *lv.index}, false);
        lv.index = index.reg;
    }
    return lv;
}

std::optional<Place> StageLowering::eval_output_conversions(TIntermAggregate* comma) {
    // glslang's topology (ParseHelper.cpp, addOutputArgumentConversions):
    //     (f(.., tempArg, ..), target = T(tempArg), ..) or (tempReturn = f(..), target = T(tempArg), .., tempReturn)
    // with every tempArg at the call's own source location, which no symbol the shader writes has.
    const glslang::TIntermSequence& parts = comma->getSequence();
    TIntermTyped* first = parts.empty() ? nullptr : parts[0]->getAsTyped();
    if (!first) return std::nullopt;
    TIntermAggregate* call = first->getAsAggregate();
    if (TIntermBinary* b = first->getAsBinaryNode(); b && b->getOp() == glslang::EOpAssign) call = b->getRight()->getAsAggregate();
    if (!call || call->getOp() != glslang::EOpFunctionCall) return std::nullopt;
    const glslang::TSourceLoc& at = call->getLoc();
    const auto temporary = [&](const glslang::TIntermSymbol* s) {
        return s && s->getName() == "tempArg" && s->getLoc().line == at.line && s->getLoc().column == at.column &&
               s->getLoc().string == at.string;
    };
    // The tempArg a part converts to its target, or nullptr.
    const auto converted = [&](TIntermNode* n) -> const glslang::TIntermSymbol* {
        TIntermBinary* b = n->getAsBinaryNode();
        if (!b || b->getOp() != glslang::EOpAssign) return nullptr;
        TIntermTyped* from = b->getRight();
        if (TIntermUnary* u = from->getAsUnaryNode()) from = u->getOperand();
        const glslang::TIntermSymbol* s = from->getAsSymbolNode();
        return temporary(s) ? s : nullptr;
    };
    const auto saved_variables = variable_top_;
    std::vector<long long> ids;
    for (std::size_t i = 1; i < parts.size(); ++i) {
        if (const glslang::TIntermSymbol* s = converted(parts[i])) {
            // The index register outlives the call, which gives its own variables back.
            converted_outputs_[s->getId()] = {parts[i]->getAsBinaryNode()->getLeft(), allocate(B::Int, Space::Variable), std::nullopt};
            ids.push_back(s->getId());
        }
    }
    if (ids.empty()) return std::nullopt;
    Place last = eval(first);  // eval_call takes the targets' l-values where their tempArgs stand
    for (std::size_t i = 1; i < parts.size(); ++i) {
        const glslang::TIntermSymbol* s = converted(parts[i]);
        if (!s) {
            last = eval(parts[i]->getAsTyped());
            continue;
        }
        const LValue& target = converted_outputs_.at(s->getId()).lvalue.value();
        last = eval(parts[i]->getAsBinaryNode()->getRight());
        store(target, last);
    }
    for (long long id : ids) converted_outputs_.erase(id);
    variable_top_ = saved_variables;
    return last;
}

Place StageLowering::read(const LValue& lv) {
    if (!lv.index) return lv.place;
    Place r;
    for (std::size_t k = 0; k < lv.place.size(); ++k) {
        const std::uint32_t d = allocate(lv.place[k].bank, Space::Temp);
        ir::Instr& e = emit(ir::Op::LoadIndexed, lv.place[k].bank);
        e.d = d, e.a = lv.place[k].reg, e.b = *lv.index, e.c = lv.stride[k], e.count = std::uint16_t(lv.count);
        r.push_back({lv.place[k].bank, d});
    }
    return r;
}

Place StageLowering::eval_assignment(TIntermBinary* node) {
    const glslang::TOperator op = node->getOp();
    const LValue lv = lvalue(node->getLeft());
    if (op == glslang::EOpAssign && !lv.index) {
        // x = f(...): f's returns write x itself, where f cannot read x otherwise (a local of
        // this function or a temporary, not a global or an output).
        auto* call = node->getRight()->getAsAggregate();
        bool private_registers = call && call->getOp() == glslang::EOpFunctionCall && call->isUserDefined();
        for (const Slot& r : lv.place) private_registers = private_registers && !is_shared_variable(r);
        std::set<std::uint32_t> distinct;
        for (const Slot& r : lv.place) distinct.insert(r.reg | (std::uint32_t(r.bank) << 28));
        if (private_registers && distinct.size() == lv.place.size()) {
            (void)eval_call(call, &lv.place);
            return lv.place;
        }
    }
    Place value = eval(node->getRight());
    if (op != glslang::EOpAssign) {
        const Place current = read(lv);
        if (op == glslang::EOpVectorTimesMatrixAssign) {
            value = matrix_product(glslang::EOpVectorTimesMatrix, shape(node->getLeft()->getType()), shape(node->getRight()->getType()), current, value);
        } else if (op == glslang::EOpMatrixTimesMatrixAssign) {
            value = matrix_product(glslang::EOpMatrixTimesMatrix, shape(node->getLeft()->getType()), shape(node->getRight()->getType()), current, value);
        } else {
            value = arithmetic(op, node->getLeft()->getType(), current, value);
        }
    }
    store(lv, value);
    return lv.index ? value : lv.place;
}

Place StageLowering::eval_increment(TIntermUnary* node) {
    const glslang::TOperator op = node->getOp();
    const LValue lv = lvalue(node->getOperand());
    const bool post = op == glslang::EOpPostIncrement || op == glslang::EOpPostDecrement;
    const bool value_used = node != statement_value_;  // `i++;` needs no copy of i
    Place old = read(lv);
    if (post && value_used && !lv.index) {
        // the value before: the variable's registers change below
        Place copy = temps_like(old);
        assign(copy, old, false);
        old = copy;
    }
    const B bank = old[0].bank;
    const Place one{{bank, bank == B::Float ? float_constant(1.0f) : constant(bank, 1u)}};
    const bool up = op == glslang::EOpPostIncrement || op == glslang::EOpPreIncrement;
    const Place changed = arithmetic(up ? glslang::EOpAdd : glslang::EOpSub, node->getOperand()->getType(), old, one);
    store(lv, changed);
    return post ? old : changed;
}

Place StageLowering::eval_unary(TIntermUnary* node) {
    const glslang::TOperator op = node->getOp();
    // a texture function of the sampler alone (textureQueryLevels)
    if (glslang::EOpTextureGuardBegin < op && op < glslang::EOpTextureGuardEnd) {
        return eval_texture(op, node, {node->getOperand()});
    }
    switch (op) {
        case glslang::EOpPostIncrement: case glslang::EOpPostDecrement: case glslang::EOpPreIncrement:
        case glslang::EOpPreDecrement:
            return eval_increment(node);
        default: break;
    }
    if (op >= glslang::EOpConvInt8ToBool && op <= glslang::EOpConvDoubleToFloat) {
        B to;
        if (!bank_of(node->getBasicType(), to)) refuse(node, "conversion to '" + type_name(node->getType()) + "' is not supported");
        return convert(eval(node->getOperand()), to);
    }
    const Place a = eval(node->getOperand());
    const B bank = a.empty() ? B::Float : a[0].bank;
    Place r;
    switch (op) {
        case glslang::EOpNegative:
            for (const Slot& s : a) r.push_back({bank, emit1(bank == B::Float ? ir::Op::FNeg : ir::Op::INeg, bank, s.reg, 0, 0, bank)});
            return r;
        case glslang::EOpLogicalNot: case glslang::EOpVectorLogicalNot:
            for (const Slot& s : a) r.push_back({B::Bool, emit1(ir::Op::BNot, B::Bool, s.reg)});
            return r;
        case glslang::EOpBitwiseNot:
            for (const Slot& s : a) r.push_back({bank, emit1(ir::Op::INot, bank, s.reg, 0, 0, bank)});
            return r;
        case glslang::EOpCopyObject: return a;
        default: break;
    }
    return eval_builtin(op, node, {node->getOperand()}, {a});
}

Place StageLowering::eval_aggregate(TIntermAggregate* node) {
    const glslang::TOperator op = node->getOp();
    if (op == glslang::EOpFunctionCall) {
        if (!node->isUserDefined()) refuse(node, "'" + std::string(node->getName().c_str()) + "' is not supported");
        return eval_call(node);
    }
    if (op == glslang::EOpComma || op == glslang::EOpSequence) {
        if (op == glslang::EOpComma) {
            if (std::optional<Place> p = eval_output_conversions(node)) return *p;
        }
        Place last;
        for (TIntermNode* n : node->getSequence()) {
            if (auto* t = n->getAsTyped()) last = eval(t);
        }
        return last;
    }
    if ((op >= glslang::EOpConstructGuardStart && op <= glslang::EOpConstructGuardEnd)) return eval_constructor(node);
    std::vector<TIntermTyped*> args;
    for (TIntermNode* n : node->getSequence()) args.push_back(n->getAsTyped());
    if (glslang::EOpTextureGuardBegin < op && op < glslang::EOpTextureGuardEnd) return eval_texture(op, node, args);
    if (glslang::EOpSparseTextureGuardBegin < op && op < glslang::EOpSparseTextureGuardEnd) {
        refuse(node, "sparse texture functions are not supported");
    }
    // Operands left to right, each copied where a later one may change it.
    std::vector<Place> values;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i]->getBasicType() == glslang::EbtSampler) {
            values.emplace_back();
            continue;
        }
        Place v = eval(args[i]);
        bool later_changes = false;
        for (std::size_t j = i + 1; j < args.size(); ++j) later_changes = later_changes || has_side_effects(args[j]);
        if (later_changes) {
            Place copy = temps_like(v);
            assign(copy, v, false);
            v = copy;
        }
        values.push_back(v);
    }
    return eval_builtin(op, node, args, values);
}

Place StageLowering::eval_constructor(TIntermAggregate* node) {
    const glslang::TType& type = node->getType();
    const glslang::TIntermSequence& args = node->getSequence();
    std::vector<Place> values;
    for (TIntermNode* n : args) values.push_back(eval(n->getAsTyped()));
    const std::vector<B> banks = component_banks(type);
    Place r;
    if (type.isStruct() || type.isArray()) {
        for (const Place& v : values) r.insert(r.end(), v.begin(), v.end());
        if (r.size() != banks.size()) refuse(node, "constructor of '" + type_name(type) + "' with the wrong number of values");
        return r;
    }
    const B bank = banks[0];
    const glslang::TType& first = args[0]->getAsTyped()->getType();
    if (type.isMatrix()) {
        const int cols = type.getMatrixCols(), rows = type.getMatrixRows();
        if (args.size() == 1 && first.isScalar()) {
            // mat(s): s on the diagonal
            const Slot s = convert(values[0][0], B::Float);
            const Slot zero{B::Float, float_constant(0.0f)};
            for (int c = 0; c < cols; ++c) {
                for (int k = 0; k < rows; ++k) r.push_back(c == k ? s : zero);
            }
            return r;
        }
        if (args.size() == 1 && first.isMatrix()) {
            // mat(m): the upper left part, the identity elsewhere
            const int c2 = first.getMatrixCols(), r2 = first.getMatrixRows();
            const Slot zero{B::Float, float_constant(0.0f)}, one{B::Float, float_constant(1.0f)};
            for (int c = 0; c < cols; ++c) {
                for (int k = 0; k < rows; ++k) {
                    r.push_back(c < c2 && k < r2 ? values[0][std::size_t(c * r2 + k)] : c == k ? one : zero);
                }
            }
            return r;
        }
    }
    Place all;
    for (const Place& v : values) all.insert(all.end(), v.begin(), v.end());
    if (all.size() == 1 && banks.size() > 1) {
        // vec3(s): s in every component
        const Slot s = convert(all[0], bank);
        return Place(banks.size(), s);
    }
    if (all.size() < banks.size()) refuse(node, "too few values to construct '" + type_name(type) + "'");
    for (std::size_t i = 0; i < banks.size(); ++i) r.push_back(convert(all[i], bank));
    return r;
}

Place StageLowering::eval_selection(glslang::TIntermSelection* node) {
    if (node->getBasicType() == glslang::EbtVoid) refuse(node, "an if statement where a value is expected");
    auto* t = node->getTrueBlock()->getAsTyped();
    auto* f = node->getFalseBlock()->getAsTyped();
    const Place c = eval(node->getCondition());
    if (!has_side_effects(t) && !has_side_effects(f)) {
        const Place a = eval(t), b = eval(f);
        Place r;
        for (std::size_t i = 0; i < a.size(); ++i) {
            const std::uint32_t d = allocate(a[i].bank, Space::Temp);
            ir::Instr& e = emit(ir::Op::Select, a[i].bank);
            e.d = d, e.a = c[0].reg, e.b = a[i].reg, e.c = b[i].reg;
            r.push_back({a[i].bank, d});
        }
        return r;
    }
    // Only the chosen operand runs, as GLSL's ?: does.
    const Place r = allocate(node->getType(), Space::Temp);
    const std::size_t at_if = stage_.code.size();
    emit(ir::Op::If).a = c[0].reg;
    {
        const TempMark m = mark();
        assign(r, eval(t), true);
        release(m);
    }
    const std::size_t at_else = stage_.code.size();
    emit(ir::Op::Else);
    {
        const TempMark m = mark();
        assign(r, eval(f), true);
        release(m);
    }
    const std::size_t at_end = stage_.code.size();
    emit(ir::Op::EndIf);
    stage_.code[at_if].target = std::uint32_t(at_else);
    stage_.code[at_else].target = std::uint32_t(at_end);
    return r;
}

Place StageLowering::eval_call(TIntermAggregate* call, const Place* destination) {
    const std::string name = call->getName().c_str();
    auto it = functions_.find(name);
    if (it == functions_.end()) refuse(call, "function '" + name.substr(0, name.find('(')) + "' is declared but never defined");
    for (const Frame& f : frames_) {
        if (f.function == name) refuse(call, "function '" + name.substr(0, name.find('(')) + "' calls itself: GLSL has no recursion");
    }
    if (frames_.size() > 256) refuse(call, "functions nested more than 256 calls deep");
    TIntermAggregate* def = it->second;
    const glslang::TIntermSequence& parts = def->getSequence();
    const glslang::TIntermSequence& params = parts[0]->getAsAggregate()->getSequence();
    const glslang::TIntermSequence& args = call->getSequence();

    Frame frame{name, {}, {}, {}};
    if (call->getBasicType() != glslang::EbtVoid) frame.result = destination ? *destination : allocate(call->getType(), Space::Temp);
    const auto saved_variables = variable_top_;
    struct Out {
        LValue target;
        Place param;
    };
    std::vector<Out> outs;
    std::set<long long> param_ids;
    // Arguments left to right: in-values copied, out-targets named now and written after.
    for (std::size_t i = 0; i < params.size() && i < args.size(); ++i) {
        glslang::TIntermSymbol* p = params[i]->getAsSymbolNode();
        TIntermTyped* arg = args[i]->getAsTyped();
        param_ids.insert(p->getId());
        if (p->getBasicType() == glslang::EbtSampler) {
            frame.samplers.emplace(p->getId(), sampler_of(arg));
            continue;
        }
        const glslang::TStorageQualifier q = p->getQualifier().storage;
        if (q != glslang::EvqOut && q != glslang::EvqInOut && !writes_symbol(def, p->getId())) {
            // An in parameter the function never assigns reads the argument's registers, where
            // nothing the function does can change them (a temporary or constant: not a global
            // or an output, which the function may assign).
            Place value = eval(arg);
            bool private_registers = true;
            for (const Slot& r : value) private_registers = private_registers && !is_shared_variable(r);
            if (!private_registers) {
                Place copy = allocate(p->getType(), Space::Variable);
                assign(copy, value, false);
                value = copy;
            }
            frame.locals.emplace(p->getId(), value);
            continue;
        }
        Place param = allocate(p->getType(), Space::Variable);
        if (q == glslang::EvqOut || q == glslang::EvqInOut) {
            if (auto* s = arg->getAsSymbolNode()) {
                if (auto c = converted_outputs_.find(s->getId()); c != converted_outputs_.end()) {
                    c->second.lvalue = argument_lvalue(c->second.target, c->second.index);
                }
            }
            LValue target = argument_lvalue(arg);
            if (q == glslang::EvqInOut) {
                assign(param, read(target), false);
            } else {
                for (const Slot& s : param) move(s, {s.bank, constant(s.bank, 0)}, false);
            }
            outs.push_back({target, param});
        } else {
            assign(param, eval(arg), false);
        }
        frame.locals.emplace(p->getId(), param);
    }
    frames_.push_back(std::move(frame));
    const std::uint32_t call_line = line_;
    emit(ir::Op::CallBegin);
    if (parts.size() > 1 && parts[1]) {
        if (TIntermAggregate* body = parts[1]->getAsAggregate(); body && body->getOp() == glslang::EOpSequence) {
            initialise_locals(body, param_ids);
            statements(body);
        } else {
            statement(parts[1]);
        }
    }
    line_ = call_line;
    emit(ir::Op::CallEnd);
    Place result = frames_.back().result;
    frames_.pop_back();
    for (const Out& o : outs) store(o.target, o.param);
    variable_top_ = saved_variables;
    return result;
}

}  // namespace qs::frontend
