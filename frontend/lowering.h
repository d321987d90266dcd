#pragma once
// Lowering of one stage's glslang AST to the interpreter's code (ir.h). Internal to frontend/,
// like every file that includes glslang.
//
// Values live in Places: one register per scalar component, in GLSL's component order. Swizzles,
// constant indices and struct members select from a Place without code; functions are inlined
// with their parameters copied in and out; divergent control flow becomes the If/Loop/Switch
// markers the interpreter turns into masks; assignments to variables are masked, temporaries are
// not (as llvmpipe masks its stores and computes its SSA values on every lane).

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include <glslang/Include/intermediate.h>
#include <glslang/MachineIndependent/localintermediate.h>

#include "frontend/glsl_error.h"
#include "frontend/ir.h"
#include "frontend/program_interface.h"

namespace qs::frontend {

enum class StageKind { Vertex, Fragment };

struct Slot {
    ir::Bank bank;
    std::uint32_t reg;
    bool operator==(const Slot&) const = default;
};
using Place = std::vector<Slot>;

// What an assignment writes: fixed registers, or (one level of run-time indexing) an element
// picked per lane.
struct LValue {
    Place place;  // the registers written (for an indexed target: those of element 0)
    // Run-time index: the element registers are place[i].reg + index * stride[i], index in
    // [0, count).
    std::optional<std::uint32_t> index;  // int register
    std::vector<std::uint32_t> stride;
    std::uint32_t count = 0;
    Place whole;  // an indexed target: all its registers, to read the current value from
};

class StageLowering {
public:
    StageLowering(StageKind kind, const std::string& file, glslang::TIntermediate& ast, ProgramInterface& interface);
    ir::Stage run();

private:
    // ---- registers -------------------------------------------------------------------------
    // While lowering, a register is numbered within its space (the top bits); run() lays the
    // spaces out: variables, then temporaries, then constants. Constant registers are those no
    // operation writes: literals, and the inputs the interpreter fills before the stage runs.
    enum class Space : std::uint32_t { Variable = 0, Temp = 1u << 30, Constant = 2u << 30 };
    static constexpr std::uint32_t kSpaceMask = 3u << 30;
    std::uint32_t allocate(ir::Bank bank, Space space);
    Place allocate(const glslang::TType& type, Space space);
    Place temps(ir::Bank bank, int n);
    std::uint32_t constant(ir::Bank bank, std::uint32_t bits);
    std::uint32_t float_constant(float v);
    std::uint32_t int_constant(std::int32_t v);
    std::uint32_t bool_constant(bool v);
    // Temporaries are released at the end of each statement.
    struct TempMark {
        std::array<std::uint32_t, ir::kBanks> top;
    };
    TempMark mark() const { return {temp_top_}; }
    void release(const TempMark& m) { temp_top_ = m.top; }

    // ---- emitting --------------------------------------------------------------------------
    ir::Instr& emit(ir::Op op, ir::Bank bank = ir::Bank::Float);
    std::uint32_t emit1(ir::Op op, ir::Bank result, std::uint32_t a, std::uint32_t b = 0, std::uint32_t c = 0,
                        ir::Bank bank = ir::Bank::Float);
    void move(const Slot& to, const Slot& from, bool masked);
    void assign(const Place& to, const Place& from, bool masked = true);
    void store(const LValue& lv, const Place& value);
    // `p` in consecutive registers of one bank (copied to temporaries if it is not).
    std::uint32_t consecutive(const Place& p);
    Place convert(const Place& p, ir::Bank to);
    Slot convert(const Slot& s, ir::Bank to);

