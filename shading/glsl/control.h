#pragma once
// Control flow that depends on the fragment, under SIMD: each GLSL bool is a mask of lanes.
//
// `if`: both sides are computed for every lane and select keeps each lane's side:
//
//     if (d < 0.3) c = a; else c = b;        c = select(d < 0.3f, a, b);
//
// Loops: a Loop holds the variables its body assigns and the lanes still running. The body runs
// for every lane while any lane is running; each lane's variables keep the values they had when
// it left (break, return, or its condition failing), and a lane that continues resumes at the
// next iteration with the values it had at the continue. A lane that discards runs on (GLSL's
// discard makes it a helper, not a lane that stops).
//
//     float x = cx, y = cy, r = 0.0;         F x = cx, y = cy, r = 0.0f;
//                                            Loop loop(x, y, r);  // what the body assigns
//     for (int i = 0; i < 100; i++) {        for (int i = 0; loop(i < 100); i++) {
//         float nx = x * x - y * y + cx;         F nx = x * x - y * y + cx;
//         y = 2.0 * x * y + cy;                  y = 2.0f * x * y + cy;
//         x = nx;                                x = nx;
//         r = x * x + y * y;                     r = x * x + y * y;
//         if (r > 4.0) break;                    loop.break_if(r > 4.0f);
//     }                                      }
//     while (v < 1.0) { ... }                while (loop(v < 1.0f)) { ... }
//     if (c) continue;                       loop.continue_if(c);
//     if (c) return v;   (in f)              loop.return_if(ret, c, v);  ... return ret.value_or(w);
//     if (c) discard;    (in main)           loop.discard_if(out, c);
//
// Rules: register every variable declared before the loop that the body assigns (the body also
// runs for lanes that have left, on values that are then thrown away; every operation in this
// vocabulary is defined for any value, so nothing traps). A variable left out compiles, and is
// wrong for the lanes that left: the checked instantiation (number/checked.h, LoopWrites) finds
// it, naming the loop's head, wherever a rendered fragment enters the loop (`quadshade check`
// runs it on every shader it checks, `quadshade render --undefined-mask` on its frame). A loop counter the same for every lane
// stays a plain C++ int, and loop(i < 100) checks it; a C++ `break` is right only when every
// lane breaks. Statements after a break_if or continue_if in the same iteration run for the
// lanes that left too and are thrown away for them, as GLSL wants. Inside a loop, conditions of
// side effects go through the loop (return_if, discard_if), so that lanes that have left do not
// act. A loop inside a varying `if` starts with `Loop loop(inside(c), ...)`, a nested loop with
// `Loop inner(outer, ...)`: return leaves the enclosing loops as well.
//
// A for loop with continue_if and an increment of a registered variable writes the increment
// after loop.next() (`for (...; loop(c); loop.next(), t += 0.1f)`), so that lanes that continued
// rejoin before it.

#include <cstddef>
#include <memory>
#include <new>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <utility>

#include "shading/glsl/builtins.h"

namespace qs::glsl {

// Where a loop's head is written, for `check`'s report of what a Loop does not hold: what
// std::source_location gives, read with the builtins it is made of, which clang 14 (the fuzz
// build's compiler) has although its <source_location> is empty.
struct SourcePlace {
    static constexpr SourcePlace current(const char* file = __builtin_FILE(), unsigned line = __builtin_LINE()) {
        return {file, line};
    }
    constexpr const char* file_name() const { return file; }
    constexpr unsigned line() const { return at_line; }
    const char* file;
    unsigned at_line;
};

// The mask type of a variable's lanes; none for anything else.
template <class V>
struct mask_of {};
template <class V>
    requires(Number<V> || IntegerNumber<V>)
struct mask_of<V> {
    using type = Bool<V>;
};
template <class V>
    requires requires { typename V::value_type; V::N; }
struct mask_of<V> : mask_of<typename V::value_type> {};  // vectors
template <class V>
    requires requires { typename V::column_type; }
struct mask_of<V> : mask_of<typename V::value_type> {};  // matrices
template <Boolean M>
struct mask_of<M> {
    using type = M;  // bools
};
template <class V>
using mask_of_t = typename mask_of<V>::type;

// The lanes a loop inside a varying `if` starts with.
template <class M>
struct Inside {
    M lanes;
};
template <class M>
Inside<M> inside(const M& lanes) { return {lanes}; }

// A GLSL function's value per lane once its lanes return, before they reach the end.
template <class T>
class Return {
public:
    using Mask = mask_of_t<T>;

