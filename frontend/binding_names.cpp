#include "frontend/binding_names.h"

#include "scenes/shader_inputs.h"

namespace qs::frontend {

std::optional<ir::Attribute> attribute_named(const std::string& name) {
    const VertexAttributeName* a = find_vertex_attribute(name);
    if (!a) return std::nullopt;
    switch (a->attribute) {
        case VertexAttribute::Position: return ir::Attribute::Position;
        case VertexAttribute::Normal: return ir::Attribute::Normal;
        case VertexAttribute::Texcoord0: return ir::Attribute::Texcoord0;
        case VertexAttribute::Texcoord1: return ir::Attribute::Texcoord1;
        case VertexAttribute::Color: return ir::Attribute::Color;
    }
    return std::nullopt;
}

std::optional<ir::TransformUniform> transform_named(const std::string& name) {
    const SceneMatrixName* m = find_scene_matrix(name);
    if (!m) return std::nullopt;
    switch (m->matrix) {
        case SceneMatrix::ModelViewProjection: return ir::TransformUniform::ModelViewProjection;
        case SceneMatrix::Model: return ir::TransformUniform::Model;
        case SceneMatrix::View: return ir::TransformUniform::View;
        case SceneMatrix::Projection: return ir::TransformUniform::SceneProjection;
        case SceneMatrix::Normal: return ir::TransformUniform::SceneNormal;
    }
    return std::nullopt;
}

std::string transform_description(ir::TransformUniform t) {
    switch (t) {
        case ir::TransformUniform::ModelViewProjection: return "model-view-projection matrix";
        case ir::TransformUniform::ModelView: return "model-view matrix";
        case ir::TransformUniform::Projection:
        case ir::TransformUniform::SceneProjection: return "projection matrix";
        case ir::TransformUniform::Normal:
        case ir::TransformUniform::SceneNormal: return "normal matrix";
        case ir::TransformUniform::Model: return "model matrix";
        case ir::TransformUniform::View: return "view matrix";
    }
    return "matrix";
}

std::string attribute_names_help() {
    std::string names;
    for (const VertexAttributeName& a : kVertexAttributes) names += (names.empty() ? "" : ", ") + std::string(a.name);
    return "name it one of " + names + ", or use gl_Vertex, gl_Normal, gl_MultiTexCoord0, gl_MultiTexCoord1, gl_Color";
}

}  // namespace qs::frontend
