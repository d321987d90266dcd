#pragma once
// Whether a fragment stage asks for wide batches (ShaderInfo::wide_batches): the rule the C++
// writer applies to a shader it translates, read from the operations the front end lowered it to.
// The catalogue's hand translations set the flag where quadshade-bench-batch-width measured the
// pair of batches as one number of twice the width at most 0.95 of two batches' time; this rule
// predicts that measurement from what the code shows (docs/design.md, "Whole blocks are shaded
// two at a time").

#include "frontend/ir.h"

namespace qs::frontend {

// What the rule reads of a stage.
struct BatchWidthTraits {
    int peak_live_floats = 0;  // the most float registers live at once, over the inlined code in order
    int largest_table = 0;     // the most elements an indexed read (LoadIndexed) chooses among
    bool texture_in_loop = false;
};

BatchWidthTraits batch_width_traits(const ir::Stage& fragment);

// Twice the width pays unless the pair's values outgrow the registers (more than 128 float values
// live at once: the five-octave noises), the shader reads tables by index (a gather per lane either
// way, the permutation tables' 3D noises), or a loop waits on texture lookups.
bool wide_batches_pay(const BatchWidthTraits& t);
inline bool wide_batches_pay(const ir::Stage& fragment) { return wide_batches_pay(batch_width_traits(fragment)); }

}  // namespace qs::frontend
