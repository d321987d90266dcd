#include "scenes/object_uniforms.h"

#include <cmath>

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace qs {

std::vector<UniformSetting> object_uniforms(const Scene& scene, std::size_t i, const Pose& pose, double aspect) {
    const Object& o = scene.objects[i];
    const Material& m = o.look;
    const std::string origin = scene.file.string() + ": " + o.material;
    auto setting = [&](const char* name, std::vector<double> values) {
        return UniformSetting{name, std::move(values), origin};
    };
    auto matrix = [](const auto& mat, int n) {
        std::vector<double> v;
        for (int c = 0; c < n; ++c) {
            for (int r = 0; r < n; ++r) v.push_back(mat[c][r]);
        }
        return v;
    };
    const glm::dmat4 model_view = scene.view_from_object(pose, i);
    glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(model_view)));
    // An animation may scale an object to nothing: it draws nothing then, lit by anything finite.
    for (int c = 0; c < 3; ++c) {
        for (int r = 0; r < 3; ++r) {
            if (!std::isfinite(float(normal_matrix[c][r]))) normal_matrix = glm::dmat3(1.0);
        }
    }
    const glm::dmat4 p = scene.camera.projection(aspect);
    const int lighting = m.unlit ? 0 : scene.meshes[o.mesh].has_normals ? 1 : 2;
    return {
        setting("uBaseColorFactor",
                {m.base_color_factor.r, m.base_color_factor.g, m.base_color_factor.b, m.base_color_factor.a}),
        setting("uBaseColorTexCoord", {m.texcoord == 0 ? 0.0 : 1.0}),
        setting("uTextureTransform", matrix(m.texture_transform, 3)),
        setting("uAlphaMode", {double(int(m.alpha_mode))}),
        setting("uAlphaCutoff", {m.alpha_cutoff}),
        setting("uLighting", {double(lighting)}),
        setting("uModelView", matrix(model_view, 4)),
        setting("uNormalMatrix", matrix(normal_matrix, 3)),
        setting("uUnproject", {1.0 / p[0][0], 1.0 / p[1][1], p[2][3], p[3][3]}),
    };
}

}  // namespace qs
