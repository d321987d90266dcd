#include "study/stability.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "images/image_io.h"
#include "render/frame_image.h"
#include "render/scene_render.h"
#include "shading/shade_choice.h"
#include "study/image_error.h"

namespace qs::study {

namespace fs = std::filesystem;

Stability stability(const Scene& original, const std::string& shader, std::optional<double> time, int threads,
                    const fs::path& dir, const std::string& relative) {
    Scene scene = original;
    FrameRequest f;
    f.width = scene.width, f.height = scene.height;
    f.shader_override = shader;
    f.time = time;
    f.shading.threads = threads;
    const Image single = colour_image(render_frame(scene, f));
    f.shading.precision = Precision::Double;
    const Image twice = colour_image(render_frame(scene, f));
    Stability s;
    const Error e = error_of(single, twice);
    s.rms = e.rms, s.max = e.max;
    for (std::size_t p = 0; p < single.rgba.size() / 4; ++p) {
        int worst = 0;
        for (int c = 0; c < 3; ++c) {
            worst = std::max(worst, std::abs(int(unorm8(single.rgba[p * 4 + c])) - int(unorm8(twice.rgba[p * 4 + c]))));
        }
        s.over_1 += worst > 1;
    }
    write_image(dir / "float.png", single);
    write_image(dir / "double.png", twice);
    write_image(dir / "float-vs-double.png", difference_heat_map(single, twice, 8.0f / 255.0f));
    s.float_image = relative + "/float.png", s.double_image = relative + "/double.png";
    s.heat_image = relative + "/float-vs-double.png";
    f.shading.precision = Precision::Float;
    f.shading.check_undefined = true;
    try {
        const Framebuffer fb = render_frame(scene, f);
        s.checked = true;
        s.undefined = count_undefined(fb);
        write_image(dir / "undefined.png", undefined_mask_image(fb));
        s.mask_image = relative + "/undefined.png";
    } catch (const UnsupportedRequest& e) {
        s.note = e.what();
    }
    return s;
}

void offset_coordinates(Scene& scene, const glm::dvec3& offset) {
    const glm::vec3 o(offset);
    for (Mesh& m : scene.meshes) {
        for (Vertex& v : m.vertices) v.position += o, v.texcoord += glm::vec2(o);
    }
    for (Object& object : scene.objects)
        object.world_from_object = object.world_from_object * glm::translate(glm::dmat4(1.0), -glm::dvec3(o));
}

}  // namespace qs::study
