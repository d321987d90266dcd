#pragma once
// The same-pixels check of a compiled translation against the interpreter running its GLSL.

#include <bit>
#include <cstdint>
#include <string>
#include <utility>

#include <catch2/catch.hpp>

#include "render/scene_render.h"
#include "tests/shading_modes.h"

namespace qs::test {

inline std::size_t differing_pixels(const Framebuffer& a, const Framebuffer& b) {
    std::size_t n = 0;
    for (std::size_t p = 0; p < a.rgba.size() / 4; ++p) {
        bool differs = false;
        for (std::size_t c = 0; c < 4; ++c) {
            differs = differs || std::bit_cast<std::uint32_t>(a.rgba[p * 4 + c]) != std::bit_cast<std::uint32_t>(b.rgba[p * 4 + c]);
        }
        n += differs;
    }
    return n;
}

// A frame of the first pixel's colour everywhere.
inline Framebuffer uniform_like(const Framebuffer& f) {
    Framebuffer u = f;
    for (std::size_t p = 0; p < u.rgba.size() / 4; ++p) {
        for (std::size_t c = 0; c < 4; ++c) u.rgba[p * 4 + c] = f.rgba[c];
    }
    return u;
}

// Renders `scene` with the interpreted program and then the compiled one under each shading mode,
// and checking undefined cases: the two must agree to the bit (and, where `picture`, on a picture
// rather than one colour).
inline void check_same_pixels(Scene& scene, const Program& interpreted, const Program& compiled, const std::string& what,
                              bool picture = true) {
    // Renders both with the request's settings: the interpreted frame, then the compiled one.
    const auto both = [&](FrameRequest r) {
        r.width = 64, r.height = 48;
        r.shader_override = interpreted.info().name;
        Framebuffer expected = render_frame(scene, r);
        r.shader_override = compiled.info().name;
        return std::pair{std::move(expected), render_frame(scene, r)};
    };
    for (const ShadingMode& m : kShadingModes) {
        FrameRequest r;
        r.shading.derivatives = m.derivatives;
        r.shading.precision = m.precision;
        const auto [expected, got] = both(r);
        INFO(what << ", " << m.what);
        CHECK(differing_pixels(expected, got) == 0);
        if (picture) CHECK(differing_pixels(expected, uniform_like(expected)) > 0);
    }
    // And shaded in the instantiation that checks undefined cases (Checked numbers; the loops'
    // rule checked too): the same colours.
    FrameRequest r;
    r.shading.check_undefined = true;
    const auto [expected, got] = both(r);
    INFO(what << ", undefined cases checked");
    CHECK(differing_pixels(expected, got) == 0);
}

}  // namespace qs::test
