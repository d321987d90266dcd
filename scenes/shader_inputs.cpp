#include "scenes/shader_inputs.h"

#include <glm/matrix.hpp>

#include "scenes/scene.h"

namespace qs {

std::string_view scene_matrix_names() { return "mvp, modelViewProjection, model, view, projection, normalMatrix"; }

std::string_view vertex_attribute_names() { return "position, normal, texcoord, texcoord0, texcoord1, color"; }

ObjectTransforms object_transforms(const Scene& scene, const Object& object, float aspect) {
    ObjectTransforms t;
    t.model_view_projection = scene.model_view_projection(object, aspect);
    t.model = object.world_from_object;
    t.view = scene.camera.view;
    t.projection = scene.camera.projection(aspect);
    t.normal = glm::transpose(glm::inverse(glm::mat3(t.view * t.model)));
    return t;
}

}  // namespace qs
