#include "frontend/binding_names.h"

namespace qs::frontend {

std::optional<ir::Attribute> attribute_named(const std::string& name) {
    if (name == "position") return ir::Attribute::Position;
    if (name == "normal") return ir::Attribute::Normal;
    if (name == "texcoord" || name == "texcoord0" || name == "uv") return ir::Attribute::Texcoord0;
    if (name == "texcoord1" || name == "uv1") return ir::Attribute::Texcoord1;
    if (name == "color") return ir::Attribute::Color;
    return std::nullopt;
}

std::optional<ir::TransformUniform> transform_named(const std::string& name) {
    if (name == "mvp" || name == "modelViewProjection") return ir::TransformUniform::ModelViewProjection;
    if (name == "modelView") return ir::TransformUniform::ModelView;
    if (name == "projection") return ir::TransformUniform::Projection;
    if (name == "normalMatrix") return ir::TransformUniform::Normal;
    return std::nullopt;
}

std::string transform_description(ir::TransformUniform t) {
    switch (t) {
        case ir::TransformUniform::ModelViewProjection: return "model-view-projection matrix";
        case ir::TransformUniform::ModelView: return "model-view matrix";
        case ir::TransformUniform::Projection: return "projection matrix";
        case ir::TransformUniform::Normal: return "normal matrix";
    }
    return "matrix";
}

std::string attribute_names_help() {
    return "name it position, normal, texcoord (or texcoord0, uv), texcoord1 (or uv1) or color, or use gl_Vertex, "
           "gl_Normal, gl_MultiTexCoord0, gl_MultiTexCoord1, gl_Color";
}

}  // namespace qs::frontend
