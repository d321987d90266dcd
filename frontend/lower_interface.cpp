// The stage's interface (lowering.h): uniforms, samplers, vertex attributes, varyings, the
// built-in inputs and outputs, and the names by which quadshade binds a user's own attributes
// and matrices (frontend/binding_names.h).

#include <algorithm>
#include <array>
#include <bit>
#include <map>

#include "frontend/binding_names.h"
#include "frontend/glsl_types.h"
#include "frontend/lowering.h"

namespace qs::frontend {

using glslang::TIntermSymbol;
using B = ir::Bank;

std::string StageLowering::where(const TIntermNode* node) const { return position(node->getLoc()); }

Place StageLowering::bound_input(ir::Source source, std::uint16_t slot, const std::vector<B>& banks, std::uint16_t first) {
    Place p;
    for (std::size_t i = 0; i < banks.size(); ++i) {
        const std::uint32_t r = allocate(banks[i], Space::Constant);
        stage_.inputs.push_back({source, slot, std::uint16_t(first + i), banks[i], r});
        p.push_back({banks[i], r});
    }
    return p;
}

Place StageLowering::bound_output(ir::Source source, const std::vector<B>& banks, std::uint16_t first) {
    Place p;
    for (std::size_t i = 0; i < banks.size(); ++i) {
        const std::uint32_t r = allocate(banks[i], Space::Variable);
        stage_.outputs.push_back({source, 0, std::uint16_t(first + i), banks[i], r});
        move({banks[i], r}, {banks[i], constant(banks[i], 0)}, false);
        p.push_back({banks[i], r});
    }
    return p;
}

Place StageLowering::transform_uniform(ir::TransformUniform which, int size, bool transposed) {
    const std::string key = "transform " + std::to_string(int(which)) + (transposed ? "T" : "");
    if (auto it = fixed_inputs_.find(key); it != fixed_inputs_.end()) return it->second;
    // Components of the 4x4 (or, for the normal matrix, 3x3) matrix column by column; a
    // transposed matrix reads row by row.
    Place p;
    for (int c = 0; c < size; ++c) {
        for (int r = 0; r < size; ++r) {
            const int index = transposed ? r * size + c : c * size + r;
            const std::uint32_t reg = allocate(B::Float, Space::Constant);
            stage_.inputs.push_back({ir::Source::Transform, std::uint16_t(which), std::uint16_t(index), B::Float, reg});
            p.push_back({B::Float, reg});
        }
    }
    fixed_inputs_.emplace(key, p);
    return p;
}

Place StageLowering::attribute(ir::Attribute which, int components) {
    const std::string key = "attribute " + std::to_string(int(which)) + " " + std::to_string(components);
    if (auto it = fixed_inputs_.find(key); it != fixed_inputs_.end()) return it->second;
    bool listed = false;
    for (ir::Attribute a : interface_.program.attributes) listed = listed || a == which;
    if (!listed) interface_.program.attributes.push_back(which);
    Place p = bound_input(ir::Source::Attribute, std::uint16_t(which), std::vector<B>(std::size_t(components), B::Float));
    fixed_inputs_.emplace(key, p);
    return p;
}

Place StageLowering::generic_attribute(TIntermSymbol* node) {
    const glslang::TType& type = node->getType();
    const std::string name = node->getName().c_str();
    const auto found = attribute_locations_.find(node->getId());
    if (found == attribute_locations_.end()) refuse(node, "attribute '" + name + "' has no location");
    if (type.isStruct() || type.getBasicType() == glslang::EbtBool) refuse(node, "attribute '" + name + "' of this type is not supported");
    B bank;
    if (!bank_of(type.getBasicType(), bank)) refuse(node, "attribute '" + name + "' of type '" + type_name(type) + "' is not supported");
    const int elements = type.isArray() ? type.getOuterArraySize() : 1;
    const int columns = type.isMatrix() ? type.getMatrixCols() : 1;
    const int components = type.isMatrix() ? type.getMatrixRows() : type.getVectorSize();
    ir::GenericAttribute g{name, found->second, elements * columns, components, bank};
    interface_.program.generic_attributes.push_back(g);
    Place p;
    for (int s = 0; s < g.slots; ++s) {
        const Place slot = bound_input(ir::Source::GenericAttribute, std::uint16_t(g.location + s),
                                       std::vector<B>(std::size_t(components), bank));
        p.insert(p.end(), slot.begin(), slot.end());
    }
    return p;
}

// Locations for the vertex inputs bound to generic attributes: those the options bind by name,
// then those with a layout(location), then the rest at the lowest free ones, as GL's linker.
void StageLowering::assign_attribute_locations(const std::vector<TIntermSymbol*>& symbols) {
    const std::map<std::string, int>& bound = *interface_.options.attribute_locations;
    constexpr int kLocations = 16;  // GL_MAX_VERTEX_ATTRIBS
    std::array<bool, kLocations> used{};
    std::vector<std::pair<TIntermSymbol*, int>> inputs;  // and their slots
    for (TIntermSymbol* s : symbols) {
        const glslang::TQualifier& q = s->getQualifier();
        if (q.storage != glslang::EvqVaryingIn || q.builtIn != glslang::EbvNone) continue;
        const glslang::TType& t = s->getType();
        const int slots = (t.isArray() ? std::max(t.getOuterArraySize(), 1) : 1) * (t.isMatrix() ? t.getMatrixCols() : 1);
        inputs.emplace_back(s, slots);
    }
    const auto take = [&](TIntermSymbol* s, int location, int slots) {
        if (location < 0 || location + slots > kLocations) {
            refuse(s, "attribute '" + std::string(s->getName().c_str()) + "' needs locations beyond the " +
                          std::to_string(kLocations) + " generic attributes");
        }
        for (int i = 0; i < slots; ++i) used[std::size_t(location + i)] = true;
        attribute_locations_[s->getId()] = location;
    };
    for (int pass = 0; pass < 3; ++pass) {
        for (const auto& [s, slots] : inputs) {
            if (attribute_locations_.count(s->getId())) continue;
            const auto named = bound.find(s->getName().c_str());
            if (pass == 0 && named != bound.end()) {
                take(s, named->second, slots);
            } else if (pass == 1 && s->getQualifier().hasLocation()) {
                take(s, int(s->getQualifier().layoutLocation), slots);
            } else if (pass == 2) {
                int at = 0;
                while (at + slots <= kLocations) {
                    bool free = true;
                    for (int i = 0; i < slots; ++i) free = free && !used[std::size_t(at + i)];
                    if (free) break;
                    ++at;
                }
                take(s, at, slots);
            }
        }
    }
}

Place StageLowering::front_facing() {
    interface_.program.reads_front_facing = true;
    if (auto it = fixed_inputs_.find("gl_FrontFacing"); it != fixed_inputs_.end()) return it->second;
    Place p = bound_input(ir::Source::FrontFacing, 0, {B::Bool});
    fixed_inputs_.emplace("gl_FrontFacing", p);
    return p;
}

// Whether the shader redeclares the built-in variable `name` (`flat in vec4 gl_Color;`): glslang
// lists a redeclared built-in among the linker objects, and one only used, not.
bool StageLowering::redeclared(const std::string& name) const {
    glslang::TIntermAggregate* root = ast_.getTreeRoot() ? ast_.getTreeRoot()->getAsAggregate() : nullptr;
    if (!root) return false;
    for (TIntermNode* n : root->getSequence()) {
        auto* a = n->getAsAggregate();
        if (!a || a->getOp() != glslang::EOpLinkerObjects) continue;
        for (TIntermNode* o : a->getSequence()) {
            if (auto* s = o->getAsSymbolNode(); s && name == s->getName().c_str()) return true;
        }
    }
    return false;
}

// A fragment's gl_Color or gl_SecondaryColor: the vertex stage's front colour, interpolated as
// the declaration says or, without a qualifier, as the shade model does; with two-sided colour,
// the back colour on back-facing primitives.
Place StageLowering::color_input(TIntermSymbol* node, const std::string& front, const std::string& back) {
    const glslang::TQualifier& q = node->getQualifier();
    // glslang marks every fragment input without an interpolation qualifier smooth, the built-in
    // declaration of gl_Color included: only a redeclaration's smooth is the shader's. (One
    // without a qualifier reads as smooth too; glslang keeps nothing that tells them apart.)
    const bool smooth = q.smooth && redeclared(node->getName().c_str());
    const bool flat = q.flat || (!smooth && !q.nopersp && interface_.options.flat_colors);
    const std::vector<B> banks(4, B::Float);
    VaryingSlot& f = interface_.fragment_varying(front, 4, B::Float, flat, where(node), q.nopersp);
    const Place front_value = bound_input(ir::Source::Varying, 0, banks, std::uint16_t(f.first));
    if (!interface_.options.two_sided_color) return front_value;
    VaryingSlot& b = interface_.fragment_varying(back, 4, B::Float, flat, where(node), q.nopersp);
    const Place back_value = bound_input(ir::Source::Varying, 0, banks, std::uint16_t(b.first));
    const Place facing = front_facing();
    Place p;
    for (std::size_t i = 0; i < 4; ++i) {
        const Slot r{B::Float, allocate(B::Float, Space::Variable)};
        ir::Instr& in = emit(ir::Op::Select, B::Float);
        in.d = r.reg, in.a = facing[0].reg, in.b = front_value[i].reg, in.c = back_value[i].reg;
        p.push_back(r);
    }
    return p;
}

// The colours the fragment stage reads and the vertex stage does not write. GL leaves them
// undefined but links; quadshade gives what llvmpipe gives: a back colour not written is the
// front one (so one-sided shaders draw the same with two-sided colour on), a front colour not
// written is zero.
void StageLowering::supply_unwritten_colors() {
    for (const auto& [front, back] : {std::pair{"gl_Color", "gl_BackColor"}, {"gl_SecondaryColor", "gl_BackSecondaryColor"}}) {
        VaryingSlot* f = interface_.find_varying(front);
        if (!f) continue;
        std::array<std::uint32_t, 4> value;
        value.fill(float_constant(0.0f));
        if (f->written) {
            for (const ir::Binding& o : stage_.outputs) {
                const int k = int(o.index) - f->first;
                if (o.source == ir::Source::Varying && k >= 0 && k < 4) value[std::size_t(k)] = o.reg;
            }
        }
        for (VaryingSlot* v : {f, interface_.find_varying(back)}) {
            if (!v || v->written) continue;
            for (std::uint16_t k = 0; k < 4; ++k) {
                stage_.outputs.push_back({ir::Source::Varying, 0, std::uint16_t(v->first + k), B::Float, value[k]});
            }
            v->written = true;
        }
    }
}

Place StageLowering::ftransform() {
    if (kind_ != StageKind::Vertex) throw GlslError(source_position(file_, int(line_)) + "ftransform() exists in vertex shaders only");
    const Place mvp = transform_uniform(ir::TransformUniform::ModelViewProjection, 4, false);
    const Place vertex = attribute(ir::Attribute::Position, 4);
    return matrix_product(glslang::EOpMatrixTimesVector, {4, 4}, {1, 4}, mvp, vertex);
}

int StageLowering::sampler_uniform(TIntermSymbol* node, const std::string& name, const glslang::TType& type) {
    const glslang::TSampler& s = type.getSampler();
    if (s.isShadow() && s.dim != glslang::Esd2D && s.dim != glslang::EsdCube) {
        refuse(node, "sampler type '" + std::string(type.getSampler().getString().c_str()) +
                         "' is not supported (of the shadow samplers, sampler2DShadow and samplerCubeShadow are)");
    }
    if (s.isArrayed() || s.isMultiSample() || s.isBuffer() || s.isRect() || s.isImage() || s.isSubpass() ||
        s.isExternal() || s.isYuv() || s.type != glslang::EbtFloat) {
        refuse(node, "sampler type '" + std::string(type.getSampler().getString().c_str()) +
                         "' is not supported (sampler2D, sampler3D and samplerCube are)");
    }
    int dims = 0;
    switch (s.dim) {
        case glslang::Esd2D: dims = 2; break;
        case glslang::Esd3D: dims = 3; break;
        case glslang::EsdCube: dims = ir::kCubeSampler; break;
        default:
            refuse(node, "sampler type '" + std::string(type.getSampler().getString().c_str()) +
                             "' is not supported (sampler2D, sampler3D and samplerCube are)");
    }
    const int slot = interface_.sampler(name, dims, s.isShadow(), where(node));
    if (!type.isArray() && name == node->getName().c_str()) global_samplers_.emplace(node->getId(), slot);
    return slot;
}

namespace {

// The leaves of a uniform: each scalar, vector or matrix inside it, with GL's name for it.
struct UniformLeaf {
    std::string name;
    glslang::TBasicType basic;
    int components;
    int columns;  // 1 unless a matrix
    std::string type;
    int first;  // its first component among the uniform's
};

void uniform_leaves(const std::string& name, const glslang::TType& t, int first, std::vector<UniformLeaf>& out) {
    if (t.isArray()) {
        const glslang::TType e = element_type(t);
        const int size = component_count(e);
        for (int i = 0; i < t.getOuterArraySize(); ++i) uniform_leaves(name + "[" + std::to_string(i) + "]", e, first + i * size, out);
        return;
    }
    if (t.isStruct()) {
        const glslang::TTypeList& members = *t.getStruct();
        for (std::size_t i = 0; i < members.size(); ++i) {
            uniform_leaves(name + "." + members[i].type->getFieldName().c_str(), *members[i].type, first + member_offset(t, int(i)), out);
        }
        return;
    }
    out.push_back({name, t.getBasicType(), component_count(t), t.isMatrix() ? t.getMatrixCols() : 1, type_name(t), first});
}

}  // namespace

Place StageLowering::uniform_variable(TIntermSymbol* node) {
    const std::string name = node->getName().c_str();
    const glslang::TType& type = node->getType();
    if (name.rfind("gl_", 0) == 0) {
        struct BuiltIn {
            const char* name;
            ir::TransformUniform which;
            int size;
            bool transposed;
        };
        static constexpr BuiltIn kBuiltIns[] = {
            {"gl_ModelViewProjectionMatrix", ir::TransformUniform::ModelViewProjection, 4, false},
            {"gl_ModelViewMatrix", ir::TransformUniform::ModelView, 4, false},
            {"gl_ProjectionMatrix", ir::TransformUniform::Projection, 4, false},
            {"gl_NormalMatrix", ir::TransformUniform::Normal, 3, false},
            {"gl_ModelViewProjectionMatrixTranspose", ir::TransformUniform::ModelViewProjection, 4, true},
            {"gl_ModelViewMatrixTranspose", ir::TransformUniform::ModelView, 4, true},
            {"gl_ProjectionMatrixTranspose", ir::TransformUniform::Projection, 4, true},
        };
        for (const BuiltIn& b : kBuiltIns) {
            if (name == b.name) return transform_uniform(b.which, b.size, b.transposed);
        }
        refuse(node, "built-in uniform '" + name + "' is not supported");
    }
    if (name == "time" && type.getBasicType() == glslang::EbtFloat && type.isScalar() && !type.isArray()) {
        interface_.program.reads_time = true;
        if (auto it = fixed_inputs_.find("time"); it != fixed_inputs_.end()) return it->second;
        Place p = bound_input(ir::Source::Time, 0, {B::Float});
        fixed_inputs_.emplace("time", p);
        return p;
    }
    if (name == "dims" && type.getBasicType() == glslang::EbtFloat && type.getVectorSize() == 2 && !type.isArray() &&
        !type.isMatrix()) {
        // The texture's size, as the chapter's demo binds it beside teximage.
        if (auto it = fixed_inputs_.find("dims"); it != fixed_inputs_.end()) return it->second;
        Place p = bound_input(ir::Source::TeximageSize, 0, {B::Float, B::Float});
        fixed_inputs_.emplace("dims", p);
        return p;
    }
    if (const std::optional<ir::TransformUniform> t = transform_named(name)) {
        const int size = *t == ir::TransformUniform::SceneNormal ? 3 : 4;
        if (!type.isMatrix() || type.getMatrixCols() != size || type.getMatrixRows() != size || type.isArray()) {
            refuse(node, "uniform '" + name + "' is bound to the scene's " + transform_description(*t) + ": declare it mat" +
                             std::to_string(size));
        }
        return transform_uniform(*t, size, false);
    }
    std::vector<UniformLeaf> leaves;
    uniform_leaves(name, type, 0, leaves);
    Place whole(std::size_t(component_count(type)));
    const glslang::TConstUnionArray& initial = node->getConstArray();
    for (const UniformLeaf& leaf : leaves) {
        ir::Uniform u;
        u.name = leaf.name;
        B bank;
        if (!bank_of(leaf.basic, bank)) refuse(node, "uniform '" + leaf.name + "' of type '" + leaf.type + "' is not supported");
        u.bank = bank;
        u.components = leaf.components;
        u.columns = leaf.columns;
        for (int i = 0; i < u.components && leaf.first + i < initial.size(); ++i) {
            const glslang::TConstUnion& c = initial[leaf.first + i];
            switch (bank) {
                case B::Float: u.initial[std::size_t(i)] = std::bit_cast<std::uint32_t>(float(c.getDConst())); break;
                case B::Int: u.initial[std::size_t(i)] = std::bit_cast<std::uint32_t>(c.getIConst()); break;
                case B::Uint: u.initial[std::size_t(i)] = c.getUConst(); break;
                case B::Bool: u.initial[std::size_t(i)] = c.getBConst() ? 1u : 0u; break;
            }
        }
        const int slot = interface_.uniform(u, where(node), initial.size() > 0);
        if (slot > 0xFFFF) refuse(node, "more than 65536 uniform values");
        const Place p = bound_input(ir::Source::UserUniform, std::uint16_t(slot), std::vector<B>(std::size_t(u.components), bank));
        for (std::size_t i = 0; i < p.size(); ++i) whole[std::size_t(leaf.first) + i] = p[i];
    }
    return whole;
}

Place StageLowering::input_variable(TIntermSymbol* node, const glslang::TType& type, const std::string& name) {
    const glslang::TQualifier& q = type.getQualifier();
    if (type.getBasicType() == glslang::EbtBlock) return block_variable(node, type, false);
    if (kind_ == StageKind::Vertex) {
        switch (q.builtIn) {
            case glslang::EbvVertex: return attribute(ir::Attribute::Position, 4);
            case glslang::EbvNormal: return attribute(ir::Attribute::Normal, 3);
            case glslang::EbvColor: return attribute(ir::Attribute::Color, 4);
            case glslang::EbvMultiTexCoord0: return attribute(ir::Attribute::Texcoord0, 4);
            case glslang::EbvMultiTexCoord1: return attribute(ir::Attribute::Texcoord1, 4);
            case glslang::EbvNone: break;
            default: refuse(node, "vertex input '" + name + "' is not supported");
        }
        if (interface_.options.attribute_locations) return generic_attribute(node);
        const std::optional<ir::Attribute> a = attribute_named(name);
        if (!a) refuse(node, "attribute '" + name + "' is none quadshade provides: " + attribute_names_help());
        if (type.isArray() || type.isMatrix() || type.getBasicType() != glslang::EbtFloat) {
            refuse(node, "attribute '" + name + "' must be a float or a float vector");
        }
        return attribute(*a, type.getVectorSize());
    }
    // A fragment input: a varying, by name.
    std::string varying = name;
    switch (q.builtIn) {
        case glslang::EbvColor: return color_input(node, "gl_Color", "gl_BackColor");
        case glslang::EbvSecondaryColor: return color_input(node, "gl_SecondaryColor", "gl_BackSecondaryColor");
        case glslang::EbvFogFragCoord: varying = "gl_FogFragCoord"; break;
        case glslang::EbvTexCoord: {
            // gl_TexCoord[i]: each element its own varying, as the vertex stage writes them.
            Place whole;
            for (int i = 0; i < type.getOuterArraySize(); ++i) {
                VaryingSlot& v = interface_.fragment_varying("gl_TexCoord[" + std::to_string(i) + "]", 4, B::Float, false, where(node));
                const Place p = bound_input(ir::Source::Varying, 0, {B::Float, B::Float, B::Float, B::Float}, std::uint16_t(v.first));
                whole.insert(whole.end(), p.begin(), p.end());
            }
            return whole;
        }
        case glslang::EbvNone: break;
        default: refuse(node, "fragment input '" + name + "' is not supported");
    }
    std::vector<B> banks;
    try {
        component_banks(type, banks);
    } catch (const GlslError& e) {
        refuse(node, e.what());
    }
    const bool flat = q.flat || banks[0] != B::Float;
    VaryingSlot& v = interface_.fragment_varying(varying, int(banks.size()), banks[0], flat, where(node), q.nopersp && !flat);
    if (v.components != int(banks.size())) refuse(node, "varying '" + varying + "' is declared twice with different types");
    return bound_input(ir::Source::Varying, 0, banks, std::uint16_t(v.first));
}

Place StageLowering::output_variable(TIntermSymbol* node, const glslang::TType& type, const std::string& name) {
    const glslang::TQualifier& q = type.getQualifier();
    if (type.getBasicType() == glslang::EbtBlock) return block_variable(node, type, true);
    std::vector<B> banks;
    const auto plain = [&] {
        // An implicitly sized built-in array no code indexes (gl_ClipDistance[]) takes no registers.
        if (type.isUnsizedArray() || (type.isArray() && type.getOuterArraySize() <= 0)) return Place{};
        return allocate(type, Space::Variable);
    };
    if (kind_ == StageKind::Fragment) {
        if (q.storage == glslang::EvqFragColor || q.builtIn == glslang::EbvFragData) {
            // gl_FragColor, and gl_FragData[0]: the one colour buffer quadshade draws into
            Place p = bound_output(ir::Source::Color, {B::Float, B::Float, B::Float, B::Float});
            if (q.builtIn == glslang::EbvFragData) {
                Place rest = allocate(type, Space::Variable);
                for (std::size_t i = 0; i < 4; ++i) rest[i] = p[i];
                return rest;
            }
            return p;
        }
        if (q.storage == glslang::EvqFragDepth) refuse(node, "gl_FragDepth is not supported: quadshade's depth is the interpolated one");
        if (q.storage != glslang::EvqVaryingOut || q.builtIn != glslang::EbvNone) refuse(node, "fragment output '" + name + "' is not supported");
        if (type.isArray() || type.isStruct() || type.isMatrix() || type.getBasicType() != glslang::EbtFloat) {
            refuse(node, "fragment output '" + name + "' must be a float or a float vector (quadshade draws into one RGBA colour buffer)");
        }
        if (q.hasLocation() && q.layoutLocation != 0) return plain();  // another buffer: not drawn
        // Missing components read as GL fills them: (x, 0, 0, 1).
        Place p = bound_output(ir::Source::Color, std::vector<B>(std::size_t(type.getVectorSize()), B::Float));
        for (int i = type.getVectorSize(); i < 4; ++i) {
            const std::uint32_t r = allocate(B::Float, Space::Variable);
            stage_.outputs.push_back({ir::Source::Color, 0, std::uint16_t(i), B::Float, r});
            move({B::Float, r}, {B::Float, float_constant(i == 3 ? 1.0f : 0.0f)}, false);
        }
        return p;
    }
    if (q.storage == glslang::EvqPosition || q.builtIn == glslang::EbvPosition) {
        return bound_output(ir::Source::Position, {B::Float, B::Float, B::Float, B::Float});
    }
    if (q.storage == glslang::EvqClipVertex || q.builtIn == glslang::EbvClipVertex) {
        return bound_output(ir::Source::ClipVertex, {B::Float, B::Float, B::Float, B::Float});
    }
    if (q.builtIn == glslang::EbvClipDistance) {
        // An array GLSL may leave unsized: it holds every distance the renderer clips with.
        const int n = type.isArray() && type.getOuterArraySize() > 0 ? type.getOuterArraySize() : ir::kMaxClipDistances;
        if (n > ir::kMaxClipDistances) refuse(node, "more than " + std::to_string(ir::kMaxClipDistances) + " clip distances");
        return bound_output(ir::Source::ClipDistance, std::vector<B>(std::size_t(n), B::Float));
    }
    if (q.storage == glslang::EvqPointSize || q.builtIn == glslang::EbvPointSize || q.builtIn == glslang::EbvCullDistance) {
        return plain();  // nothing quadshade draws reads it
    }
    std::string varying = name;
    switch (q.builtIn) {
        case glslang::EbvFrontColor: varying = "gl_Color"; break;
        case glslang::EbvFrontSecondaryColor: varying = "gl_SecondaryColor"; break;
        case glslang::EbvBackColor: varying = "gl_BackColor"; break;  // read with two-sided colour only
        case glslang::EbvBackSecondaryColor: varying = "gl_BackSecondaryColor"; break;
        case glslang::EbvFogFragCoord: varying = "gl_FogFragCoord"; break;
        case glslang::EbvTexCoord: {
            Place whole = plain();
            for (int i = 0; i < type.getOuterArraySize(); ++i) {
                VaryingSlot* v = interface_.find_varying("gl_TexCoord[" + std::to_string(i) + "]");
                if (!v) continue;
                v->written = true;
                const Place p = bound_output(ir::Source::Varying, {B::Float, B::Float, B::Float, B::Float}, std::uint16_t(v->first));
                for (std::size_t k = 0; k < 4; ++k) whole[std::size_t(i) * 4 + k] = p[k];
            }
            return whole;
        }
        case glslang::EbvNone: break;
        default: refuse(node, "vertex output '" + name + "' is not supported");
    }
    VaryingSlot* v = interface_.find_varying(varying);
    if (!v) return plain();  // no fragment stage reads it
    try {
        component_banks(type, banks);
    } catch (const GlslError& e) {
        refuse(node, e.what());
    }
    if (int(banks.size()) != v->components || banks[0] != v->bank) {
        throw GlslLinkError(where(node) + "varying '" + varying + "' has another type in the fragment shader (" + v->where + ")");
    }
    v->written = true;
    return bound_output(ir::Source::Varying, banks, std::uint16_t(v->first));
}

// An interface block (gl_PerVertex, a user's in or out block): its members one after another,
// each bound as the variable it is.
Place StageLowering::block_variable(TIntermSymbol* node, const glslang::TType& type, bool output) {
    if (type.isArray()) refuse(node, "arrays of interface blocks are not supported");
    Place whole;
    for (const glslang::TTypeLoc& m : *type.getStruct()) {
        const std::string member = m.type->getFieldName().c_str();
        const Place p = output ? output_variable(node, *m.type, member) : input_variable(node, *m.type, member);
        whole.insert(whole.end(), p.begin(), p.end());
    }
    return whole;
}

Place StageLowering::interface_variable(TIntermSymbol* node) {
    const glslang::TStorageQualifier q = node->getQualifier().storage;
    switch (q) {
        case glslang::EvqUniform:
            if (node->getBasicType() == glslang::EbtBlock) refuse(node, "uniform blocks are not supported");
            return uniform_variable(node);
        case glslang::EvqVaryingIn: return input_variable(node, node->getType(), node->getName().c_str());
        case glslang::EvqFragCoord: {
            interface_.program.reads_frag_coord = true;
            if (auto it = fixed_inputs_.find("gl_FragCoord"); it != fixed_inputs_.end()) return it->second;
            Place p = bound_input(ir::Source::FragCoord, 0, {B::Float, B::Float, B::Float, B::Float});
            fixed_inputs_.emplace("gl_FragCoord", p);
            return p;
        }
        case glslang::EvqFace: return front_facing();
        case glslang::EvqPointCoord: refuse(node, "gl_PointCoord is not supported: quadshade draws no points");
        case glslang::EvqVertexId: {
            interface_.program.reads_vertex_id = true;
            return bound_input(ir::Source::VertexId, 0, {B::Int});
        }
        case glslang::EvqInstanceId: return {{B::Int, int_constant(0)}};  // quadshade draws one instance
        case glslang::EvqVaryingOut: case glslang::EvqFragColor: case glslang::EvqFragDepth: case glslang::EvqPosition:
        case glslang::EvqPointSize: case glslang::EvqClipVertex:
            return output_variable(node, node->getType(), node->getName().c_str());
        default: refuse(node, "'" + std::string(node->getName().c_str()) + "' is not supported");
    }
}

// Globals and outputs get their registers before main, so that the registers a call's locals
// take and give back never hold them.
void StageLowering::declare_globals(glslang::TIntermAggregate* root) {
    class Symbols : public glslang::TIntermTraverser {
    public:
        std::vector<TIntermSymbol*> order;
        std::set<long long> seen;
        void visitSymbol(TIntermSymbol* s) override {
            if (seen.insert(s->getId()).second) order.push_back(s);
        }
    };
    Symbols all;
    std::vector<TIntermSymbol*> initialised_uniforms;
    for (TIntermNode* n : root->getSequence()) {
        // Declared is not used: the linker's list of declarations is not code. (A fragment
        // input no code reads needs no vertex stage to write it, as in GL.) Except a uniform
        // with an initializer, which Mesa keeps active unused: the script may set it, and the
        // other stage may read it without one.
        if (auto* a = n->getAsAggregate(); a && a->getOp() == glslang::EOpLinkerObjects) {
            for (TIntermNode* o : a->getSequence()) {
                TIntermSymbol* s = o->getAsSymbolNode();
                if (s && s->getQualifier().storage == glslang::EvqUniform && s->getConstArray().size() > 0 &&
                    s->getBasicType() != glslang::EbtSampler && s->getBasicType() != glslang::EbtBlock) {
                    initialised_uniforms.push_back(s);
                }
            }
            continue;
        }
        n->traverse(&all);
    }
    for (TIntermSymbol* s : initialised_uniforms) all.visitSymbol(s);
    if (kind_ == StageKind::Vertex && interface_.options.attribute_locations) assign_attribute_locations(all.order);
    for (TIntermSymbol* s : all.order) {
        const glslang::TStorageQualifier q = s->getQualifier().storage;
        // A symbol with values is a const variable glslang folded, or a uniform's initializer.
        if (s->getBasicType() == glslang::EbtSampler || (s->getConstArray().size() > 0 && q != glslang::EvqUniform)) continue;
        if (q == glslang::EvqGlobal) {
            Place p = allocate(s->getType(), Space::Variable);
            for (const Slot& r : p) move(r, {r.bank, constant(r.bank, 0)}, false);
            globals_.emplace(s->getId(), std::move(p));
        } else if (q == glslang::EvqVaryingOut || q == glslang::EvqFragColor || q == glslang::EvqFragDepth ||
                   q == glslang::EvqPosition || q == glslang::EvqPointSize || q == glslang::EvqClipVertex ||
                   q == glslang::EvqUniform || q == glslang::EvqVaryingIn || q == glslang::EvqFragCoord ||
                   q == glslang::EvqFace || q == glslang::EvqPointCoord || q == glslang::EvqVertexId ||
                   q == glslang::EvqInstanceId) {
            globals_.emplace(s->getId(), interface_variable(s));
        }
    }
}

}  // namespace qs::frontend
