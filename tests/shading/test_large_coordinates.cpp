// Noise at large coordinates: float against a double evaluation of the same code, with and
// without reducing the coordinates by the noise period first (noise/noise_period.h). Prints
// the table docs/results.md quotes.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <functional>

#include "shading/noise/cellular.h"
#include "shading/noise/noise_period.h"
#include "shading/noise/simplex2d.h"
#include "shading/noise/simplex3d.h"

namespace qs::glsl {

namespace {

struct Noise {
    const char* name;
    std::function<double(glm::dvec3, bool)> eval;  // at a point, in double (true) or float
    std::function<glm::dvec3(glm::dvec3)> wrap;
};

template <class F>
F eval2(const char* which, glm::dvec3 p) {
    const vec2<F> v{F(p.x), F(p.y)};
    if (which[0] == 's') return noise::snoise(v);
    return noise::cellular(v).x;
}

const Noise kNoises[] = {
    {"simplex 2D",
     [](glm::dvec3 p, bool dbl) { return dbl ? eval2<double>("s", p) : double(eval2<float>("s", p)); },
     [](glm::dvec3 p) { return glm::dvec3(noise::wrap_simplex2d(glm::dvec2(p)), p.z); }},
    {"simplex 3D",
     [](glm::dvec3 p, bool dbl) {
         return dbl ? noise::snoise3<noise::Simplex3dDemo>(vec3<double>(p.x, p.y, p.z))
                    : double(noise::snoise3<noise::Simplex3dDemo>(vec3<float>(float(p.x), float(p.y), float(p.z))));
     },
     [](glm::dvec3 p) { return noise::wrap_simplex3d(p); }},
    {"cellular 2D F1",
     [](glm::dvec3 p, bool dbl) { return dbl ? eval2<double>("c", p) : double(eval2<float>("c", p)); },
     [](glm::dvec3 p) { return glm::dvec3(noise::wrap_cellular(glm::dvec2(p)), p.z); }},
    {"cellular 3D F1",
     [](glm::dvec3 p, bool dbl) {
         return dbl ? noise::cellular(vec3<double>(p.x, p.y, p.z)).x
                    : double(noise::cellular(vec3<float>(float(p.x), float(p.y), float(p.z))).x);
     },
     [](glm::dvec3 p) { return noise::wrap_cellular(p); }},
};

// Largest errors over a 24x24 grid in a unit square at `offset`, against the double evaluation
// at the wrapped point: the noise's periodic continuation. (The double evaluation at the point
// itself is no reference beyond about 1e5: the GLSL constants are float-rounded, so 1/289 and the
// skew factors are exact only to 1e-8, which large coordinates multiply into whole cells; the
// period test below checks the wrap against it where it still holds.)
struct Errors {
    double plain = 0.0, wrapped = 0.0, period = 0.0;
};
Errors errors_at(const Noise& n, double offset) {
    Errors e;
    for (int j = 0; j < 24; ++j) {
        for (int i = 0; i < 24; ++i) {
            const glm::dvec3 p(offset + (i + 0.37) / 24.0, 0.7 * offset + (j + 0.61) / 24.0, 0.3 * offset + 0.45);
            const glm::dvec3 w = n.wrap(p);
            const double truth = n.eval(w, true);
            e.plain = std::max(e.plain, std::abs(n.eval(p, false) - truth));
            e.wrapped = std::max(e.wrapped, std::abs(n.eval(w, false) - truth));
            e.period = std::max(e.period, std::abs(n.eval(p, true) - truth));
        }
    }
    return e;
}

}  // namespace

TEST_CASE("large coordinates: float noise breaks where float runs out of fraction, wrapping by the period fixes it",
          "[noise][stability]") {
    std::printf("large coordinates: max |float - double| over a unit square at offset (x, 0.7x, 0.3x)\n");
    std::printf("%-16s", "offset");
    for (int k = 0; k <= 8; ++k) std::printf(" 1e%d      ", k);
    std::printf("\n");
    for (const Noise& n : kNoises) {
        Errors e[9];
        for (int k = 0; k <= 8; ++k) e[k] = errors_at(n, std::pow(10.0, k));
        std::printf("%-16s", n.name);
        for (int k = 0; k <= 8; ++k) std::printf(" %-9.2g", e[k].plain);
        std::printf("\n%-16s", "  wrapped");
        for (int k = 0; k <= 8; ++k) std::printf(" %-9.2g", e[k].wrapped);
        std::printf("\n");
        // What float achieves anywhere inside the first period: the bar for wrapped coordinates.
        // (Not zero: cellular 3D hashes with floor(p * 1/49), and at p a multiple of 49 float
        // and double round to different sides, moving one feature point: measured 0.12.)
        double first_period = 0.0;
        for (int s = 0; s < 12; ++s) first_period = std::max(first_period, errors_at(n, 23.7 * s + 0.5).wrapped);
        std::printf("%-16s float vs double anywhere in the first period: %.2g\n", "", first_period);
        INFO(n.name);
        for (int k = 0; k <= 4; ++k) CHECK(e[k].period < 1e-9);  // the wrap is a period of the formula
        CHECK(e[1].plain < 1e-4);   // at 10 float is as good as anywhere
        CHECK(e[7].plain > 0.1);    // at 1e7 the fraction is gone (float spacing 1 above 8.4e6)
        for (int k = 0; k <= 8; ++k) {
            INFO("offset 1e" << k);
            CHECK(e[k].wrapped <= std::max(1e-3, first_period));  // wrapped: as good as in the first period
        }
    }
}

}  // namespace qs::glsl
