// The vertex stage, one vertex at a time in float, as GL's vertex stage computes it.
#include "interpreter/run_stage_impl.h"

namespace qs::interpreter {

namespace {

// Component `index` of a vertex attribute, with the values GL supplies for the components an
// array lacks: (x, y, z, 1) for positions and texture coordinates, (r, g, b, a) colours.
float attribute_component(const VertexIn& in, ir::Attribute which, int index) {
    switch (which) {
        case ir::Attribute::Position: return index < 3 ? in.position[index] : 1.0f;
        case ir::Attribute::Texcoord0: return index < 2 ? in.texcoord[index] : index == 3 ? 1.0f : 0.0f;
        case ir::Attribute::Normal: return index < 3 ? in.normal[index] : 0.0f;
        case ir::Attribute::Color: return in.color[index];
        case ir::Attribute::Texcoord1: return index < 2 ? in.texcoord1[index] : index == 3 ? 1.0f : 0.0f;
    }
    return 0.0f;
}

}  // namespace

RunResult run_vertex(const ir::Program& program, const VertexIn& in, const Uniforms& u, const TextureSlots& textures,
                     VertexOut& out) {
    const ir::Stage& stage = program.vertex;
    Registers<float>& r = thread_registers<float>(stage);
    fill_uniforms(program, stage, u, r);
    for (const ir::Binding& b : stage.inputs) {
        if (b.source == ir::Source::Attribute) r.f[b.reg] = attribute_component(in, ir::Attribute(b.slot), b.index);
    }
    const RunResult result = Executor<float>::run(stage, r, textures);
    for (const ir::Binding& b : stage.outputs) {
        if (b.source == ir::Source::Position) {
            out.clip[b.index] = r.f[b.reg];
        } else if (b.source == ir::Source::Varying) {
            // An int varying travels as its bits (it is flat: never interpolated).
            switch (b.bank) {
                case ir::Bank::Float: out.varyings[b.index] = r.f[b.reg]; break;
                case ir::Bank::Int: out.varyings[b.index] = std::bit_cast<float>(r.i[b.reg][0]); break;
                case ir::Bank::Uint: out.varyings[b.index] = std::bit_cast<float>(r.u[b.reg][0]); break;
                case ir::Bank::Bool: break;
            }
        }
    }
    return result;
}

}  // namespace qs::interpreter
