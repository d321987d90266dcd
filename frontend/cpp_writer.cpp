#include "frontend/cpp_writer.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

#include <glslang/Include/intermediate.h>
#include <glslang/MachineIndependent/localintermediate.h>

#include "frontend/batch_width.h"
#include "frontend/binding_names.h"
#include "frontend/exact_products.h"
#include "frontend/glsl_statements.h"
#include "frontend/iteration_slices.h"
#include "frontend/loop_bound.h"
#include "frontend/parse_stage.h"
#include "frontend/shadow_lookup.h"
#include "frontend/variable_writes.h"

namespace qs::frontend {

using glslang::TIntermAggregate;
using glslang::TIntermBinary;
using glslang::TIntermConstantUnion;
using glslang::TIntermSymbol;
using glslang::TIntermTyped;
using glslang::TIntermUnary;
using glslang::TOperator;
using glslang::TType;

std::string comment_text(const std::string& text) {
    std::string s;
    for (char c : text) s += (c >= 0x20 && c < 0x7F && c != '\\' && c != '"') ? c : '?';
    return s;
}

namespace {

enum class Stage { Vertex, Fragment };

bool is_identifier(const std::string& s) {
    if (s.empty() || s.size() > 256) return false;
    const auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
    if (!alpha(s[0])) return false;
    for (char c : s) {
        if (!alpha(c) && !(c >= '0' && c <= '9')) return false;
    }
    return true;
}

// Names C++ or the translation gives a meaning a GLSL name must not take: C++'s keywords and
// alternative tokens, macros of the C library and GCC, the vocabulary's own names that GLSL does
// not have, and the names the translation declares itself.
const std::set<std::string>& reserved_names() {
    static const std::set<std::string> names = {
        // C++ keywords that are not GLSL's
        "alignas", "alignof", "and", "and_eq", "asm", "auto", "bitand", "bitor", "catch", "char", "char8_t", "char16_t",
        "char32_t", "class", "compl", "concept", "consteval", "constexpr", "constinit", "const_cast", "co_await",
        "co_return", "co_yield", "decltype", "delete", "double", "dynamic_cast", "enum", "explicit", "export", "extern",
        "false", "friend", "goto", "inline", "long", "mutable", "namespace", "new", "noexcept", "not", "not_eq",
        "nullptr", "operator", "or", "or_eq", "private", "protected", "public", "register", "reinterpret_cast",
        "requires", "short", "signed", "sizeof", "static", "static_assert", "static_cast", "template", "this",
        "thread_local", "throw", "true", "try", "typedef", "typeid", "typename", "union", "unsigned", "using", "virtual",
        "volatile", "wchar_t", "xor", "xor_eq", "final", "override", "import", "module", "int", "float", "bool", "void",
        "const", "struct", "return", "if", "else", "for", "while", "do", "switch", "case", "default", "break",
        "continue",
        // macros of the C library and GCC's predefined ones
        "assert", "errno", "NULL", "EOF", "INFINITY", "NAN", "HUGE_VAL", "M_PI", "M_E", "stdin", "stdout", "stderr",
        "major", "minor", "makedev", "unix", "linux", "i386", "offsetof", "setjmp", "va_arg", "isnan", "isinf",
        "signbit", "fpclassify", "isfinite", "isnormal", "BUFSIZ", "FILENAME_MAX", "RAND_MAX", "EXIT_SUCCESS",
        "EXIT_FAILURE", "CHAR_BIT", "INT_MAX", "INT_MIN", "UINT_MAX", "FLT_MAX", "FLT_MIN", "FLT_EPSILON",
        // the vocabulary's and the translation's own names
        "F", "T", "M", "u", "in", "out", "std", "qs", "glsl", "simd", "select", "any", "none", "Loop", "loop", "Return",
        "ret", "inside", "table", "uniform", "vec", "mat", "Bool", "int_t", "uint_t", "Uniforms", "VertexIn",
        "FragmentIn", "FragmentOut", "VertexOutputs", "VertexStage", "Varyings", "fields", "vertex", "fragment",
        "info", "sampler2D", "sampler3D", "samplerCube", "Texture", "shade", "transform_point", "ShaderInfo", "Needs",
        "UniformDecl", "main_", "Lanes", "Pixels", "Quads", "Dual2", "Checked", "kUniforms", "IterationLanes", "lanes_alike"};
    return names;
}

// A GLSL name as C++ names it: checked, and renamed (a trailing underscore, or a prefix for
// names C++ reserves) where C++ or the translation gives it a meaning.
std::string cpp_identifier(const std::string& glsl, const std::string& where) {
    if (!is_identifier(glsl)) throw GlslError(where + "error: '" + comment_text(glsl) + "' is not an identifier the C++ can name");
    if (glsl.find("__") != std::string::npos || (glsl[0] == '_' && glsl.size() > 1 && glsl[1] >= 'A' && glsl[1] <= 'Z')) {
        std::string s = "glsl_";
        for (char c : glsl) {
            if (c == '_' && !s.empty() && s.back() == '_') continue;
            s += c;
        }
        return s + "_";
    }
    if (reserved_names().contains(glsl)) return glsl + "_";
    return glsl;
}

std::string float_literal(double d) {
    const float f = float(d);
    if (std::isnan(f)) return "std::numeric_limits<float>::quiet_NaN()";
    if (std::isinf(f)) return f > 0 ? "std::numeric_limits<float>::infinity()" : "-std::numeric_limits<float>::infinity()";
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, f);
    std::string s(buf, r.ptr);
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    if (s.find('e') != std::string::npos && s.find('.') == std::string::npos) s.insert(s.find('e'), ".0");
    return s + "f";
}

// C++ precedence, higher binds tighter.
enum Prec { kComma = 0, kAssign = 1, kOr = 3, kAnd = 4, kBitOr = 5, kBitXor = 6, kBitAnd = 7, kEquality = 8, kRelational = 9,
            kShift = 10, kAdditive = 11, kMultiplicative = 12, kUnary = 13, kPostfix = 14, kPrimary = 15 };

struct Expr {
    std::string text;
    int prec = kPrimary;
    bool plain = false;  // a C++ scalar (literal, or a loop counter the same for every fragment), not of F
};

std::string parens(const Expr& e, int at_least) { return e.prec >= at_least ? e.text : "(" + e.text + ")"; }

struct Local {
    std::string name;
    int mask_depth = 0;      // the varying conditions open where it is declared
    bool declared = false;
    bool plain_counter = false;
    const TIntermNode* declaring = nullptr;  // the statement that declares it by its first assignment
};

bool is_assignment(TOperator op) { return op >= glslang::EOpAssign && op <= glslang::EOpRightShiftAssign; }

// GLSL 1.50's block of the vertex stage's built-in outputs (gl_Position, gl_PointSize,
// gl_ClipDistance[]), which the translation writes as its gl_Position alone.
bool is_per_vertex_block(const TType& t) {
    return t.getBasicType() == glslang::EbtBlock && std::string(t.getTypeName().c_str()) == "gl_PerVertex";
}

class StageWriter {
public:
    StageWriter(Stage stage, const std::string& file, glslang::TIntermediate& ast, const ir::Program& program)
        : stage_(stage), file_(file), ast_(ast), program_(program) {}

    // The members and functions of the stage's struct (without its braces), at an indent of 4.
    std::string write();
    bool discards() const { return discards_; }
    // The stage's outputs (vertex: its varyings), by GLSL name and C++ name.
    const std::vector<std::pair<std::string, std::string>>& varying_outputs() const { return varying_outputs_; }
    std::string position_output;  // the C++ name of gl_Position's value
    std::string color_output;      // the fragment colour
    // Whether the fragment colour is written before anything could read it (written_first()).
    bool color_written_first() const { return color_written_first_; }

private:
    Stage stage_;
    std::string file_;
    glslang::TIntermediate& ast_;
    const ir::Program& program_;
    bool discards_ = false;
    long long color_symbol_ = -1;
    bool color_written_first_ = false;
    std::vector<std::pair<std::string, std::string>> varying_outputs_;

    std::ostringstream body_;  // the function being written
    int indent_ = 1;
    std::map<long long, Local> locals_;  // the function's locals and parameters, by symbol id
    std::map<long long, std::string> globals_;  // members: interface variables and globals
    std::vector<std::string> member_lines_;
    std::set<std::string> member_names_;
    std::vector<std::string> masks_;  // the conditions open, innermost last: each the whole mask
    struct LoopScope {
        std::string name;
        int mask_depth;
    };
    std::vector<LoopScope> loops_;
    int counter_ = 0;
    int loops_in_function_ = 0;
    bool uses_return_ = false;
    std::string return_type_;

    std::string where(const TIntermNode* n) const { return source_position(file_, n ? n->getLoc().line : 0, n ? n->getLoc().column : 0); }
    [[noreturn]] void refuse(const TIntermNode* n, const std::string& what) const {
        throw GlslError(where(n) + "error: " + what + " (the interpreter runs it; the C++ writer does not write it)");
    }
    void line(const std::string& text, const TIntermNode* at) {
        body_ << std::string(std::size_t(indent_) * 4, ' ') << text;
        if (at) body_ << "  // " << at->getLoc().line;
        body_ << "\n";
    }
    std::string fresh(const std::string& base) { return base + std::to_string(++counter_); }

    // ---- types ---------------------------------------------------------------------------------
    std::string type(const TType& t, const TIntermNode* at) const;
    std::string scalar_type(glslang::TBasicType b, const TIntermNode* at) const;
    std::string sampler_type(const TType& t, const TIntermNode* at) const;

    // ---- names ---------------------------------------------------------------------------------
    std::string symbol_name(TIntermSymbol* s);
    std::string global_member(TIntermSymbol* s);
    void uniform_member(TIntermSymbol* s, const std::string& name);
    void input_member(TIntermSymbol* s, const std::string& name);
    void output_member(TIntermSymbol* s, const std::string& name);
    // A member of gl_PerVertex: gl_Position, the one the translation writes.
    std::string per_vertex_member(TIntermBinary* b) {
        if (TIntermSymbol* block = b->getLeft()->getAsSymbolNode()) symbol_name(block);  // declares gl_Position
        const int i = b->getRight()->getAsConstantUnion()->getConstArray()[0].getIConst();
        const std::string field = (*b->getLeft()->getType().getStruct())[std::size_t(i)].type->getFieldName().c_str();
        if (field != "gl_Position") refuse(b, field + " (a vertex output other than gl_Position or a varying)");
        return "gl_Position";
    }

    // ---- expressions ---------------------------------------------------------------------------
    Expr expr(TIntermTyped* n);
    Expr as_typed(TIntermTyped* n, const TType& t);  // plain values made F's
    Expr constant(TIntermConstantUnion* c);
    Expr constant_value(const glslang::TConstUnionArray& a, int first, const TType& t, const TIntermNode* at);
    Expr binary(TIntermBinary* b);
    Expr unary(TIntermUnary* u);
    Expr aggregate(TIntermAggregate* a);
    Expr call(TIntermAggregate* a);
    Expr builtin(const std::string& name, TIntermTyped* node, const glslang::TIntermSequence& args);
    Expr shadow_lookup(TOperator op, TIntermTyped* node, const std::vector<std::string>& v);
    Expr cube_lookup(TOperator op, TIntermTyped* node, const glslang::TIntermSequence& args,
                     const std::vector<std::string>& v);
    Expr constructor(TIntermAggregate* a);
    Expr conversion(TIntermTyped* from, const TType& to, TIntermTyped* at);
    std::string swizzle(TIntermBinary* b);
    // A constant array read at a run-time index: table members (glsl/table.h), one per contents,
    // a vector's components each a table of its own.
    std::string constant_table(TIntermConstantUnion* c, int component);
    Expr table_read(TIntermConstantUnion* c, TIntermTyped* index);
    std::map<std::string, std::string> tables_;  // contents -> name
    std::string lvalue(TIntermTyped* n);

    // ---- statements ----------------------------------------------------------------------------
    void statement(TIntermNode* n);
    void block(TIntermNode* n);
    void assignment(TIntermBinary* b);
    void assign_to(TIntermTyped* target, const std::string& value, const TIntermNode* at);
    void if_statement(glslang::TIntermSelection* s);
    void loop(glslang::TIntermLoop* l, TIntermNode* init);
    void branch(glslang::TIntermBranch* b);
    bool masked_target(TIntermTyped* target);
    std::string mask() const { return masks_.empty() ? "" : masks_.back(); }
    std::string and_mask(const std::string& c) const { return masks_.empty() ? c : masks_.back() + " && " + c; }
    void declare_locals(TIntermNode* body);
    void function(TIntermAggregate* f);
    std::vector<long long> assigned_outside(TIntermNode* body);
    bool plain_counter(TIntermAggregate* for_sequence, long long id);
    void write_zeroes(TIntermNode* block);
    std::map<const TIntermNode*, std::vector<long long>> pending_zero_;  // locals zeroed where a block begins
    std::string functions_text_;
    std::map<long long, TIntermSymbol*> zero_symbols_;
    std::vector<std::string> structs_;
    std::optional<ExactProducts> exact_;  // the multiply-adds that round once (frontend/exact_products.h)
    std::optional<Expr> exact_product_add(TIntermBinary* b);