    // `if (c) return v;`: the lanes of c that have not returned yet return v.
    void return_if(const Mask& c, const T& v) {
        const Mask now = c && !returned_;
        value_ = select(now, v, value_);
        returned_ = returned_ || now;
    }
    // The function's value: what each lane returned, or `otherwise` for the lanes that reach
    // the end.
    T value_or(const T& otherwise) const { return select(returned_, value_, otherwise); }
    const Mask& returned() const { return returned_; }

private:
    T value_{};
    Mask returned_ = Mask(false);
};

struct LoopTag {};

namespace loop_detail {

// The values lanes left or paused with, of every loop running on this thread, innermost last.
// They are in memory on purpose: a loop reads and writes them only where lanes leave or pause
// and at its end, and held in registers they take those the body iterates in. (Mandelbrot on
// AVX2: its three variables, their saved values, cx, cy and the running lanes are 18 registers
// for 16 lanes, of 16; as members of the Loop, GCC spilled the body's variables, not the saved
// ones, and each iteration waited on a store and a reload.)
class SavedValues {
public:
    // GLSL has no recursion: the loops running at once are the shader's nesting, a few.
    static constexpr std::size_t kBytes = 16 * 1024;

    // Room for a T, released by pop(mark) where mark is top() from before.
    template <class T>
    T* push() {
        const std::size_t at = (top_ + alignof(T) - 1) / alignof(T) * alignof(T);
        if (at + sizeof(T) > kBytes) throw std::length_error("shader loops: the variables of the loops running at once exceed 16 KiB");
        top_ = at + sizeof(T);
        return reinterpret_cast<T*>(bytes_ + at);
    }
    std::size_t top() const { return top_; }
    void pop(std::size_t mark) { top_ = mark; }

private:
    alignas(64) std::byte bytes_[kBytes] = {};
    std::size_t top_ = 0;
};
inline constinit thread_local SavedValues saved_values;

// This thread's SavedValues, looked up once per loop: the pointer passes through an empty asm so
// that GCC keeps it instead of repeating the lookup (in position-independent code, a call that
// makes the body's vectors go to the stack and back) where the loop ends.
inline SavedValues* this_threads_saved_values() {
    SavedValues* p = &saved_values;
    asm("" : "+r"(p));
    return p;
}

}  // namespace loop_detail

// The lanes of a loop: running and paused (continue); every other lane has left (break, return,
// condition failed) or never entered. Nested loops reach their parents through this.
template <class M>
class LoopLanes : public LoopTag {
public:
    // Lanes running the current iteration: what side effects in the body are masked with.
    const M& active() const { return active_; }

protected:
    LoopLanes(const M& entry, LoopLanes* parent) : active_(entry), parent_(parent) {}
    LoopLanes(const LoopLanes&) = delete;
    LoopLanes& operator=(const LoopLanes&) = delete;

    // `lanes` leave this loop and every enclosing one (return). Their variables are left as the
    // loops find them: the function's value for them is in its Return.
    void leave_all(const M& lanes) {
        for (LoopLanes* l = this; l; l = l->parent_) {
            l->active_ = l->active_ && !lanes;
            l->paused_ = l->paused_ && !lanes;
        }
    }

    M active_;
    M paused_ = M(false);
    bool any_paused_ = false;
    LoopLanes* parent_;
};

template <class M, class... Vars>
class Loop final : public LoopLanes<M> {
    // The checked instantiation's loops tell LoopWrites what they hold (number/checked.h).
    static constexpr bool kChecked = is_checked_mask<M>::value;
    using Here = SourcePlace;

public:
    explicit Loop(Vars&... vars) : Loop(M(true), nullptr, vars...) {}
    Loop(Inside<M> entry, Vars&... vars) : Loop(entry.lanes, nullptr, vars...) {}
    Loop(LoopLanes<M>& parent, Vars&... vars) : Loop(parent.active(), &parent, vars...) {}
    ~Loop() {
        end();
        stack_->pop(mark_);
        if constexpr (kChecked) loop_writes.leave(checked_);
    }

    // The loop's head: the lanes that continued rejoin, the lanes whose condition fails leave.
    // False, with every variable restored, once no lane runs.
    bool operator()(const M& condition, Here here = Here::current()) {
        [[maybe_unused]] const Bookkeeping own(*this, here);
        next();
        const M failing = this->active_ && !condition;
        if (any(failing)) leave(failing);
        if (any(this->active_)) return true;
        end();
        return false;
    }
    // A condition the same for every lane (a loop counter); false ends the loop for all. (Per
    // pixel, where a mask is one bool, the overload above is this one.)
    bool operator()(bool uniform, Here here = Here::current())
        requires(!std::is_same_v<M, bool>)
    {
        [[maybe_unused]] const Bookkeeping own(*this, here);
        next();
        if (uniform && any(this->active_)) return true;
        end();
        return false;
    }
    bool operator()(bool uniform, const M& condition, Here here = Here::current()) {
        return uniform ? (*this)(condition, here) : (*this)(false, here);
    }
    bool operator()(Here here = Here::current()) { return (*this)(true, here); }

