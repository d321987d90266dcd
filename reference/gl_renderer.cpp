// The one file that calls OpenGL.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include "reference/gl_renderer.h"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include <glm/gtc/type_ptr.hpp>

#include "reference/texture_image.h"

namespace qs {

namespace {

std::string read_glsl(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    if (!in) {
        throw std::runtime_error(p.string() + ": no such GLSL file (quadshade shaders --export-glsl " +
                                 p.parent_path().string() + " writes the catalogue's)");
    }
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Throws with the driver's log when a shader or program object reports failure.
template <class GetStatus, class GetLog>
void check(GLuint object, GLenum status, GetStatus get_status, GetLog get_log, const std::string& what) {
    GLint ok = 0;
    get_status(object, status, &ok);
    if (ok) return;
    char log[4096] = {};
    get_log(object, GLsizei(sizeof log), nullptr, log);
    throw std::runtime_error(what + ":\n" + log);
}

GLuint compile(GLenum stage, const std::filesystem::path& file) {
    const std::string source = read_glsl(file);
    GLuint s = glCreateShader(stage);
    const char* text = source.c_str();
    glShaderSource(s, 1, &text, nullptr);
    glCompileShader(s);
    check(s, GL_COMPILE_STATUS, glGetShaderiv, glGetShaderInfoLog, file.string() + ": GLSL does not compile");
    return s;
}

// The uniforms a program may declare besides its samplers, each bound by name as the chapter's
// demo binds them.
const std::set<std::string> kKnownUniforms = {"time", "dims"};

// A linked program's active uniforms, as (name, GL type).
std::vector<std::pair<std::string, GLenum>> active_uniforms(GLuint p) {
    std::vector<std::pair<std::string, GLenum>> r;
    GLint count = 0;
    glGetProgramiv(p, GL_ACTIVE_UNIFORMS, &count);
    for (GLint i = 0; i < count; ++i) {
        char uniform[256] = {};
        GLint size = 0;
        GLenum type = 0;
        glGetActiveUniform(p, GLuint(i), GLsizei(sizeof uniform), nullptr, &size, &type, uniform);
        r.emplace_back(uniform, type);
    }
    return r;
}

// Its sampler uniforms, bound per object by name, as (name, dimensions).
std::vector<std::pair<std::string, int>> samplers_of(GLuint p) {
    std::vector<std::pair<std::string, int>> r;
    for (const auto& [name, type] : active_uniforms(p)) {
        if (type == GL_SAMPLER_2D || type == GL_SAMPLER_3D) r.emplace_back(name, type == GL_SAMPLER_3D ? 3 : 2);
    }
    return r;
}

GLuint link_program(const std::filesystem::path& glsl_dir, const std::string& name) {
    GLuint vs = compile(GL_VERTEX_SHADER, glsl_dir / (name + ".vert"));
    GLuint fs = compile(GL_FRAGMENT_SHADER, glsl_dir / (name + ".frag"));
    GLuint p = glCreateProgram();
    glAttachShader(p, vs);
    glAttachShader(p, fs);
    glLinkProgram(p);
    check(p, GL_LINK_STATUS, glGetProgramiv, glGetProgramInfoLog, name + ": GLSL does not link");
    glDeleteShader(vs);
    glDeleteShader(fs);
    // A uniform nothing binds would read 0: refuse it rather than render something else.
    for (const auto& [u, type] : active_uniforms(p)) {
        const bool sampler = type == GL_SAMPLER_2D || type == GL_SAMPLER_3D;  // bound per object, by name
        if (u.rfind("gl_", 0) != 0 && !sampler && !kKnownUniforms.count(u)) {
            glDeleteProgram(p);
            throw std::runtime_error(name + ": uniform '" + u +
                                     "' is none the reference binds (time, dims, and sampler2D/sampler3D uniforms)");
        }
    }
    return p;
}

GLint gl_enum(Wrap w) { return GLint(w); }      // glTF keeps GL's values
GLint gl_enum(Filter f) { return GLint(f); }

}  // namespace

GlPrograms::~GlPrograms() {
    for (const auto& [name, id] : linked_) glDeleteProgram(id);
}

unsigned GlPrograms::program(const std::string& shader) {
    for (const auto& [name, id] : linked_) {
        if (name == shader) return id;
    }
    linked_.emplace_back(shader, link_program(glsl_dir_, shader));
    return linked_.back().second;
}

GlSceneRenderer::GlSceneRenderer(const Scene& scene, const GlFrameRequest& request, GlContext& context,
                                 const std::filesystem::path& glsl_dir)
    : scene_(scene),
      request_(request),
      context_(context),
      own_programs_(std::make_unique<GlPrograms>(glsl_dir)),
      textures_(scene.textures.size()) {
    prepare(*own_programs_);
}

GlSceneRenderer::GlSceneRenderer(const Scene& scene, const GlFrameRequest& request, GlContext& context,
                                 GlPrograms& programs)
    : scene_(scene), request_(request), context_(context), textures_(scene.textures.size()) {
    prepare(programs);
}

void GlSceneRenderer::prepare(GlPrograms& programs) {
    context_.make_current();
    for (const Object& o : scene_.objects) {
        const std::string& name = request_.shader_override.empty() ? o.shader : request_.shader_override;
        if (name.empty()) {
            throw std::runtime_error(scene_.file.string() + ": material '" + o.material + "' of '" + o.name +
                                     "' names no shader (extras.shader); pass --shader NAME");
        }
        const GLuint p = programs.program(name);
        programs_.push_back(p);
        std::vector<Binding> bindings;
        for (const auto& [uniform, dims] : samplers_of(p)) {
            const int unit = int(bindings.size());
            bindings.push_back({glGetUniformLocation(p, uniform.c_str()), unit, &texture_of(o, name, uniform, dims)});
        }
        bound_.push_back(std::move(bindings));
    }
}

const GlSceneRenderer::Texture& GlSceneRenderer::texture_of(const Object& o, const std::string& shader,
                                                            const std::string& uniform, int dims) {
    const int index = o.texture_for(uniform);
    const std::string what = scene_.file.string() + ": material '" + o.material + "': shader '" + shader + "' samples " +
                             (dims == 3 ? "a sampler3D" : "a sampler2D") + " '" + uniform + "'";
    if (index < 0) {
        throw std::runtime_error(what + (uniform == "teximage" ? " but the material has no pbrMetallicRoughness.baseColorTexture, "
                                                                 "extras.teximage or extras.textures.teximage"
                                                               : " but the material's extras.textures binds no texture to it"));
    }
    const qs::Texture& source = scene_.textures[std::size_t(index)];
    if (source.dims != dims) throw std::runtime_error(what + " but " + source.field + " is a " + std::to_string(source.dims) + "D texture");
    Texture& t = textures_[std::size_t(index)];
    if (t.id) return t;
    DecodedImage image;
    try {
        image = decode_texture_image(source.image);
    } catch (const std::exception& e) {
        throw std::runtime_error(scene_.file.string() + ": " + source.field + ": " + e.what());
    }
    const GLenum type = image.sixteen_bits ? GL_UNSIGNED_SHORT : GL_UNSIGNED_BYTE;
    t.target = dims == 3 ? GL_TEXTURE_3D : GL_TEXTURE_2D;
    t.width = image.width, t.height = image.height;
    glGenTextures(1, &t.id);
    glBindTexture(t.target, t.id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // The first row of the image goes first: glTF's UV (0, 0) is the image's top-left corner. A
    // 3D texture's slices follow one another in the image's rows, as glTexImage3D reads them.
    if (dims == 3) {
        if (image.height % source.depth != 0) {
            throw std::runtime_error(scene_.file.string() + ": " + source.field + ": a " + std::to_string(image.width) + "x" +
                                     std::to_string(image.height) + " image does not stack " + std::to_string(source.depth) +
                                     " slices of equal height");
        }
        t.height = image.height / source.depth;
        glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, image.width, t.height, source.depth, 0, GL_RGBA, type, image.bytes.data());
    } else {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, type, image.bytes.data());
    }
    const Sampler& s = source.sampler;
    glTexParameteri(t.target, GL_TEXTURE_MIN_FILTER, gl_enum(s.min_filter));
    glTexParameteri(t.target, GL_TEXTURE_MAG_FILTER, gl_enum(s.mag_filter));
    glTexParameteri(t.target, GL_TEXTURE_WRAP_S, gl_enum(s.wrap_s));
    glTexParameteri(t.target, GL_TEXTURE_WRAP_T, gl_enum(s.wrap_t));
    if (dims == 3) glTexParameteri(t.target, GL_TEXTURE_WRAP_R, gl_enum(s.wrap_r));
    if (uses_mipmaps(s.min_filter)) glGenerateMipmap(t.target);
    if (GLenum e = glGetError(); e != GL_NO_ERROR) {
        throw std::runtime_error(scene_.file.string() + ": " + source.field + ": OpenGL error " + std::to_string(e) +
                                 " uploading the texture");
    }
    return t;
}

GlSceneRenderer::~GlSceneRenderer() {
    for (const Texture& t : textures_) {
        if (t.id) glDeleteTextures(1, &t.id);
    }
}

void GlSceneRenderer::draw() {
    context_.make_current();
    const int width = context_.width(), height = context_.height();
    const float aspect = float(width) / float(height);
    const float time = request_.time.value_or(scene_.time);
    glViewport(0, 0, width, height);
    glClearColor(scene_.clear_color.r, scene_.clear_color.g, scene_.clear_color.b, scene_.clear_color.a);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
        const Object& o = scene_.objects[i];
        const GLuint p = programs_[i];
        glUseProgram(p);
        // The scene model's MVP, as the projection; gl_ModelViewProjectionMatrix = P * I.
        const glm::mat4 mvp = scene_.model_view_projection(o, aspect);
        glMatrixMode(GL_PROJECTION);
        glLoadMatrixf(glm::value_ptr(mvp));
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        if (GLint loc = glGetUniformLocation(p, "time"); loc >= 0) glUniform1f(loc, time);
        for (const Binding& b : bound_[i]) {
            glActiveTexture(GLenum(GL_TEXTURE0 + b.unit));
            glBindTexture(b.texture->target, b.texture->id);
            glUniform1i(b.location, b.unit);
        }
        if (GLint loc = glGetUniformLocation(p, "dims"); loc >= 0) {
            const int teximage = o.texture_for("teximage");
            if (teximage < 0 || !textures_[std::size_t(teximage)].id) throw std::runtime_error(o.material + ": dims without teximage");
            const Texture& t = textures_[std::size_t(teximage)];
            glUniform2f(loc, float(t.width), float(t.height));
        }
        const Mesh& mesh = scene_.meshes[o.mesh];
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glVertexPointer(3, GL_FLOAT, sizeof(Vertex), &mesh.vertices[0].position);
        glTexCoordPointer(2, GL_FLOAT, sizeof(Vertex), &mesh.vertices[0].texcoord);
        glDrawElements(GL_TRIANGLES, GLsizei(mesh.indices.size()), GL_UNSIGNED_INT, mesh.indices.data());
    }
    glFinish();
    if (GLenum e = glGetError(); e != GL_NO_ERROR) throw std::runtime_error("OpenGL error " + std::to_string(e));
}

Image GlSceneRenderer::render() {
    draw();
    return Image{context_.width(), context_.height(), context_.read_rgba()};
}

Image8 GlSceneRenderer::read_unorm8() const {
    const int w = context_.width(), h = context_.height();
    const std::size_t row = std::size_t(w) * 4;
    std::vector<std::uint8_t> gl_rows(row * std::size_t(h));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, gl_rows.data());
    if (GLenum e = glGetError(); e != GL_NO_ERROR) throw std::runtime_error("glReadPixels: OpenGL error " + std::to_string(e));
    Image8 out{w, h, std::vector<std::uint8_t>(gl_rows.size())};
    for (int y = 0; y < h; ++y) {  // GL's rows are bottom-up
        std::copy_n(&gl_rows[std::size_t(h - 1 - y) * row], row, &out.rgba[std::size_t(y) * row]);
    }
    return out;
}

}  // namespace qs
