#include "render/scene_render.h"

#include <algorithm>
#include <cmath>

#include "raster/triangle_setup.h"
#include "shading/catalogue.h"
#include "render/atlas_program.h"
#include "render/textures.h"
#include "render/uniform_binding.h"
#if defined(QUADSHADE_HAS_RAYCAST)
#include "raycast/embree_scene.h"
#include "raycast/ray_caster.h"
#endif

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

bool binds_samplers(const Scene& scene, const ShaderInfo& info) {
    for (const Object& o : scene.objects) {
        if (info.needs.texture && o.texture < 0) return false;
        for (const SamplerUse& s : info.needs.samplers) {
            if (!s.name.empty() && o.texture_for(s.name) < 0) return false;
        }
    }
    return !scene.objects.empty();
}

void check_supported(const FrameRequest& request) {
    const ShadingSettings& s = request.shading;
    check_supported(ShadeRequest{s.derivatives, s.precision, s.check_undefined, request.raster.force_general_path});
    if (request.backend != Backend::RayCaster) return;
    if (request.atlas) throw UnsupportedRequest("an atlas bake is drawn by the rasterizer, not the ray caster");
    // The ray caster's rays meet the surface in double: it has no fill rule, no plane
    // interpolation to fuse, and shades every draw as its needs say.
    if (request.raster != RasterSettings{}) {
        throw UnsupportedRequest("the ray caster has no fill rule, plane interpolation or general path: those are the "
                                 "rasterizer's settings");
    }
}

const glsl::Texture& SceneRenderer::texture_for(const Object& o, const Program& program, std::string_view uniform, int dims) {
    const std::string what = scene_.file.string() + ": material '" + o.material + "': shader '" +
                             std::string(program.info().name) + "' samples " + (dims == 3 ? "a sampler3D" : "a sampler2D") +
                             " '" + std::string(uniform) + "'";
    const int index = o.texture_for(uniform);
    if (index < 0) {
        throw SceneError(what + (uniform == "teximage" ? " but the material has no pbrMetallicRoughness.baseColorTexture, "
                                                         "extras.teximage or extras.textures.teximage"
                                                       : " but the material's extras.textures binds no texture to it"));
    }
    const Texture& source = scene_.textures[std::size_t(index)];
    if (source.dims != dims) {
        throw SceneError(what + " but " + source.field + " is a " + std::to_string(source.dims) + "D texture" +
                         (dims == 3 ? " (a 3D texture's binding gives its depth)" : ""));
    }
    std::unique_ptr<glsl::Texture>& t = textures_[std::size_t(index)];
    if (!t) t = load_texture(scene_, source);
    return *t;
}

#if defined(QUADSHADE_HAS_RAYCAST)
struct SceneRenderer::Caster {
    Caster(std::span<const DrawCall> draws, const glm::mat4& clip_from_world) : caster(draws, clip_from_world) {}
    RayCaster caster;
};
#else
struct SceneRenderer::Caster {};
#endif

