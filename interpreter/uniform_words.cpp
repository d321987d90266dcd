#include "interpreter/uniform_words.h"

#include <bit>

namespace qs::interpreter {

namespace {

// Component `index` of a transform as the reference sets GL's matrices: the scene's
// model-view-projection matrix as the projection, the model-view matrix the identity (and so the
// normal matrix).
float transform_component(const Uniforms& u, ir::TransformUniform which, int index) {
    switch (which) {
        case ir::TransformUniform::ModelViewProjection:
        case ir::TransformUniform::Projection: return u.model_view_projection[index / 4][index % 4];
        case ir::TransformUniform::ModelView: return index / 4 == index % 4 ? 1.0f : 0.0f;
        case ir::TransformUniform::Normal: return index / 3 == index % 3 ? 1.0f : 0.0f;
    }
    return 0.0f;
}

}  // namespace

bool uniform_word(const ir::Program& program, const ir::Binding& b, const Uniforms& u, std::uint32_t& word) {
    switch (b.source) {
        case ir::Source::UserUniform:
            word = u.user ? u.user[std::size_t(b.slot) * kUniformWords + b.index] : program.uniforms[b.slot].initial[b.index];
            return true;
        case ir::Source::Time: word = std::bit_cast<std::uint32_t>(u.time); return true;
        case ir::Source::TeximageSize: {
            const float size = u.teximage ? float(b.index == 0 ? u.teximage->width : u.teximage->height) : 0.0f;
            word = std::bit_cast<std::uint32_t>(size);
            return true;
        }
        case ir::Source::Transform:
            word = std::bit_cast<std::uint32_t>(transform_component(u, ir::TransformUniform(b.slot), b.index));
            return true;
        default: return false;
    }
}

}  // namespace qs::interpreter
