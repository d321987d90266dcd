#pragma once
// The interpreter's inner loop: one stage of a GLSL program (frontend/ir.h) run over the lanes
// of a number type F (float, double, Pixels, Quads, Dual2, Checked).
//
// Each operation calls the vocabulary's function of the same name (shading/glsl/), so a GLSL
// shader run here computes what its hand translation computes, bit for bit; only the dispatch
// is new, and it is shared by every lane of F: a batch of 16 fragments, or a pair of batches as
// one number of twice the width (the rasterizer shades blocks in pairs). Divergent control flow
// runs as llvmpipe runs it: every lane executes every operation, and writes to variables keep
// the lanes outside the running mask (cond & break & continue & switch & return) as they were;
// loops go round while a lane that has not discarded runs, and leave after 65,535 iterations of
// all the stage's loops together (llvmpipe's loop limiter, counted per 8-lane vector as
// llvmpipe's is).

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <vector>

#include "frontend/ir.h"
#include "jit/compiled_blocks.h"
#include "shading/glsl.h"
#include "shading/glsl/float_functions.h"
#include "shading/glsl/hyperbolic.h"
#include "shading/glsl/integer_functions.h"
#include "shading/glsl/texture.h"

namespace qs::interpreter {

inline constexpr std::int32_t kLoopLimit = 65535;  // llvmpipe's LP_MAX_TGSI_LOOP_ITERATIONS
inline constexpr int kVectorLanes = 8;             // llvmpipe's vector: two quads, one limiter
inline constexpr int kMaxVectors = 4;              // in the widest number type (32 lanes)

// One bank of registers (a std::vector<bool> would not hold the vertex stage's masks).
template <class T>
class Bank {
public:
    void assign(std::size_t n, const T& value) {
        if (n != size_) data_ = std::make_unique<T[]>(n), size_ = n;
        std::fill(data_.get(), data_.get() + n, value);
    }
    std::size_t size() const { return size_; }
    T* data() { return data_.get(); }
    T& operator[](std::size_t i) { return data_[i]; }
    const T& operator[](std::size_t i) const { return data_[i]; }

private:
    std::unique_ptr<T[]> data_;
    std::size_t size_ = 0;
};

// The register file of one stage for number type F.
template <class F>
struct Registers {
    using I = int_t<F>;
    using U = uint_t<F>;
    using M = Bool<F>;
    Bank<F> f;
    Bank<I> i;
    Bank<U> u;
    Bank<M> b;
    std::uint64_t constants_of = 0;  // the serial of the stage whose constants the registers hold

