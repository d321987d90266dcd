// The one file that calls OpenGL.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include "reference/gl_renderer.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <glm/gtc/type_ptr.hpp>

#include "shading/catalogue.h"
#include "raster/framebuffer.h"
#include "render/scene_render.h"

namespace qs {

namespace {

std::string read_file(const std::filesystem::path& p) {
    std::ifstream in(p);
    if (!in) throw std::runtime_error(p.string() + ": cannot read GLSL source");
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

GLuint compile(GLenum stage, const std::string& source, const std::string& what) {
    GLuint s = glCreateShader(stage);
    const char* text = source.c_str();
    glShaderSource(s, 1, &text, nullptr);
    glCompileShader(s);
    check(s, GL_COMPILE_STATUS, glGetShaderiv, glGetShaderInfoLog, what + ": GLSL does not compile");
    return s;
}

GLuint link_program(const ShaderInfo& info, const std::filesystem::path& shading_dir) {
    const std::string name(info.name);
    GLuint vs = compile(GL_VERTEX_SHADER, glsl_source(info, true, shading_dir), name + " (vertex)");
    GLuint fs = compile(GL_FRAGMENT_SHADER, glsl_source(info, false, shading_dir), name + " (fragment)");
    GLuint p = glCreateProgram();
    glAttachShader(p, vs);
    glAttachShader(p, fs);
    glLinkProgram(p);
    check(p, GL_LINK_STATUS, glGetProgramiv, glGetProgramInfoLog, name + ": GLSL does not link");
    glDeleteShader(vs);
    glDeleteShader(fs);
    return p;
}

// Texels as GL_RGBA8: the files are 8-bit, so k/255 survives the round trip exactly.
GLuint upload_texture(const glsl::sampler2D& t) {
    std::vector<unsigned char> bytes(t.rgba.size());
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = unorm8(t.rgba[i]);
    GLuint id = 0;
    glGenTextures(1, &id);
    glBindTexture(GL_TEXTURE_2D, id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, t.width, t.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return id;
}

}  // namespace

std::string glsl_source(const ShaderInfo& info, bool vertex_stage, const std::filesystem::path& shading_dir) {
    // ShaderInfo::glsl_version; from 1.50 on the compatibility profile (gl_Vertex, gl_FragColor).
    std::string src = "#version " + std::to_string(info.glsl_version) + (info.glsl_version >= 150 ? " compatibility\n" : "\n");
    src += info.glsl_defines;
    for (std::string_view file : vertex_stage ? info.glsl_vertex : info.glsl_fragment) {
        if (file.empty()) continue;
        src += "#line 1\n";
        src += read_file(shading_dir / file);
    }
    return src;
}

GlSceneRenderer::GlSceneRenderer(Scene& scene, const GlFrameRequest& request, GlContext& context,
                                 const std::filesystem::path& shading_dir)
    : scene_(scene), request_(request), context_(context) {
    std::map<const Program*, GLuint> linked;
    std::map<int, GLuint> uploaded;
    for (const Object& o : scene.objects) {
        const Program& program = program_for(scene, o, request.shader_override);
        GLuint& p = linked[&program];
        if (!p) p = link_program(program.info(), shading_dir);
        infos_.push_back(&program.info());
        programs_.push_back(p);
        GLuint tex = 0;
        const glsl::sampler2D* texels = nullptr;
        if (program.info().needs.texture) {
            texels = &texture_for(scene, o, program);
            GLuint& id = uploaded[o.texture];
            if (!id) id = upload_texture(*texels);
            tex = id;
        }
        textures_.push_back(tex);
        texels_.push_back(texels);
    }
}

GlSceneRenderer::~GlSceneRenderer() {
    std::vector<GLuint> p(programs_.begin(), programs_.end());
    std::sort(p.begin(), p.end());
    p.erase(std::unique(p.begin(), p.end()), p.end());
    for (GLuint id : p) glDeleteProgram(id);
    std::vector<GLuint> t(textures_.begin(), textures_.end());
    std::sort(t.begin(), t.end());
    t.erase(std::unique(t.begin(), t.end()), t.end());
    for (GLuint id : t) {
        if (id) glDeleteTextures(1, &id);
    }
}

void GlSceneRenderer::draw() {
    const int width = context_.width(), height = context_.height();
    const float aspect = float(width) / float(height);
    const float time = request_.time.value_or(scene_.time);
    glViewport(0, 0, width, height);
    glClearColor(scene_.clear_color.r, scene_.clear_color.g, scene_.clear_color.b, scene_.clear_color.a);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);  // as any GL application drawing a 3D scene
    glDepthFunc(GL_LESS);
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
        const Object& o = scene_.objects[i];
        const GLuint p = programs_[i];
        glUseProgram(p);
        // The MVP quadshade computed, as the projection; gl_ModelViewProjectionMatrix = P * I.
        const glm::mat4 mvp = scene_.model_view_projection(o, aspect);
        glMatrixMode(GL_PROJECTION);
        glLoadMatrixf(glm::value_ptr(mvp));
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        if (GLint loc = glGetUniformLocation(p, "time"); loc >= 0) glUniform1f(loc, time);
        if (textures_[i]) {
            const glsl::sampler2D& t = *texels_[i];
            glActiveTexture(GL_TEXTURE0);
            glBindTexture(GL_TEXTURE_2D, textures_[i]);
            if (GLint loc = glGetUniformLocation(p, "teximage"); loc >= 0) glUniform1i(loc, 0);
            if (GLint loc = glGetUniformLocation(p, "dims"); loc >= 0) glUniform2f(loc, float(t.width), float(t.height));
        }
        const Mesh& mesh = scene_.meshes[o.mesh];
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glVertexPointer(3, GL_FLOAT, sizeof(VertexIn), &mesh.vertices[0].position);
        glTexCoordPointer(2, GL_FLOAT, sizeof(VertexIn), &mesh.vertices[0].texcoord);
        glDrawElements(GL_TRIANGLES, GLsizei(mesh.indices.size()), GL_UNSIGNED_INT, mesh.indices.data());
    }
    glFinish();
    if (GLenum e = glGetError(); e != GL_NO_ERROR) throw std::runtime_error("OpenGL error " + std::to_string(e));
}

Image GlSceneRenderer::render() {
    draw();
    return Image{context_.width(), context_.height(), context_.read_rgba()};
}

Image render_gl(Scene& scene, const GlFrameRequest& request, GlContext& context,
                const std::filesystem::path& shading_dir) {
    return GlSceneRenderer(scene, request, context, shading_dir).render();
}

}  // namespace qs
