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

// The uniforms a program may declare, each bound by name as the chapter's demo binds them.
const std::set<std::string> kKnownUniforms = {"time", "teximage", "dims"};

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
    GLint count = 0;
    glGetProgramiv(p, GL_ACTIVE_UNIFORMS, &count);
    for (GLint i = 0; i < count; ++i) {
        char uniform[256] = {};
        GLint size = 0;
        GLenum type = 0;
        glGetActiveUniform(p, GLuint(i), GLsizei(sizeof uniform), nullptr, &size, &type, uniform);
        const std::string u(uniform);
        if (u.rfind("gl_", 0) != 0 && !kKnownUniforms.count(u)) {
            glDeleteProgram(p);
            throw std::runtime_error(name + ": uniform '" + u + "' is none the reference binds (time, teximage, dims)");
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
        bound_.push_back(glGetUniformLocation(p, "teximage") >= 0 ? &texture_of(o, name) : nullptr);
    }
}

const GlSceneRenderer::Texture& GlSceneRenderer::texture_of(const Object& o, const std::string& shader) {
    if (o.texture < 0) {
        throw std::runtime_error(scene_.file.string() + ": material '" + o.material + "': shader '" + shader +
                                 "' samples teximage but the material has no pbrMetallicRoughness.baseColorTexture "
                                 "or extras.teximage");
    }
    Texture& t = textures_[std::size_t(o.texture)];
    if (t.id) return t;
    const qs::Texture& source = scene_.textures[std::size_t(o.texture)];
    DecodedImage image;
    try {
        image = decode_texture_image(source.image);
    } catch (const std::exception& e) {
        throw std::runtime_error(scene_.file.string() + ": " + source.field + ": " + e.what());
    }
    t.width = image.width, t.height = image.height;
    glGenTextures(1, &t.id);
    glBindTexture(GL_TEXTURE_2D, t.id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // The first row of the image goes first: glTF's UV (0, 0) is the image's top-left corner.
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA,
                 image.sixteen_bits ? GL_UNSIGNED_SHORT : GL_UNSIGNED_BYTE, image.bytes.data());
    const Sampler& s = source.sampler;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, gl_enum(s.min_filter));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, gl_enum(s.mag_filter));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, gl_enum(s.wrap_s));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, gl_enum(s.wrap_t));
    if (uses_mipmaps(s.min_filter)) glGenerateMipmap(GL_TEXTURE_2D);
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
        if (const Texture* t = bound_[i]) {
            glActiveTexture(GL_TEXTURE0);
            glBindTexture(GL_TEXTURE_2D, t->id);
            glUniform1i(glGetUniformLocation(p, "teximage"), 0);
            if (GLint loc = glGetUniformLocation(p, "dims"); loc >= 0) glUniform2f(loc, float(t->width), float(t->height));
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