    // ---- expressions -----------------------------------------------------------------------
    Place eval(glslang::TIntermTyped* node);
    Place eval_constant(glslang::TIntermConstantUnion* node);
    Place eval_symbol(glslang::TIntermSymbol* node);
    Place eval_binary(glslang::TIntermBinary* node);
    Place eval_unary(glslang::TIntermUnary* node);
    Place eval_aggregate(glslang::TIntermAggregate* node);
    Place eval_selection(glslang::TIntermSelection* node);
    Place eval_constructor(glslang::TIntermAggregate* node);
    Place eval_builtin(glslang::TOperator op, glslang::TIntermTyped* node, const std::vector<glslang::TIntermTyped*>& args,
                       const std::vector<Place>& values);
    Place eval_texture(glslang::TOperator op, glslang::TIntermTyped* node, const std::vector<glslang::TIntermTyped*>& args);
    Place eval_filtered(glslang::TOperator op, glslang::TIntermTyped* node, int slot, int dims,
                        const std::vector<Place>& v, const Place& zero);
    Place emit_lookup(ir::Op o, int slot, int dims, const Place& coords, const Place* extra, const Place* ddx = nullptr,
                      const Place* ddy = nullptr, const Place* offset = nullptr);
    Place project(const Place& p, int count);
    Place eval_texel_fetch(glslang::TOperator op, int slot, int dims, const std::vector<Place>& v);
    Place eval_texture_size(int slot, int dims, const std::vector<Place>& v);
    Place eval_query_lod(glslang::TIntermTyped* node, int slot, int dims, const std::vector<Place>& v);
    Place eval_gather(glslang::TOperator op, glslang::TIntermTyped* node, int slot,
                      const std::vector<glslang::TIntermTyped*>& args, const std::vector<Place>& v);
    Place emit_gather(int slot, const Place& p, const Place* ref, const Place* offset, int comp);
    Place eval_cube(glslang::TOperator op, glslang::TIntermTyped* node, int slot, const std::vector<glslang::TIntermTyped*>& args,
                    const std::vector<Place>& v);
    // a * b where a has `columns` columns (or is a vector) of `rows` rows, and b `columns_b`.
    struct Shape {
        int columns, rows;
    };
    static Shape shape(const glslang::TType& t);
    Place matrix_product(glslang::TOperator op, Shape left, Shape right, const Place& a, const Place& b);
    Place select_part(glslang::TIntermBinary* node, const Place& base);
    Place read(const LValue& lv);
    Place temps_like(const Place& p);
    Place convert_bits(const Place& p, ir::Bank to);
    Place unary(ir::Op op, const Place& a, ir::Bank bank, ir::Bank result);
    Place broadcast(const Place& p, std::size_t n);
    // `destination`: registers the function's returns write (else temporaries of its own).
    Place eval_call(glslang::TIntermAggregate* call, const Place* destination = nullptr);
    Place eval_index(glslang::TIntermBinary* node);
    Place eval_assignment(glslang::TIntermBinary* node);
    Place eval_increment(glslang::TIntermUnary* node);
    Place componentwise(ir::Op op, ir::Bank result, const Place& a, const Place& b, ir::Bank bank);
    Place arithmetic(glslang::TOperator op, const glslang::TType& type, const Place& a, const Place& b);
    Place compare(glslang::TOperator op, const Place& a, const Place& b);
    Place logical(glslang::TIntermBinary* node);
    int sampler_of(glslang::TIntermTyped* node);

    LValue lvalue(glslang::TIntermTyped* node);
    // An out or inout argument's l-value, its run-time index fixed where the call stands: the
    // function may assign what the index was computed from.
    LValue argument_lvalue(glslang::TIntermTyped* node, std::optional<std::uint32_t> index_register = std::nullopt);
    // glslang's comma for out arguments of another type: f(.., tempArg, ..), target = T(tempArg).
    // The target's l-value is taken where tempArg stands among the arguments, as GLSL takes it.
    std::optional<Place> eval_output_conversions(glslang::TIntermAggregate* comma);

    // ---- statements ------------------------------------------------------------------------
    void statement(TIntermNode* node);
    void statements(glslang::TIntermAggregate* sequence);
    void if_statement(glslang::TIntermSelection* node);
    void loop(glslang::TIntermLoop* node);
    void branch(glslang::TIntermBranch* node);
    void switch_statement(glslang::TIntermSwitch* node);
    void initialise_locals(glslang::TIntermAggregate* body, const std::set<long long>& parameters);

    // ---- a derivative probe ----------------------------------------------------------------
    // The probe's expression, taken out of main's body (null without one).
    glslang::TIntermTyped* take_probe(glslang::TIntermAggregate* main);
    // Evaluates it where main has ended and writes its derivatives as the colour.
    void write_probe(glslang::TIntermTyped* expression);

