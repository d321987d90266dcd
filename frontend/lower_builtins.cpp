// GLSL's built-in functions (lowering.h): each becomes the interpreter operation that calls the
// vocabulary's function of the same name (shading/glsl/), component by component where GLSL
// defines it so, on whole vectors and matrices where it does not.

#include "frontend/glsl_types.h"
#include "frontend/shadow_lookup.h"
#include "frontend/lowering.h"

namespace qs::frontend {

using glslang::TIntermTyped;
using B = ir::Bank;

Place StageLowering::unary(ir::Op op, const Place& a, B bank, B result) {
    Place r;
    for (const Slot& s : a) r.push_back({result, emit1(op, result, s.reg, 0, 0, bank)});
    return r;
}

Place StageLowering::broadcast(const Place& p, std::size_t n) { return p.size() == 1 && n > 1 ? Place(n, p[0]) : p; }

namespace {

ir::Op float_unary(glslang::TOperator op) {
    switch (op) {
        case glslang::EOpRadians: return ir::Op::FRadians;
        case glslang::EOpDegrees: return ir::Op::FDegrees;
        case glslang::EOpSin: return ir::Op::FSin;
        case glslang::EOpCos: return ir::Op::FCos;
        case glslang::EOpTan: return ir::Op::FTan;
        case glslang::EOpAsin: return ir::Op::FAsin;
        case glslang::EOpAcos: return ir::Op::FAcos;
        case glslang::EOpAtan: return ir::Op::FAtan;
        case glslang::EOpSinh: return ir::Op::FSinh;
        case glslang::EOpCosh: return ir::Op::FCosh;
        case glslang::EOpTanh: return ir::Op::FTanh;
        case glslang::EOpAsinh: return ir::Op::FAsinh;
        case glslang::EOpAcosh: return ir::Op::FAcosh;
        case glslang::EOpAtanh: return ir::Op::FAtanh;
        case glslang::EOpExp: return ir::Op::FExp;
        case glslang::EOpLog: return ir::Op::FLog;
        case glslang::EOpExp2: return ir::Op::FExp2;
        case glslang::EOpLog2: return ir::Op::FLog2;
        case glslang::EOpSqrt: return ir::Op::FSqrt;
        case glslang::EOpInverseSqrt: return ir::Op::FInverseSqrt;
        case glslang::EOpFloor: return ir::Op::FFloor;
        case glslang::EOpTrunc: return ir::Op::FTrunc;
        // GLSL lets round() take halves either way; Mesa takes them to even.
        case glslang::EOpRound: return ir::Op::FRoundEven;
        case glslang::EOpRoundEven: return ir::Op::FRoundEven;
        case glslang::EOpCeil: return ir::Op::FCeil;
        case glslang::EOpFract: return ir::Op::FFract;
        case glslang::EOpDPdx: return ir::Op::FDdx;
        case glslang::EOpDPdy: return ir::Op::FDdy;
        case glslang::EOpFwidth: return ir::Op::FFwidth;
        case glslang::EOpDPdxFine: return ir::Op::FDdxFine;
        case glslang::EOpDPdyFine: return ir::Op::FDdyFine;
        case glslang::EOpFwidthFine: return ir::Op::FFwidthFine;
        case glslang::EOpDPdxCoarse: return ir::Op::FDdxCoarse;
        case glslang::EOpDPdyCoarse: return ir::Op::FDdyCoarse;
        case glslang::EOpFwidthCoarse: return ir::Op::FFwidthCoarse;
        default: return ir::Op::Mov;
    }
}

bool is_derivative(glslang::TOperator op) {
    return op == glslang::EOpDPdx || op == glslang::EOpDPdy || op == glslang::EOpFwidth || op == glslang::EOpDPdxFine ||
           op == glslang::EOpDPdyFine || op == glslang::EOpFwidthFine || op == glslang::EOpDPdxCoarse ||
           op == glslang::EOpDPdyCoarse || op == glslang::EOpFwidthCoarse;
}

}  // namespace

Place StageLowering::eval_builtin(glslang::TOperator op, TIntermTyped* node, const std::vector<TIntermTyped*>& args,
                                  const std::vector<Place>& v) {
    const glslang::TType& type = node->getType();
    B bank = B::Float;
    bank_of(type.getBasicType(), bank);
    const std::size_t n = std::size_t(type.isMatrix() ? type.getMatrixCols() * type.getMatrixRows() : type.getVectorSize());
    const auto arg_bank = [&](std::size_t i) { return v[i].empty() ? B::Float : v[i][0].bank; };
    // (Operands are made consecutive before the operation is emitted: the copies come first.)
    const auto composite = [&](ir::Op o, int result_components, int width) {
        const std::uint32_t a = consecutive(v[0]);
        const std::uint32_t b = v.size() > 1 ? consecutive(v[1]) : 0;
        const std::uint32_t c = v.size() > 2 ? consecutive(v[2]) : 0;
        Place r = temps(B::Float, result_components);
        ir::Instr& e = emit(o);
        e.d = r[0].reg, e.a = a, e.b = b, e.c = c, e.n = std::uint8_t(width);
        return r;
    };

    if (const ir::Op f = float_unary(op); f != ir::Op::Mov && v.size() == 1) {
        if (is_derivative(op)) {
            if (kind_ != StageKind::Fragment) refuse(node, "derivatives exist in fragment shaders only");
            stage_.derivatives = true;
        }
        return unary(f, v[0], B::Float, B::Float);
    }
    switch (op) {
        case glslang::EOpAtan:  // atan(y, x)
            return componentwise(ir::Op::FAtan2, B::Float, v[0], v[1], B::Float);
        case glslang::EOpAbs:
            return arg_bank(0) == B::Float ? unary(ir::Op::FAbs, v[0], B::Float, B::Float) : unary(ir::Op::IAbs, v[0], bank, bank);
        case glslang::EOpSign:
            return arg_bank(0) == B::Float ? unary(ir::Op::FSign, v[0], B::Float, B::Float) : unary(ir::Op::ISign, v[0], bank, bank);
        case glslang::EOpIsNan: return unary(ir::Op::FIsNan, v[0], B::Float, B::Bool);
        case glslang::EOpIsInf: return unary(ir::Op::FIsInf, v[0], B::Float, B::Bool);
        case glslang::EOpPow: return componentwise(ir::Op::FPow, B::Float, v[0], v[1], B::Float);
        case glslang::EOpMod: return arithmetic(op, type, v[0], v[1]);
        case glslang::EOpMin: case glslang::EOpMax: {
            const bool fl = bank == B::Float;
            const ir::Op o = op == glslang::EOpMin ? (fl ? ir::Op::FMin : ir::Op::IMin) : (fl ? ir::Op::FMax : ir::Op::IMax);
            return componentwise(o, bank, v[0], v[1], bank);
        }
        case glslang::EOpStep: {  // step(edge, x)
            const Place e = broadcast(v[0], n), x = broadcast(v[1], n);
            return componentwise(ir::Op::FStep, B::Float, e, x, B::Float);
        }
        case glslang::EOpClamp: case glslang::EOpSmoothStep: case glslang::EOpMix: case glslang::EOpFma: {
            if (op == glslang::EOpMix && arg_bank(2) == B::Bool) {
                // mix(x, y, b): y where b (GLSL 1.30), for floats, and integers and bools (4.50)
                Place r;
                for (std::size_t i = 0; i < n; ++i) {
                    const std::uint32_t d = allocate(bank, Space::Temp);
                    ir::Instr& e = emit(ir::Op::Select, bank);
                    e.d = d, e.a = broadcast(v[2], n)[i].reg, e.b = v[1][i].reg, e.c = v[0][i].reg;
                    r.push_back({bank, d});
                }
                return r;
            }
            ir::Op o = ir::Op::FClamp;
            if (op == glslang::EOpClamp && bank != B::Float) o = ir::Op::IClamp;
            if (op == glslang::EOpSmoothStep) o = ir::Op::FSmoothStep;
            if (op == glslang::EOpMix) o = ir::Op::FMix;
            if (op == glslang::EOpFma) o = ir::Op::FFma;
            const Place a = broadcast(v[0], n), b = broadcast(v[1], n), c = broadcast(v[2], n);
            Place r;
            for (std::size_t i = 0; i < n; ++i) r.push_back({bank, emit1(o, bank, a[i].reg, b[i].reg, c[i].reg, bank)});
            return r;
        }
        case glslang::EOpModf: case glslang::EOpFrexp: {
            // the second result through the out parameter
            const LValue out = lvalue(args[1]);
            const B second = op == glslang::EOpModf ? B::Float : B::Int;
            Place r = temps(B::Float, int(n)), s = temps(second, int(n));
            for (std::size_t i = 0; i < n; ++i) {
                ir::Instr& e = emit(op == glslang::EOpModf ? ir::Op::FModf : ir::Op::FFrexp);
                e.d = r[i].reg, e.a = v[0][i].reg, e.c = s[i].reg;
            }
            store(out, s);
            return r;
        }
        case glslang::EOpLdexp: return componentwise(ir::Op::FLdexp, B::Float, v[0], v[1], B::Float);
        case glslang::EOpLength: return composite(ir::Op::Length, 1, int(v[0].size()));
        case glslang::EOpDistance: return composite(ir::Op::Distance, 1, int(v[0].size()));
        case glslang::EOpDot: return composite(ir::Op::Dot, 1, int(v[0].size()));
        case glslang::EOpNormalize: return composite(ir::Op::Normalize, int(v[0].size()), int(v[0].size()));
        case glslang::EOpCross: return composite(ir::Op::Cross, 3, 3);
        case glslang::EOpReflect: return composite(ir::Op::Reflect, int(v[0].size()), int(v[0].size()));
        case glslang::EOpRefract: return composite(ir::Op::Refract, int(v[0].size()), int(v[0].size()));
        case glslang::EOpFaceForward: return composite(ir::Op::FaceForward, int(v[0].size()), int(v[0].size()));
        case glslang::EOpLessThan: case glslang::EOpLessThanEqual: case glslang::EOpGreaterThan:
        case glslang::EOpGreaterThanEqual: case glslang::EOpVectorEqual: case glslang::EOpVectorNotEqual:
            return compare(op, v[0], v[1]);
        case glslang::EOpAny: case glslang::EOpAll: {
            std::uint32_t r = v[0][0].reg;
            for (std::size_t i = 1; i < v[0].size(); ++i) r = emit1(op == glslang::EOpAny ? ir::Op::BOr : ir::Op::BAnd, B::Bool, r, v[0][i].reg);
            if (v[0].size() == 1) {
                const std::uint32_t d = allocate(B::Bool, Space::Temp);
                move({B::Bool, d}, v[0][0], false);
                r = d;
            }
            return {{B::Bool, r}};
        }
        case glslang::EOpVectorLogicalNot: return unary(ir::Op::BNot, v[0], B::Bool, B::Bool);
        case glslang::EOpMul: return componentwise(bank == B::Float ? ir::Op::FMul : ir::Op::IMul, bank, v[0], v[1], bank);
        case glslang::EOpOuterProduct: {  // column k = c * r[k]
            const Place& c = v[0];
            const Place& rv = v[1];
            Place r;
            for (const Slot& rk : rv) {
                for (const Slot& ci : c) r.push_back({B::Float, emit1(ir::Op::FMul, B::Float, ci.reg, rk.reg)});
            }
            return r;
        }
        case glslang::EOpTranspose: {
            const glslang::TType& m = args[0]->getType();
            const int cols = m.getMatrixCols(), rows = m.getMatrixRows();
            Place r;
            for (int c = 0; c < rows; ++c) {
                for (int k = 0; k < cols; ++k) r.push_back(v[0][std::size_t(k * rows + c)]);
            }
            return r;
        }
        case glslang::EOpDeterminant: case glslang::EOpMatrixInverse: {
            const int size = args[0]->getType().getMatrixCols();
            const bool inverse = op == glslang::EOpMatrixInverse;
            const std::uint32_t a = consecutive(v[0]);
            Place r = temps(B::Float, inverse ? size * size : 1);
            ir::Instr& e = emit(inverse ? ir::Op::Inverse : ir::Op::Determinant);
            e.d = r[0].reg, e.a = a, e.n = std::uint8_t(size);
            return r;
        }
        case glslang::EOpFloatBitsToInt: return unary(ir::Op::FloatBitsToInt, v[0], B::Float, B::Int);
        case glslang::EOpFloatBitsToUint: return unary(ir::Op::FloatBitsToUint, v[0], B::Float, B::Uint);
        case glslang::EOpIntBitsToFloat: return unary(ir::Op::IntBitsToFloat, v[0], B::Int, B::Float);
        case glslang::EOpUintBitsToFloat: return unary(ir::Op::UintBitsToFloat, v[0], B::Uint, B::Float);
        case glslang::EOpBitFieldReverse: return unary(ir::Op::IBitfieldReverse, v[0], bank, bank);
        case glslang::EOpBitCount: return unary(ir::Op::IBitCount, v[0], arg_bank(0), B::Int);
        case glslang::EOpFindLSB: return unary(ir::Op::IFindLsb, v[0], arg_bank(0), B::Int);
        case glslang::EOpFindMSB: return unary(ir::Op::IFindMsb, v[0], arg_bank(0), B::Int);
        case glslang::EOpBitfieldExtract: {
            Place r;
            const Slot offset = convert_bits(v[1], B::Int)[0], bits = convert_bits(v[2], B::Int)[0];
            for (const Slot& s : v[0]) r.push_back({bank, emit1(ir::Op::IBitfieldExtract, bank, s.reg, offset.reg, bits.reg, bank)});
            return r;
        }
        case glslang::EOpBitfieldInsert: {
            const Place ob = temps(B::Int, 2);
            move(ob[0], convert_bits(v[2], B::Int)[0], false);
            move(ob[1], convert_bits(v[3], B::Int)[0], false);
            Place r;
            for (std::size_t i = 0; i < v[0].size(); ++i) {
                r.push_back({bank, emit1(ir::Op::IBitfieldInsert, bank, v[0][i].reg, v[1][i].reg, ob[0].reg, bank)});
            }
            return r;
        }
        case glslang::EOpAddCarry: case glslang::EOpSubBorrow: case glslang::EOpUMulExtended:
        case glslang::EOpIMulExtended: {
            const bool mul = op == glslang::EOpUMulExtended || op == glslang::EOpIMulExtended;
            const B k = arg_bank(0);
            const ir::Op o = op == glslang::EOpAddCarry ? ir::Op::IAddCarry : op == glslang::EOpSubBorrow ? ir::Op::ISubBorrow : ir::Op::IMulExtended;
            Place first = temps(k, int(v[0].size())), second = temps(k, int(v[0].size()));
            for (std::size_t i = 0; i < v[0].size(); ++i) {
                ir::Instr& e = emit(o, k);
                e.d = first[i].reg, e.a = v[0][i].reg, e.b = v[1][i].reg, e.c = second[i].reg;
            }
            if (mul) {
                // umulExtended(x, y, out msb, out lsb)
                store(lvalue(args[2]), first);
                store(lvalue(args[3]), second);
                return {};
            }
            store(lvalue(args[2]), second);  // the carry or borrow
            return first;
        }
        case glslang::EOpFtransform: return ftransform();
        case glslang::EOpNoise: {
            // Mesa's noise1..noise4 return 0.
            Place r;
            for (std::size_t i = 0; i < n; ++i) r.push_back({B::Float, float_constant(0.0f)});
            return r;
        }
        default: break;
    }
    refuse(node, "this built-in function is not supported");
}

int StageLowering::sampler_of(TIntermTyped* node) {
    if (auto* s = node->getAsSymbolNode()) {
        for (auto f = frames_.rbegin(); f != frames_.rend(); ++f) {
            if (auto it = f->samplers.find(s->getId()); it != f->samplers.end()) return it->second;
            break;  // a sampler parameter belongs to the innermost call
        }
        if (auto it = global_samplers_.find(s->getId()); it != global_samplers_.end()) return it->second;
        return sampler_uniform(s, s->getName().c_str(), s->getType());
    }
    if (auto* b = node->getAsBinaryNode(); b && b->getOp() == glslang::EOpIndexDirect) {
        auto* array = b->getLeft()->getAsSymbolNode();
        if (array && array->getQualifier().storage == glslang::EvqUniform) {
            const int k = b->getRight()->getAsConstantUnion()->getConstArray()[0].getIConst();
            return sampler_uniform(array, std::string(array->getName().c_str()) + "[" + std::to_string(k) + "]",
                                   element_type(array->getType()));
        }
    }
    refuse(node, "a sampler must be a uniform, an element of a uniform array at a constant index, or a parameter");
}

// texelFetch and texelFetchOffset: integer texel coordinates, a level (0 where none is given).
Place StageLowering::eval_texel_fetch(glslang::TOperator op, int slot, int dims, const std::vector<Place>& v) {
    const Place coords = convert_bits(v[0], B::Int);
    const Place lod = v.size() > 1 ? convert_bits(v[1], B::Int) : Place{{B::Int, int_constant(0)}};
    const std::uint32_t a = consecutive(Place(coords.begin(), coords.begin() + dims));
    std::uint32_t c = 0;
    if (op == glslang::EOpTextureFetchOffset) {
        const Place offset = convert_bits(v[2], B::Int);
        c = consecutive(Place(offset.begin(), offset.begin() + dims));
    }
    Place r = temps(B::Float, 4);
    ir::Instr& e = emit(op == glslang::EOpTextureFetch ? ir::Op::TexelFetch : ir::Op::TexelFetchOffset);
    e.d = r[0].reg, e.a = a, e.b = lod[0].reg, e.c = c, e.n = std::uint8_t(dims), e.count = std::uint16_t(slot);
    return r;
}

// textureSize at a level (0 where none is given).
Place StageLowering::eval_texture_size(int slot, int dims, const std::vector<Place>& v) {
    Place r = temps(B::Int, dims);
    const Place lod = v.empty() ? Place{{B::Int, int_constant(0)}} : convert_bits(v[0], B::Int);
    ir::Instr& e = emit(ir::Op::TextureSize);
    e.d = r[0].reg, e.b = lod[0].reg, e.n = std::uint8_t(dims), e.count = std::uint16_t(slot);
    return r;
}

// textureQueryLod: the level an implicit lookup at the coordinates would take, from the quad.
Place StageLowering::eval_query_lod(TIntermTyped* node, int slot, int dims, const std::vector<Place>& v) {
    if (kind_ == StageKind::Vertex) refuse(node, "textureQueryLod exists in fragment shaders only");
    stage_.derivatives = true;  // the quad's, as an implicit lookup's
    const std::uint32_t a = consecutive(Place(v[0].begin(), v[0].begin() + dims));
    Place r = temps(B::Float, 2);
    ir::Instr& e = emit(ir::Op::TextureQueryLod);
    e.d = r[0].reg, e.a = a, e.n = std::uint8_t(dims), e.count = std::uint16_t(slot);
    return r;
}

// The filtered lookup `o` at `coords` (the first `dims` of them), with its level of detail or
// bias (`extra`), or derivatives along x and y, and texel offsets where it takes them.
Place StageLowering::emit_lookup(ir::Op o, int slot, int dims, const Place& coords, const Place* extra,
                                 const Place* ddx, const Place* ddy, const Place* offset) {
    // A sampler2DShadow's compares the coordinate after the `dims` (m = 4) and gives one result.
    const bool shadow = interface_.program.samplers[std::size_t(slot)].shadow;
    const std::uint32_t a = consecutive(Place(coords.begin(), coords.begin() + dims + (shadow ? 1 : 0)));
    std::uint32_t b = 0, c = 0;
    if (extra) b = (*extra)[0].reg;
    if (ddx) {
        Place both(ddx->begin(), ddx->begin() + dims);
        both.insert(both.end(), ddy->begin(), ddy->begin() + dims);
        b = consecutive(both);
    }
    if (offset) {
        const Place o_int = convert_bits(*offset, B::Int);
        c = consecutive(Place(o_int.begin(), o_int.begin() + dims));
    }
    Place r = temps(B::Float, shadow ? 1 : 4);
    ir::Instr& e = emit(o);
    e.d = r[0].reg, e.a = a, e.b = b, e.c = c, e.n = std::uint8_t(dims), e.m = shadow ? 4 : 1;
    e.count = std::uint16_t(slot);
    return r;
}

// A projective lookup's coordinates: the first `count` (a shadow lookup's reference value too)
// times the reciprocal of the last one, as Mesa lowers them.
Place StageLowering::project(const Place& p, int count) {
    const std::uint32_t q = emit1(ir::Op::FDiv, B::Float, float_constant(1.0f), p.back().reg);
    Place coords;
    for (int i = 0; i < count; ++i) {
        coords.push_back({B::Float, emit1(ir::Op::FMul, B::Float, p[std::size_t(i)].reg, q)});
    }
    return coords;
}

// texture, textureProj, textureLod, textureGrad and their Offset and Proj forms on a sampler2D,
// sampler3D or sampler2DShadow (P's third component the reference value, projected too in a
// projective lookup; shadow2D's vec4 is (r, r, r, 1), as GL_DEPTH_TEXTURE_MODE's default,
// GL_LUMINANCE, makes it); `zero`: level 0, which a vertex shader's implicit lookups read (it has
// no neighbours to take a level from).
Place StageLowering::eval_filtered(glslang::TOperator op, TIntermTyped* node, int slot, int dims,
                                   const std::vector<Place>& v, const Place& zero) {
    const bool vertex = kind_ == StageKind::Vertex;
    const bool shadow = interface_.program.samplers[std::size_t(slot)].shadow;
    if (shadow && !shadow_lookup_function(op)) {
        refuse(node, "this texture function on a sampler2DShadow is not supported (texture, textureProj, textureLod, "
                     "textureGrad, their Offset forms, shadow2D, shadow2DProj, shadow2DLod, textureSize, the "
                     "gathers and textureQueryLod are)");
    }
    const int taken = dims + (shadow ? 1 : 0);
    const auto lookup = [&](ir::Op plain, ir::Op with_offset, const Place& coords, const Place* extra, const Place* ddx,
                            const Place* ddy, const Place* offset) {
        const Place r = emit_lookup(offset ? with_offset : plain, slot, dims, coords, extra, ddx, ddy, offset);
        if (!shadow || node->getType().getVectorSize() != 4) return r;
        Place luminance = temps(B::Float, 4);
        for (std::size_t i = 0; i < 3; ++i) move(luminance[i], r[0], false);
        move(luminance[3], {B::Float, float_constant(1.0f)}, false);
        return luminance;
    };
    const auto implicit = [&](const Place& coords, const Place* bias, const Place* offset) {
        if (vertex) {
            return lookup(ir::Op::TextureLod, ir::Op::TextureLodOffset, coords, &zero, nullptr, nullptr, offset);
        }
        if (bias) return lookup(ir::Op::TextureBias, ir::Op::TextureBiasOffset, coords, bias, nullptr, nullptr, offset);
        return lookup(ir::Op::Texture, ir::Op::TextureOffset, coords, nullptr, nullptr, nullptr, offset);
    };
    const auto at_level = [&](const Place& coords, const Place& lod, const Place* offset) {
        return lookup(ir::Op::TextureLod, ir::Op::TextureLodOffset, coords, &lod, nullptr, nullptr, offset);
    };
    const auto gradient = [&](const Place& coords, const Place& ddx, const Place& ddy, const Place* offset) {
        return lookup(ir::Op::TextureGrad, ir::Op::TextureGradOffset, coords, nullptr, &ddx, &ddy, offset);
    };
    switch (op) {
        case glslang::EOpTexture: return implicit(v[0], v.size() == 2 ? &v[1] : nullptr, nullptr);
        case glslang::EOpTextureProj: return implicit(project(v[0], taken), v.size() == 2 ? &v[1] : nullptr, nullptr);
        case glslang::EOpTextureOffset: return implicit(v[0], v.size() == 3 ? &v[2] : nullptr, &v[1]);
        case glslang::EOpTextureProjOffset:
            return implicit(project(v[0], taken), v.size() == 3 ? &v[2] : nullptr, &v[1]);
        case glslang::EOpTextureLod: return at_level(v[0], v[1], nullptr);
        case glslang::EOpTextureProjLod: return at_level(project(v[0], taken), v[1], nullptr);
        case glslang::EOpTextureLodOffset: return at_level(v[0], v[1], &v[2]);
        case glslang::EOpTextureProjLodOffset: return at_level(project(v[0], taken), v[1], &v[2]);
        case glslang::EOpTextureGrad: return gradient(v[0], v[1], v[2], nullptr);
        case glslang::EOpTextureProjGrad: return gradient(project(v[0], taken), v[1], v[2], nullptr);
        case glslang::EOpTextureGradOffset: return gradient(v[0], v[1], v[2], &v[3]);
        case glslang::EOpTextureProjGradOffset: return gradient(project(v[0], taken), v[1], v[2], &v[3]);
        default: break;
    }
    refuse(node, "this texture function is not supported (supported: texture, texture2D, texture3D with or without a "
                 "bias, their Proj, Lod, Grad and Offset forms, texelFetch, texelFetchOffset, textureSize, "
                 "textureGather, textureGatherOffset, textureGatherOffsets, textureQueryLod, textureQueryLevels)");
}

Place StageLowering::eval_texture(glslang::TOperator op, TIntermTyped* node, const std::vector<TIntermTyped*>& args) {
    if (op == glslang::EOpTextureQuerySamples) refuse(node, "textureSamples is not supported (no multisample sampler is)");
    const int slot = sampler_of(args[0]);
    const int dims = interface_.program.samplers[std::size_t(slot)].dims;
    if (op == glslang::EOpTextureQueryLevels) {
        Place r = temps(B::Int, 1);
        ir::Instr& e = emit(ir::Op::TextureQueryLevels);
        e.d = r[0].reg, e.n = std::uint8_t(dims == ir::kCubeSampler ? 3 : dims), e.count = std::uint16_t(slot);
        return r;
    }
    std::vector<Place> v;
    for (std::size_t i = 1; i < args.size(); ++i) v.push_back(eval(args[i]));
    if (dims == ir::kCubeSampler) return eval_cube(op, node, slot, args, v);
    const Place zero{{B::Float, float_constant(0.0f)}};
    switch (op) {
        case glslang::EOpTextureFetch: case glslang::EOpTextureFetchOffset: return eval_texel_fetch(op, slot, dims, v);
        case glslang::EOpTextureQuerySize: return eval_texture_size(slot, dims, v);
        case glslang::EOpTextureGather: case glslang::EOpTextureGatherOffset: case glslang::EOpTextureGatherOffsets:
            return eval_gather(op, node, slot, args, v);
        case glslang::EOpTextureQueryLod: return eval_query_lod(node, slot, dims, v);
        default: return eval_filtered(op, node, slot, dims, v, zero);
    }
}

// A gather at p on a 2D texture (level 0's four texels of a bilinear lookup): channel `comp`, or,
// channel 4, each texel compared with the reference value `ref`; at a texel offset where given.
Place StageLowering::emit_gather(int slot, const Place& p, const Place* ref, const Place* offset, int comp) {
    const std::uint32_t a = consecutive(Place(p.begin(), p.begin() + 2));
    std::uint32_t c = 0;
    if (offset) {
        const Place o = convert_bits(*offset, B::Int);
        c = consecutive(Place(o.begin(), o.begin() + 2));
    }
    Place r = temps(B::Float, 4);
    ir::Instr& e = emit(offset ? ir::Op::TextureGatherOffset : ir::Op::TextureGather);
    e.d = r[0].reg, e.a = a, e.b = ref ? (*ref)[0].reg : 0, e.c = c, e.n = 2, e.m = std::uint8_t(comp);
    e.count = std::uint16_t(slot);
    return r;
}

// textureGather, textureGatherOffset and textureGatherOffsets on a sampler2D (a channel, a
// constant expression, last) or a sampler2DShadow (a reference value after P, each texel
// compared with it). textureGatherOffsets is four gathers, each at its offset (a constant array
// of four ivec2, as GLSL requires), component i the i0 j0 texel of the i-th: their w, as Mesa
// lowers it (nir_lower_tex).
Place StageLowering::eval_gather(glslang::TOperator op, TIntermTyped* node, int slot,
                                 const std::vector<TIntermTyped*>& args, const std::vector<Place>& v) {
    const ir::Sampler& sampler = interface_.program.samplers[std::size_t(slot)];
    if (sampler.dims != 2) refuse(node, "a gather on this sampler");
    const std::size_t after = sampler.shadow ? 2 : 1;  // v's index of the offset or offsets
    const Place* ref = sampler.shadow ? &v[1] : nullptr;
    int comp = sampler.shadow ? 4 : 0;
    const std::size_t comp_arg = op == glslang::EOpTextureGather ? 2 : 3;
    if (!sampler.shadow && args.size() > comp_arg) {
        const glslang::TIntermConstantUnion* k = args[comp_arg]->getAsConstantUnion();
        if (!k) refuse(node, "a gather's channel must be a constant expression");
        comp = k->getConstArray()[0].getIConst();
        if (comp < 0 || comp > 3) refuse(node, "a gather of this channel");
    }
    if (op == glslang::EOpTextureGather) return emit_gather(slot, v[0], ref, nullptr, comp);
    if (op == glslang::EOpTextureGatherOffset) return emit_gather(slot, v[0], ref, &v[after], comp);
    const glslang::TIntermConstantUnion* k = args[after + 1]->getAsConstantUnion();
    if (!k) refuse(node, "textureGatherOffsets' offsets must be a constant expression");
    const glslang::TConstUnionArray& o = k->getConstArray();
    Place r = temps(B::Float, 4);
    for (int i = 0; i < 4; ++i) {
        const Place offset{{B::Int, int_constant(o[2 * i].getIConst())},
                           {B::Int, int_constant(o[2 * i + 1].getIConst())}};
        move(r[std::size_t(i)], emit_gather(slot, v[0], ref, &offset, comp)[3], false);
    }
    return r;
}

// A lookup in a samplerCube (P a direction) or a samplerCubeShadow (P.xyz a direction, P.w the
// reference value, compared as a sampler2DShadow's lookups compare). GLSL gives a cube no
// projective, offset or fetch lookups.
Place StageLowering::eval_cube(glslang::TOperator op, TIntermTyped* node, int slot, const std::vector<TIntermTyped*>& args,
                               const std::vector<Place>& v) {
    const bool shadow = interface_.program.samplers[std::size_t(slot)].shadow;
    if (op == glslang::EOpTextureGather) {
        // The channel is a constant expression (glslang checks it is one, 0 to 3); a shadow
        // gather's third argument is the reference value instead, marked by channel 4.
        int comp = 0;
        std::uint32_t b = 0;
        if (shadow) {
            comp = 4, b = v[1][0].reg;
        } else if (args.size() > 2) {
            const glslang::TIntermConstantUnion* k = args[2]->getAsConstantUnion();
            if (!k) refuse(node, "textureGather's channel must be a constant expression");
            comp = k->getConstArray()[0].getIConst();
        }
        if (comp < 0 || comp > 4) refuse(node, "textureGather of this channel");
        const std::uint32_t a = consecutive(Place(v[0].begin(), v[0].begin() + 3));
        Place r = temps(B::Float, 4);
        ir::Instr& e = emit(ir::Op::TextureGather);
        e.d = r[0].reg, e.a = a, e.b = b, e.n = 3, e.m = std::uint8_t(comp), e.count = std::uint16_t(slot);
        return r;
    }
    if (op == glslang::EOpTextureQuerySize) {
        Place r = temps(B::Int, 2);
        const Place lod = v.empty() ? Place{{B::Int, int_constant(0)}} : convert_bits(v[0], B::Int);
        ir::Instr& e = emit(ir::Op::TextureSize);
        e.d = r[0].reg, e.b = lod[0].reg, e.n = 2, e.count = std::uint16_t(slot);
        return r;
    }
    // On a samplerCubeShadow as on a samplerCube, as GL defines it (llvmpipe 22.3 differs there:
    // docs/glsl.md).
    if (op == glslang::EOpTextureQueryLod) return eval_query_lod(node, slot, 3, v);
    // A samplerCubeShadow's lookups compare P.w: four coordinates, one result (m = 4).
    const auto lookup = [&](ir::Op o, const Place* extra, const Place* ddx = nullptr, const Place* ddy = nullptr) {
        const std::uint32_t a = consecutive(Place(v[0].begin(), v[0].begin() + (shadow ? 4 : 3)));
        std::uint32_t b = 0;
        if (extra) b = (*extra)[0].reg;
        if (ddx) {
            Place both(ddx->begin(), ddx->begin() + 3);
            both.insert(both.end(), ddy->begin(), ddy->begin() + 3);
            b = consecutive(both);
        }
        Place r = temps(B::Float, shadow ? 1 : 4);
        ir::Instr& e = emit(o);
        e.d = r[0].reg, e.a = a, e.b = b, e.n = 3, e.m = shadow ? 4 : 1, e.count = std::uint16_t(slot);
        return r;
    };
    const Place zero{{B::Float, float_constant(0.0f)}};
    switch (op) {
        case glslang::EOpTexture:
            // A vertex shader's implicit lookups read level 0 (it has no neighbours to take a level from).
            if (kind_ == StageKind::Vertex) return lookup(ir::Op::TextureLod, &zero);
            return v.size() == 2 ? lookup(ir::Op::TextureBias, &v[1]) : lookup(ir::Op::Texture, nullptr);
        case glslang::EOpTextureLod:
            if (shadow) break;
            return lookup(ir::Op::TextureLod, &v[1]);
        case glslang::EOpTextureGrad: return lookup(ir::Op::TextureGrad, nullptr, &v[1], &v[2]);
        default: break;
    }
    if (shadow) {
        refuse(node, "this texture function on a samplerCubeShadow is not supported (texture with or without a bias, "
                     "textureGrad, textureGather and textureSize are)");
    }
    refuse(node, "this texture function on a samplerCube is not supported (texture and textureCube with or without a "
                 "bias, textureLod, textureCubeLod, textureGrad, textureGather, textureSize and textureQueryLod are)");
}

}  // namespace qs::frontend
