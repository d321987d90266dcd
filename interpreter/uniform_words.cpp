#include "interpreter/uniform_words.h"

#include <bit>

namespace qs::interpreter {

namespace {

// Component `index` of a transform. GL's built-in matrices as the reference sets them: the
// scene's model-view-projection matrix as the projection, the model-view matrix the identity (and
// so the normal matrix); the scene's own transforms, by name, as they are.
float transform_component(const Uniforms& u, ir::TransformUniform which, int index) {
    const int column4 = index / 4, row4 = index % 4, column3 = index / 3, row3 = index % 3;
    switch (which) {
        case ir::TransformUniform::ModelViewProjection:
        case ir::TransformUniform::Projection: return u.model_view_projection[column4][row4];
        case ir::TransformUniform::ModelView: return column4 == row4 ? 1.0f : 0.0f;
        case ir::TransformUniform::Normal: return column3 == row3 ? 1.0f : 0.0f;
        case ir::TransformUniform::Model: return u.model[column4][row4];
        case ir::TransformUniform::View: return u.view[column4][row4];
        case ir::TransformUniform::SceneProjection: return u.projection[column4][row4];
        case ir::TransformUniform::SceneNormal: return u.normal_matrix[column3][row3];
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
