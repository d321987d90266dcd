#pragma once
// From a loaded scene to a framebuffer: resolves each object's shader in the catalogue, loads the
// textures the drawn shaders sample (and no others), and builds the draw calls. Shared by the
// command line, the reference comparisons and the benchmarks.

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "raster/rasterizer.h"
#include "render/compiled_glsl.h"
#include "scenes/scene.h"
#include "shading/shade_choice.h"

namespace qs {

enum class Backend { Rasterizer, RayCaster };

struct FrameRequest {
    int width = 0, height = 0;           // 0: the scene's size
    std::optional<double> time;          // default: the scene's time
    // Hand each shader time modulo its period (ShaderInfo::time_period), reduced in double: long
    // animations keep their frame spacing. Off: time goes to the shader as float, as GL would.
    bool stable_time = false;
    std::string shader_override;         // draw every object with this shader
    // --uniform values: they replace the materials' of the same name, for every object whose
    // shader declares it (render/uniform_binding.h); a name no drawn shader declares throws
    // UniformOptionError.
    std::vector<UniformSetting> uniforms;
    Backend backend = Backend::Rasterizer;
    // Draw each triangle at its TEXCOORD_0 in the frame instead of where the camera sees it: an
    // atlas bake (render/atlas_program.h). The rasterizer only.
    bool atlas = false;
    ShadingSettings shading;  // both backends
    RasterSettings raster;    // the rasterizer's only: the ray caster refuses any but the defaults

    RasterOptions raster_options() const { return {shading, raster}; }
    void set(const RasterOptions& options) {
        shading = options;
        raster = options;
    }
};

// Whether every object of `scene` binds the textures `info` samples: the scenes a shader can be
// drawn on with its materials (quadshade check and gallery pick scenes so).
bool binds_samplers(const Scene& scene, const ShaderInfo& info);

// Throws UnsupportedRequest (shading/shade_choice.h) for a request no backend honours as asked:
// a shading request no instantiation honours, or rasterizer settings (fill rule, interpolation,
// the general path) other than their defaults given to the ray caster, which has none of them.
void check_supported(const FrameRequest& request);
// What the frame asks of the shaders' instantiations (shading/shade_choice.h).
ShadeRequest shade_request(const FrameRequest& request);

// A scene made ready for frames: shaders resolved, textures loaded, draw calls built and, for the
// ray caster, the BVH built; each frame then changes the time and, in an animated scene, where
// the objects and the camera are (Scene::pose) and the blended objects' order. Objects whose
// material names no shader are drawn with the default material (kDefaultMaterialShader); a
// sampler the material binds no texture to reads white (white_texture), said once per shader
// in notes() for a catalogue shader. Throws UnsupportedRequest as check_supported does, before
// anything is loaded; SceneError for an unknown shader (naming the scene file and material),
// textures that cannot be read (naming the file and the field of each), a 2D texture bound where
// a shader declares a sampler3D or the reverse, alpha blending with the ray caster;
// std::runtime_error when the ray caster was not built in.
class SceneRenderer {
public:
    SceneRenderer(Scene& scene, const FrameRequest& request);
    ~SceneRenderer();
    SceneRenderer(const SceneRenderer&) = delete;
    SceneRenderer& operator=(const SceneRenderer&) = delete;

    // A frame at `time`, or the rows of `band` only (image_bands, rasterizer.h): the same pixels.
    void render_into(Framebuffer& fb, std::optional<double> time, RenderStats* stats = nullptr, RowBand band = {});
    int width() const { return width_; }
    int height() const { return height_; }
    double bvh_build_seconds() const;  // 0 for the rasterizer
    // Whether a frame's image depends on its time: some drawn shader declares Needs::time. An
    // animation of a scene that does not is one image, rendered once.
    bool depends_on_time() const;

