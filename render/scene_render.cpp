#include "render/scene_render.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "raster/triangle_setup.h"
#include "shading/catalogue.h"
#include "render/atlas_program.h"
#include "render/memory_plan.h"
#include "render/glsl_shaders.h"
#include "render/textures.h"
#include "shading/glsl/texture_cube.h"
#include "render/uniform_binding.h"
#include "interpreter/glsl_program.h"
#include "scenes/object_uniforms.h"
#include "scenes/shader_inputs.h"
#if defined(QUADSHADE_HAS_RAYCAST)
#include "raycast/embree_scene.h"
#include "raycast/ray_caster.h"
#include "raycast/screen_footprint.h"
#endif

namespace qs {

namespace {

// What the ray caster holds per triangle: world positions, planes, the footprint on screen and
// Embree's BVH. Measured, rounded up (docs/results.md, "The cost of one call").
constexpr std::uint64_t kRayCastBytesPerTriangle = 512;

}  // namespace

const Program& program_for(const Scene& scene, const Object& object, const std::string& shader_override, GlslWay way,
                           const std::vector<ShadeRequest>& shading) {
    if (shader_override.empty() && !object.glsl_fragment.empty()) {
        try {
            const std::optional<std::filesystem::path> vertex =
                object.glsl_vertex.empty() ? std::nullopt : std::optional<std::filesystem::path>(object.glsl_vertex);
            return *load_glsl_shader(object.glsl_fragment, vertex, way, shading).program;
        } catch (const std::runtime_error& e) {
            throw SceneError(scene.file.string() + ": " + object.material + ": extras.glsl: " + e.what());
        }
    }
    const std::string& name = !shader_override.empty() ? shader_override
                              : !object.shader.empty() ? object.shader
                                                       : std::string(kDefaultMaterialShader);
    const Program* p = find_program(name);
    if (!p) {
        throw SceneError((shader_override.empty() ? scene.file.string() + ": " + object.material + ": extras.shader"
                                                  : std::string("--shader")) +
                         ": unknown shader '" + name + "' (quadshade shaders lists them)");
    }
    return *p;
}

void check_programs(const Scene& scene, const std::string& shader_override, GlslWay way,
                    const std::vector<ShadeRequest>& shading) {
    std::vector<std::string> problems;
    for (const Object& o : scene.objects) {
        try {
            program_for(scene, o, shader_override, way, shading);
        } catch (const SceneError& e) {
            if (std::find(problems.begin(), problems.end(), e.what()) == problems.end()) problems.push_back(e.what());
        }
    }
    if (problems.empty()) return;
    std::string all;
    for (const std::string& p : problems) all += (all.empty() ? "" : "\n") + p;
    throw SceneError(all);
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

ShadeRequest shade_request(const FrameRequest& request) {
    const ShadingSettings& s = request.shading;
    return {s.derivatives, s.precision, s.check_undefined, request.raster.force_general_path};
}

namespace {

// A cube map's kind has one number in the scene (a texture's dims), a GLSL program (a sampler's)
// and the sampled texture, which this file passes from one to the next.
static_assert(kCubeMap == glsl::kCubeDims && ir::kCubeSampler == glsl::kCubeDims);

// Whether the sampler `uniform` of `program` is a shadow sampler.
bool shadow_sampler(const Program& program, std::string_view uniform) {
    for (const SamplerUse& s : program.info().needs.samplers) {
        if (s.name == uniform) return s.shadow;
    }
    return false;
}

}  // namespace

void check_supported(const FrameRequest& request) {
    check_supported(shade_request(request));
    if (request.backend != Backend::RayCaster) return;
    if (request.atlas) throw UnsupportedRequest("an atlas bake is drawn by the rasterizer, not the ray caster");
    // The ray caster's rays meet the surface in double: it has no fill rule, no plane
    // interpolation to fuse, and shades every draw as its needs say.
    if (request.raster != RasterSettings{}) {
        throw UnsupportedRequest("the ray caster has no fill rule, plane interpolation or general path: those are the "
                                 "rasterizer's settings");
    }
}

const glsl::Texture& SceneRenderer::texture_for(const Object& o, const Program& program, std::string_view uniform,
                                                int dims) {
    const int index = o.texture_for(uniform);
    const std::string shader(program.info().name);
    if (index < 0) {
        // The default material reads white where the material has no base colour texture, as
        // glTF asks; another shader is told once, with every material it concerns.
        if (shader != kDefaultMaterialShader) {
            std::vector<std::string>& materials = missing_samplers_[shader + "' samples '" + std::string(uniform)];
            // Objects share materials: a material is counted once, however many nodes draw it.
            if (std::find(materials.begin(), materials.end(), o.material) == materials.end()) {
                materials.push_back(o.material);
            }
        }
        return white_texture(dims);
    }
    const Texture& source = scene_.textures[std::size_t(index)];
    const bool shadow = shadow_sampler(program, uniform);
    const bool cube = dims == glsl::kCubeDims;
    const auto kind = [](int d, bool depth) {
        return std::string(d == glsl::kCubeDims ? (depth ? "samplerCubeShadow" : "samplerCube")
                           : d == 3             ? "sampler3D"
                                                : (depth ? "sampler2DShadow" : "sampler2D"));
    };
    const auto texture_kind = [](const Texture& t) {
        return std::string(t.dims == kCubeMap ? "a cube map" : t.dims == 3 ? "a 3D texture" : "a 2D texture");
    };
    if (source.dims != dims) {
        throw SceneError(scene_.file.string() + ": " + o.material + ": shader '" + shader + "' samples a " +
                         kind(dims, shadow) + " '" + std::string(uniform) + "' but " + source.field + " is " +
                         texture_kind(source) +
                         (dims == 3 ? " (a 3D texture's binding gives its depth)"
                          : cube    ? " (a cube map's binding gives its six faces)"
                                    : ""));
    }
    // A shadow sampler reads a depth comparison texture, and only it does (GL leaves either
    // mismatch undefined).
    if (shadow != source.compare.has_value()) {
        throw SceneError(scene_.file.string() + ": " + o.material + ": shader '" + shader + "' samples a " +
                         kind(dims, shadow) + " '" + std::string(uniform) + "' but " + source.field +
                         (shadow ? " is not a depth comparison texture (its binding needs a \"compare\" function)"
                                  : " is a depth comparison texture, for a " + kind(dims, true)));
    }
    std::unique_ptr<glsl::Texture>& t = textures_[std::size_t(index)];
    if (!t) {
        try {
            std::uint64_t loading = 0;
            t = load_texture(scene_, source, &loading);
            texture_loading_ = std::max(texture_loading_, loading);
        } catch (const SceneError& e) {
            // Every texture that cannot be read is reported, not only the first; the draw reads
            // white meanwhile and the constructor throws them all.
            if (std::find(failures_.begin(), failures_.end(), e.what()) == failures_.end()) {
                failures_.push_back(e.what());
            }
            return white_texture(dims);
        }
    }
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

namespace {

// The glTF mesh a scene mesh was read from ("meshes[3]" of "meshes[3].primitives[1]"), for counts.
std::string gltf_mesh_of(const Mesh& mesh) {
    const std::string& s = mesh.source.empty() ? mesh.name : mesh.source;
    return s.substr(0, s.find('.'));
}

// One line for a kind of note: `what` on N primitives of M meshes; first: ...
std::string counted(const std::string& what, const std::vector<const Mesh*>& meshes, const std::string& after) {
    std::set<std::string> gltf_meshes;
    for (const Mesh* m : meshes) gltf_meshes.insert(gltf_mesh_of(*m));
    const Mesh& first = *meshes.front();
    const std::string name =
        first.source.empty() || first.name == first.source ? first.name : first.source + " '" + first.name + "'";
    return what + " on " + std::to_string(meshes.size()) + (meshes.size() == 1 ? " primitive" : " primitives") +
           " of " + std::to_string(gltf_meshes.size()) + (gltf_meshes.size() == 1 ? " mesh" : " meshes") + after +
           "; first: " + name;
}

}  // namespace

SceneRenderer::SceneRenderer(Scene& scene, const FrameRequest& request)
    : scene_(scene),
      request_(request),
      width_(request.width > 0 ? request.width : scene.width),
      height_(request.height > 0 ? request.height : scene.height) {
    check_supported(request);
    check_programs(scene, request.shader_override);
    vertices_.resize(scene.meshes.size());
    textures_.resize(scene.textures.size());
    object_draws_.resize(scene.objects.size());
    uniform_words_.resize(scene.objects.size());
    MissingCoordinates missing;
    missing.counted.assign(scene.meshes.size() * 2, false);
    for (std::size_t i = 0; i < scene.objects.size(); ++i) prepare_draw(i, missing);
    if (!failures_.empty()) {
        std::string all;
        for (const std::string& f : failures_) all += (all.empty() ? "" : "\n") + f;
        throw SceneError(all);
    }
    note_missing(missing);
    pose(request.time.value_or(double(scene.time)));
    check_uniform_options();
    if (request.backend == Backend::RayCaster) build_caster();
}

void SceneRenderer::prepare_draw(std::size_t i, MissingCoordinates& missing) {
    const Object& o = scene_.objects[i];
    const Program& program = program_for(scene_, o, request_.shader_override);
    const ShaderInfo& info = program.info();
    if (request_.backend == Backend::RayCaster && o.look.alpha_mode == AlphaMode::Blend &&
        info.name == kDefaultMaterialShader) {
        throw SceneError(scene_.file.string() + ": " + o.material +
                         ": alphaMode BLEND: the ray caster shades the "
                         "nearest surface only and blends nothing; render with the rasterizer (--backend raster)");
    }
    DrawCall& d = object_draws_[i];
    const Mesh& mesh = scene_.meshes[o.mesh];
    std::vector<VertexIn>& vertices = vertices_[o.mesh];
    if (vertices.empty()) {
        vertices.reserve(mesh.vertices.size());
        for (const Vertex& v : mesh.vertices) {
            VertexIn in{v.position, v.texcoord, v.normal, v.color, v.texcoord1};
            in.id = std::uint32_t(vertices.size());  // gl_VertexID
            vertices.push_back(in);
        }
    }
    d.vertices = vertices;
    d.indices = mesh.indices;
    d.program = &program;
    if (request_.atlas) d.program = atlas_programs_.emplace_back(std::make_unique<AtlasProgram>(program)).get();
    const Needs& needs = info.needs;
    // The texture coordinates the draw reads: TEXCOORD_0 for a shader of them, the base colour
    // texture's set for the default material with a texture.
    const bool default_material = info.name == kDefaultMaterialShader;
    const bool reads_set0 = needs.coordinates == Coordinates::Texcoord2D &&
                            (!default_material || (o.texture >= 0 && o.look.texcoord == 0));
    const bool reads_set1 = default_material && o.texture >= 0 && o.look.texcoord != 0;
    if ((reads_set0 && !mesh.has_texcoords) || (reads_set1 && !mesh.has_texcoord1)) {
        const std::string set = "TEXCOORD_" + std::to_string(reads_set0 ? 0 : o.look.texcoord);
        const std::size_t key = o.mesh * 2 + (reads_set0 ? 0 : 1);
        if (!missing.counted[key]) {
            missing.counted[key] = true;
            missing.meshes[set].push_back(&mesh);
        }
        std::string quoted(1, '\'');
        quoted.append(info.name).push_back('\'');
        missing.shaders[set].insert(std::move(quoted));
    }
    if (needs.texture) {
        d.uniforms.teximage = static_cast<const glsl::sampler2D*>(&texture_for(o, program, "teximage", 2));
        d.texture_lod = d.uniforms.teximage->needs_lod();
    }
    for (std::size_t k = 0; k < needs.samplers.size() && !needs.samplers[k].name.empty(); ++k) {
        const glsl::Texture& t = texture_for(o, program, needs.samplers[k].name, needs.samplers[k].dims);
        d.uniforms.samplers[k] = &t;
        d.texture_lod = d.texture_lod || t.needs_lod();
    }
    d.blend = o.look.alpha_mode == AlphaMode::Blend && default_material && !request_.atlas;
}

void SceneRenderer::note_missing(MissingCoordinates& missing) {
    for (const auto& [set, meshes] : missing.meshes) {
        std::string shaders;
        for (const std::string& name : missing.shaders[set]) shaders += (shaders.empty() ? "" : ", ") + name;
        notes_.push_back(scene_.file.string() + ": " +
                         counted(set + " missing", meshes,
                                 " drawn by shaders that read it (" + shaders + "): (0, 0) at every vertex, as in GL"));
    }
    for (const auto& [what, materials] : missing_samplers_) {
        notes_.push_back(scene_.file.string() + ": shader '" + what + "', which " + std::to_string(materials.size()) +
                         (materials.size() == 1 ? " material binds" : " materials bind") +
                         " no texture to: it reads white (1, 1, 1, 1) there; first: " + materials.front());
    }
}

void SceneRenderer::check_uniform_options() const {
    for (const UniformSetting& s : request_.uniforms) {
        bool declared = false;
        for (const DrawCall& d : draws_) declared = declared || declares_uniform(d.program->info(), s.name);
        if (!declared) throw UniformOptionError(s.origin + ": no shader in this scene declares a uniform '" + s.name + "'");
    }
}

void SceneRenderer::build_caster() {
#if defined(QUADSHADE_HAS_RAYCAST)
    const double aspect = double(width_) / double(height_);
    caster_view_ = scene_.pose(*posed_at_).view;
    try {
        caster_ = std::make_unique<Caster>(draws_, glm::mat4(scene_.camera.projection(aspect) * caster_view_));
    } catch (const RayCastError& e) {
        throw SceneError(scene_.file.string() + ": " + e.what());
    }
#else
    throw std::runtime_error("this quadshade was built without the ray caster (QUADSHADE_RAYCAST=OFF: no Embree)");
#endif
}

void SceneRenderer::pose(double time) {
    if (posed_at_ && (*posed_at_ == time || !scene_.animated())) return;
    const Pose pose = scene_.pose(time);
    const double aspect = double(width_) / double(height_);
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
        const Object& o = scene_.objects[i];
        DrawCall& d = object_draws_[i];
        const ObjectTransforms transforms = object_transforms(scene_, pose, i, aspect);
        d.uniforms.model_view_projection = transforms.model_view_projection;
        d.uniforms.model = transforms.model;
        d.uniforms.view = transforms.view;
        d.uniforms.projection = transforms.projection;
        d.uniforms.normal_matrix = transforms.normal;
        // An atlas bake draws every triangle in texture space, where winding says nothing of facing.
        if (!request_.atlas) {
            d.culling = {!o.double_sided, mirrors(pose, i) ? Winding::Clockwise : Winding::CounterClockwise};
        }
        // The scene's values for the uniforms the shader declares, replaced by the material's
        // extras.uniforms, then by --uniform.
        const ShaderInfo& info = d.program->info();
        std::vector<UniformSetting> given = object_uniforms(scene_, i, pose, aspect);
        std::erase_if(given, [&](const UniformSetting& s) { return !declares_uniform(info, s.name); });
        uniform_words_[i] = bind_uniforms(info, merge_uniforms(merge_uniforms(given, o.uniforms), request_.uniforms),
                                          width_, height_, !request_.shader_override.empty());
        d.uniforms.user = uniform_words_[i].data();
    }
    draws_.clear();
    for (std::size_t i : scene_.draw_order(pose)) draws_.push_back(object_draws_[i]);
    posed_at_ = time;
}

SceneRenderer::~SceneRenderer() = default;

bool SceneRenderer::depends_on_time() const {
    if (scene_.animated()) return true;
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

std::uint64_t render_working_bytes(std::uint64_t pixels, std::uint64_t vertices, std::uint64_t triangles, bool depth,
                                   bool undefined) {
    const std::uint64_t per_pixel = 4 * sizeof(float) + (depth ? sizeof(float) : 0) + (undefined ? 1 : 0);
    // Clipped vertices (vertex stage output) and triangle setups with their tile bins; a
    // triangle clipped into a fan counts about twice. Measured sizes, rounded up.
    constexpr std::uint64_t kPerVertex = 128, kPerTriangle = 2 * (sizeof(TriangleSetup) + 64);
    return pixels * per_pixel + vertices * kPerVertex + triangles * kPerTriangle;
}

std::uint64_t SceneRenderer::frame_bytes(int rows) const {
    // The rasterizer decides on a depth buffer per frame (depth_buffer.h): counted whenever it may.
    const bool depth = request_.backend == Backend::Rasterizer;
    std::uint64_t vertices = 0, triangles = 0;
    for (const DrawCall& d : draws_) {
        vertices += d.vertices.size();
        triangles += d.indices.size() / 3;
    }
    std::uint64_t bytes = render_working_bytes(std::uint64_t(width_) * std::uint64_t(rows), vertices, triangles, depth,
                                               request_.shading.check_undefined);
#if defined(QUADSHADE_HAS_RAYCAST)
    if (caster_) bytes += BlockCoverage::bytes(width_, rows);  // what the rays of each 4x4 block may hit
#endif
    return bytes;
}

SceneRenderer::HeldBytes SceneRenderer::held_bytes() const {
    HeldBytes held;
    std::uint64_t triangles = 0;
    held.scene = scene_bytes(scene_);
    for (const DrawCall& d : draws_) triangles += d.indices.size() / 3;
    for (const std::vector<VertexIn>& v : vertices_) held.scene += v.capacity() * sizeof(VertexIn);
    for (const std::vector<std::uint32_t>& words : uniform_words_) held.scene += words.capacity() * sizeof(std::uint32_t);
    if (caster_) held.scene += triangles * kRayCastBytesPerTriangle;
    for (const std::unique_ptr<glsl::Texture>& t : textures_) {
        if (t) held.textures += t->texels.capacity() * sizeof(std::uint32_t) + t->levels.capacity() * sizeof(glsl::Texture::Level);
    }
    held.texture_loading = texture_loading_;
    return held;
}

void SceneRenderer::render_into(Framebuffer& fb, std::optional<double> time, RenderStats* stats, RowBand band) {
    const double t = time.value_or(request_.time.value_or(double(scene_.time)));
    if (scene_.animated() && posed_at_ != t) {
        pose(t);
#if defined(QUADSHADE_HAS_RAYCAST)
        const glm::dmat4 view = scene_.pose(t).view;
        if (caster_ && view != caster_view_) {  // the camera moved: rays from its new place
            const double aspect = double(width_) / double(height_);
            caster_view_ = view;
            try {
                caster_ = std::make_unique<Caster>(draws_, glm::mat4(scene_.camera.projection(aspect) * view));
            } catch (const RayCastError& e) { throw SceneError(scene_.file.string() + ": " + e.what()); }
        }
#endif
    }
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

void load_libraries(const FrameRequest& request) {
#if defined(QUADSHADE_HAS_RAYCAST)
    if (request.backend == Backend::RayCaster) EmbreeScene::load_library();
#else
    (void)request;  // the SceneRenderer refuses the ray caster
#endif
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
