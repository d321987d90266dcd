#include "scenes/shader_inputs.h"

#include <glm/matrix.hpp>

#include "scenes/scene.h"

namespace qs {

std::string_view scene_matrix_names() { return "mvp, modelViewProjection, model, view, projection, normalMatrix"; }

std::string_view vertex_attribute_names() { return "position, normal, texcoord, texcoord0, texcoord1, color"; }

ObjectTransforms object_transforms(const Scene& scene, const Pose& pose, std::size_t i, double aspect) {
    ObjectTransforms t;
    t.model_view_projection = scene.clip_from_object(pose, i, aspect);
    t.model = glm::mat4(pose.world_from_object[i]);
    t.view = glm::mat4(pose.view);
    t.projection = glm::mat4(scene.camera.projection(aspect));
    t.normal = glm::mat3(glm::transpose(glm::inverse(glm::dmat3(scene.view_from_object(pose, i)))));
    return t;
}

}  // namespace qs
