// A Loop's rule, checked (shading/glsl/control.h, number/checked.h's LoopWrites): in the checked
// instantiation a loop body's write to a variable declared before the loop that the loop does not
// hold throws, naming the loop's head; what the rule allows does not. The unchecked
// instantiations run the same code without a word and get it wrong, which is why the check
// exists. And every catalogue shader holds what its loops write.
#include <catch2/catch.hpp>

#include <cstring>
#include <stdexcept>
#include <string>

#include "shading/catalogue.h"
#include "shading/glsl.h"
#include "shading/program_of.h"
#include "tests/shading/number_types.h"

namespace qs::glsl {

namespace {

using Checked16 = Checked<Quads<float, 4>>;

// The Mandelbrot: n counts the iterations, and the loop is not given it.
template <class F, bool HoldN>
int_t<F> escape_count(const F& cx, const F& cy) {
    F x = cx, y = cy;
    int_t<F> n = 0;
    auto body = [&](auto& loop) {
        for (int i = 0; loop(i < 40); i++) {
            loop.break_if(x * x + y * y > 4.0f);
            F nx = x * x - y * y + cx;
            y = 2.0f * x * y + cy;
            x = nx;
            n++;
        }
    };
    if constexpr (HoldN) {
        Loop loop(x, y, n);
        body(loop);
    } else {
        Loop loop(x, y);
        body(loop);
    }
    return n;
}

template <class F>
F ramp(float from, float step) {
    double v[16];
    for (int i = 0; i < 16; ++i) v[i] = from + step * float(i);
    return test::from_values<F>(v);
}

std::string message_of(auto&& f) {
    try {
        f();
    } catch (const std::logic_error& e) {
        return e.what();
    }
    return {};
}

}  // namespace

TEST_CASE("a loop body writing a variable its Loop does not hold fails the checked instantiation, naming the loop",
          "[loops][undefined]") {
    using F = Checked16;
    const F cx = ramp<F>(-1.9f, 0.15f), cy = ramp<F>(-0.3f, 0.04f);
    CHECK(message_of([&] { escape_count<F, true>(cx, cy); }).empty());
    const std::string m = message_of([&] { escape_count<F, false>(cx, cy); });
    INFO(m);
    CHECK(m.find("writes an int declared before the loop") != std::string::npos);
    CHECK(m.find("test_loop_writes.cpp:") != std::string::npos);  // the loop's head
    CHECK(m.find("give it to the Loop") != std::string::npos);

    // Unchecked, the same code runs and is wrong: n counts on for the lanes that left.
    using P = Pixels<float, 16>;
    const P px = ramp<P>(-1.9f, 0.15f), py = ramp<P>(-0.3f, 0.04f);
    const int_t<P> right = escape_count<P, true>(px, py), wrong = escape_count<P, false>(px, py);
    int differ = 0;
    for (int i = 0; i < 16; ++i) differ += lane(right, i) != lane(wrong, i);
    CHECK(differ > 0);
}

TEST_CASE("the checked loop rule: floats, vectors, bools and discards named, what the rule allows passes", "[loops][undefined]") {
    using F = Checked16;
    const F v = ramp<F>(0.0f, 0.5f);

    // A vector component, unheld.
    CHECK(message_of([&] {
              F t = v;
              vec2<F> acc(0.0f);
              Loop loop(t);
              while (loop(t < 6.0f)) {
                  t += 1.0f;
                  acc.y += t;
              }
          }).find("writes a float") != std::string::npos);
    // A bool, unheld.
    CHECK(message_of([&] {
              F t = v;
              Bool<F> found(false);
              Loop loop(t);
              while (loop(t < 6.0f)) {
                  t += 1.0f;
                  found = found || t > 3.0f;
              }
          }).find("writes a bool") != std::string::npos);
    // discard straight from a loop's body, not through the loop.
    CHECK(!message_of([&] {
               F t = v;
               FragmentOut<F> out;
               Loop loop(t);
               while (loop(t < 6.0f)) {
                   t += 1.0f;
                   out.discard_if(t > 5.0f);
               }
           }).empty());
    // Held by the outer loop but not by the inner one that writes it.
    CHECK(!message_of([&] {
               F t = v, k = 0.0f;
               Loop outer(t, k);
               while (outer(t < 4.0f)) {
                   Loop inner(outer, t);
                   for (int j = 0; inner(j < 3); j++) {
                       t += 0.75f;
                       k += 1.0f;
                   }
               }
           }).empty());
    // Declared after the Loop but before its head: still before the loop.
    CHECK(!message_of([&] {
               F t = v;
               Loop loop(t);
               F late = 0.0f;
               while (loop(t < 6.0f)) {
                   t += 1.0f;
                   late = t;
               }
           }).empty());

    // Allowed: everything held, discard and return through the loop, variables of the body,
    // writes before the head and after the loop's end, nested loops holding what they write.
    CHECK(message_of([&] {
              F t = v, k = 0.0f, sum = 0.0f;
              vec3<F> colour(0.0f);
              FragmentOut<F> out;
              Return<F> ret;
              Loop loop(t, sum);
              sum = 1.0f;  // before the head
              while (loop(t < 6.0f)) {
                  F step = 0.5f + 0.25f * t;  // the body's own
                  step *= 2.0f;
                  t += step;
                  sum += t;
                  loop.discard_if(out, t > 5.5f);
                  loop.return_if(ret, t > 4.0f, t);
                  loop.continue_if(t > 3.0f);
                  sum -= 0.5f;
              }
              colour = vec3<F>(sum, t, ret.value_or(-1.0f));  // after the loop's end
              Loop outer(t, k);
              while (outer(t < 12.0f)) {
                  Loop inner(outer, t);
                  for (int j = 0; inner(j < 3); j++) t += 0.75f;
                  k += 1.0f;
              }
              colour.x = k;
          }).empty());
}

TEST_CASE("every catalogue shader's loops hold what they write (its checked instantiation, quads)", "[loops][undefined]") {
    FragmentBatch in{};
    for (int i = 0; i < kBatchLanes; ++i) {
        const float x = 3.5f + float(i % 4) + 4.0f * float(i / 8), y = 7.5f + float((i / 4) % 2) + 3.0f * float(i % 2);
        in.frag_coord[0][i] = 17.0f * x, in.frag_coord[1][i] = 13.0f * y, in.frag_coord[2][i] = 0.5f, in.frag_coord[3][i] = 1.0f;
        for (int v = 0; v < kMaxVaryings; ++v) in.varying[v][i] = 0.01f * float(7 * i + 13 * v) - 0.3f;
    }
    const ShadeMode mode{Derivatives::Fine, Precision::Float, true};
    int shaded = 0;
    for (const Program* p : catalogue()) {
        if (samples_textures(p->info().needs)) continue;  // no texture here; no catalogue loop samples one
        ColorBatch out{};
        INFO(p->info().name);
        CHECK_NOTHROW(p->shade(mode, in, Uniforms{}, out));
        ++shaded;
    }
    CHECK(shaded > 90);
}

}  // namespace qs::glsl