SceneRenderer::SceneRenderer(Scene& scene, const FrameRequest& request)
    : scene_(scene),
      request_(request),
      width_(request.width > 0 ? request.width : scene.width),
      height_(request.height > 0 ? request.height : scene.height) {
    check_supported(request);
    const float aspect = float(width_) / float(height_);
    vertices_.resize(scene.meshes.size());
    textures_.resize(scene.textures.size());
    draws_.reserve(scene.objects.size());
    for (const Object& o : scene.objects) {
        const Program& program = program_for(scene, o, request.shader_override);
        DrawCall d;
        const Mesh& mesh = scene.meshes[o.mesh];
        std::vector<VertexIn>& vertices = vertices_[o.mesh];
        if (vertices.empty()) {
            vertices.reserve(mesh.vertices.size());
            for (const Vertex& v : mesh.vertices) {
                VertexIn in{v.position, v.texcoord};
                in.id = std::uint32_t(vertices.size());  // gl_VertexID
                vertices.push_back(in);
            }
        }
        d.vertices = vertices;
        d.indices = mesh.indices;
        d.program = &program;
        if (request.atlas) d.program = atlas_programs_.emplace_back(std::make_unique<AtlasProgram>(program)).get();
        d.uniforms.model_view_projection = scene.model_view_projection(o, aspect);
        // An atlas bake draws every triangle in texture space, where winding says nothing of facing.
        if (!request.atlas) d.culling = {!o.double_sided, o.mirrors() ? Winding::Clockwise : Winding::CounterClockwise};
        d.uniforms.time = float(request.time.value_or(double(scene.time)));
        const Needs& needs = program.info().needs;
        if (needs.coordinates == Coordinates::Texcoord2D && !mesh.has_texcoords) {
            const std::string note = scene.file.string() + ": mesh '" + mesh.name + "' has no TEXCOORD_0: shader '" +
                                     std::string(program.info().name) +
                                     "' reads texture coordinates, (0, 0) at every vertex (as in GL)";
            if (std::find(notes_.begin(), notes_.end(), note) == notes_.end()) notes_.push_back(note);
        }
        if (needs.texture) {
            d.uniforms.teximage = static_cast<const glsl::sampler2D*>(&texture_for(o, program, "teximage", 2));
            d.texture_lod = d.uniforms.teximage->needs_lod();
        }
        for (std::size_t i = 0; i < needs.samplers.size() && !needs.samplers[i].name.empty(); ++i) {
            const glsl::Texture& t = texture_for(o, program, needs.samplers[i].name, needs.samplers[i].dims);
            d.uniforms.samplers[i] = &t;
            d.texture_lod = d.texture_lod || t.needs_lod();
        }
        uniform_words_.push_back(bind_uniforms(program.info(), merge_uniforms(o.uniforms, request.uniforms), width_,
                                               height_, !request.shader_override.empty()));
        d.uniforms.user = uniform_words_.back().data();  // its buffer stays put as the outer vector grows
        draws_.push_back(d);
    }
    for (const UniformSetting& s : request.uniforms) {
        bool declared = false;
        for (const DrawCall& d : draws_) declared = declared || declares_uniform(d.program->info(), s.name);
        if (!declared) throw UniformOptionError(s.origin + ": no shader in this scene declares a uniform '" + s.name + "'");
    }
    if (request.backend == Backend::RayCaster) {
#if defined(QUADSHADE_HAS_RAYCAST)
        const Camera& c = scene.camera;
        try {
            caster_ = std::make_unique<Caster>(draws_, c.projection(aspect) * c.view);
        } catch (const RayCastError& e) {
            throw SceneError(scene.file.string() + ": " + e.what());
        }
#else
        throw std::runtime_error("this quadshade was built without the ray caster (QUADSHADE_RAYCAST=OFF: no Embree)");
#endif
    }
}

SceneRenderer::~SceneRenderer() = default;

bool SceneRenderer::depends_on_time() const {
    for (const DrawCall& d : draws_) {
        if (d.program->info().needs.time) return true;
    }
    return false;
}

double SceneRenderer::bvh_build_seconds() const {
#if defined(QUADSHADE_HAS_RAYCAST)
    if (caster_) return caster_->caster.build_seconds();
#endif
    return 0.0;
}

std::uint64_t SceneRenderer::frame_bytes(int rows) const {
    // The rasterizer decides on a depth buffer per frame (depth_buffer.h): counted whenever it may.
    const bool depth = request_.backend == Backend::Rasterizer;
    std::uint64_t vertices = 0, triangles = 0;
    for (const DrawCall& d : draws_) {
        vertices += d.vertices.size();
        triangles += d.indices.size() / 3;
    }
    const std::uint64_t pixels = std::uint64_t(width_) * std::uint64_t(rows);
    const std::uint64_t per_pixel = 4 * sizeof(float) + (depth ? sizeof(float) : 0) + (request_.shading.check_undefined ? 1 : 0);
    // Clipped vertices (vertex stage output) and triangle setups with their tile bins; a
    // triangle clipped into a fan counts about twice. Measured sizes, rounded up.
    constexpr std::uint64_t kPerVertex = 128, kPerTriangle = 2 * (sizeof(TriangleSetup) + 64);
    return pixels * per_pixel + vertices * kPerVertex + triangles * kPerTriangle;
}

void SceneRenderer::render_into(Framebuffer& fb, std::optional<double> time, RenderStats* stats, RowBand band) {
    const double t = time.value_or(request_.time.value_or(double(scene_.time)));
    for (DrawCall& d : draws_) {
        const double period = d.program->info().time_period;
        d.uniforms.time = float(request_.stable_time && period > 0.0 ? t - period * std::floor(t / period) : t);
    }
#if defined(QUADSHADE_HAS_RAYCAST)
    if (caster_) {
        try {
            caster_->caster.render_into(fb, width_, height_, scene_.clear_color, draws_, request_.shading, stats, band);
        } catch (const RayCastError& e) {
            throw SceneError(scene_.file.string() + ": " + e.what());
        }
        return;
    }
#endif
    rasterize_into(fb, width_, height_, scene_.clear_color, draws_, request_.raster_options(), stats, band,
                   &raster_memory_);
}

Framebuffer render_frame(Scene& scene, const FrameRequest& request, RenderStats* stats) {
    Framebuffer fb;
    render_frame_into(fb, scene, request, stats);
    return fb;
}

void render_frame_into(Framebuffer& fb, Scene& scene, const FrameRequest& request, RenderStats* stats) {
    SceneRenderer(scene, request).render_into(fb, std::nullopt, stats);
}

}  // namespace qs