    // ---- a loop nest's part run across its iterations (frontend/iteration_slices.h) ------------
    void iteration_lanes(const IterationSlice& slice);
    bool names_apart(const IterationSlice& slice);
    std::string unused_name(const std::string& base);
    std::set<std::string> taken_names_;  // every name of the GLSL, and those the writer gave
    std::map<const TIntermNode*, std::string> across_iterations_;  // a part's declaration -> its value read back
    std::set<const glslang::TIntermLoop*> inner_levels_;  // loops a nest's part was planned around
};

std::string StageWriter::scalar_type(glslang::TBasicType b, const TIntermNode* at) const {
    switch (b) {
        case glslang::EbtFloat: return "F";
        case glslang::EbtInt: return "int_t<F>";
        case glslang::EbtUint: return "uint_t<F>";
        case glslang::EbtBool: return "Bool<F>";
        case glslang::EbtVoid: return "void";
        default: refuse(at, "a value of this type");
    }
}

// A sampler's texture (shading/glsl/texture.h): one of the kinds the renderer binds.
std::string StageWriter::sampler_type(const TType& t, const TIntermNode* at) const {
    const glslang::TSampler& s = t.getSampler();
    const bool plain = !t.isArray() && s.isCombined() && !s.isArrayed() && !s.isMultiSample() &&
                       s.getBasicType() == glslang::EbtFloat;
    if (plain && s.dim == glslang::Esd2D) return "sampler2D";  // a sampler2DShadow's depth comparison texture too
    if (plain && !s.isShadow() && s.dim == glslang::Esd3D) return "sampler3D";
    if (plain && s.dim == glslang::EsdCube) return "samplerCube";  // a samplerCubeShadow's too
    refuse(at, "a sampler of this kind");
}

std::string StageWriter::type(const TType& t, const TIntermNode* at) const {
    if (t.isArray()) {
        TType e(t, 0);
        if (t.getOuterArraySize() <= 0) refuse(at, "an array of unknown size");
        return "std::array<" + type(e, at) + ", " + std::to_string(t.getOuterArraySize()) + ">";
    }
    if (t.isStruct()) return cpp_identifier(t.getTypeName().c_str(), where(at));
    if (t.isMatrix()) {
        if (t.getBasicType() != glslang::EbtFloat) refuse(at, "a matrix of this type");
        const int c = t.getMatrixCols(), r = t.getMatrixRows();
        return c == r ? "mat" + std::to_string(c) + "<F>" : "mat" + std::to_string(c) + "x" + std::to_string(r) + "<F>";
    }
    if (t.isVector()) {
        const std::string n = std::to_string(t.getVectorSize());
        switch (t.getBasicType()) {
            case glslang::EbtFloat: return "vec" + n + "<F>";
            case glslang::EbtInt: return "ivec" + n + "<F>";
            case glslang::EbtUint: return "uvec" + n + "<F>";
            case glslang::EbtBool: return "bvec" + n + "<F>";
            default: refuse(at, "a vector of this type");
        }
    }
    return scalar_type(t.getBasicType(), at);
}

// ---- names --------------------------------------------------------------------------------------

std::string StageWriter::symbol_name(TIntermSymbol* s) {
    if (auto it = locals_.find(s->getId()); it != locals_.end()) return it->second.name;
    if (auto it = globals_.find(s->getId()); it != globals_.end()) return it->second;
    return global_member(s);
}

std::string StageWriter::global_member(TIntermSymbol* s) {
    const glslang::TQualifier& q = s->getQualifier();
    const std::string glsl = s->getName().c_str();
    if (is_per_vertex_block(s->getType()) && stage_ == Stage::Vertex && q.storage == glslang::EvqVaryingOut) {
        globals_[s->getId()] = "gl_Position";  // the one member the translation has
        if (member_names_.insert("gl_Position").second) {
            member_lines_.push_back("vec4<F> gl_Position{};");
            position_output = "gl_Position";
        }
        return "gl_Position";
    }
    std::string name;
    if (q.builtIn != glslang::EbvNone || glsl.rfind("gl_", 0) == 0) {
        name = glsl;
        if (!is_identifier(name)) refuse(s, "a built-in variable");
    } else {
        name = cpp_identifier(glsl, where(s));
    }
    globals_[s->getId()] = name;
    if (member_names_.contains(name)) return name;
    member_names_.insert(name);
    switch (q.storage) {
        case glslang::EvqUniform: uniform_member(s, name); break;
        case glslang::EvqVaryingIn: case glslang::EvqFragCoord: case glslang::EvqVertexId: case glslang::EvqIn:
            input_member(s, name);
            break;
        case glslang::EvqVaryingOut: case glslang::EvqFragColor: case glslang::EvqPosition: case glslang::EvqOut:
            output_member(s, name);
            break;
        case glslang::EvqGlobal: case glslang::EvqTemporary:
            member_lines_.push_back(type(s->getType(), s) + " " + name + "{};  // a global");
            break;
        default: refuse(s, "a variable of this storage");
    }
    return name;
}

void StageWriter::uniform_member(TIntermSymbol* s, const std::string& name) {
    const TType& t = s->getType();
    const std::string glsl = s->getName().c_str();
    if (t.getBasicType() == glslang::EbtSampler) {
        if (glsl == "teximage") {
            member_lines_.push_back("const sampler2D& teximage = *u.teximage;");
            return;
        }
        int other = 0;
        for (const ir::Sampler& p : program_.samplers) {
            if (p.name == "teximage" && p.dims == 2) continue;
            if (p.name == glsl) {
                if (p.dims == ir::kCubeSampler) {
                    member_lines_.push_back("const samplerCube& " + name + " = static_cast<const samplerCube&>(*u.samplers[" +
                                            std::to_string(other) + "]);");
                    return;
                }
                const std::string kind = p.dims == 3 ? "sampler3D" : "sampler2D";
                member_lines_.push_back("const " + kind + "& " + name + " = u." + kind + "(" + std::to_string(other) + ");");
                return;
            }
            ++other;
        }
        refuse(s, "this sampler");
    }
    if (glsl.rfind("gl_", 0) == 0 || transform_named(glsl)) {
        const std::optional<ir::TransformUniform> which =
            glsl == "gl_ModelViewProjectionMatrix" ? ir::TransformUniform::ModelViewProjection
            : glsl == "gl_ProjectionMatrix"        ? ir::TransformUniform::Projection
            : glsl == "gl_ModelViewMatrix"         ? ir::TransformUniform::ModelView
            : glsl == "gl_NormalMatrix"            ? ir::TransformUniform::Normal
                                                   : transform_named(glsl);
        if (!which) refuse(s, "this built-in uniform");
        switch (*which) {
            case ir::TransformUniform::ModelViewProjection: case ir::TransformUniform::Projection:
                member_lines_.push_back("const mat4<F> " + name + " = transform<F>(u.model_view_projection);  // the scene's");
                return;
            case ir::TransformUniform::ModelView:
                member_lines_.push_back("const mat4<F> " + name + " = mat4<F>(F(1.0f));  // the model-view-projection is the projection");
                return;
            case ir::TransformUniform::Normal:
                member_lines_.push_back("const mat3<F> " + name + " = mat3<F>(F(1.0f));  // the model-view is the identity");
                return;
            case ir::TransformUniform::Model:
                member_lines_.push_back("const mat4<F> " + name + " = transform<F>(u.model);  // the scene's");
                return;
            case ir::TransformUniform::View:
                member_lines_.push_back("const mat4<F> " + name + " = transform<F>(u.view);  // the scene's");
                return;
            case ir::TransformUniform::SceneProjection:
                member_lines_.push_back("const mat4<F> " + name + " = transform<F>(u.projection);  // the scene's");
                return;
            case ir::TransformUniform::SceneNormal:
                member_lines_.push_back("const mat3<F> " + name + " = transform<F>(u.normal_matrix);  // the scene's");
                return;
        }
    }
    if (glsl == "time" && t.getBasicType() == glslang::EbtFloat && t.isScalar() && !t.isArray()) {
        member_lines_.push_back("const F time = F(u.time);");
        return;
    }
    if (glsl == "dims" && t.getBasicType() == glslang::EbtFloat && t.getVectorSize() == 2 && !t.isArray() && !t.isMatrix()) {
        member_lines_.push_back("const vec2<F> dims = texture_size<F>(u.teximage);  // the texture's size");
        return;
    }
    if (t.isArray() || t.isStruct()) refuse(s, "an array or struct uniform");
    for (std::size_t i = 0; i < program_.uniforms.size(); ++i) {
        if (program_.uniforms[i].name != glsl) continue;
        const std::string cpp = type(t, s);
        member_lines_.push_back("const " + cpp + " " + name + " = uniform<" + cpp + ">(u, " + std::to_string(i) + ");");
        return;
    }
    refuse(s, "this uniform");
}

void StageWriter::input_member(TIntermSymbol* s, const std::string& name) {
    const TType& t = s->getType();
    const std::string glsl = s->getName().c_str();
    const std::string cpp = type(t, s);
    if (stage_ == Stage::Fragment) {
        if (s->getQualifier().storage == glslang::EvqFragCoord) {
            member_lines_.push_back("const vec4<F>& gl_FragCoord = in.gl_FragCoord;");
            return;
        }
        if (glsl.rfind("gl_", 0) == 0 || t.getBasicType() != glslang::EbtFloat || t.isArray() || t.isMatrix() || t.isStruct()) {
            refuse(s, "a varying other than a float or vec");
        }
        // read in place: a fragment shader's inputs are read-only
        member_lines_.push_back("const " + cpp + "& " + name + " = in." + name + ";  // varying");
        return;
    }
    // Vertex attributes, with the components GL supplies where the scene's data has fewer.
    std::optional<ir::Attribute> a;
    if (glsl == "gl_Vertex") a = ir::Attribute::Position;
    else if (glsl == "gl_Normal") a = ir::Attribute::Normal;
    else if (glsl == "gl_Color") a = ir::Attribute::Color;
    else if (glsl == "gl_MultiTexCoord0") a = ir::Attribute::Texcoord0;
    else if (glsl == "gl_MultiTexCoord1") a = ir::Attribute::Texcoord1;
    else a = attribute_named(glsl);
    if (!a || t.getBasicType() != glslang::EbtFloat || t.isArray() || t.isMatrix()) refuse(s, "this vertex input");
    const int n = t.getVectorSize();
    std::string c[4];
    for (int i = 0; i < 4; ++i) {
        switch (*a) {
            case ir::Attribute::Position: c[i] = i < 3 ? "F(in.position[" + std::to_string(i) + "])" : "F(1.0f)"; break;
            case ir::Attribute::Normal: c[i] = i < 3 ? "F(in.normal[" + std::to_string(i) + "])" : "F(0.0f)"; break;
            case ir::Attribute::Color: c[i] = "F(in.color[" + std::to_string(i) + "])"; break;
            case ir::Attribute::Texcoord0: c[i] = i < 2 ? "F(in.texcoord[" + std::to_string(i) + "])" : i == 3 ? "F(1.0f)" : "F(0.0f)"; break;
            case ir::Attribute::Texcoord1: c[i] = i < 2 ? "F(in.texcoord1[" + std::to_string(i) + "])" : i == 3 ? "F(1.0f)" : "F(0.0f)"; break;
        }
    }
    std::string init = n == 1 ? c[0] : cpp + "(";
    if (n > 1) {
        for (int i = 0; i < n; ++i) init += (i ? ", " : "") + c[i];
        init += ")";
    }
    member_lines_.push_back("const " + cpp + " " + name + " = " + init + ";  // attribute");
}

void StageWriter::output_member(TIntermSymbol* s, const std::string& name) {
    const TType& t = s->getType();
    const std::string glsl = s->getName().c_str();
    if (stage_ == Stage::Fragment) {
        if (t.getBasicType() != glslang::EbtFloat || t.getVectorSize() != 4 || t.isArray()) {
            refuse(s, "a fragment output other than a vec4");
        }
        member_lines_.push_back("vec4<F>& " + name + " = out.gl_FragColor;  // the fragment's colour");
        color_output = name;
        color_symbol_ = s->getId();
        return;
    }
    if (s->getQualifier().storage == glslang::EvqPosition || glsl == "gl_Position") {
        member_lines_.push_back("vec4<F> gl_Position{};");
        position_output = "gl_Position";
        return;
    }
    if (glsl.rfind("gl_", 0) == 0 || t.getBasicType() != glslang::EbtFloat || t.isArray() || t.isMatrix() || t.isStruct()) {
        refuse(s, "a vertex output other than gl_Position or a float or vec varying");
    }
    member_lines_.push_back(type(t, s) + " " + name + "{};  // varying");
    varying_outputs_.push_back({glsl, name});
}

// ---- expressions ---------------------------------------------------------------------------------

Expr StageWriter::constant_value(const glslang::TConstUnionArray& a, int first, const TType& t, const TIntermNode* at) {
    if (t.isArray() || t.isStruct()) refuse(at, "a constant array or struct");
    const int n = t.isMatrix() ? t.getMatrixCols() * t.getMatrixRows() : t.getVectorSize();
    std::vector<std::string> c;
    for (int i = 0; i < n; ++i) {
        const glslang::TConstUnion& v = a[first + i];
        switch (t.getBasicType()) {
            case glslang::EbtFloat: c.push_back(float_literal(v.getDConst())); break;
            case glslang::EbtInt: c.push_back(std::to_string(v.getIConst())); break;
            case glslang::EbtUint: c.push_back(std::to_string(v.getUConst()) + "u"); break;
            case glslang::EbtBool: c.push_back(v.getBConst() ? "true" : "false"); break;
            default: refuse(at, "a constant of this type");
        }
    }
    if (n == 1) return {c[0], c[0][0] == '-' ? kUnary : kPrimary, true};
    bool same = true;
    for (const std::string& s : c) same = same && s == c[0];
    const std::string element = scalar_type(t.getBasicType(), at);
    std::string text = type(t, at) + "(";
    if (same && !t.isMatrix()) {
        text += element + "(" + c[0] + ")";
    } else {
        for (std::size_t i = 0; i < c.size(); ++i) text += (i ? ", " : "") + (element == "F" ? c[i] : element + "(" + c[i] + ")");
    }
    return {text + ")", kPrimary, false};
}

std::string StageWriter::constant_table(TIntermConstantUnion* c, int component) {
    const TType& t = c->getType();
    const TType element_type(t, 0);
    if (!t.isArray() || t.getArraySizes()->getNumDims() != 1 || element_type.isMatrix() || element_type.isStruct()) {
        refuse(c, "a constant array of arrays, matrices or structs read at a run-time index");
    }
    const int n = t.getOuterArraySize(), size = element_type.getVectorSize();
    const glslang::TConstUnionArray& a = c->getConstArray();
    std::string element, values;
    for (int i = 0; i < n; ++i) {
        const glslang::TConstUnion& x = a[i * size + component];
        std::string v;
        switch (t.getBasicType()) {
            case glslang::EbtFloat: element = "float", v = float_literal(x.getDConst()); break;
            case glslang::EbtInt: element = "int", v = std::to_string(x.getIConst()); break;
            case glslang::EbtUint: element = "unsigned", v = std::to_string(x.getUConst()) + "u"; break;
            default: refuse(c, "a constant array of bools read at a run-time index");
        }
        values += (i ? ", " : "") + v;
    }
    const std::string key = element + ":" + values;
    if (auto it = tables_.find(key); it != tables_.end()) return it->second;
    const std::string name = "table" + std::to_string(tables_.size() + 1);
    tables_[key] = name;
    const std::string what = size == 1 ? "" : std::string(" (its ") + "xyzw"[component] + "s)";
    member_lines_.push_back("// the constant array of GLSL line " + std::to_string(c->getLoc().line) + what + ", read per fragment");
    member_lines_.push_back("static constexpr table<" + element + ", " + std::to_string(n) + "> " + name + "{{" + values + "}};");
    return name;
}

Expr StageWriter::table_read(TIntermConstantUnion* c, TIntermTyped* index) {
    const std::string i = "[" + as_typed(index, index->getType()).text + "]";
    const TType element_type(c->getType(), 0);
    if (element_type.isScalar()) return {constant_table(c, 0) + i, kPostfix, false};
    std::string text = type(element_type, c) + "(";
    for (int k = 0; k < element_type.getVectorSize(); ++k) text += (k ? ", " : "") + constant_table(c, k) + i;
    return {text + ")", kPrimary, false};
}

Expr StageWriter::constant(TIntermConstantUnion* c) { return constant_value(c->getConstArray(), 0, c->getType(), c); }

// A plain C++ value as a value of its GLSL type over F.
Expr StageWriter::as_typed(TIntermTyped* n, const TType& t) {
    Expr e = expr(n);
    if (!e.plain) return e;
    return {scalar_type(t.getBasicType(), n) + "(" + e.text + ")", kPrimary, false};
}

Expr StageWriter::expr(TIntermTyped* n) {
    if (auto* c = n->getAsConstantUnion()) return constant(c);
    if (auto* s = n->getAsSymbolNode()) {
        if (auto it = locals_.find(s->getId()); it != locals_.end()) return {it->second.name, kPrimary, it->second.plain_counter};
        if (s->getQualifier().storage == glslang::EvqConst && s->getConstArray().size() > 0 && !s->getType().isArray()) {
            return constant_value(s->getConstArray(), 0, s->getType(), s);
        }
        return {symbol_name(s), kPrimary, false};
    }
    if (auto* b = n->getAsBinaryNode()) return binary(b);
    if (auto* u = n->getAsUnaryNode()) return unary(u);
    if (auto* a = n->getAsAggregate()) return aggregate(a);
    if (auto* s = n->getAsSelectionNode()) {
        if (!s->getTrueBlock() || !s->getFalseBlock()) refuse(n, "this selection");
        Expr c = expr(s->getCondition());
        Expr t = as_typed(s->getTrueBlock()->getAsTyped(), n->getType());
        Expr f = as_typed(s->getFalseBlock()->getAsTyped(), n->getType());
        if (c.plain) return {parens(c, kOr) + " ? " + parens(t, kAssign) + " : " + parens(f, kAssign), kAssign, false};
        return {"select(" + c.text + ", " + t.text + ", " + f.text + ")", kPrimary, false};
    }
    refuse(n, "this expression");
}

std::string StageWriter::swizzle(TIntermBinary* b) {
    static const char* sets[] = {"xyzw", "rgba", "stpq"};
    std::string name;
    const std::string glsl_hint;
    for (TIntermNode* k : b->getRight()->getAsAggregate()->getSequence()) {
        const int i = k->getAsConstantUnion()->getConstArray()[0].getIConst();
        name += sets[0][i];
    }
    (void)sets;
    return name;
}

std::string StageWriter::lvalue(TIntermTyped* n) {
    if (auto* s = n->getAsSymbolNode()) return expr(s).text;
    if (auto* b = n->getAsBinaryNode()) {
        const std::string base = lvalue(b->getLeft());
        switch (b->getOp()) {
            case glslang::EOpIndexDirect: {
                const int i = b->getRight()->getAsConstantUnion()->getConstArray()[0].getIConst();
                const TType& t = b->getLeft()->getType();
                if (t.isVector()) return base + "." + std::string(1, "xyzw"[i]);
                return base + "[" + std::to_string(i) + "]";
            }
            case glslang::EOpIndexDirectStruct: {
                if (is_per_vertex_block(b->getLeft()->getType())) return per_vertex_member(b);
                const int i = b->getRight()->getAsConstantUnion()->getConstArray()[0].getIConst();
                return base + "." + cpp_identifier((*b->getLeft()->getType().getStruct())[std::size_t(i)].type->getFieldName().c_str(), where(b));
            }
            case glslang::EOpVectorSwizzle: {
                const std::string s = swizzle(b);
                return s.size() == 1 ? base + "." + s : base + "." + s + "()";
            }
            case glslang::EOpIndexIndirect: {
                Expr i = expr(b->getRight());
                if (!i.plain || b->getLeft()->getType().isVector()) refuse(b, "a write at an index that varies per fragment");
                return base + "[" + i.text + "]";
            }
            default: break;
        }
    }
    refuse(n, "this assignment target");
}

Expr StageWriter::binary(TIntermBinary* b) {
    const TOperator op = b->getOp();
    switch (op) {
        case glslang::EOpIndexDirect: case glslang::EOpIndexDirectStruct: case glslang::EOpVectorSwizzle: {
            if (op == glslang::EOpIndexDirectStruct && is_per_vertex_block(b->getLeft()->getType())) {
                return {per_vertex_member(b), kPrimary, false};
            }
            Expr base = expr(b->getLeft());
            if (op == glslang::EOpIndexDirect && b->getLeft()->getAsConstantUnion()) break;
            const std::string lv = [&] {
                if (op == glslang::EOpIndexDirect) {
                    const int i = b->getRight()->getAsConstantUnion()->getConstArray()[0].getIConst();
                    if (b->getLeft()->getType().isVector()) return "." + std::string(1, "xyzw"[i]);
                    return "[" + std::to_string(i) + "]";
                }
                if (op == glslang::EOpIndexDirectStruct) {
                    const int i = b->getRight()->getAsConstantUnion()->getConstArray()[0].getIConst();
                    return "." + cpp_identifier((*b->getLeft()->getType().getStruct())[std::size_t(i)].type->getFieldName().c_str(), where(b));
                }
                const std::string s = swizzle(b);
                return s.size() == 1 ? "." + s : "." + s + "()";
            }();
            return {parens(base, kPostfix) + lv, kPostfix, false};
        }
        case glslang::EOpIndexIndirect: {
            if (auto* c = b->getLeft()->getAsConstantUnion()) return table_read(c, b->getRight());
            Expr base = expr(b->getLeft());
            Expr i = expr(b->getRight());
            if (!i.plain) refuse(b, "an index that varies per fragment");
            return {parens(base, kPostfix) + "[" + i.text + "]", kPostfix, false};
        }
        default: break;
    }
    if (b->getAsBinaryNode() && (op == glslang::EOpAssign || b->getType().getQualifier().storage == glslang::EvqTemporary) &&
        is_assignment(op)) {
        refuse(b, "an assignment inside an expression");
    }
    if (std::optional<Expr> fused = exact_product_add(b)) return *fused;
    Expr l = expr(b->getLeft());
    Expr r = expr(b->getRight());
    bool plain = l.plain && r.plain;
    const bool integer = b->getLeft()->getType().getBasicType() == glslang::EbtInt ||
                         b->getLeft()->getType().getBasicType() == glslang::EbtUint;
    // Of values the same for every fragment, C++ keeps comparisons, logic and the integer sums
    // and products an index needs. Integer division, remainder and shifts are the vocabulary's
    // (a zero divisor and a negative or wide shift have the interpreter's results, not C++'s
    // undefined ones), and float arithmetic is F's (in double precision it runs in double, as
    // the interpreter runs it).
    const bool integer_only_in_f = integer && (op == glslang::EOpDiv || op == glslang::EOpMod ||
                                               op == glslang::EOpLeftShift || op == glslang::EOpRightShift);
    const bool float_arithmetic = b->getType().getBasicType() == glslang::EbtFloat &&
                                  (op == glslang::EOpAdd || op == glslang::EOpSub || op == glslang::EOpMul || op == glslang::EOpDiv);
    if (plain && (integer_only_in_f || float_arithmetic)) {
        l = as_typed(b->getLeft(), b->getLeft()->getType());
        if (integer_only_in_f) r = as_typed(b->getRight(), b->getRight()->getType());  // F and a float make an F
        plain = false;
    }
    // An integer or bool literal beside a value of F: written as a value of its type.
    if (!plain) {
        if (l.plain && b->getLeft()->getType().getBasicType() != glslang::EbtFloat) l = as_typed(b->getLeft(), b->getLeft()->getType());
        if (r.plain && b->getRight()->getType().getBasicType() != glslang::EbtFloat) r = as_typed(b->getRight(), b->getRight()->getType());
    }
    const auto infix = [&](const char* o, int prec) {
        return Expr{parens(l, prec) + " " + o + " " + parens(r, prec + 1), prec, plain};
    };
    switch (op) {
        case glslang::EOpAdd: return infix("+", kAdditive);
        case glslang::EOpSub: return infix("-", kAdditive);
        case glslang::EOpMul: case glslang::EOpVectorTimesScalar: case glslang::EOpVectorTimesMatrix:
        case glslang::EOpMatrixTimesVector: case glslang::EOpMatrixTimesScalar: case glslang::EOpMatrixTimesMatrix:
            return infix("*", kMultiplicative);
        case glslang::EOpDiv: return infix("/", kMultiplicative);
        case glslang::EOpMod: return infix("%", kMultiplicative);
        case glslang::EOpLessThan: return infix("<", kRelational);
        case glslang::EOpGreaterThan: return infix(">", kRelational);
        case glslang::EOpLessThanEqual: return infix("<=", kRelational);
        case glslang::EOpGreaterThanEqual: return infix(">=", kRelational);
        case glslang::EOpEqual: return infix("==", kEquality);
        case glslang::EOpNotEqual: return infix("!=", kEquality);
        case glslang::EOpLogicalAnd: return infix("&&", kAnd);
        case glslang::EOpLogicalOr: return infix("||", kOr);
        case glslang::EOpLogicalXor: return infix("!=", kEquality);
        case glslang::EOpAnd: return infix("&", kBitAnd);
        case glslang::EOpInclusiveOr: return infix("|", kBitOr);
        case glslang::EOpExclusiveOr: return infix("^", kBitXor);
        case glslang::EOpLeftShift: return infix("<<", kShift);
        case glslang::EOpRightShift: return infix(">>", kShift);
        default: break;
    }
    (void)integer;
    refuse(b, "this operator");
}

// A multiply-add whose product is exact for every input, rounded once: the same bits as GLSL's
// two roundings, one instruction where the target fuses.
std::optional<Expr> StageWriter::exact_product_add(TIntermBinary* b) {
    const std::optional<FusibleProduct> f = exact_ ? exact_->fusible(b) : std::nullopt;
    if (!f) return std::nullopt;
    Expr a = expr(f->product_left), m = expr(f->product_right), c = expr(f->addend);
    if (a.plain && m.plain && c.plain) {
        // A C++ float the same for every fragment (a loop counter's) stays one, as GLSL writes it.
        const Expr p{parens(a, kMultiplicative) + " * " + parens(m, kMultiplicative + 1), kMultiplicative, true};
        const bool product_first = b->getLeft() != f->addend;
        const Expr& l = product_first ? p : c;
        const Expr& r = product_first ? c : p;
        const char* o = b->getOp() == glslang::EOpSub ? " - " : " + ";
        return Expr{parens(l, kAdditive) + o + parens(r, kAdditive + 1), kAdditive, true};
    }
    const std::string t = type(b->getType(), b);
    const auto typed = [&](TIntermTyped* n, const Expr& e) {
        const bool same = !e.plain && n->getType().isScalar() == b->getType().isScalar() &&
                          n->getType().getVectorSize() == b->getType().getVectorSize();
        return same ? e : Expr{t + "(" + e.text + ")", kPrimary, false};
    };
    a = typed(f->product_left, a);
    m = typed(f->product_right, m);
    c = typed(f->addend, c);
    if (f->subtract_product) return Expr{"exact_sub_product(" + c.text + ", " + a.text + ", " + m.text + ")", kPostfix, false};
    const std::string name = f->subtract_addend ? "exact_product_sub(" : "exact_product_add(";
    return Expr{name + a.text + ", " + m.text + ", " + c.text + ")", kPostfix, false};
}

Expr StageWriter::conversion(TIntermTyped* from, const TType& to, TIntermTyped* at) {
    Expr e = expr(from);
    const TType& ft = from->getType();
    const std::string target = scalar_type(to.getBasicType(), at);
    const bool to_bool = to.getBasicType() == glslang::EbtBool;
    const auto one = [&](const std::string& x) {
        if (to_bool) {
            const std::string zero = ft.getBasicType() == glslang::EbtFloat ? "F(0.0f)" : scalar_type(ft.getBasicType(), at) + "(0)";
            return x + " != " + zero;
        }
        return target + "(" + x + ")";
    };
    if (e.plain) {
        if (to.getBasicType() == glslang::EbtFloat) return {"float(" + e.text + ")", kPrimary, true};
        if (to.getBasicType() == glslang::EbtInt) return {"int(" + e.text + ")", kPrimary, true};
        if (to.getBasicType() == glslang::EbtUint) return {"unsigned(" + e.text + ")", kPrimary, true};
        return {"bool(" + e.text + ")", kPrimary, true};
    }
    if (!ft.isVector()) return {one(e.text), to_bool ? kEquality : kPrimary, false};
    // Component by component, from a named value.
    std::string text = type(to, at) + "(";
    const std::string src = parens(e, kPostfix);
    if (from->getAsSymbolNode()) {
        for (int i = 0; i < ft.getVectorSize(); ++i) text += (i ? ", " : "") + one(src + "." + std::string(1, "xyzw"[i]));
        return {text + ")", kPrimary, false};
    }
    if (to_bool) refuse(at, "a conversion to a bool vector of an expression (of a variable it is written)");
    return {"convert<" + type(to, at) + ">(" + e.text + ")", kPrimary, false};
}

Expr StageWriter::unary(TIntermUnary* u) {
    const TOperator op = u->getOp();
    TIntermTyped* a = u->getOperand();
    switch (op) {
        case glslang::EOpNegative: {
            Expr e = expr(a);
            return {"-" + parens(e, kUnary), kUnary, e.plain};
        }
        case glslang::EOpLogicalNot: case glslang::EOpVectorLogicalNot: {
            Expr e = expr(a);
            return {"!" + parens(e, kUnary), kUnary, e.plain};
        }
        case glslang::EOpBitwiseNot: {
            Expr e = expr(a);
            return {"~" + parens(e, kUnary), kUnary, e.plain};
        }
        case glslang::EOpPostIncrement: case glslang::EOpPostDecrement: case glslang::EOpPreIncrement:
        case glslang::EOpPreDecrement:
            refuse(u, "an increment inside an expression");
        default: break;
    }
    if (op >= glslang::EOpConvInt8ToBool && op <= glslang::EOpConvDoubleToFloat) return conversion(a, u->getType(), u);
    glslang::TIntermSequence args;
    args.push_back(a);
    return builtin("", u, args);
}

Expr StageWriter::aggregate(TIntermAggregate* a) {
    const TOperator op = a->getOp();
    if (op == glslang::EOpFunctionCall) return call(a);
    if (op >= glslang::EOpConstructGuardStart && op < glslang::EOpConstructGuardEnd) return constructor(a);
    if (op == glslang::EOpComma) refuse(a, "the comma operator");
    return builtin("", a, a->getSequence());
}

Expr StageWriter::constructor(TIntermAggregate* a) {
    const TType& t = a->getType();
    const glslang::TIntermSequence& args = a->getSequence();
    std::string text = type(t, a) + "(";
    if (t.isArray() || t.isStruct()) text = type(t, a) + "{";
    if (!t.isArray() && !t.isStruct() && !t.isMatrix() && args.size() == 1) {
        const TType& at = args[0]->getAsTyped()->getType();
        if (at.getBasicType() != t.getBasicType()) {
            if (at.isScalar() && t.isScalar()) return conversion(args[0]->getAsTyped(), t, a);
            if (at.isScalar()) {
                Expr c = conversion(args[0]->getAsTyped(), TType(t.getBasicType()), a);
                return {type(t, a) + "(" + c.text + ")", kPrimary, false};
            }
            return conversion(args[0]->getAsTyped(), t, a);
        }
    }
    for (std::size_t i = 0; i < args.size(); ++i) {
        TIntermTyped* arg = args[i]->getAsTyped();
        Expr e = arg->getType().getBasicType() != glslang::EbtFloat ? as_typed(arg, arg->getType()) : expr(arg);
        if (arg->getType().getBasicType() != t.getBasicType() && !t.isStruct() && !t.isArray()) {
            e = conversion(arg, TType(t.getBasicType(), glslang::EvqTemporary, arg->getType().getVectorSize()), a);
        }
        if (t.isScalar() && args.size() == 1) return e.plain ? Expr{scalar_type(t.getBasicType(), a) + "(" + e.text + ")"} : e;
        text += (i ? ", " : "") + e.text;
    }
    return {text + ((t.isArray() || t.isStruct()) ? "}" : ")"), kPrimary, false};
}

Expr StageWriter::call(TIntermAggregate* a) {
    const std::string mangled = a->getName().c_str();
    const std::string name = cpp_identifier(mangled.substr(0, mangled.find('(')), where(a));
    std::string text = name + "(";
    const glslang::TIntermSequence& args = a->getSequence();
    const glslang::TQualifierList& q = a->getQualifierList();
    for (std::size_t i = 0; i < args.size(); ++i) {
        TIntermTyped* arg = args[i]->getAsTyped();
        const bool out = i < q.size() && (q[i] == glslang::EvqOut || q[i] == glslang::EvqInOut);
        if (out && !masks_.empty()) refuse(a, "a call with out parameters under a condition that varies per fragment");
        text += (i ? ", " : "") + (out ? lvalue(arg) : as_typed(arg, arg->getType()).text);
    }
    return {text + ")", kPostfix, false};
}

// A lookup in a sampler2DShadow (shading/glsl/texture_shadow.h): the vocabulary's function of its
// name takes GLSL's arguments in GLSL's order. A vertex shader's implicit lookup reads level 0, as
// the lowering reads it (its Lod form at level 0).
Expr StageWriter::shadow_lookup(TOperator op, TIntermTyped* node, const std::vector<std::string>& v) {
    std::vector<std::string> w = v;
    if (stage_ == Stage::Vertex) {
        const TOperator at_level = op == glslang::EOpTexture             ? glslang::EOpTextureLod
                                   : op == glslang::EOpTextureProj       ? glslang::EOpTextureProjLod
                                   : op == glslang::EOpTextureOffset     ? glslang::EOpTextureLodOffset
                                   : op == glslang::EOpTextureProjOffset ? glslang::EOpTextureProjLodOffset
                                                                         : op;
        if (at_level != op) w.insert(w.begin() + 2, "F(0.0f)");
        op = at_level;
    }
    const char* name = shadow_lookup_function(op);
    if (!name) refuse(node, "this texture function on a sampler2DShadow");
    std::string t = std::string(name) + "(";
    for (std::size_t i = 0; i < w.size(); ++i) t += (i ? ", " : "") + w[i];
    t += ")";
    if (node->getType().getVectorSize() == 4) t = "depthLuminance(" + t + ")";
    return {t, kPostfix, false};
}

// The GLSL built-ins the vocabulary (shading/glsl/) has under their GLSL names, taking their
// arguments as they are; null for the others. round() is roundEven: GLSL leaves halves to the
// implementation, and llvmpipe rounds them to even.
const char* same_name_builtin(TOperator op) {
    switch (op) {
        case glslang::EOpRadians: return "radians";
        case glslang::EOpDegrees: return "degrees";
        case glslang::EOpSin: return "sin";
        case glslang::EOpCos: return "cos";
        case glslang::EOpTan: return "tan";
        case glslang::EOpAsin: return "asin";
        case glslang::EOpAcos: return "acos";
        case glslang::EOpAtan: return "atan";
        case glslang::EOpSinh: return "sinh";
        case glslang::EOpCosh: return "cosh";
        case glslang::EOpTanh: return "tanh";
        case glslang::EOpAsinh: return "asinh";
        case glslang::EOpAcosh: return "acosh";
        case glslang::EOpAtanh: return "atanh";
        case glslang::EOpPow: return "pow";
        case glslang::EOpExp: return "exp";
        case glslang::EOpLog: return "log";
        case glslang::EOpExp2: return "exp2";
        case glslang::EOpLog2: return "log2";
        case glslang::EOpSqrt: return "sqrt";
        case glslang::EOpInverseSqrt: return "inversesqrt";
        case glslang::EOpAbs: return "abs";
        case glslang::EOpSign: return "sign";
        case glslang::EOpFloor: return "floor";
        case glslang::EOpTrunc: return "trunc";
        case glslang::EOpRound: return "roundEven";
        case glslang::EOpRoundEven: return "roundEven";
        case glslang::EOpCeil: return "ceil";
        case glslang::EOpFract: return "fract";
        case glslang::EOpMod: return "mod";
        case glslang::EOpMin: return "min";
        case glslang::EOpMax: return "max";
        case glslang::EOpClamp: return "clamp";
        case glslang::EOpMix: return "mix";
        case glslang::EOpStep: return "step";
        case glslang::EOpSmoothStep: return "smoothstep";
        case glslang::EOpFma: return "fma";
        case glslang::EOpIsNan: return "isnan";
        case glslang::EOpIsInf: return "isinf";
        case glslang::EOpLength: return "length";
        case glslang::EOpDistance: return "distance";
        case glslang::EOpDot: return "dot";
        case glslang::EOpCross: return "cross";
        case glslang::EOpNormalize: return "normalize";
        case glslang::EOpFaceForward: return "faceforward";
        case glslang::EOpReflect: return "reflect";
        case glslang::EOpRefract: return "refract";
        case glslang::EOpDPdx: return "dFdx";
        case glslang::EOpDPdy: return "dFdy";
        case glslang::EOpFwidth: return "fwidth";
        case glslang::EOpDPdxFine: return "dFdxFine";
        case glslang::EOpDPdyFine: return "dFdyFine";
        case glslang::EOpFwidthFine: return "fwidthFine";
        case glslang::EOpDPdxCoarse: return "dFdxCoarse";
        case glslang::EOpDPdyCoarse: return "dFdyCoarse";
        case glslang::EOpFwidthCoarse: return "fwidthCoarse";
        case glslang::EOpLessThan: return "lessThan";
        case glslang::EOpLessThanEqual: return "lessThanEqual";
        case glslang::EOpGreaterThan: return "greaterThan";
        case glslang::EOpGreaterThanEqual: return "greaterThanEqual";
        case glslang::EOpVectorEqual: return "equal";
        case glslang::EOpVectorNotEqual: return "notEqual";
        case glslang::EOpAny: return "any";
        case glslang::EOpAll: return "all";
        case glslang::EOpTranspose: return "transpose";
        case glslang::EOpDeterminant: return "determinant";
        case glslang::EOpMatrixInverse: return "inverse";
        case glslang::EOpOuterProduct: return "outerProduct";
        case glslang::EOpMul: return "matrixCompMult";
        case glslang::EOpFloatBitsToInt: return "floatBitsToInt";
        case glslang::EOpFloatBitsToUint: return "floatBitsToUint";
        case glslang::EOpIntBitsToFloat: return "intBitsToFloat";
        case glslang::EOpUintBitsToFloat: return "uintBitsToFloat";
        case glslang::EOpBitFieldReverse: return "bitfieldReverse";
        case glslang::EOpBitCount: return "bitCount";
        case glslang::EOpFindLSB: return "findLSB";
        case glslang::EOpFindMSB: return "findMSB";
        case glslang::EOpBitfieldExtract: return "bitfieldExtract";
        case glslang::EOpBitfieldInsert: return "bitfieldInsert";
        case glslang::EOpLdexp: return "ldexp";
        default: return nullptr;
    }
}

// A lookup in a samplerCube or samplerCubeShadow (shading/glsl/texture_cube.h), as the lowering
// makes it.
Expr StageWriter::cube_lookup(TOperator op, TIntermTyped* node, const glslang::TIntermSequence& args,
                              const std::vector<std::string>& v) {
    const auto call = [&](const std::string& name, std::size_t n) {
        std::string t = name + "(";
        for (std::size_t i = 0; i < n; ++i) t += (i ? ", " : "") + v[i];
        return Expr{t + ")", kPostfix, false};
    };
    if (op == glslang::EOpTextureQuerySize) return call("textureSize<F>", v.size());
    const bool shadow = args[0]->getAsTyped()->getType().getSampler().isShadow();
    if (op == glslang::EOpTextureGather) {
        if (shadow) return call("textureGatherCompare", 3);
        // The channel, a constant expression, as the plain int the function takes.
        std::vector<std::string> w = v;
        if (args.size() > 2) {
            const glslang::TIntermConstantUnion* k = args[2]->getAsConstantUnion();
            if (!k) refuse(node, "textureGather with a channel that is not a constant");
            w[2] = std::to_string(k->getConstArray()[0].getIConst());
        }
        std::string t = "textureGather(";
        for (std::size_t i = 0; i < w.size(); ++i) t += (i ? ", " : "") + w[i];
        return {t + ")", kPostfix, false};
    }
    const bool vertex = stage_ == Stage::Vertex;
    if (shadow) {
        // a vertex shader's implicit lookup at level 0, as the lowering reads it
        if (op == glslang::EOpTexture && vertex) {
            return {"textureCubeShadowLod(" + v[0] + ", " + v[1] + ", F(0.0f))", kPostfix, false};
        }
        if (op == glslang::EOpTexture) return call("textureCubeShadow", v.size());
        if (op == glslang::EOpTextureGrad) return call("textureCubeShadowGrad", v.size());
        refuse(node, "this texture function on a samplerCubeShadow");
    }
    if (op == glslang::EOpTexture && !vertex) return call("textureCube", v.size());
    if (op == glslang::EOpTextureLod) return call("textureCubeLod", v.size());
    if (op == glslang::EOpTextureGrad) return call("textureGrad", v.size());
    refuse(node, vertex && op == glslang::EOpTexture ? "a texture lookup in a vertex shader"
                                                     : "this texture function on a samplerCube");
}

Expr StageWriter::builtin(const std::string&, TIntermTyped* node, const glslang::TIntermSequence& args) {
    const TOperator op = node->getAsOperator()->getOp();
    std::vector<std::string> v;
    for (TIntermNode* n : args) {
        const glslang::TIntermConstantUnion* k = n->getAsConstantUnion();
        if (op == glslang::EOpTextureGatherOffsets && k && k->getType().isArray()) {
            // the offsets, a constant expression (as GLSL requires), as the array the function takes
            const glslang::TConstUnionArray& o = k->getConstArray();
            std::string offsets = "std::array<ivec2<F>, 4>{";
            for (int i = 0; i < 4; ++i) {
                offsets += std::string(i ? ", " : "") + "ivec2<F>(int_t<F>(" + std::to_string(o[2 * i].getIConst()) +
                           "), int_t<F>(" + std::to_string(o[2 * i + 1].getIConst()) + "))";
            }
            v.push_back(offsets + "}");
            continue;
        }
        v.push_back(as_typed(n->getAsTyped(), n->getAsTyped()->getType()).text);
    }
    const auto fn = [&](const std::string& name) {
        std::string t = name + "(";
        for (std::size_t i = 0; i < v.size(); ++i) t += (i ? ", " : "") + v[i];
        return Expr{t + ")", kPostfix, false};
    };
    if (const char* name = same_name_builtin(op)) return fn(name);
    switch (op) {
        case glslang::EOpModf: case glslang::EOpFrexp: {
            // The whole part or exponent goes to a variable, written for every lane.
            if (!masks_.empty()) refuse(node, "modf or frexp under a condition that varies per fragment");
            if (!args[1]->getAsSymbolNode()) refuse(node, "modf or frexp into a part of a variable");
            return {std::string(op == glslang::EOpModf ? "modf(" : "frexp(") + v[0] + ", " +
                        lvalue(args[1]->getAsTyped()) + ")",
                    kPostfix, false};
        }
        case glslang::EOpFtransform:
            if (stage_ != Stage::Vertex) refuse(node, "ftransform() outside a vertex shader");
            if (!member_names_.contains("gl_ModelViewProjectionMatrix")) {
                member_names_.insert("gl_ModelViewProjectionMatrix");
                member_lines_.push_back("const mat4<F> gl_ModelViewProjectionMatrix = transform<F>(u.model_view_projection);");
            }
            if (!member_names_.contains("gl_Vertex")) {
                member_names_.insert("gl_Vertex");
                member_lines_.push_back("const vec4<F> gl_Vertex = vec4<F>(F(in.position[0]), F(in.position[1]), F(in.position[2]), F(1.0f));");
            }
            return {"gl_ModelViewProjectionMatrix * gl_Vertex", kMultiplicative, false};
        case glslang::EOpTexture: case glslang::EOpTextureProj: case glslang::EOpTextureLod: case glslang::EOpTextureProjLod:
        case glslang::EOpTextureFetch: case glslang::EOpTextureQuerySize: case glslang::EOpTextureGrad:
        case glslang::EOpTextureProjGrad: case glslang::EOpTextureOffset: case glslang::EOpTextureProjOffset:
        case glslang::EOpTextureLodOffset: case glslang::EOpTextureProjLodOffset: case glslang::EOpTextureGradOffset:
        case glslang::EOpTextureProjGradOffset: case glslang::EOpTextureFetchOffset: {
            const TType& st = args[0]->getAsTyped()->getType();
            if (st.getSampler().dim == glslang::EsdCube) return cube_lookup(op, node, args, v);
            if (st.getSampler().isShadow() && op != glslang::EOpTextureQuerySize) {
                return shadow_lookup(op, node, v);
            }
            const bool three = st.getSampler().dim == glslang::Esd3D;
            const std::string base = three ? "texture3D" : "texture2D";
            const bool vertex = stage_ == Stage::Vertex;
            // The integer lookups name the float type, which their arguments do not give.
            if (op == glslang::EOpTextureFetch) return fn("texelFetch<F>");
            if (op == glslang::EOpTextureFetchOffset) return fn("texelFetchOffset<F>");
            if (op == glslang::EOpTextureQuerySize) return fn("textureSize<F>");
            if (op == glslang::EOpTexture && !vertex) return fn(base);
            if (op == glslang::EOpTextureProj && !vertex) return fn(base + "Proj");
            if (op == glslang::EOpTextureOffset && !vertex) return fn("textureOffset");
            if (op == glslang::EOpTextureProjOffset && !vertex) return fn("textureProjOffset");
            if (op == glslang::EOpTextureLod) return fn(base + "Lod");
            if (op == glslang::EOpTextureProjLod) return fn(base + "ProjLod");
            if (op == glslang::EOpTextureLodOffset) return fn("textureLodOffset");
            if (op == glslang::EOpTextureProjLodOffset) return fn("textureProjLodOffset");
            if (op == glslang::EOpTextureGrad) return fn("textureGrad");
            if (op == glslang::EOpTextureProjGrad) return fn("textureProjGrad");
            if (op == glslang::EOpTextureGradOffset) return fn("textureGradOffset");
            if (op == glslang::EOpTextureProjGradOffset) return fn("textureProjGradOffset");
            refuse(node, "a texture lookup in a vertex shader");
        }
        case glslang::EOpTextureGather: case glslang::EOpTextureGatherOffset: {
            const glslang::TSampler& sampler = args[0]->getAsTyped()->getType().getSampler();
            if (sampler.dim == glslang::EsdCube) return cube_lookup(op, node, args, v);
            if (sampler.isShadow()) {
                return fn(op == glslang::EOpTextureGather ? "textureGatherCompare" : "textureGatherOffsetCompare");
            }
            // The channel, a constant expression, as the plain int the function takes.
            const std::size_t comp_arg = op == glslang::EOpTextureGatherOffset ? 3 : 2;
            if (args.size() > comp_arg) {
                const glslang::TIntermConstantUnion* k = args[comp_arg]->getAsConstantUnion();
                if (!k) refuse(node, "textureGather with a channel that is not a constant");
                v[comp_arg] = std::to_string(k->getConstArray()[0].getIConst());
            }
            return fn(op == glslang::EOpTextureGather ? "textureGather" : "textureGatherOffset");
        }
        case glslang::EOpTextureGatherOffsets: {
            if (args[0]->getAsTyped()->getType().getSampler().isShadow()) return fn("textureGatherOffsetsCompare");
            if (args.size() > 3) {
                // the channel, a constant expression, as the plain int the function takes
                const glslang::TIntermConstantUnion* k = args[3]->getAsConstantUnion();
                if (!k) refuse(node, "textureGatherOffsets with a channel that is not a constant");
                v[3] = std::to_string(k->getConstArray()[0].getIConst());
            }
            return fn("textureGatherOffsets");
        }
        case glslang::EOpTextureQueryLevels: return fn("textureQueryLevels<F>");
        case glslang::EOpTextureQueryLod: return fn("textureQueryLod");
        default: break;
    }
    refuse(node, "this built-in function");
}

// ---- statements ------------------------------------------------------------------------------------

// Whether a write to `target` keeps the lanes outside the conditions open: those a condition
// opened since the variable was declared.
bool StageWriter::masked_target(TIntermTyped* target) {
    TIntermTyped* n = target;
    while (auto* b = n->getAsBinaryNode()) n = b->getLeft();
    auto* s = n->getAsSymbolNode();
    if (!s) refuse(target, "this assignment target");
    if (auto it = locals_.find(s->getId()); it != locals_.end()) return int(masks_.size()) > it->second.mask_depth;
    return !masks_.empty();
}

void StageWriter::assign_to(TIntermTyped* target, const std::string& value, const TIntermNode* at) {
    const std::string lv = lvalue(target);
    if (masked_target(target)) {
        std::string current = lv;
        if (lv.back() == ')') current = type(target->getType(), at) + "(" + lv + ")";
        line(lv + " = select(" + mask() + ", " + value + ", " + current + ");", at);
    } else {
        line(lv + " = " + value + ";", at);
    }
}

void StageWriter::assignment(TIntermBinary* b) {
    const TOperator op = b->getOp();
    TIntermTyped* target = b->getLeft();
    // `a = b = v`, `a += b *= v`: the inner assignment first, then the outer reads its target.
    TIntermTyped* value = b->getRight();
    if (auto* inner = value->getAsBinaryNode(); inner && is_assignment(inner->getOp())) {
        assignment(inner);
        value = inner->getLeft();
    }
    if (op == glslang::EOpAssign) {
        if (auto* s = target->getAsSymbolNode()) {
            auto it = locals_.find(s->getId());
                if (it != locals_.end() && !it->second.declared && it->second.declaring == b) {
                it->second.declared = true;
                it->second.mask_depth = int(masks_.size());
                Expr v = it->second.plain_counter ? expr(value) : as_typed(value, b->getType());
                const std::string t = it->second.plain_counter ? "int" : type(s->getType(), b);
                const auto across = across_iterations_.find(b);
                const std::string v_text = across == across_iterations_.end() ? v.text : across->second + parens(v, kAssign);
                line(t + " " + it->second.name + " = " + v_text + ";", b);
                return;
            }
        }
        assign_to(target, as_typed(value, b->getType()).text, b);
        return;
    }
    const char* o = nullptr;
    switch (op) {
        case glslang::EOpAddAssign: o = "+"; break;
        case glslang::EOpSubAssign: o = "-"; break;
        case glslang::EOpMulAssign: case glslang::EOpVectorTimesScalarAssign: case glslang::EOpVectorTimesMatrixAssign:
        case glslang::EOpMatrixTimesScalarAssign: case glslang::EOpMatrixTimesMatrixAssign: o = "*"; break;
        case glslang::EOpDivAssign: o = "/"; break;
        case glslang::EOpModAssign: o = "%"; break;
        case glslang::EOpAndAssign: o = "&"; break;
        case glslang::EOpInclusiveOrAssign: o = "|"; break;
        case glslang::EOpExclusiveOrAssign: o = "^"; break;
        case glslang::EOpLeftShiftAssign: o = "<<"; break;
        case glslang::EOpRightShiftAssign: o = ">>"; break;
        default: refuse(b, "this assignment");
    }
    Expr r = expr(value);
    if (r.plain && value->getType().getBasicType() != glslang::EbtFloat) r = as_typed(value, value->getType());
    const std::string lv = lvalue(target);
    const bool widened = !target->getType().isScalar() && value->getType().isScalar();
    if (masked_target(target) || widened) {
        assign_to(target, (lv.back() == ')' ? type(target->getType(), b) + "(" + lv + ")" : lv) + " " + o + " " +
                              parens(r, kMultiplicative + 1), b);
    } else {
        line(lv + " " + o + "= " + r.text + ";", b);
    }
}

void StageWriter::block(TIntermNode* n) {
    ++indent_;
    if (n) {
        write_zeroes(n);
        auto* a = n->getAsAggregate();
        if (a && a->getOp() == glslang::EOpSequence && !is_for_sequence(a)) {
            for (TIntermNode* s : statements_of(a)) statement(s);
        } else {
            statement(n);
        }
    }
    --indent_;
}

void StageWriter::if_statement(glslang::TIntermSelection* s) {
    Expr c = expr(s->getCondition());
    if (c.plain) {
        line("if (" + c.text + ") {", s);
        block(s->getTrueBlock());
        if (s->getFalseBlock()) {
            line("} else {", nullptr);
            block(s->getFalseBlock());
        }
        line("}", nullptr);
        return;
    }
    // `if (c) break;` and the like: one call with the condition.
    TIntermNode* only = s->getTrueBlock();
    if (auto* a = only ? only->getAsAggregate() : nullptr; a && a->getOp() == glslang::EOpSequence && a->getSequence().size() == 1) {
        only = a->getSequence()[0];
    }
    if (auto* br = only ? only->getAsBranchNode() : nullptr; br && !s->getFalseBlock()) {
        masks_.push_back(and_mask(parens(c, kAnd + 1)));
        branch(br);
        masks_.pop_back();
        return;
    }
    // A condition that varies per fragment: both sides run, each write keeps the lanes of the other.
    // The condition is taken once, before either side writes what it reads.
    const std::string name = fresh("if");
    line("const Bool<F> " + name + " = " + and_mask(parens(c, kAnd + 1)) + ";  // if", s);
    line("{", nullptr);
    masks_.push_back(name);
    block(s->getTrueBlock());
    masks_.pop_back();
    line("}", nullptr);
    if (s->getFalseBlock()) {
        const std::string other = fresh("else");
        line("const Bool<F> " + other + " = " + and_mask("!" + name) + ";  // else", nullptr);
        line("{", nullptr);
        masks_.push_back(other);
        block(s->getFalseBlock());
        masks_.pop_back();
        line("}", nullptr);
    }
}

void StageWriter::branch(glslang::TIntermBranch* b) {
    switch (b->getFlowOp()) {
        case glslang::EOpKill:
            if (stage_ != Stage::Fragment) refuse(b, "discard outside a fragment shader");
            discards_ = true;
            if (!loops_.empty()) line(loops_.back().name + ".discard_if(out, " + (masks_.empty() ? "Bool<F>(true)" : mask()) + ");", b);
            else line("out.discard_if(" + (masks_.empty() ? "Bool<F>(true)" : mask()) + ");", b);
            return;
        case glslang::EOpBreak:
            if (loops_.empty()) refuse(b, "break outside a loop");
            line(loops_.back().name + ".break_if(" + (masks_.size() > std::size_t(loops_.back().mask_depth) ? mask() : "Bool<F>(true)") + ");", b);
            return;
        case glslang::EOpContinue:
            if (loops_.empty()) refuse(b, "continue outside a loop");
            line(loops_.back().name + ".continue_if(" + (masks_.size() > std::size_t(loops_.back().mask_depth) ? mask() : "Bool<F>(true)") + ");", b);
            return;
        case glslang::EOpReturn: {
            std::string v;
            if (b->getExpression()) v = as_typed(b->getExpression(), b->getExpression()->getType()).text;
            if (masks_.empty() && loops_.empty()) {
                if (uses_return_) line("return ret.value_or(" + v + ");", b);
                else line(v.empty() ? "return;" : "return " + v + ";", b);
                return;
            }
            if (v.empty()) refuse(b, "a return from a void function under a condition");
            uses_return_ = true;
            if (!loops_.empty()) line(loops_.back().name + ".return_if(ret, " + (masks_.empty() ? "Bool<F>(true)" : mask()) + ", " + v + ");", b);
            else line("ret.return_if(" + mask() + ", " + v + ");", b);
            return;
        }
        default: refuse(b, "this branch");
    }
}

// Symbols of locals declared outside `body` that `body` assigns.
std::vector<long long> StageWriter::assigned_outside(TIntermNode* body) {
    std::vector<long long> ids;
    for_each_write(body, [&](long long id, glslang::TIntermTyped*) { ids.push_back(id); });
    std::vector<long long> out;
    for (long long id : ids) {
        auto it = locals_.find(id);
        if (it == locals_.end()) {
            if (!globals_.contains(id)) continue;
        } else if (!it->second.declared) {
            continue;
        }
        if (std::find(out.begin(), out.end(), id) == out.end()) out.push_back(id);
    }
    return out;
}

// Whether the variable `symbol` is written before anything could read it: its one use in the
// shader (`code`: the functions and global initialisers) is the left side of a plain assignment
// among main's top-level statements, and no statement before that one returns from main. Then
// the colour needs no zero for the lanes GLSL leaves it unwritten for: there are none.
static bool written_first(const std::vector<TIntermNode*>& code, TIntermAggregate* main, long long symbol) {
    struct Uses : glslang::TIntermTraverser {
        long long symbol = -1;
        int count = 0;
        void visitSymbol(TIntermSymbol* s) override { count += s->getId() == symbol; }
    } uses;
    uses.symbol = symbol;
    for (TIntermNode* n : code) n->traverse(&uses);
    if (uses.count != 1) return false;
    struct Returns : glslang::TIntermTraverser {
        bool found = false;
        bool visitBranch(glslang::TVisit, glslang::TIntermBranch* b) override {
            found = found || b->getFlowOp() == glslang::EOpReturn;
            return true;
        }
    };
    const glslang::TIntermSequence& parts = main->getSequence();
    TIntermAggregate* body = parts.size() > 1 && parts[1] ? parts[1]->getAsAggregate() : nullptr;
    if (!body || body->getOp() != glslang::EOpSequence) return false;
    for (TIntermNode* n : body->getSequence()) {
        if (!n) continue;
        const glslang::TIntermBinary* b = n->getAsBinaryNode();
        const TIntermSymbol* left = b && b->getOp() == glslang::EOpAssign ? b->getLeft()->getAsSymbolNode() : nullptr;
        if (left && left->getId() == symbol) return true;
        Returns r;
        n->traverse(&r);
        if (r.found) return false;
    }
    return false;
}

// Whether a lane can leave `l` before its condition ends it, or pause in it: a break or continue
// of its own, or a return or discard anywhere in it.
static bool lanes_may_leave(glslang::TIntermLoop* l) {
    struct Finder : glslang::TIntermTraverser {
        Finder() : glslang::TIntermTraverser(true, false, true) {}
        int depth = 0;  // loops inside l
        bool found = false;
        bool visitBranch(glslang::TVisit, glslang::TIntermBranch* b) override {
            const glslang::TOperator op = b->getFlowOp();
            found = found || op == glslang::EOpReturn || op == glslang::EOpKill ||
                    (depth == 0 && (op == glslang::EOpBreak || op == glslang::EOpContinue));
            return true;
        }
        bool visitLoop(glslang::TVisit visit, glslang::TIntermLoop*) override {
            depth += visit == glslang::EvPreVisit ? 1 : -1;
            return true;
        }
    } f;
    if (l->getBody()) l->getBody()->traverse(&f);
    return f.found;
}

// The C++ of a for loop's step `x op= v`, or null for another step.
static const char* step_operator(glslang::TOperator op) {
    switch (op) {
        case glslang::EOpAddAssign: return " += ";
        case glslang::EOpSubAssign: return " -= ";
        case glslang::EOpMulAssign: return " *= ";
        case glslang::EOpDivAssign: return " /= ";
        default: return nullptr;
    }
}

void StageWriter::loop(glslang::TIntermLoop* l, TIntermNode* init) {
    std::optional<IterationSlice> slice;
    // The vertex stage runs one vertex at a time, in float: no lanes to run iterations in.
    if (init && stage_ == Stage::Fragment && !inner_levels_.contains(l)) {
        const auto plain = [&](long long id) { return locals_.contains(id) && locals_[id].plain_counter; };
        const auto at_nest = [&](long long id) {
            auto it = locals_.find(id);
            if (it == locals_.end() || !it->second.declared) return LocalAtNest::Other;
            return it->second.plain_counter ? LocalAtNest::PlainCounter : LocalAtNest::DeclaredBefore;
        };
        slice = iteration_slice(l, init->getAsBinaryNode(), ast_.getTreeRoot()->getAsAggregate(), plain, at_nest);
        if (slice && !names_apart(*slice)) slice.reset();
        if (slice) {
            iteration_lanes(*slice);
            inner_levels_.insert(slice->loops.begin() + 1, slice->loops.end());
        }
    }
    const std::vector<long long> vars = assigned_outside(l);
    std::string list;
    for (long long id : vars) {
        const std::string n = locals_.contains(id) ? locals_[id].name : globals_[id];
        if (locals_.contains(id) && locals_[id].plain_counter) continue;
        list += ", " + n;
    }
    std::string init_text;
    const Local* counter = nullptr;  // the one the initialiser declares
    if (init) {
        auto* b = init->getAsBinaryNode();
        auto* s = b ? b->getLeft()->getAsSymbolNode() : nullptr;
        if (!s || !locals_.contains(s->getId())) refuse(init, "this loop initialiser");
        Local& lo = locals_[s->getId()];
        counter = &lo;
        lo.declared = true;
        lo.mask_depth = int(masks_.size());
        Expr v = lo.plain_counter ? expr(b->getRight()) : as_typed(b->getRight(), b->getType());
        init_text = (lo.plain_counter ? "int" : type(s->getType(), b)) + " " + lo.name + " = " + v.text;
    }
    Expr c = l->getTest() ? expr(l->getTest()) : Expr{"true", kPrimary, true};
    // A loop every lane runs the same number of times is a C++ loop, as a person writes it: its
    // condition is the same for every lane and no lane leaves or pauses it on its own.
    const bool plain = c.plain && !lanes_may_leave(l);
    std::string name;
    if (!plain && counter && !counter->plain_counter) {
        // A counter of its own per lane is declared before the Loop, which holds it: the step
        // runs on for the lanes that have left.
        line(init_text + ";", l);
        list += ", " + counter->name;
        init_text.clear();
    }
    if (!plain) {
        // Each Loop of a function has its own name: loop, loop2, ...
        name = ++loops_in_function_ == 1 ? "loop" : "loop" + std::to_string(loops_in_function_);
        std::string head;
        if (!loops_.empty()) head = "Loop " + name + "(" + loops_.back().name + list + ");";
        else if (!masks_.empty()) head = "Loop " + name + "(inside(" + mask() + ")" + list + ");";
        else head = "Loop " + name + "(" + (list.empty() ? "" : list.substr(2)) + ");";
        if (list.empty() && loops_.empty() && masks_.empty()) head = "Loop<Bool<F>> " + name + ";";
        line(head + "  // the variables the loop assigns", nullptr);
    }
    const std::string test = plain ? c.text : name + "(" + c.text + ")";
    std::string step;
    if (TIntermTyped* t = l->getTerminal()) {
        if (auto* u = t->getAsUnaryNode(); u && u->getOp() >= glslang::EOpPostIncrement && u->getOp() <= glslang::EOpPreDecrement) {
            const bool inc = u->getOp() == glslang::EOpPostIncrement || u->getOp() == glslang::EOpPreIncrement;
            auto* sym = u->getOperand()->getAsSymbolNode();
            const bool plain_counter = sym && locals_.contains(sym->getId()) && locals_[sym->getId()].plain_counter;
            const glslang::TBasicType bt = u->getOperand()->getType().getBasicType();
            const std::string one = bt == glslang::EbtFloat ? "1.0f" : scalar_type(bt, u) + "(1)";
            step = plain_counter ? lvalue(u->getOperand()) + (inc ? "++" : "--") : lvalue(u->getOperand()) + (inc ? " += " : " -= ") + one;
        } else if (auto* b = t->getAsBinaryNode(); b && b->getLeft()->getType().isScalar() && step_operator(b->getOp())) {
            Expr r = expr(b->getRight());
            auto* sym = b->getLeft()->getAsSymbolNode();
            const bool plain_counter = sym && locals_.contains(sym->getId()) && locals_[sym->getId()].plain_counter;
            if (r.plain && b->getRight()->getType().getBasicType() != glslang::EbtFloat && !plain_counter) {
                r = as_typed(b->getRight(), b->getRight()->getType());
            }
            step = lvalue(b->getLeft()) + step_operator(b->getOp()) + r.text;
        } else {
            refuse(t, "this loop step");
        }
    }
    const bool has_continue = [&] {
        struct Finder : glslang::TIntermTraverser {
            bool found = false;
            bool visitBranch(glslang::TVisit, glslang::TIntermBranch* b) override {
                found = found || b->getFlowOp() == glslang::EOpContinue;
                return true;
            }
            bool visitLoop(glslang::TVisit, glslang::TIntermLoop*) override { return false; }
        } f;
        if (l->getBody()) l->getBody()->traverse(&f);
        return f.found;
    }();
    if (has_continue && !step.empty()) step = name + ".next(), " + step;
    if (!plain) loops_.push_back({name, int(masks_.size())});
    if (!l->testFirst()) {
        if (c.plain && c.text == "true") refuse(l, "a do loop without a condition");
        line("do {", l);
        block(l->getBody());
        line("} while (" + test + ");", nullptr);
    } else if (init || !step.empty()) {
        line("for (" + init_text + "; " + test + "; " + step + ") {", l);
        block(l->getBody());
        line("}", nullptr);
    } else {
        line("while (" + (plain || c.text != "true" ? test : name + "()") + ") {", l);
        block(l->getBody());
        line("}", nullptr);
    }
    if (!plain) loops_.pop_back();
}

// Before the nest: the part's declarations for every iteration at once, where the values they
// read are alike in every lane; in the nest, each declaration reads its iteration's lane there.
void StageWriter::iteration_lanes(const IterationSlice& slice) {
    const std::string each = unused_name("each");
    std::string counts, firsts, counters, at;
    for (std::size_t k = 0; k < slice.counters.size(); ++k) {
        const std::string& c = locals_[slice.counters[k]->getId()].name;
        counts += ", " + std::to_string(slice.count[k]);
        firsts += (k ? ", " : "") + std::to_string(slice.first[k]);
        counters += (k ? ", " : "") + c + " = " + each + ".counter(" + std::to_string(k) + ")";
        at += ", " + c;
    }
    std::string inputs;
    for (std::size_t k = 0; k < slice.inputs.size(); ++k) {
        inputs += (k == 0 ? "" : k + 1 == slice.inputs.size() ? " and " : ", ") + locals_[slice.inputs[k]].name;
    }
    int iterations = 1;
    for (int n : slice.count) iterations *= n;
    int first_line = slice.declarations.front()->getLoc().line, last_line = first_line;
    for (TIntermBinary* d : slice.declarations) {
        first_line = std::min(first_line, d->getLoc().line);
        last_line = std::max(last_line, d->getLoc().line);
    }
    const std::string lines = first_line == last_line ? "line " + std::to_string(first_line)
                                                      : "lines " + std::to_string(first_line) + "-" + std::to_string(last_line);
    const bool one = first_line == last_line;
    const std::string all = std::string(one ? " runs" : " run") + " here for all " + std::to_string(iterations) + " iterations at once,";
    if (slice.inputs.empty()) line("// " + lines + (one ? " reads the loop counters alone: it" : " read the loop counters alone: they") + all, nullptr);
    else line("// Where " + inputs + (slice.inputs.size() == 1 ? " is" : " are") + " the same in every lane, " + lines + all, nullptr);
    line("// one in each lane (shading/glsl/iteration_lanes.h).", nullptr);
    std::string alike;
    for (std::size_t k = 0; k < slice.inputs.size(); ++k) alike += (k ? ", " : "") + locals_[slice.inputs[k]].name;
    line("const IterationLanes<F" + counts + "> " + each + "({" + firsts + "}, lanes_alike(" + alike + "));", nullptr);
    // What each iteration computed, declared a type to a line.
    std::vector<std::string> holders;
    std::string declared, declared_type;
    for (TIntermBinary* d : slice.declarations) {
        const Local& lo = locals_[d->getLeft()->getAsSymbolNode()->getId()];
        holders.push_back(unused_name(lo.name + "_" + each));
        across_iterations_[d] = each + ".alike ? " + each + ".at(" + holders.back() + at + ") : ";
        const std::string t = type(d->getType(), d);
        if (t != declared_type && !declared.empty()) line(declared + ";", nullptr), declared.clear();
        declared += (declared.empty() ? t + " " : ", ") + holders.back() + "{}";
        declared_type = t;
    }
    line(declared + ";", nullptr);
    line("if (" + each + ".alike) {", nullptr);
    ++indent_;
    // The counters, each iteration's in its lane: per-lane ints for the part's expressions.
    for (TIntermSymbol* c : slice.counters) locals_[c->getId()].plain_counter = false;
    line("const int_t<F> " + counters + ";", nullptr);
    for (TIntermBinary* d : slice.declarations) {
        const Local& lo = locals_[d->getLeft()->getAsSymbolNode()->getId()];
        line("const " + type(d->getType(), d) + " " + lo.name + " = " + as_typed(d->getRight(), d->getType()).text + ";", d);
    }
    for (TIntermSymbol* c : slice.counters) locals_[c->getId()].plain_counter = true;
    for (std::size_t k = 0; k < slice.declarations.size(); ++k) {
        line(holders[k] + " = " + locals_[slice.declarations[k]->getLeft()->getAsSymbolNode()->getId()].name + ";", nullptr);
    }
    --indent_;
    line("}", nullptr);
}

// Whether the part's counters, the values it reads and the names it declares are all different
// names in C++: its copy before the nest declares the counters and its names in one scope, and
// GLSL may reuse a name in an inner one (an inner loop's counter, a local named as a counter).
bool StageWriter::names_apart(const IterationSlice& slice) {
    std::set<std::string> names;
    for (TIntermSymbol* c : slice.counters) {
        if (!names.insert(locals_[c->getId()].name).second) return false;
    }
    for (long long id : slice.inputs) {
        if (!names.insert(locals_[id].name).second) return false;
    }
    for (TIntermBinary* d : slice.declarations) {
        if (!names.insert(locals_[d->getLeft()->getAsSymbolNode()->getId()].name).second) return false;
    }
    return true;
}

// `base`, or base2, base3, ...: a name neither the GLSL nor the writer has taken.
std::string StageWriter::unused_name(const std::string& base) {
    std::string name = base;
    for (int k = 2; taken_names_.contains(name) || reserved_names().contains(name); ++k) name = base + std::to_string(k);
    taken_names_.insert(name);
    return name;
}

void StageWriter::statement(TIntermNode* n) {
    if (!n) return;
    if (auto* a = n->getAsAggregate()) {
        if (is_declaration(a)) {
            for (TIntermNode* d : a->getSequence()) statement(d);
            return;
        }
        if (a->getOp() == glslang::EOpSequence) {
            // A for loop's initialiser and the loop, as glslang nests them.
            if (is_for_sequence(a)) {
                const std::vector<TIntermNode*> s = statements_of(a);
                auto* sym = s[0]->getAsBinaryNode()->getLeft()->getAsSymbolNode();
                if (sym && locals_.contains(sym->getId()) && locals_[sym->getId()].declaring == s[0]) {
                    loop(s[1]->getAsLoopNode(), s[0]);
                    return;
                }
                // An initialiser that declares nothing (`for (i = 0; ...)`): an assignment before the loop.
                statement(s[0]);
                loop(s[1]->getAsLoopNode(), nullptr);
                return;
            }
            line("{", nullptr);
            block(a);
            line("}", nullptr);
            return;
        }
        if (a->getOp() == glslang::EOpFunctionCall || a->getOp() < glslang::EOpConstructGuardStart) {
            const Expr e = expr(a);
            line(e.text + ";", a);
            return;
        }
        refuse(n, "this statement");
    }
    if (auto* b = n->getAsBinaryNode()) {
        if (is_assignment(b->getOp())) return assignment(b);
        refuse(n, "an expression statement with no effect");
    }
    if (auto* u = n->getAsUnaryNode()) {
        const TOperator op = u->getOp();
        if (op >= glslang::EOpPostIncrement && op <= glslang::EOpPreDecrement) {
            const bool inc = op == glslang::EOpPostIncrement || op == glslang::EOpPreIncrement;
            TIntermTyped* t = u->getOperand();
            const std::string lv = lvalue(t);
            const std::string one = t->getType().getBasicType() == glslang::EbtFloat ? "1.0f" : scalar_type(t->getType().getBasicType(), u) + "(1)";
            if (masked_target(t)) assign_to(t, lv + (inc ? " + " : " - ") + one, u);
            else line(lv + (inc ? " += " : " -= ") + one + ";", u);
            return;
        }
        refuse(n, "an expression statement with no effect");
    }
    if (auto* s = n->getAsSelectionNode()) return if_statement(s);
    if (auto* l = n->getAsLoopNode()) return loop(l, nullptr);
    if (auto* b = n->getAsBranchNode()) return branch(b);
    if (n->getAsSwitchNode()) refuse(n, "switch");
    if (n->getAsSymbolNode() || n->getAsConstantUnion()) return;  // a declaration glslang kept as its symbol
    refuse(n, "this statement");
}

// The locals of a function: named, and declared in the innermost block holding every use, by
// their first assignment where that is a statement of that block, else zeroed before the first
// statement that uses them (GLSL leaves them undefined; the interpreter zeroes them).
void StageWriter::declare_locals(TIntermNode* body) {
    struct Finder : glslang::TIntermTraverser {
        std::map<long long, std::vector<TIntermNode*>> path;  // the common blocks of every use
        std::map<long long, TIntermSymbol*> symbol;
        std::map<long long, TIntermNode*> first_statement;  // in the common block
        std::vector<TIntermNode*> blocks;
        Finder() : glslang::TIntermTraverser(true, false, true) {}
        void use(TIntermSymbol* s) {
            const long long id = s->getId();
            if (!path.contains(id)) {
                path[id] = blocks;
                symbol[id] = s;
            } else {
                std::vector<TIntermNode*>& p = path[id];
                std::size_t k = 0;
                while (k < p.size() && k < blocks.size() && p[k] == blocks[k]) ++k;
                p.resize(k);
            }
        }
        void visitSymbol(TIntermSymbol* s) override {
            const glslang::TStorageQualifier q = s->getQualifier().storage;
            if (q == glslang::EvqTemporary) use(s);
        }
        bool visitAggregate(glslang::TVisit v, TIntermAggregate* a) override {
            if (a->getOp() == glslang::EOpSequence && !is_declaration(a)) {
                if (v == glslang::EvPreVisit) blocks.push_back(a);
                else if (v == glslang::EvPostVisit) blocks.pop_back();
            }
            return true;
        }
    } f;
    body->traverse(&f);
    for (auto& [id, p] : f.path) {
        if (locals_.contains(id)) continue;  // a parameter
        TIntermSymbol* s = f.symbol[id];
        Local l;
        l.name = cpp_identifier(s->getName().c_str(), where(s));
        TIntermNode* block = p.empty() ? body : p.back();
        auto* agg = block->getAsAggregate();
        // The statement of the block that first uses it.
        if (agg) {
            for (TIntermNode* st : statements_of(agg)) {
                struct Uses : glslang::TIntermTraverser {
                    long long id;
                    bool found = false;
                    void visitSymbol(TIntermSymbol* s) override { found = found || s->getId() == id; }
                } u;
                u.id = id;
                st->traverse(&u);
                if (!u.found) continue;
                auto* b = st->getAsBinaryNode();
                if (b && b->getOp() == glslang::EOpAssign && b->getLeft()->getAsSymbolNode() &&
                    b->getLeft()->getAsSymbolNode()->getId() == id) {
                    Uses r;
                    r.id = id;
                    b->getRight()->traverse(&r);
                    if (!r.found) l.declaring = b;
                }
                break;
            }
        }
        if (l.declaring && is_for_sequence(agg) && statements_of(agg)[0] == l.declaring) {
            l.plain_counter = plain_counter(agg, id);
        }
        // `vec2 c = c + d;` reads the c of an enclosing scope, where C++'s would read itself: the
        // inner one takes another name.
        if (l.declaring) {
            struct Reads : glslang::TIntermTraverser {
                long long id;
                std::string name;
                bool found = false;
                void visitSymbol(TIntermSymbol* s) override {
                    found = found || (s->getId() != id && s->getName().c_str() == name);
                }
            } r;
            r.id = id;
            r.name = s->getName().c_str();
            l.declaring->getAsBinaryNode()->getRight()->traverse(&r);
            if (r.found) l.name = unused_name(l.name + "_");
        }
        l.declared = false;
        locals_[id] = l;
        if (!l.declaring) {
            // zeroed where its block begins
            pending_zero_[block].push_back(id);
            zero_symbols_[id] = s;
        }
    }
}

// A for loop's counter the same for every fragment, kept a C++ int: an int from a constant,
// tested against a constant, stepped by a constant, and written nowhere else.
bool StageWriter::plain_counter(TIntermAggregate* seq, long long id) {
    const std::vector<TIntermNode*> parts = statements_of(seq);
    auto* init = parts[0]->getAsBinaryNode();
    glslang::TIntermLoop* lp = parts[1]->getAsLoopNode();
    const TType& t = init->getLeft()->getType();
    if (t.getBasicType() != glslang::EbtInt || !t.isScalar() || !init->getRight()->getAsConstantUnion() || !lp->testFirst()) {
        return false;
    }
    // Written in the body, or handed to a function (whose parameter is a per-lane int): not plain.
    bool written = false;
    for_each_write(lp->getBody(), [&](long long written_id, glslang::TIntermTyped*) { written = written || written_id == id; });
    struct Arguments : glslang::TIntermTraverser {
        long long id;
        bool found = false;
        bool visitAggregate(glslang::TVisit, TIntermAggregate* a) override {
            if (a->getOp() != glslang::EOpFunctionCall) return true;
            for (TIntermNode* x : a->getSequence()) {
                TIntermTyped* arg = x->getAsTyped();
                while (auto* b = arg->getAsBinaryNode()) arg = b->getLeft();
                found = found || (arg->getAsSymbolNode() && arg->getAsSymbolNode()->getId() == id);
            }
            return true;
        }
    } w;
    w.id = id;
    if (lp->getBody()) lp->getBody()->traverse(&w);
    if (written || w.found) return false;

    TIntermTyped* step = lp->getTerminal();
    if (!step) return false;
    if (auto* b = step->getAsBinaryNode(); b && !b->getRight()->getAsConstantUnion()) return false;
    auto* test = lp->getTest() ? lp->getTest()->getAsBinaryNode() : nullptr;
    return test && test->getRight()->getAsConstantUnion() && test->getLeft()->getAsSymbolNode() &&
           test->getLeft()->getAsSymbolNode()->getId() == id;
}

void StageWriter::write_zeroes(TIntermNode* block) {
    auto it = pending_zero_.find(block);
    if (it == pending_zero_.end()) return;
    for (long long id : it->second) {
        Local& l = locals_[id];
        l.declared = true;
        l.mask_depth = int(masks_.size());
        // the interpreter's value for what GLSL leaves undefined
        TIntermSymbol* s = zero_symbols_[id];
        line(type(s->getType(), s) + " " + l.name + "{};", nullptr);
    }
}

void StageWriter::function(TIntermAggregate* f) {
    locals_.clear();
    masks_.clear();
    loops_.clear();
    loops_in_function_ = 0;
    uses_return_ = false;
    pending_zero_.clear();
    const std::string mangled = f->getName().c_str();
    const std::string glsl_name = mangled.substr(0, mangled.find('('));
    const bool is_main = glsl_name == "main";
    const std::string name = is_main ? "main" : cpp_identifier(glsl_name, where(f));
    const glslang::TIntermSequence& parts = f->getSequence();
    std::string params;
    if (!parts.empty() && parts[0]) {
        for (TIntermNode* p : parts[0]->getAsAggregate()->getSequence()) {
            TIntermSymbol* s = p->getAsSymbolNode();
            if (!s) continue;
            const glslang::TStorageQualifier q = s->getQualifier().storage;
            Local l;
            l.name = s->getName().empty() ? fresh("unnamed") : cpp_identifier(s->getName().c_str(), where(s));
            l.declared = true;
            locals_[s->getId()] = l;
            const bool ref = q == glslang::EvqOut || q == glslang::EvqInOut;
            const std::string t = s->getType().getBasicType() == glslang::EbtSampler ? "const " + sampler_type(s->getType(), s) + "&"
                                  : ref ? type(s->getType(), s) + "&"
                                        : type(s->getType(), s);
            params += (params.empty() ? "" : ", ") + t + " " + l.name;
        }
    }
    return_type_ = type(f->getType(), f);
    TIntermNode* body = parts.size() > 1 ? parts[1] : nullptr;
    if (body && body->getAsAggregate()) declare_locals(body);
    body_.str("");
    indent_ = 2;
    if (body) {
        auto* a = body->getAsAggregate();
        write_zeroes(body);
        if (a && a->getOp() == glslang::EOpSequence) {
            for (TIntermNode* s : statements_of(a)) statement(s);
        } else {
            statement(body);
        }
    }
    std::string text = body_.str();
    std::string head = "    " + return_type_ + " " + name + "(" + params + ") {  // " + std::to_string(f->getLoc().line) + "\n";
    if (uses_return_) head += "        Return<" + return_type_ + "> ret;  // the value of the fragments that returned early\n";
    if (uses_return_ && f->getType().getBasicType() != glslang::EbtVoid) {
        // falls off the end only where GLSL leaves the value undefined
        const std::string tail = "return ret.value_or";
        if (text.find(tail) == std::string::npos) text += "        return ret.value_or(" + return_type_ + "{});\n";
    }
    functions_text_ += head + text + "    }\n";
}

// The struct types the stage uses, inner ones first.
void collect_structs(const TType& t, std::vector<const TType*>& out, std::set<std::string>& seen) {
    if (!t.isStruct() || is_per_vertex_block(t)) return;
    for (const glslang::TTypeLoc& m : *t.getStruct()) collect_structs(*m.type, out, seen);
    const std::string name = t.getTypeName().c_str();
    if (seen.insert(name).second) out.push_back(&t);
}

std::string StageWriter::write() {
    TIntermAggregate* root = ast_.getTreeRoot() ? ast_.getTreeRoot()->getAsAggregate() : nullptr;
    if (!root) throw GlslError(source_position(file_, 0) + "error: the shader has no code");
    exact_.emplace(root);
    struct Names : glslang::TIntermTraverser {
        std::set<std::string>* taken;
        void visitSymbol(TIntermSymbol* s) override {
            const std::string n = s->getName().c_str();
            taken->insert(n);
            taken->insert(n + "_");  // its name where C++ or the translation reserves it
        }
    } names;
    names.taken = &taken_names_;
    root->traverse(&names);
    for (TIntermNode* n : root->getSequence()) {
        TIntermAggregate* a = n->getAsAggregate();
        if (!a || a->getOp() != glslang::EOpFunction) continue;
        const std::string mangled = a->getName().c_str();
        taken_names_.insert(mangled.substr(0, mangled.find('(')));
        taken_names_.insert(mangled.substr(0, mangled.find('(')) + "_");
    }
    // Struct types first: members and functions use them.
    std::vector<const TType*> structs;
    std::set<std::string> seen;
    struct Types : glslang::TIntermTraverser {
        std::vector<const TType*>* out;
        std::set<std::string>* seen;
        void visitSymbol(TIntermSymbol* s) override { collect_structs(s->getType(), *out, *seen); }
    } types;
    types.out = &structs;
    types.seen = &seen;
    root->traverse(&types);
    std::string struct_text;
    for (const TType* t : structs) {
        taken_names_.insert(t->getTypeName().c_str());
        taken_names_.insert(std::string(t->getTypeName().c_str()) + "_");
        struct_text += "    struct " + cpp_identifier(t->getTypeName().c_str(), file_ + ": ") + " {\n";
        for (const glslang::TTypeLoc& m : *t->getStruct()) {
            struct_text += "        " + type(*m.type, nullptr) + " " + cpp_identifier(m.type->getFieldName().c_str(), file_ + ": ") + "{};\n";
        }
        struct_text += "    };\n";
    }
    // The code outside functions (globals' initialisers) runs first, as main()'s first statements.
    TIntermAggregate* main = nullptr;
    std::string globals;
    std::vector<TIntermNode*> code;  // functions and initialisers, without the linker's list of objects
    for (TIntermNode* n : root->getSequence()) {
        TIntermAggregate* a = n->getAsAggregate();
        if (!a || a->getOp() != glslang::EOpLinkerObjects) code.push_back(n);
        if (a && a->getOp() == glslang::EOpFunction) {
            if (std::string(a->getName().c_str()) == "main(") {
                main = a;
            } else {
                function(a);
            }
        } else if (a && a->getOp() == glslang::EOpLinkerObjects) {
            continue;
        } else {
            locals_.clear();
            body_.str("");
            indent_ = 2;
            statement(n);
            globals += body_.str();
        }
    }
    if (!main) throw GlslError(source_position(file_, 0) + "error: the shader has no main()");
    const std::size_t before = functions_text_.size();
    function(main);
    color_written_first_ = color_symbol_ >= 0 && written_first(code, main, color_symbol_);
    if (!globals.empty()) {
        const std::size_t open = functions_text_.find('\n', before);
        functions_text_.insert(open + 1, globals);
    }
    std::string members;
    for (const std::string& m : member_lines_) members += "    " + m + "\n";
    return struct_text + members + "\n" + functions_text_;
}

// A string literal holding `s`, with everything outside printable ASCII, and quotes and
// backslashes, replaced.
std::string string_literal(const std::string& s) {
    std::string out = "\"";
    for (char c : s) out += (c >= 0x20 && c < 0x7F && c != '"' && c != '\\' && c != '?') ? c : '_';
    return out + "\"";
}

const char* uniform_type(const ir::Uniform& u, const std::string& where) {
    if (u.columns > 1) {
        if (u.components == u.columns * u.columns) {
            if (u.columns == 2) return "Mat2";
            if (u.columns == 3) return "Mat3";
            if (u.columns == 4) return "Mat4";
        }
        throw GlslError(where + "uniform '" + u.name + "': non-square matrices cannot be set as uniforms here");
    }
    if (u.bank == ir::Bank::Float) {
        constexpr const char* t[] = {"Float", "Vec2", "Vec3", "Vec4"};
        return t[u.components - 1];
    }
    if (u.bank == ir::Bank::Uint && u.components == 1) return "Uint";
    constexpr const char* t[] = {"Int", "IVec2", "IVec3", "IVec4"};
    return t[u.components - 1];
}

std::string to_camel(const std::string& snake) {
    std::string out;
    bool up = true;
    for (char c : snake) {
        if (c == '_') {
            up = true;
            continue;
        }
        out += up && c >= 'a' && c <= 'z' ? char(c - 'a' + 'A') : c;
        up = false;
    }
    return out.empty() || !((out[0] >= 'A' && out[0] <= 'Z') || (out[0] >= 'a' && out[0] <= 'z')) ? "Shader" + out : out;
}

// The GLSL as the plugin's files hold it: ShaderInfo::glsl_version gives the #version line (the
// export writes it first, shading/glsl_export.h), so the file's own is blanked, its lines kept.
std::string without_version_line(const std::string& text) {
    std::string out;
    std::istringstream in(text);
    std::string line;
    bool first = true;
    while (std::getline(in, line)) {
        std::size_t k = line.find_first_not_of(" \t");
        bool version = false;
        if (k != std::string::npos && line[k] == '#') {
            k = line.find_first_not_of(" \t", k + 1);
            version = k != std::string::npos && line.compare(k, 7, "version") == 0;
        }
        if (!first) out += '\n';
        if (!version) out += line;
        first = false;
    }
    if (!text.empty() && text.back() == '\n') out += "\n";
    return out;
}

// Where a loop of either stage may go round as often as llvmpipe's limit, which C++ loops do
// not keep: its position and a note; empty where every loop stays within it.
std::string unbounded_loop(const ParsedStage& vp, const std::string& vertex_file, const ParsedStage& fp,
                           const std::string& fragment_file) {
    std::string unbounded;
    for (const auto& [stage, file] : {std::pair{&vp, vertex_file}, std::pair{&fp, fragment_file}}) {
        const LoopBound b = loop_bound(*stage->shader->getIntermediate());
        if (!b.within_limit() && unbounded.empty()) {
            const TIntermNode* at = b.unbounded_loop;
            unbounded = source_position(file, at ? at->getLoc().line : 0, at ? at->getLoc().column : 0) +
                        (at ? "this loop may go round" : "the loops may go round") + " 65,535 times";
        }
    }
    return unbounded;
}

// The varyings the fragment stage reads, in the interpreter's order: name and floats.
std::vector<std::pair<std::string, int>> fragment_varyings(const ir::Program& p) {
    std::vector<std::pair<std::string, int>> varyings;
    for (const ir::Varying& v : p.varyings) {
        const std::string base = v.name.substr(0, v.name.find('['));
        if (!varyings.empty() && varyings.back().first == base && v.name.find('[') != std::string::npos) {
            ++varyings.back().second;
        } else {
            varyings.push_back({base, 1});
        }
    }
    return varyings;
}

// The header's opening: what it is, a loop llvmpipe would leave where there is one, its includes.
void write_preamble(std::ostream& h, const std::string& name, const std::string& frag_file, const std::string* vert_file,
                    const std::string& unbounded) {
    h << "#pragma once\n"
      << "// " << comment_text(frag_file) << (vert_file ? " and " + comment_text(*vert_file) : std::string()) << " in C++, statement by statement,\n"
      << "// written by `quadshade translate`: each line ends with its GLSL line. The shader's functions are\n"
      << "// members of a struct that holds what GLSL keeps at global scope (uniforms, inputs, outputs,\n"
      << "// globals), over the number type F. A condition that varies per fragment runs both sides, each\n"
      << "// write keeping the lanes of the other side (select); a loop a lane can leave early is a Loop object\n"
      << "// (shading/glsl/control.h), one every lane runs equally often a C++ loop.\n";
    if (!unbounded.empty()) {
        h << "// " << comment_text(unbounded) << ", where llvmpipe leaves\n"
          << "// a shader's loops and this translation does not: quadshade runs this shader in its interpreter.\n";
    }
    h
      << "#include \"shading/glsl.h\"\n"
      << "#include \"shading/glsl/generated.h\"\n"
      << "#include \"shading/program_of.h\"\n"
      << "#include \"shading/varyings.h\"\n\n"
      << "namespace " << name << " {\n"
      << "using namespace qs;\n"
      << "using namespace qs::glsl;\n\n";
}

// VertexStage: the varyings' struct and the function that runs the vertex shader for one vertex.
void write_vertex_stage(std::ostream& h, const std::string& name, const std::string& fragment_file,
                        const std::vector<std::pair<std::string, int>>& varyings) {
    h << "// What the vertex stage hands the fragment stage, one vertex at a time in float.\n"
      << "struct VertexStage {\n"
      << "    static constexpr GlslFiles glsl{" << string_literal(name + ".vert") << "};  // beside the plugin\n"
      << "    template <class T>\n"
      << "    struct Varyings {\n";
    std::string tie;
    for (const auto& [v, n] : varyings) {
        const std::string cpp = cpp_identifier(v, fragment_file + ": ");
        h << "        " << (n == 1 ? std::string("T") : "vec" + std::to_string(n) + "<T>") << " " << cpp << ";\n";
        tie += (tie.empty() ? "" : ", ") + cpp;
    }
    h << "        auto fields() { return std::tie(" << tie << "); }\n"
      << "    };\n"
      << "    static void vertex(const VertexIn& in, const Uniforms& u, VertexOutputs<VertexStage>& out) {\n"
      << "        VertexShader<float> shader{in, u};\n"
      << "        shader.main();\n";
    for (const auto& [v, n] : varyings) {
        const std::string cpp = cpp_identifier(v, fragment_file + ": ");
        h << "        out." << cpp << " = shader." << cpp << ";\n";
    }
    h << "        const vec4<float>& p = shader.gl_Position;\n"
      << "        out.gl_Position = {p.x, p.y, p.z, p.w};\n"
      << "    }\n"
      << "};\n\n";
}

// The shader's uniforms as UniformDecls, with their initial values.
void write_uniforms(std::ostream& h, const ir::Program& p, const std::string& fragment_file) {
    if (!p.uniforms.empty()) {
        h << "    static constexpr UniformDecl kUniforms[] = {\n";
        for (const ir::Uniform& u : p.uniforms) {
            const char* t = uniform_type(u, fragment_file + ": ");
            h << "        {" << string_literal(u.name) << ", UniformType::" << t << ", {";
            for (int i = 0; i < u.components; ++i) {
                double value = 0.0;
                const std::uint32_t w = u.initial[std::size_t(i)];
                if (u.bank == ir::Bank::Float) value = double(std::bit_cast<float>(w));
                else if (u.bank == ir::Bank::Uint) value = double(w);
                else value = double(std::int32_t(w));
                h << (i ? ", " : "") << float_literal(value);
            }
            h << "}},\n";
        }
        h << "    };\n";
    }
}

// ShaderInfo's fields but the uniforms: what the shader needs, its GLSL beside the plugin.
void write_shader_info(std::ostream& h, const ir::Program& p, const std::string& name, const std::string& shader_name,
                       const std::string& frag_file, const char* coordinates) {
    h << "    static constexpr ShaderInfo info{\n"
      << "        .name = " << string_literal(shader_name.empty() ? name : shader_name) << ",\n"
      << "        .description = " << string_literal("translated from " + frag_file) << ",\n"
      << "        .needs = {.coordinates = Coordinates::" << coordinates
      << ", .derivatives = " << (p.fragment.derivatives ? "true" : "false");
    bool texture = false;
    std::vector<const ir::Sampler*> samplers;
    for (const ir::Sampler& s : p.samplers) {
        if (s.name == "teximage" && s.dims == 2 && !s.shadow) texture = true;
        else samplers.push_back(&s);
    }
    h << ", .texture = " << (texture ? "true" : "false") << ", .time = " << (p.reads_time ? "true" : "false")
      << ", .frag_coord = " << (p.reads_frag_coord ? "true" : "false");
    if (!samplers.empty()) {
        h << ", .samplers = {{";
        for (std::size_t i = 0; i < samplers.size(); ++i) {
            h << (i ? ", " : "") << "{" << string_literal(samplers[i]->name) << ", " << samplers[i]->dims
              << (samplers[i]->shadow ? ", true}" : "}");
        }
        h << "}}";
    }
    h << "},\n"
      << "        .glsl_fragment = {" << string_literal(name + ".frag") << "},  // beside the plugin\n"
      << "        .glsl_version = " << p.version << ",\n";
    if (!p.uniforms.empty()) h << "        .uniforms = kUniforms,\n";
    if (wide_batches_pay(p.fragment)) h << "        .wide_batches = true,  // frontend/batch_width.h\n";
}

// The CMakeLists.txt that builds the translation as a plugin against the installed package.
std::string plugin_cmake(const std::string& name) {
    const std::string glsl_files = name + ".vert " + name + ".frag";
    return "# " + name + " as a plugin, built against the installed quadshade package:\n"
           "#   cmake -S . -B build -DCMAKE_PREFIX_PATH=<quadshade's install prefix> && cmake --build build\n"
           "#   quadshade render SCENE --plugin build/lib" + name + ".so --shader " + name + " -o out.png\n"
           "cmake_minimum_required(VERSION 3.25)\n"
           "project(" + name + " LANGUAGES CXX)\n\n"
           "find_package(quadshade REQUIRED)\n"
           "quadshade_add_shader_plugin(" + name + " SOURCES " + name + ".cpp GLSL " + glsl_files + ")\n";
}

}  // namespace