    // ---- the stage's interface (uniforms, inputs, outputs, built-ins) ------------------------
    Place interface_variable(glslang::TIntermSymbol* node);
    Place uniform_variable(glslang::TIntermSymbol* node);
    Place input_variable(glslang::TIntermSymbol* node, const glslang::TType& type, const std::string& name);
    Place output_variable(glslang::TIntermSymbol* node, const glslang::TType& type, const std::string& name);
    Place block_variable(glslang::TIntermSymbol* node, const glslang::TType& type, bool output);
    Place bound_input(ir::Source source, std::uint16_t slot, const std::vector<ir::Bank>& banks,
                      std::uint16_t first = 0);
    Place bound_output(ir::Source source, const std::vector<ir::Bank>& banks, std::uint16_t first = 0);
    int sampler_uniform(glslang::TIntermSymbol* node, const std::string& name, const glslang::TType& type);
    Place transform_uniform(ir::TransformUniform which, int size, bool transposed);
    Place attribute(ir::Attribute which, int components);
    Place generic_attribute(glslang::TIntermSymbol* node);
    void assign_attribute_locations(const std::vector<glslang::TIntermSymbol*>& symbols);
    Place front_facing();
    Place color_input(glslang::TIntermSymbol* node, const std::string& front, const std::string& back);
    void supply_unwritten_colors();
    bool redeclared(const std::string& name) const;
    Place ftransform();
    void declare_globals(glslang::TIntermAggregate* root);
    std::string where(const TIntermNode* node) const;
    // "FILE:LINE:COL: ", or the probe's option and expression for a place in it.
    std::string position(const glslang::TSourceLoc& at) const;

    [[noreturn]] void refuse(const TIntermNode* at, const std::string& what) const;
    [[noreturn]] void refuse(const glslang::TSourceLoc& at, const std::string& what) const;
    void check_size() const;

    // ---- state -----------------------------------------------------------------------------
    StageKind kind_;
    std::string file_;
    glslang::TIntermediate& ast_;
    ProgramInterface& interface_;
    ir::Stage stage_;
    std::uint32_t line_ = 0;  // of the statement being lowered

    std::array<std::uint32_t, ir::kBanks> variable_top_{}, variable_max_{}, temp_top_{}, temp_max_{}, constant_top_{};
    std::map<std::pair<ir::Bank, std::uint32_t>, std::uint32_t> constants_;  // (bank, bits) -> register

    std::unordered_map<std::string, glslang::TIntermAggregate*> functions_;  // by mangled name
    std::unordered_map<long long, Place> globals_;        // globals and interface variables
    std::unordered_map<long long, Place> const_arrays_;   // folded const variables, by symbol id
    std::unordered_map<long long, int> global_samplers_;  // sampler uniforms: their slot
    std::unordered_map<long long, int> attribute_locations_;  // generic vertex inputs: their location
    std::map<std::string, Place> fixed_inputs_;          // inputs by what they are (gl_Vertex, ...)
    struct Frame {
        std::string function;
        std::unordered_map<long long, Place> locals;
        std::unordered_map<long long, int> samplers;  // sampler parameters
        Place result;                                 // the return value's registers
    };
    std::vector<Frame> frames_;  // the inlined calls, main first
    // eval_output_conversions's targets, by the symbol id of their tempArg: the expression, the
    // register for its run-time index, and its l-value once the call has taken it.
    struct ConvertedOutput {
        glslang::TIntermTyped* target;
        std::uint32_t index;
        std::optional<LValue> lvalue;
    };
    std::unordered_map<long long, ConvertedOutput> converted_outputs_;
    int loops_ = 0;              // loops and switches open, for break
    const TIntermNode* statement_value_ = nullptr;  // an expression statement's node: its value unused
    // Variable registers below this hold globals and outputs, which any function may assign.
    std::array<std::uint32_t, ir::kBanks> shared_variables_{};
    std::map<std::pair<const void*, long long>, bool> written_symbols_;  // by (function, symbol): cached
    bool is_shared_variable(const Slot& s) const;
    bool writes_symbol(glslang::TIntermAggregate* function, long long symbol);
    void fuse_moves();
};

}  // namespace qs::frontend
