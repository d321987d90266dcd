#include "scenes/scene.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace qs {

glm::mat4 Camera::projection(float aspect) const {
    if (kind == Kind::Orthographic) {
        // glTF's orthographic projection: x / xmag, y / ymag, z mapped from [-znear, -zfar].
        glm::mat4 p(0.0f);
        p[0][0] = 1.0f / xmag;
        p[1][1] = 1.0f / ymag;
        p[2][2] = 2.0f / (znear - zfar);
        p[3][2] = (zfar + znear) / (znear - zfar);
        p[3][3] = 1.0f;
        return p;
    }
    return glm::perspective(yfov, aspect, znear, zfar);
}

int Object::texture_for(std::string_view uniform) const {
    if (uniform == "teximage") return texture;
    for (const SamplerBinding& b : samplers) {
        if (b.uniform == uniform) return b.texture;
    }
    return -1;
}

bool Object::mirrors() const { return glm::determinant(glm::mat3(world_from_object)) < 0.0f; }

glm::mat4 Scene::model_view_projection(const Object& o, float aspect) const {
    return camera.projection(aspect) * camera.view * o.world_from_object;
}

}  // namespace qs
