#pragma once
// The ProcTexGen articles' 3D cellular (Worley) noise, voronoi(), translated from worley3d.glsl beside this file,
// line for line. The metric is a run-time bool, as in the GLSL, so that the eight displays share
// one instantiation per number type.

#include "shading/glsl.h"
#include "shading/noise/perlin_permutation.h"

namespace qs::noise {
using namespace qs::glsl;

template <class F>
F perm(const F& x) requires(!is_integer_lanes<F>::value) {
    return F(perm(int_t<F>(floor(x * 256.0f)))) / 255.0f;
}
template <class F>
vec4<F> perm(const vec4<F>& x) {
    return vec4<F>(perm(x.x), perm(x.y), perm(x.z), perm(x.w));
}
template <class F>
vec4<F> perm2d(const vec2<F>& p) {
    using Int = int_t<F>;
    Int X = Int(floor(p.x * 256.0f));
    Int Y = Int(floor(p.y * 256.0f));
    Int A = perm(X) + Y;
    Int B = perm(X + 1) + Y;
    return vec4<F>(F(perm(A)), F(perm(A + 1)), F(perm(B)), F(perm(B + 1))) / 255.0f;
}

// pos1 and pos2 start at 0 where the GLSL leaves them undefined; both are written before the
// search ends (the first point always beats 1000, the second always beats it or the first).
template <class F>
void voronoi(const vec3<F>& position, F& f1, vec3<F>& pos1, F& f2, vec3<F>& pos2, float jitter, bool manhattanDistance) {
    vec3<F> thiscell = floor(position) + .5f;
    f1 = f2 = F(1000.f);
    pos1 = pos2 = vec3<F>(0.0f);

    for (float i = -1.f; i <= 1.f; i += 1.f) {
        for (float j = -1.f; j <= 1.f; j += 1.f) {
            for (float k = -1.f; k <= 1.f; k += 1.f) {
                vec3<F> testcell = thiscell + vec3<F>(i, j, k);
                vec3<F> randomUVW = testcell * vec3<F>(0.037f, 0.119f, .093f);
                vec3<F> cellnoise = perm(perm2d(randomUVW.xy()) + randomUVW.z).xyz();
                vec3<F> pos = testcell + jitter * (cellnoise - .5f);
                vec3<F> offset = pos - position;
                F dist = manhattanDistance ? abs(offset.x) + abs(offset.y) + abs(offset.z) : dot(offset, offset);
                // if (dist < f1) {...} else if (dist < f2) {...}
                const auto first = dist < f1, second = dist < f2;
                f2 = select(first, f1, select(second, dist, f2));
                pos2 = select(first, pos1, select(second, pos, pos2));
                f1 = select(first, dist, f1);
                pos1 = select(first, pos, pos1);
            }
        }
    }
    if (!manhattanDistance) {
        f1 = sqrt(f1);
        f2 = sqrt(f2);
    }
}

}  // namespace qs::noise
