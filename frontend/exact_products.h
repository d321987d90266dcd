#pragma once
// Which of a shader's multiply-adds the C++ writer may round once (exact_product_add) with the
// bits of GLSL's two roundings: those whose product is exact for every input.
//
// An analysis of glslang's syntax tree proves, per float component, that a value is a whole
// number in a known interval, from what GLSL guarantees: literals; floor, ceil, trunc, round and
// roundEven give whole numbers (bounded where their operand is); step gives 0 or 1; fract lies in
// [0, 1]; sums, differences and products of whole numbers whose every value stays below 2^24 are
// exact, so the intervals' arithmetic is the floats'; mod(x, c) and x - floor(x * (1.0 / c)) * c
// of a whole x lie in [0, c] where x is small enough that the rounded quotient cannot cross a
// whole number (what that bound is follows from c and the constant's rounding). NaN is carried
// where it can occur: a NaN operand makes both forms NaN. Local variables are followed through
// assignments, if and else (joined), and function calls (each call analysed with its arguments,
// each node's intervals joined over every call that reaches it); a variable a loop writes is
// unknown in and after the loop, except a counter `for (int i = A; i < B; i++)` that only its
// step writes. Globals are unknown.
//
// A multiply-add a * b + c (or c + a * b, a * b - c, c - a * b) is fused where, component by
// component, either a, b, c, the product and the result are whole numbers below 2^24 in
// magnitude, or one factor is a power of two (2^-24 to 2^24) and the other a whole number, an
// infinity or NaN (floor of anything) and c a bounded number: both make a * b exact, and then one
// rounding and two give the same bits (an overflow of the product overflows both ways). A
// difference negates an operand in the fused form: c in a * b - c, b in c - a * b; that operand
// must not be NaN, whose sign the negation would turn.

#include <optional>
#include <unordered_map>
#include <vector>

#include <glslang/Include/intermediate.h>

namespace qs::frontend {

// What the analysis knows of one float (or int) component.
struct KnownNumber {
    enum Kind : unsigned char {
        Unknown,
        Integral,  // a whole number of any size, an infinity or NaN
        Whole,     // a whole number in [lo, hi], |lo|, |hi| < 2^24 (or NaN where `nan`)
        Real,      // a finite number in [lo, hi] (or NaN where `nan`)
    } kind = Unknown;
    double lo = 0.0, hi = 0.0;
    bool nan = false;
};

// The operands of a multiply-add the writer may fuse: product_left * product_right + addend, or
// addend - product_left * product_right where `subtract_product` (product_right not NaN), or the
// product minus the addend where `subtract_addend` (the addend not NaN).
struct FusibleProduct {
    glslang::TIntermTyped* product_left = nullptr;
    glslang::TIntermTyped* product_right = nullptr;
    glslang::TIntermTyped* addend = nullptr;
    bool subtract_product = false;
    bool subtract_addend = false;
};

class ExactProducts {
public:
    // Analyses the stage's main() (after the globals' initialisers) and every call it makes.
    explicit ExactProducts(glslang::TIntermAggregate* root);

    // The components of `n` over every time it runs; empty where the analysis did not reach it.
    std::vector<KnownNumber> known(const glslang::TIntermTyped* n) const;
    // Whether `add_or_subtract` (an EOpAdd or EOpSub of floats) is a multiply-add whose product
    // is exact for every input, and its operands.
    std::optional<FusibleProduct> fusible(glslang::TIntermBinary* add_or_subtract) const;

private:
    std::unordered_map<const glslang::TIntermTyped*, std::vector<KnownNumber>> seen_;
};

}  // namespace qs::frontend
