#pragma once
// A scene for discard under depth testing: the Table 1.1 plane twice, a depth-tested plane
// (st_derivative_probe) behind and the discard probe in front, drawn in either order. Where the
// front discards, the back must show whichever came first: discarded fragments write no depth.

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/gltf.h"
#include "tests/test_paths.h"

namespace qs::test {

inline Scene discard_scene(bool front_first, int width, int height) {
    Scene s = load_scene(kPlane);
    Object back = s.objects[0], front = s.objects[0];
    back.name = "back", back.shader = "st_derivative_probe";
    back.world_from_object = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -0.25f));
    front.name = "front", front.shader = "discard_probe";
    front.world_from_object = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 0.25f));  // nearer the camera
    s.objects = front_first ? std::vector<Object>{front, back} : std::vector<Object>{back, front};
    s.width = width, s.height = height;
    return s;
}

}  // namespace qs::test
