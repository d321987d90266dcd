#include "frontend/glsl_types.h"

#include "frontend/glsl_error.h"

namespace qs::frontend {

bool bank_of(glslang::TBasicType t, ir::Bank& bank) {
    switch (t) {
        case glslang::EbtFloat: bank = ir::Bank::Float; return true;
        case glslang::EbtInt: bank = ir::Bank::Int; return true;
        case glslang::EbtUint: bank = ir::Bank::Uint; return true;
        case glslang::EbtBool: bank = ir::Bank::Bool; return true;
        default: return false;
    }
}

void component_banks(const glslang::TType& t, std::vector<ir::Bank>& out) {
    if (t.isArray()) {
        const glslang::TType e = element_type(t);
        const int n = t.getOuterArraySize();
        if (n <= 0) throw GlslUnsupported("an array of unknown size ('" + type_name(t) + "')");
        for (int i = 0; i < n; ++i) component_banks(e, out);
        return;
    }
    if (t.isStruct()) {
        for (const glslang::TTypeLoc& m : *t.getStruct()) component_banks(*m.type, out);
        return;
    }
    ir::Bank b;
    if (!bank_of(t.getBasicType(), b)) throw GlslUnsupported("type '" + type_name(t) + "' is not supported");
    const int n = t.isMatrix() ? t.getMatrixCols() * t.getMatrixRows() : t.getVectorSize();
    out.insert(out.end(), std::size_t(n), b);
}

std::vector<ir::Bank> component_banks(const glslang::TType& t) {
    std::vector<ir::Bank> v;
    component_banks(t, v);
    return v;
}

int component_count(const glslang::TType& t) {
    if (t.isArray()) return t.getOuterArraySize() * component_count(element_type(t));
    if (t.isStruct()) {
        int n = 0;
        for (const glslang::TTypeLoc& m : *t.getStruct()) n += component_count(*m.type);
        return n;
    }
    return t.isMatrix() ? t.getMatrixCols() * t.getMatrixRows() : t.getVectorSize();
}

glslang::TType element_type(const glslang::TType& t) { return glslang::TType(t, 0); }

glslang::TType member_type(const glslang::TType& t, int member) { return glslang::TType(t, member); }

int member_offset(const glslang::TType& t, int member) {
    int offset = 0;
    const glslang::TTypeList& members = *t.getStruct();
    for (int i = 0; i < member; ++i) offset += component_count(*members[std::size_t(i)].type);
    return offset;
}

std::string type_name(const glslang::TType& t) {
    std::string s;
    if (t.isStruct()) {
        s = "struct " + std::string(t.getTypeName().c_str());
    } else {
        s = t.getBasicTypeString().c_str();
        if (t.isMatrix()) {
            const std::string prefix = t.getBasicType() == glslang::EbtDouble ? "dmat" : "mat";
            s = prefix + std::to_string(t.getMatrixCols());
            if (t.getMatrixCols() != t.getMatrixRows()) s += "x" + std::to_string(t.getMatrixRows());
        } else if (t.isVector()) {
            std::string prefix = "vec";
            switch (t.getBasicType()) {
                case glslang::EbtInt: prefix = "ivec"; break;
                case glslang::EbtUint: prefix = "uvec"; break;
                case glslang::EbtBool: prefix = "bvec"; break;
                case glslang::EbtDouble: prefix = "dvec"; break;
                default: break;
            }
            s = prefix + std::to_string(t.getVectorSize());
        }
    }
    if (t.isArray()) {
        s += '[';
        s += std::to_string(t.getOuterArraySize());
        s += ']';
    }
    return s;
}

}  // namespace qs::frontend