    // Sized for `stage`, its constants in place.
    void prepare(const ir::Stage& stage);
};

// What a stage's texture operations read: slot -> texture (2D or 3D as the program declares).
using TextureSlots = std::array<const glsl::Texture*, 16>;

struct RunResult {
    std::uint32_t discarded = 0;  // bit i: lane i discarded
    bool loop_limit = false;      // a loop left at llvmpipe's limit
};

template <class F>
class Executor {
public:
    // Runs `stage` on registers whose inputs are filled, its compiled blocks (native_blocks.h)
    // from `native` where given. Throws std::logic_error for an operation F cannot do
    // (derivatives on independent pixels).
    static RunResult run(const ir::Stage& stage, Registers<F>& r, const TextureSlots& textures,
                         std::span<const jit::BlockCode> native = {});
};

// ---- number helpers -------------------------------------------------------------------------

namespace executor_detail {

template <class M>
bool any_lane(const M& m) {
    if constexpr (std::is_same_v<M, bool>) {
        return m;
    } else {
        return any(m);
    }
}
template <class M>
bool all_lanes(const M& m) {
    if constexpr (std::is_same_v<M, bool>) {
        return m;
    } else {
        return all(m);
    }
}

// The plain float lanes under F (F itself, a Dual2's value, a Checked number's).
template <class F>
struct plain_lanes {
    using type = F;
};
template <class T>
struct plain_lanes<Dual2<T>> : plain_lanes<T> {};
template <class L>
struct plain_lanes<Checked<L>> {
    using type = L;
};

// The mask of F's lanes [first, first + count).
template <class F>
Bool<F> lane_range(int first, int count) {
    using M = Bool<F>;
    if constexpr (std::is_same_v<M, bool>) {
        return first <= 0 && first + count > 0;
    } else {
        using P = typename plain_lanes<F>::type;
        using T = typename P::value_type;
        alignas(64) T a[P::size];
        for (int i = 0; i < P::size; ++i) a[i] = (i >= first && i < first + count) ? T(1) : T(0);
        const auto m = P::load(a) > P(T(0));
        if constexpr (is_checked_v<F>) {
            return M(m, LaneCases());
        } else {
            return m;
        }
    }
}

// The mask of F's lanes whose bit is set in `bits`.
template <class F>
Bool<F> mask_of_bits(std::uint32_t bits) {
    using M = Bool<F>;
    if constexpr (std::is_same_v<M, bool>) {
        return (bits & 1u) != 0;
    } else {
        using P = typename plain_lanes<F>::type;
        using T = typename P::value_type;
        alignas(64) T a[P::size];
        for (int i = 0; i < P::size; ++i) a[i] = (bits >> i & 1u) ? T(1) : T(0);
        const auto m = P::load(a) > P(T(0));
        if constexpr (is_checked_v<F>) {
            return M(m, LaneCases());
        } else {
            return m;
        }
    }
}

// Lane bits of a mask.
template <class M>
std::uint32_t bits_of(const M& m) {
    if constexpr (std::is_same_v<M, bool>) {
        return m ? 1u : 0u;
    } else if constexpr (is_checked_mask<M>::value) {
        return lane_bits(m.m);
    } else {
        return lane_bits(m);
    }
}

// Whether F computes in double.
template <class F>
constexpr bool in_double() {
    if constexpr (std::is_arithmetic_v<F>) {
        return std::is_same_v<F, double>;
    } else {
        return std::is_same_v<typename plain_lanes<F>::type::value_type, double>;
    }
}

// The float a 32-bit word holds, as a double, exactly: from its bits, since the conversion
// instruction reads a denormal as 0 where the shading thread flushes denormals (a constant such
// as 1e-38 is a denormal float, and a normal double).
inline double float_of_bits(std::uint32_t w) {
    const std::uint32_t exponent = (w >> 23) & 0xFFu, fraction = w & 0x7FFFFFu;
    if (exponent != 0) return double(std::bit_cast<float>(w));
    const double magnitude = double(fraction) * 0x1p-149;
    return (w >> 31) ? -magnitude : magnitude;
}

// A value of bank type T from a 32-bit word: a float's bits, an integer, or 0/1 for a bool.
template <class T, class M>
T from_word(std::uint32_t w) {
    if constexpr (std::is_same_v<T, M>) {
        return M(w != 0);
    } else if constexpr (IntegerNumber<T>) {
        return T(std::bit_cast<typename T::value_type>(w));
    } else if constexpr (in_double<T>()) {
        return T(float_of_bits(w));
    } else {
        return T(std::bit_cast<float>(w));
    }
}

}  // namespace executor_detail

template <class F>
void Registers<F>::prepare(const ir::Stage& stage) {
    using executor_detail::from_word;
    if (constants_of == stage.serial && f.size() == stage.registers[0]) return;
    f.assign(stage.registers[0], F(0.0f));
    i.assign(stage.registers[1], I(0));
    u.assign(stage.registers[2], U(0u));
    b.assign(stage.registers[3], M(false));
    for (const ir::Constant& c : stage.constants) {
        switch (c.bank) {
            case ir::Bank::Float: f[c.reg] = from_word<F, M>(c.bits); break;
            case ir::Bank::Int: i[c.reg] = from_word<I, M>(c.bits); break;
            case ir::Bank::Uint: u[c.reg] = from_word<U, M>(c.bits); break;
            case ir::Bank::Bool: b[c.reg] = from_word<M, M>(c.bits); break;
        }
    }
    constants_of = stage.serial;
}

}  // namespace qs::interpreter
