#pragma once
// A shader's height: the relief a colour shader describes besides its colour, for normal maps
// (the ProcTexGen articles: "I have the procedural function not only generate a color but a height").
//
// The convention, for a catalogue shader NAME:
//  - its translation's struct names `using Height = H;`, where H has
//        static constexpr float amplitude;          // object units of relief per unit of height
//        template <class F> static F height(const glsl::vec3<F>& P);   // in [0, 1]
//    a function of the object position P = gl_Vertex.xyz alone (no time, no uniforms, no
//    derivatives), written once over every number type like a fragment stage, and declared in
//    GLSL as `float height(vec3 P)` in a .glsl file both stages below include;
//  - the catalogue shader NAME_height draws that height as grey, vec4(vec3(h), 1): the height
//    map is its atlas, drawn like any other and so checked against OSMesa like any other;
//  - QUADSHADE_HEIGHT_FIELD(Shader, HeightShader) (shading/height_field_of.h) registers the
//    pair, and find_height_field(NAME) finds it.
// The surface the height describes is P + amplitude * h(P) N: what a displacement would build,
// and what a normal map (render/normal_bake.h) shades without moving a vertex.
//
// A HeightField evaluates h at any object positions, kBatchLanes at a time, in float or double
// lanes (what a finite-difference normal needs), and with its directional derivatives through
// Dual2 (what an analytic normal needs). Nothing here knows about atlases or images.

#include <string_view>
#include <vector>

#include "shading/program.h"

namespace qs {

// kBatchLanes object positions (or directions), structure of arrays.
struct PointBatch {
    double x[kBatchLanes], y[kBatchLanes], z[kBatchLanes];
};

class HeightField {
public:
    virtual ~HeightField() = default;
    // The colour shader the height belongs to, and the catalogue shader that draws it as grey.
    virtual std::string_view shader() const = 0;
    virtual std::string_view height_shader() const = 0;
    // Object units of relief per unit of height.
    virtual double amplitude() const = 0;
    // h(p) per lane, in `precision`'s lanes (float: p is rounded to float first, as a GPU holds it).
    virtual void heights(Precision precision, const PointBatch& p, double (&h)[kBatchLanes]) const = 0;
    // h(p) and its derivatives along t and b, d/dx and d/dy of h(p + x t + y b) at x = y = 0, by
    // Dual2: p is seeded as (p, t, p's d/dy = b), and the chain rule carries the pair through
    // every operation of the height, so h_t = grad h . t and h_b = grad h . b exactly (to the
    // rounding of `precision`), with no step to choose.
    virtual void gradients(Precision precision, const PointBatch& p, const PointBatch& t, const PointBatch& b,
                           double (&h)[kBatchLanes], double (&h_t)[kBatchLanes], double (&h_b)[kBatchLanes]) const = 0;
};

// The height of catalogue shader `shader` (NAME, not NAME_height); nullptr if it has none.
const HeightField* find_height_field(std::string_view shader);
// Every registered height, in registration order.
std::vector<const HeightField*> height_fields();
// Called by QUADSHADE_HEIGHT_FIELD's static objects.
void register_height_field(const HeightField& field);

}  // namespace qs