    // Bytes a render of `rows` rows holds while it runs: the framebuffer's colour, depth (where
    // a draw tests it) and undefined-case mask, and the vertex stage's and triangle setup's
    // working memory. What the renderer holds for every frame is held_bytes().
    std::uint64_t frame_bytes(int rows) const;
    // What the renderer holds beside its frames, counted from what it loaded: the scene (its
    // meshes and embedded images, the draw calls' vertices, the ray caster's BVH) and the
    // sampled textures with their mipmaps; and the most that loading a texture held beside
    // those (its file, the decoded image and its RGBA copy), freed since.
    struct HeldBytes {
        std::uint64_t scene = 0, textures = 0, texture_loading = 0;
    };
    HeldBytes held_bytes() const;
    // What the scene asks that renders, but probably not as its author meant (a shader reading
    // texture coordinates on meshes without them, a shader sampling a texture materials lack),
    // one line for each kind, counted over what it concerns, for the command line to warn.
    const std::vector<std::string>& notes() const { return notes_; }

private:
    // The texture coordinate sets (TEXCOORD_n) that drawn shaders read and meshes lack, to say
    // once: per set, the meshes and the shaders reading it.
    struct MissingCoordinates {
        std::map<std::string, std::vector<const Mesh*>> meshes;
        std::map<std::string, std::set<std::string>> shaders;
        std::vector<bool> counted;  // per mesh and set (0, or the other): already in `meshes`
    };
    // Object i's draw: its vertices, program, textures and blending; a coordinate set its shader
    // reads and its mesh lacks goes to `missing`.
    void prepare_draw(std::size_t i, MissingCoordinates& missing);
    // The notes of coordinate sets and samplers the scene leaves out.
    void note_missing(MissingCoordinates& missing);
    // Throws UniformOptionError for a --uniform no drawn shader declares.
    void check_uniform_options() const;
    // The ray caster's scene, built for the posed draws.
    void build_caster();
    // The texture an object binds to `uniform` (teximage or one of the program's Needs::samplers),
    // of the kind the program declares, loaded on first use; white where it binds none.
    const glsl::Texture& texture_for(const Object& object, const Program& program, std::string_view uniform, int dims);
    // Each object's transforms, culling and scene-given uniforms at `time`, and the draws in the
    // order of the pose (Scene::draw_order).
    void pose(double time);

    Scene& scene_;
    FrameRequest request_;
    int width_, height_;
    std::vector<std::vector<VertexIn>> vertices_;              // per scene mesh, empty until drawn
    std::vector<std::unique_ptr<glsl::Texture>> textures_;  // per scene texture, null until sampled
    std::vector<DrawCall> object_draws_;                    // per scene object
    std::vector<DrawCall> draws_;                           // this frame's, in drawing order
    std::uint64_t texture_loading_ = 0;                     // held_bytes().texture_loading
    std::vector<std::unique_ptr<Program>> atlas_programs_;  // per draw with FrameRequest::atlas
    std::vector<std::vector<std::uint32_t>> uniform_words_;  // per object: its Uniforms::user
    std::vector<std::string> notes_;
    std::vector<std::string> failures_;  // textures that could not be read, each said once
    std::map<std::string, std::vector<std::string>> missing_samplers_;  // per shader and sampler: the materials
    std::optional<double> posed_at_;                                    // the time of the pose the draws hold
    glm::dmat4 caster_view_{1.0};  // the camera's view the ray caster was built for
    RasterMemory raster_memory_;  // the last frame's triangles and bins, reused
    struct Caster;
    std::unique_ptr<Caster> caster_;
};

// Loads the outside libraries a render of `request` uses, as its first frame would: Embree for
// the ray caster (OpenImageIO, for its textures and its output, is images/image_io.h's). A caller
// that measures a render's time or memory calls it first, to count the render's own. Throws
// std::runtime_error naming the library when it cannot be loaded.
void load_libraries(const FrameRequest& request);

// Bytes a render of `pixels` pixels holds while it runs (SceneRenderer::frame_bytes counts its own
// with it): colour, depth, the undefined-case mask, and the vertex stage's and triangle setup's
// working memory for that many vertices and triangles drawn.
std::uint64_t render_working_bytes(std::uint64_t pixels, std::uint64_t vertices, std::uint64_t triangles, bool depth,
                                   bool undefined);

// One frame, for callers that render a scene once.
Framebuffer render_frame(Scene& scene, const FrameRequest& request, RenderStats* stats = nullptr);
void render_frame_into(Framebuffer& fb, Scene& scene, const FrameRequest& request, RenderStats* stats = nullptr);

// The shader each object is drawn with under `shader_override`, checked against the catalogue. A
// material's GLSL (extras.glsl) is loaded once per process, the first time `way` (as --glsl's:
// render/compiled_glsl.h) for `shading`, and drawn so in every frame after.
const Program& program_for(const Scene& scene, const Object& object, const std::string& shader_override,
                           GlslWay way = GlslWay::Cached, const std::vector<ShadeRequest>& shading = {});
// Throws one SceneError naming every material whose shader the catalogue lacks (program_for).
void check_programs(const Scene& scene, const std::string& shader_override, GlslWay way = GlslWay::Cached,
                    const std::vector<ShadeRequest>& shading = {});

}  // namespace qs
