#include "render/volume_bake.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "shading/catalogue.h"

namespace qs {

float volume_texel_centre(int index, int size) { return -1.0f + 2.0f * (float(index) + 0.5f) / float(size); }

Scene volume_slice_scene(const VolumeRequest& request, int k) {
    const int n = request.size;
    Scene s;
    if (request.material_scene) {
        s.file = request.material_scene->file;
        s.textures = request.material_scene->textures;
        s.inputs = request.material_scene->inputs;
    }
    const float z = volume_texel_centre(k, n);
    Mesh square{"volume slice", {}, {0, 1, 2, 0, 2, 3}};
    // st as a glTF plane maps it: (0, 0) at the top-left corner.
    square.vertices = {{{-1.0f, -1.0f, z}, {0.0f, 1.0f}}, {{1.0f, -1.0f, z}, {1.0f, 1.0f}},
                       {{1.0f, 1.0f, z}, {1.0f, 0.0f}}, {{-1.0f, 1.0f, z}, {0.0f, 0.0f}}};
    s.meshes = {square};
    Object o;
    if (request.material_scene && !request.material_scene->objects.empty()) o = request.material_scene->objects.front();
    o.name = "volume slice " + std::to_string(k), o.mesh = 0, o.world_from_object = glm::mat4(1.0f);
    o.shader = request.shader;
    s.objects = {o};
    s.camera.kind = Camera::Kind::Orthographic;
    s.camera.view = glm::lookAt(glm::vec3(0.0f, 0.0f, 3.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    s.camera.xmag = s.camera.ymag = 1.0f;
    s.camera.znear = 1.0f, s.camera.zfar = 5.0f;
    s.clear_color = glm::vec4(0.0f);
    s.width = s.height = n;
    return s;
}

Image bake_volume(const VolumeRequest& request) {
    const int n = request.size;
    if (n < 1 || n > kMaxVolumeSide) {
        throw std::invalid_argument("a volume's side must be 1 to " + std::to_string(kMaxVolumeSide) + " texels, got " +
                                    std::to_string(n));
    }
    FrameRequest frame = request.frame;
    frame.width = frame.height = n;
    frame.shader_override.clear();
    Image volume{n, n * n, std::vector<float>(std::size_t(n) * std::size_t(n) * std::size_t(n) * 4)};
    const std::size_t row_floats = std::size_t(n) * 4;
    // A volume has no material of its own: a shader that samples textures needs a --scene whose
    // first object binds them (a render reads white for an unbound one; a bake would keep it).
    if (const Program* p = find_program(request.shader); p && !binds_samplers(volume_slice_scene(request, 0), p->info())) {
        throw SceneError("bake-volume: shader '" + request.shader + "' samples textures that " +
                         (request.material_scene ? request.material_scene->file.string() + "'s first object does not bind"
                                                 : std::string("only a scene's material binds (--scene)")));
    }
    for (int k = 0; k < n; ++k) {
        Scene slice = volume_slice_scene(request, k);
        const Framebuffer fb = render_frame(slice, frame);
        // The frame's top row is y = +1, the last texel row of the slice.
        for (int j = 0; j < n; ++j) {
            const float* from = fb.rgba.data() + std::size_t(n - 1 - j) * row_floats;
            std::memcpy(volume.rgba.data() + (std::size_t(k) * std::size_t(n) + std::size_t(j)) * row_floats, from,
                        row_floats * sizeof(float));
        }
    }
    return volume;
}

}  // namespace qs
