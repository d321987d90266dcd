#pragma once
// The contract between the shader translations and whatever produces fragments (the rasterizer,
// the ray caster). A Program is one catalogue shader with its vertex stage and its fragment
// stage instantiated for every number type; the caller picks the instantiation per batch with a
// ShadeMode. Nothing here knows about images, tiles or threads: a FragmentBatch is just
// kBatchLanes fragments' inputs, laid out as 4 quads when a quad mode is used.

#include "shading/batches.h"
#include "shading/shade_mode.h"
#include "shading/shader_info.h"
#include "shading/shader_uniforms.h"

namespace qs {

class Program {
public:
    virtual ~Program() = default;
    virtual const ShaderInfo& info() const = 0;
    virtual void vertex(const VertexIn& in, const Uniforms& u, VertexOut& out) const = 0;
    // Precondition: mode.derivatives != None unless !info().needs.derivatives.
    virtual void shade(ShadeMode mode, const FragmentBatch& in, const Uniforms& u, ColorBatch& out) const = 0;
    // Shades two batches at once, with the same results as shade() on each. For a shader with
    // ShaderInfo::wide_batches, shaded in float on AVX-512 (a batch is then one register) per
    // pixel or in quads by llvmpipe's rule, both go through the shader as one number of twice
    // the width: every operation becomes two independent instructions, which the CPU overlaps,
    // while one batch alone leaves a noise shader's long dependency chains exposed. Otherwise
    // two shade() calls.
    virtual void shade_pair(ShadeMode mode, const FragmentBatch& a, const FragmentBatch& b, const Uniforms& u,
                            ColorBatch& out_a, ColorBatch& out_b) const = 0;
};

}  // namespace qs
