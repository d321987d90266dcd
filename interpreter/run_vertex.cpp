// The vertex stage, one vertex at a time in float, as GL's vertex stage computes it.
#include "interpreter/run_stage_impl.h"

namespace qs::interpreter {

static_assert(ir::kMaxClipDistances == kMaxClipDistances);

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
        switch (b.source) {
            case ir::Source::Attribute: r.f[b.reg] = attribute_component(in, ir::Attribute(b.slot), b.index); break;
            case ir::Source::GenericAttribute: {
                const AttributeValue* values = b.slot < kMaxGenericAttributes ? u.attributes[b.slot] : nullptr;
                // Without an array, GL's current value: (0, 0, 0, 1), in the attribute's type.
                const std::uint32_t one = b.bank == ir::Bank::Float ? std::bit_cast<std::uint32_t>(1.0f) : 1u;
                const std::uint32_t word = values ? values[in.id][b.index] : b.index == 3 ? one : 0u;
                using namespace executor_detail;
                switch (b.bank) {
                    case ir::Bank::Float: r.f[b.reg] = from_word<float, Bool<float>>(word); break;
                    case ir::Bank::Int: r.i[b.reg] = from_word<int_t<float>, Bool<float>>(word); break;
                    case ir::Bank::Uint: r.u[b.reg] = from_word<uint_t<float>, Bool<float>>(word); break;
                    case ir::Bank::Bool: break;
                }
                break;
            }
            case ir::Source::VertexId: r.i[b.reg] = int_t<float>(std::int32_t(in.id)); break;
            default: break;
        }
    }
    const RunResult result = Executor<float>::run(stage, r, textures);
    bool clip_vertex = false;
    glm::vec4 clip_vertex_value(0.0f);
    for (const ir::Binding& b : stage.outputs) {
        if (b.source == ir::Source::Position) {
            out.clip[b.index] = r.f[b.reg];
        } else if (b.source == ir::Source::ClipDistance) {
            out.clip_distances[b.index] = r.f[b.reg];
        } else if (b.source == ir::Source::ClipVertex) {
            clip_vertex = true;
            clip_vertex_value[b.index] = r.f[b.reg];
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
    // gl_ClipVertex: each user plane's distance, as GL's clipping takes it.
    if (clip_vertex) {
        for (int i = 0; i < kMaxClipDistances; ++i) {
            const glm::vec4& p = u.clip_planes[std::size_t(i)];
            out.clip_distances[std::size_t(i)] =
                p.x * clip_vertex_value.x + p.y * clip_vertex_value.y + p.z * clip_vertex_value.z + p.w * clip_vertex_value.w;
        }
    }
    return result;
}

}  // namespace qs::interpreter