    // if (c) break;
    void break_if(const M& c) {
        [[maybe_unused]] const Bookkeeping own(*this);
        const M going = this->active_ && c;
        if (any(going)) leave(going);
    }
    // if (c) continue;
    void continue_if(const M& c) {
        [[maybe_unused]] const Bookkeeping own(*this);
        const M pausing = this->active_ && c;
        if (!any(pausing)) return;
        save(pausing);
        this->paused_ = this->paused_ || pausing;
        this->active_ = this->active_ && !pausing;
        this->any_paused_ = true;
    }
    // if (c) return v;  (`ret` is the function's Return; the lanes leave the enclosing loops too)
    template <class T>
    void return_if(Return<T>& ret, const M& c, const T& v) {
        [[maybe_unused]] const Bookkeeping own(*this);
        const M going = this->active_ && c;
        if (!any(going)) return;
        ret.return_if(going, v);
        this->leave_all(going);
    }
    // if (c) discard;  (`out` is the fragment's output, shading/program_of.h.) The lanes that
    // discard run on to the loop's end and beyond, as helpers for their quad's derivatives:
    // llvmpipe's values for them, measured by discard_probe, are those of a lane that went on.
    template <class Out>
    void discard_if(Out& out, const M& c) {
        [[maybe_unused]] const Bookkeeping own(*this);
        out.discard_if(this->active_ && c);
    }

    // The lanes that continued rejoin, with the values they had at the continue.
    void next() {
        [[maybe_unused]] const Bookkeeping own(*this);
        if (!this->any_paused_) return;
        restore(this->paused_);
        this->active_ = this->active_ || this->paused_;
        this->paused_ = M(false);
        this->any_paused_ = false;
    }
    // Every lane's variables as it left them. Called by the head that ends the loop and by the
    // destructor; call it after a C++ break.
    void end() {
        [[maybe_unused]] const Bookkeeping own(*this);
        if (ended_) return;
        ended_ = true;
        const M kept = !this->active_;  // left, paused, or never entered (saved as they came)
        if (any(kept)) restore(kept);
        if constexpr (kChecked) loop_writes.end(checked_);
    }

private:
    Loop(const M& entry, LoopLanes<M>* parent, Vars&... vars)
        : LoopLanes<M>(entry, parent),
          vars_(vars...),
          stack_(loop_detail::this_threads_saved_values()),
          mark_(stack_->top()),
          saved_(new (stack_->template push<std::tuple<Vars...>>()) std::tuple<Vars...>(vars...)) {
        if constexpr (kChecked) {
            checked_ = loop_writes.enter({LoopWrites::Held{std::addressof(vars), std::addressof(vars) + 1}...});
        }
    }

    // The loop's own writes (the lanes' saved values, its masks), left out of the checked
    // instantiation's check; the head also says where the loop is.
    struct CheckedBookkeeping {
        explicit CheckedBookkeeping(Loop&) : suspend(loop_writes) {}
        CheckedBookkeeping(Loop& loop, const Here& here) : suspend(loop_writes) {
            if (!loop.ended_) loop_writes.head(loop.checked_, here.file_name(), here.line());
        }
        LoopWrites::Suspend suspend;
    };
    struct Unchecked {
        explicit Unchecked(Loop&) {}
        Unchecked(Loop&, const Here&) {}
    };
    using Bookkeeping = std::conditional_t<kChecked, CheckedBookkeeping, Unchecked>;

    void leave(const M& lanes) {
        save(lanes);
        this->active_ = this->active_ && !lanes;
    }
    void save(const M& lanes) {
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            ((std::get<I>(*saved_) = select(lanes, std::get<I>(vars_), std::get<I>(*saved_))), ...);
        }(std::index_sequence_for<Vars...>());
    }
    void restore(const M& lanes) {
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            ((std::get<I>(vars_) = select(lanes, std::get<I>(*saved_), std::get<I>(vars_))), ...);
        }(std::index_sequence_for<Vars...>());
    }

    static_assert(std::is_trivially_destructible_v<std::tuple<Vars...>>, "the saved values are released without a destructor");
    std::tuple<Vars&...> vars_;
    loop_detail::SavedValues* stack_;
    std::size_t mark_;
    std::tuple<Vars...>* saved_;  // per lane: the value it left or paused with (in stack_)
    bool ended_ = false;
    std::size_t checked_ = 0;  // its place in LoopWrites (checked instantiation only)
};

template <class V, class... Vs>
Loop(V&, Vs&...) -> Loop<mask_of_t<V>, V, Vs...>;
template <class M, class... Vs>
Loop(Inside<M>, Vs&...) -> Loop<M, Vs...>;
template <class M, class... Vs>
Loop(LoopLanes<M>&, Vs&...) -> Loop<M, Vs...>;

}  // namespace qs::glsl
