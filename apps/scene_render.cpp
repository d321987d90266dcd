#include "scene_render.h"

#include "catalogue.h"
#include "image_io.h"

namespace qs {

const Program& program_for(const Scene& scene, const Object& object, const std::string& shader_override) {
    const std::string& name = shader_override.empty() ? object.shader : shader_override;
    if (name.empty()) {
        throw SceneError(scene.file.string() + ": material '" + object.material + "' of '" + object.name +
                         "' names no shader (extras.shader); pass --shader NAME");
    }
    const Program* p = find_program(name);
    if (!p) {
        throw SceneError((shader_override.empty() ? scene.file.string() + ": material '" + object.material +
                                                        "' extras.shader"
                                                  : std::string("--shader")) +
                         ": unknown shader '" + name + "' (quadshade shaders lists them)");
    }
    return *p;
}

const glsl::sampler2D& texture_for(Scene& scene, const Object& o, const Program& program) {
    if (o.texture < 0) {
        throw SceneError(scene.file.string() + ": material '" + o.material + "': shader '" +
                         std::string(program.info().name) + "' samples a texture but extras.teximage is missing");
    }
    Texture& t = scene.textures[std::size_t(o.texture)];
    if (!t.loaded) {
        try {
            t.texels = load_texture(t.path);
        } catch (const ImageError& e) {
            throw SceneError(scene.file.string() + ": material '" + o.material + "' extras.teximage: " + e.what());
        }
        t.loaded = true;
    }
    return t.texels;
}

Framebuffer render_frame(Scene& scene, const FrameRequest& request, RasterStats* stats) {
    Framebuffer fb;
    render_frame_into(fb, scene, request, stats);
    return fb;
}

void render_frame_into(Framebuffer& fb, Scene& scene, const FrameRequest& request, RasterStats* stats) {
    const int width = request.width > 0 ? request.width : scene.width;
    const int height = request.height > 0 ? request.height : scene.height;
    const float aspect = float(width) / float(height);
    std::vector<DrawCall> draws;
    draws.reserve(scene.objects.size());
    for (const Object& o : scene.objects) {
        const Program& program = program_for(scene, o, request.shader_override);
        DrawCall d;
        const Mesh& mesh = scene.meshes[o.mesh];
        d.vertices = mesh.vertices;
        d.indices = mesh.indices;
        d.program = &program;
        d.uniforms.model_view_projection = scene.model_view_projection(o, aspect);
        d.uniforms.time = request.time.value_or(scene.time);
        if (program.info().needs.texture) d.uniforms.teximage = &texture_for(scene, o, program);
        draws.push_back(d);
    }
    rasterize_into(fb, width, height, scene.clear_color, draws, request.raster, stats);
}

}  // namespace qs