Translation translate_glsl(const GlslSource& fragment, const std::optional<GlslSource>& vertex, const std::string& name,
                           const std::string& shader_name) {
    if (!is_identifier(name) || name.find("__") != std::string::npos || name[0] == '_') {
        throw GlslError("'" + comment_text(name) + "' cannot name a translation: letters, digits and single underscores, "
                        "a letter first");
    }
    const CompiledProgram compiled = compile_glsl(fragment, vertex);
    const ir::Program& p = compiled.program;
    std::vector<std::string> warnings;
    ParsedStage fp = parse(fragment, EShLangFragment, warnings);
    ParsedStage vp = parse(compiled.vertex, EShLangVertex, warnings);
    StageWriter vw(Stage::Vertex, compiled.vertex.file, *vp.shader->getIntermediate(), p);
    const std::string vertex_body = vw.write();
    StageWriter fw(Stage::Fragment, fragment.file, *fp.shader->getIntermediate(), p);
    const std::string fragment_body = fw.write();
    const std::string unbounded = unbounded_loop(vp, compiled.vertex.file, fp, fragment.file);
    const std::vector<std::pair<std::string, int>> varyings = fragment_varyings(p);
    bool texcoords = false;
    for (ir::Attribute a : p.attributes) texcoords = texcoords || a == ir::Attribute::Texcoord0;
    const char* coordinates = varyings.empty() ? "None" : texcoords ? "Texcoord2D" : "Object3D";

    const std::string struct_name = to_camel(name);
    const std::string frag_file = std::filesystem::path(fragment.file).filename().string();
    const std::string vert_file = vertex ? std::filesystem::path(vertex->file).filename().string() : "";
    std::ostringstream h;
    write_preamble(h, name, frag_file, vertex ? &vert_file : nullptr, unbounded);
    h << "// " << comment_text(std::filesystem::path(compiled.vertex.file).filename().string()) << "\n"
      << "template <class F>\n"
      << "struct VertexShader {\n"
      << "    const VertexIn& in;\n"
      << "    const Uniforms& u;\n"
      << vertex_body << "};\n\n";
    write_vertex_stage(h, name, fragment.file, varyings);
    h << "// " << comment_text(frag_file) << "\n"
      << "template <class F>\n"
      << "struct FragmentShader {\n"
      // The colour zeroed by name, as GLSL's unwritten output reads, unless main writes it before
      // anything could read it; a value-initialised `out` would zero the whole shader struct
      // (padding included) with a memset the compiler cannot drop, and spill the inputs around it.
      << "    FragmentShader(const FragmentIn<F, VertexStage>& in_, const Uniforms& u_)\n"
      << "        : in(in_), u(u_)" << (fw.color_written_first() ? "" : ", out{vec4<F>(F(0.0f))}") << " {}"
      << (fw.color_written_first() ? "  // main() writes the colour first" : "") << "\n"
      << "    const FragmentIn<F, VertexStage>& in;\n"
      << "    const Uniforms& u;\n"
      << "    FragmentOut<F> out;\n"
      << fragment_body << "};\n\n";
    h << "struct " << struct_name << " {\n";
    write_uniforms(h, p, fragment.file);
    write_shader_info(h, p, name, shader_name, frag_file, coordinates);
    h << "    };\n"
      << "    using VertexStage = " << name << "::VertexStage;\n\n"
      << "    template <class F>\n"
      << "    static auto fragment(const FragmentIn<F, VertexStage>& in, const Uniforms& u) {\n"
      << "        FragmentShader<F> shader(in, u);\n"
      << "        shader.main();\n"
      << "        return shader.out" << (fw.discards() ? "" : ".gl_FragColor") << ";\n"
      << "    }\n"
      << "};\n\n"
      << "}  // namespace " << name << "\n";

    Translation t;
    t.name = name;
    t.struct_name = struct_name;
    t.header = h.str();
    t.source = "// The plugin's registration of " + name + ": quadshade render --plugin lib" + name + ".so --shader " + name + "\n" +
               "#include \"" + name + ".h\"\n\n" + "namespace " + name + " {\n\nQUADSHADE_SHADERS(" + struct_name +
               ")\n\n}  // namespace " + name + "\n";
    t.vertex_glsl = without_version_line(compiled.vertex.text);
    t.unbounded_loop = unbounded;
    t.fragment_glsl = without_version_line(fragment.text);
    t.cmake = plugin_cmake(name);
    return t;
}

}  // namespace qs::frontend
