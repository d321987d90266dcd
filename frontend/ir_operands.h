#pragma once
// Which registers an operation reads and writes: each operand field of an Instr with its bank
// and how many consecutive registers it spans. Used to check a stage before it runs (every
// register an operation touches exists, so the interpreter never reads outside its register
// file) and to lay out registers after the front end has built the code.

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "frontend/ir.h"

namespace qs::ir {

enum class Field : std::uint8_t { D, A, B, C };

struct Operand {
    Field field;
    Bank bank;
    std::uint32_t span = 1;  // consecutive registers
    bool written = false;
};

struct Operands {
    std::array<Operand, 4> list{};
    int size = 0;
    void add(Field f, Bank b, std::uint32_t span = 1, bool written = false) { list[std::size_t(size++)] = {f, b, span, written}; }
    const Operand* begin() const { return list.data(); }
    const Operand* end() const { return list.data() + size; }
};

// The operands of `in`.
Operands operands(const Instr& in);

// Whether `op` jumps to Instr::target (If, Else, LoopBegin, LoopEnd).
inline bool jumps(Op op) { return op == Op::If || op == Op::Else || op == Op::LoopBegin || op == Op::LoopEnd; }

// The register field of `in` that `f` names.
inline std::uint32_t& field(Instr& in, Field f) {
    switch (f) {
        case Field::D: return in.d;
        case Field::A: return in.a;
        case Field::B: return in.b;
        case Field::C: return in.c;
    }
    return in.d;
}
inline std::uint32_t field(const Instr& in, Field f) { return field(const_cast<Instr&>(in), f); }

// Throws std::logic_error naming the instruction when an operand lies outside the stage's
// registers, a jump target outside its code, or the control flow markers do not nest.
void validate(const Stage& stage, int samplers);

}  // namespace qs::ir
