// Calls OpenGL, as depth_mipmaps.cpp does for its one readback.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include "reference/gl_renderer.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include <glm/gtc/type_ptr.hpp>

#include "reference/texture_image.h"
#include "scenes/object_uniforms.h"
#include "scenes/shader_inputs.h"

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

GLuint compile(GLenum stage, const std::filesystem::path& file, bool atlas = false) {
    const std::string source = atlas ? atlas_vertex_source(read_glsl(file)) : read_glsl(file);
    GLuint s = glCreateShader(stage);
    const char* text = source.c_str();
    glShaderSource(s, 1, &text, nullptr);
    glCompileShader(s);
    check(s, GL_COMPILE_STATUS, glGetShaderiv, glGetShaderInfoLog, file.string() + ": GLSL does not compile");
    return s;
}

// The uniforms bound by name as the chapter's demo binds them, besides the samplers; any other is
// the shader's own (set from the scene or --uniform, else its initializer), or uResolution.
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

// A linked program's active vertex inputs, as (name, GL type).
std::vector<std::pair<std::string, GLenum>> active_attributes(GLuint p) {
    std::vector<std::pair<std::string, GLenum>> r;
    GLint count = 0;
    glGetProgramiv(p, GL_ACTIVE_ATTRIBUTES, &count);
    for (GLint i = 0; i < count; ++i) {
        char attribute[256] = {};
        GLint size = 0;
        GLenum type = 0;
        glGetActiveAttrib(p, GLuint(i), GLsizei(sizeof attribute), nullptr, &size, &type, attribute);
        r.emplace_back(attribute, type);
    }
    return r;
}

// Its sampler uniforms, bound per object by name.
struct SamplerUniform {
    std::string name;
    int dims;     // 2, 3, or kCubeMap
    bool shadow;  // a sampler2DShadow or samplerCubeShadow
};
bool is_sampler(GLenum type) {
    return type == GL_SAMPLER_2D || type == GL_SAMPLER_3D || type == GL_SAMPLER_2D_SHADOW || type == GL_SAMPLER_CUBE ||
           type == GL_SAMPLER_CUBE_SHADOW;
}
std::vector<SamplerUniform> samplers_of(GLuint p) {
    std::vector<SamplerUniform> r;
    for (const auto& [name, type] : active_uniforms(p)) {
        if (!is_sampler(type)) continue;
        const int dims = type == GL_SAMPLER_3D ? 3 : type == GL_SAMPLER_CUBE || type == GL_SAMPLER_CUBE_SHADOW ? kCubeMap : 2;
        r.push_back({name, dims, type == GL_SAMPLER_2D_SHADOW || type == GL_SAMPLER_CUBE_SHADOW});
    }
    return r;
}

// A uniform type's number of components and whether they are integers; 0 for a type the
// reference cannot set from numbers (samplers, bools).
struct GlUniformType {
    int components = 0;
    bool integer = false, unsigned_integer = false;
};
GlUniformType gl_uniform_type(GLenum type) {
    switch (type) {
        case GL_FLOAT: return {1};
        case GL_FLOAT_VEC2: return {2};
        case GL_FLOAT_VEC3: return {3};
        case GL_FLOAT_VEC4: return {4};
        case GL_INT: return {1, true};
        case GL_INT_VEC2: return {2, true};
        case GL_INT_VEC3: return {3, true};
        case GL_INT_VEC4: return {4, true};
        case GL_UNSIGNED_INT: return {1, true, true};
        case GL_FLOAT_MAT2: return {4};
        case GL_FLOAT_MAT3: return {9};
        case GL_FLOAT_MAT4: return {16};
        default: return {};
    }
}

// Whether the GLSL text declares `uniform TYPE name` (a uniform the compiler dropped as unused
// is in no list GL gives).
bool declares_uniform(const std::string& glsl, const std::string& name) {
    for (std::size_t at = glsl.find("uniform"); at != std::string::npos; at = glsl.find("uniform", at + 1)) {
        std::size_t i = at + 7;
        auto skip_space = [&] { while (i < glsl.size() && std::isspace(static_cast<unsigned char>(glsl[i]))) ++i; };
        auto word = [&] {
            const std::size_t b = i;
            while (i < glsl.size() && (std::isalnum(static_cast<unsigned char>(glsl[i])) || glsl[i] == '_')) ++i;
            return glsl.substr(b, i - b);
        };
        skip_space();
        word();  // the type
        skip_space();
        if (word() == name) return true;
    }
    return false;
}

// Whether either stage of `shader` declares a uniform of that name.
bool glsl_declares(const std::filesystem::path& glsl_dir, const std::string& shader, const std::string& uniform) {
    return declares_uniform(read_glsl(glsl_dir / (shader + ".frag")), uniform) ||
           declares_uniform(read_glsl(glsl_dir / (shader + ".vert")), uniform);
}

GLuint link_program(const std::filesystem::path& glsl_dir, const std::string& name, bool atlas) {
    GLuint vs = compile(GL_VERTEX_SHADER, glsl_dir / (name + ".vert"), atlas);
    GLuint fs = compile(GL_FRAGMENT_SHADER, glsl_dir / (name + ".frag"));
    GLuint p = glCreateProgram();
    glAttachShader(p, vs);
    glAttachShader(p, fs);
    glLinkProgram(p);
    check(p, GL_LINK_STATUS, glGetProgramiv, glGetProgramInfoLog, name + ": GLSL does not link");
    glDeleteShader(vs);
    glDeleteShader(fs);
    // A uniform or an attribute the reference cannot set: refuse it rather than render something else.
    auto refuse = [&](const std::string& why) {
        glDeleteProgram(p);
        throw std::runtime_error(name + ": " + why);
    };
    for (const auto& [u, type] : active_uniforms(p)) {
        // bound per object, by name
        const bool sampler = is_sampler(type);
        if (const SceneMatrixName* m = find_scene_matrix(u)) {
            if (type != (m->columns == 4 ? GL_FLOAT_MAT4 : GL_FLOAT_MAT3)) {
                refuse("uniform '" + u + "' is the scene's transform: declare it " + (m->columns == 4 ? "mat4" : "mat3"));
            }
        } else if (u.rfind("gl_", 0) != 0 && !sampler && !kKnownUniforms.count(u) && gl_uniform_type(type).components == 0) {
            refuse("uniform '" + u + "' is none the reference binds (time, dims, the scene's transforms " +
                   std::string(scene_matrix_names()) +
                   ", sampler2D/sampler3D uniforms, or a float, vec, int, ivec, uint or mat of the shader's own)");
        }
    }
    for (const auto& [a, type] : active_attributes(p)) {
        if (a.rfind("gl_", 0) == 0) continue;
        if (!find_vertex_attribute(a)) {
            refuse("vertex input '" + a + "' is none the scene feeds (" + std::string(vertex_attribute_names()) +
                   ": scenes/shader_inputs.h)");
        }
        if (type != GL_FLOAT && type != GL_FLOAT_VEC2 && type != GL_FLOAT_VEC3 && type != GL_FLOAT_VEC4) {
            refuse("vertex input '" + a + "' is the scene's " + std::string(find_vertex_attribute(a)->gltf) +
                   ": declare it float, vec2, vec3 or vec4");
        }
    }
    return p;
}

// glUniform* of the numbers a setting gives, as the type takes them.
void set_uniform(GLint location, GLenum type, const std::vector<double>& values) {
    float f[16] = {};
    GLint i[4] = {};
    GLuint u[1] = {};
    for (std::size_t k = 0; k < values.size() && k < 16; ++k) {
        f[k] = float(values[k]);
        if (k < 4) i[k] = GLint(std::int64_t(values[k]));
        if (k < 1) u[k] = GLuint(std::int64_t(values[k]));
    }
    switch (type) {
        case GL_FLOAT: glUniform1fv(location, 1, f); break;
        case GL_FLOAT_VEC2: glUniform2fv(location, 1, f); break;
        case GL_FLOAT_VEC3: glUniform3fv(location, 1, f); break;
        case GL_FLOAT_VEC4: glUniform4fv(location, 1, f); break;
        case GL_INT: glUniform1iv(location, 1, i); break;
        case GL_INT_VEC2: glUniform2iv(location, 1, i); break;
        case GL_INT_VEC3: glUniform3iv(location, 1, i); break;
        case GL_INT_VEC4: glUniform4iv(location, 1, i); break;
        case GL_UNSIGNED_INT: glUniform1uiv(location, 1, u); break;
        case GL_FLOAT_MAT2: glUniformMatrix2fv(location, 1, GL_FALSE, f); break;
        case GL_FLOAT_MAT3: glUniformMatrix3fv(location, 1, GL_FALSE, f); break;
        case GL_FLOAT_MAT4: glUniformMatrix4fv(location, 1, GL_FALSE, f); break;
        default: throw std::logic_error("set_uniform: a type uniform_values refused");
    }
}

GLint gl_enum(Wrap w) { return GLint(w); }      // glTF keeps GL's values
GLint gl_enum(Filter f) { return GLint(f); }

}  // namespace

std::string atlas_vertex_source(const std::string& source) {
    // #version must stay the first line; #extension lines after it may follow the #define.
    std::size_t body = 0;
    if (source.starts_with("#version")) {
        body = source.find('\n');
        body = body == std::string::npos ? source.size() : body + 1;
    }
    return source.substr(0, body) + "#define main qs_user_main\n" + source.substr(body) +
           "\n#undef main\n"
           "void main() {\n"
           "    qs_user_main();\n"
           "    gl_Position = vec4(gl_MultiTexCoord0.st * 2.0 - 1.0, 0.0, 1.0);\n"
           "}\n";
}

GlPrograms::~GlPrograms() {
    for (const Linked& l : linked_) glDeleteProgram(l.id);
}

unsigned GlPrograms::program(const std::string& shader, bool atlas) {
    for (const Linked& l : linked_) {
        if (l.shader == shader && l.atlas == atlas) return l.id;
    }
    linked_.push_back({shader, atlas, link_program(glsl_dir_, shader, atlas)});
    return linked_.back().id;
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
        if (request_.shader_override.empty() && !o.glsl_fragment.empty()) {
            // Its vertex shader may be one quadshade's front end writes, which the reference does not include.
            throw std::runtime_error(scene_.file.string() + ": " + o.material + ": extras.glsl: a material drawn by its own GLSL "
                                     "file is not rendered by the reference; compare it with quadshade check --glsl " +
                                     o.glsl_fragment.string());
        }
        const std::string name = !request_.shader_override.empty() ? request_.shader_override
                                 : !o.shader.empty()               ? o.shader
                                                                   : std::string(kDefaultMaterialShader);
        shaders_.push_back(name);
        const GLuint p = programs.program(name, request_.atlas);
        programs_.push_back(p);
        std::vector<Binding> bindings;
        for (const SamplerUniform& s : samplers_of(p)) {
            const int unit = int(bindings.size());
            const Texture& t = texture_of(o, name, s.name, s.dims, s.shadow);
            bindings.push_back({glGetUniformLocation(p, s.name.c_str()), unit, &t});
        }
        bound_.push_back(std::move(bindings));
        // Under --shader a material's uniforms were written for its own shader: only the ones the
        // drawn program has apply.
        std::vector<UniformSetting> settings = merge_uniforms(o.uniforms, request_.uniforms);
        if (!request_.shader_override.empty()) {
            std::erase_if(settings, [&](const UniformSetting& s) {
                return !s.origin.starts_with("--uniform") && glGetUniformLocation(p, s.name.c_str()) < 0;
            });
        }
        uniforms_.push_back(uniform_values(p, name, settings, programs.glsl_dir()));
        // The scene's transforms and vertex attributes the program reads by name.
        std::vector<MatrixBinding> matrices;
        for (const auto& [u, type] : active_uniforms(p)) {
            if (u.starts_with("gl_")) continue;  // GL's own state (gl_ModelViewProjectionMatrix), set by GL
            if (const SceneMatrixName* m = find_scene_matrix(u)) {
                matrices.push_back({glGetUniformLocation(p, u.c_str()), m->matrix});
            } else if (type == GL_FLOAT_MAT2 || type == GL_FLOAT_MAT3 || type == GL_FLOAT_MAT4) {
                // A matrix of the shader's own that nothing sets is all zeros: never a transform
                // it means (a vertex stage reading one under a name the scene does not feed would
                // draw nothing), so it is refused rather than drawn.
                bool set = false;
                for (const UniformValue& v : uniforms_.back()) set = set || v.location == glGetUniformLocation(p, u.c_str());
                float value[16] = {};
                glGetUniformfv(p, glGetUniformLocation(p, u.c_str()), value);
                bool zero = true;
                for (float x : value) zero = zero && x == 0.0f;
                if (!set && zero) {
                    throw std::runtime_error(name + ": uniform " + (type == GL_FLOAT_MAT4 ? "mat4" : type == GL_FLOAT_MAT3 ? "mat3" : "mat2") +
                                             " '" + u + "' is none of the scene's transforms (" + std::string(scene_matrix_names()) +
                                             ") and nothing sets it (no initializer, material extras.uniforms or --uniform): it "
                                             "would be all zeros");
                }
            }
        }
        matrices_.push_back(std::move(matrices));
        std::vector<AttributeBinding> attributes;
        for (const auto& [a, type] : active_attributes(p)) {
            if (const VertexAttributeName* v = find_vertex_attribute(a)) {
                attributes.push_back({glGetAttribLocation(p, a.c_str()), v->attribute});
                attribute_array(scene_.meshes[o.mesh], v->attribute, name, a);  // refuses what the scene cannot feed
            }
        }
        attributes_.push_back(std::move(attributes));
    }
    for (const UniformSetting& s : request_.uniforms) {
        bool found = false;
        for (std::size_t i = 0; i < programs_.size(); ++i) {
            found = found || glGetUniformLocation(programs_[i], s.name.c_str()) >= 0 ||
                    glsl_declares(programs.glsl_dir(), shaders_[i], s.name);
        }
        if (!found) throw UniformOptionError(s.origin + ": no shader in this scene declares a uniform '" + s.name + "'");
    }
}

std::vector<GlSceneRenderer::UniformValue> GlSceneRenderer::uniform_values(unsigned program, const std::string& shader,
                                                                           const std::vector<UniformSetting>& settings,
                                                                           const std::filesystem::path& glsl_dir) const {
    std::vector<UniformValue> out;
    for (const UniformSetting& s : settings) {
        const bool from_option = s.origin.starts_with("--uniform");
        auto refuse = [&](const std::string& what) {
            if (from_option) throw UniformOptionError(s.origin + ": " + what);
            throw std::runtime_error(s.origin + ": " + what);
        };
        if (s.name == kResolutionUniform) refuse("uResolution is the frame's size, set by the renderer");
        if (find_scene_matrix(s.name)) refuse(s.name + " is the scene's transform, set by the renderer");
        const GLint location = glGetUniformLocation(program, s.name.c_str());
        if (location < 0) {
            // Declared but compiled away: nothing to set. A command line's may be another program's.
            if (from_option || glsl_declares(glsl_dir, shader, s.name)) {
                continue;
            }
            refuse("shader '" + shader + "' has no uniform '" + s.name + "'");
        }
        GLenum type = 0;
        for (const auto& [name, t] : active_uniforms(program)) {
            if (name == s.name) type = t;
        }
        const GlUniformType g = gl_uniform_type(type);
        if (g.components == 0) refuse("uniform '" + s.name + "' of shader '" + shader + "' is of a type the reference cannot set");
        if (int(s.values.size()) != g.components) {
            refuse("uniform '" + s.name + "' of shader '" + shader + "' takes " + std::to_string(g.components) +
                   " number(s), got " + std::to_string(s.values.size()));
        }
        for (double v : s.values) {
            const double lo = g.unsigned_integer ? 0.0 : -2147483648.0, hi = g.unsigned_integer ? 4294967295.0 : 2147483647.0;
            if (g.integer && (v != std::trunc(v) || v < lo || v > hi)) {
                refuse("uniform '" + s.name + "' of shader '" + shader + "' is an integer type: " + std::to_string(v) + " is not one");
            }
        }
        out.push_back({location, type, s.values});
    }
    return out;
}

GlSceneRenderer::AttributeArray GlSceneRenderer::attribute_array(const Mesh& mesh, VertexAttribute attribute,
                                                                 const std::string& shader, const std::string& name) const {
    const Vertex& first = mesh.vertices.front();
    switch (attribute) {
        case VertexAttribute::Position: return {&first.position.x, 3};
        case VertexAttribute::Texcoord0: return {&first.texcoord.x, 2};
        case VertexAttribute::Normal:
        case VertexAttribute::Texcoord1:
        case VertexAttribute::Color: break;
    }
    std::string gltf;
    for (const VertexAttributeName& a : kVertexAttributes) {
        if (a.attribute == attribute) gltf = a.gltf;
    }
    throw std::runtime_error(scene_.file.string() + ": mesh '" + mesh.name + "': shader '" + shader + "' reads vertex input '" + name +
                             "' (glTF " + gltf + "), which the scene model does not carry");
}

const GlSceneRenderer::Texture& GlSceneRenderer::texture_of(const Object& o, const std::string& shader,
                                                            const std::string& uniform, int dims, bool shadow) {
    const int index = o.texture_for(uniform);
    const bool cube = dims == kCubeMap;
    const std::string what = scene_.file.string() + ": " + o.material + ": shader '" + shader + "' samples " +
                             (dims == 3 ? "a sampler3D"
                              : cube    ? (shadow ? "a samplerCubeShadow" : "a samplerCube")
                                        : (shadow ? "a sampler2DShadow" : "a sampler2D")) +
                             " '" + uniform + "'";
    if (index < 0) return white(dims);
    const qs::Texture& source = scene_.textures[std::size_t(index)];
    if (source.dims != dims) {
        throw std::runtime_error(what + " but " + source.field + " is " +
                                 (source.dims == kCubeMap ? std::string("a cube map") : std::to_string(source.dims) + "D texture"));
    }
    if (source.compare.has_value() != shadow) {
        throw std::runtime_error(what + " but " + source.field +
                                 (shadow ? " is not a depth comparison texture" : " is a depth comparison texture"));
    }
    Texture& t = textures_[std::size_t(index)];
    if (t.id) return t;
    if (cube) return upload_cube(source, t);
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
    } else if (source.compare) {
        // The depth is the red byte as llvmpipe turns a unorm8 into a float (times the float
        // nearest 1/255), uploaded as floats so that no conversion (GL_DEPTH_COMPONENT from bytes
        // is 24-bit unorm) comes between.
        if (image.sixteen_bits) {
            throw std::runtime_error(scene_.file.string() + ": " + source.field +
                                     ": a depth comparison texture is an 8-bit image (its red channel is the depth)");
        }
        std::vector<float> depth(std::size_t(image.width) * std::size_t(image.height));
        for (std::size_t i = 0; i < depth.size(); ++i) depth[i] = float(image.bytes[4 * i]) * float(1.0 / 255.0);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, image.width, image.height, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                     depth.data());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GLint(*source.compare));
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

// A cube map's six faces, +X first, each a GL_TEXTURE_CUBE_MAP face image in GL's order; a depth
// comparison cube map's red bytes as GL_DEPTH_COMPONENT32F, as a 2D one's. GL's default leaves
// GL_TEXTURE_CUBE_MAP_SEAMLESS off: a lookup stays on its face.
const GlSceneRenderer::Texture& GlSceneRenderer::upload_cube(const qs::Texture& source, Texture& t) {
    std::array<DecodedImage, 6> faces;
    for (std::size_t f = 0; f < 6; ++f) {
        const std::string where = scene_.file.string() + ": " + source.field + "[" + std::to_string(f) + "]: ";
        try {
            faces[f] = decode_texture_image(source.faces.at(f));
        } catch (const std::exception& e) {
            throw std::runtime_error(where + e.what());
        }
        if (faces[f].width != faces[f].height || faces[f].width != faces[0].width) {
            throw std::runtime_error(where + "a cube map's faces are square and of one size");
        }
        if (source.compare && faces[f].sixteen_bits) {
            throw std::runtime_error(where + "a depth comparison texture is an 8-bit image (its red channel is the depth)");
        }
    }
    t.target = GL_TEXTURE_CUBE_MAP;
    t.width = t.height = faces[0].width;
    glGenTextures(1, &t.id);
    glBindTexture(t.target, t.id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (std::size_t f = 0; f < 6; ++f) {
        const GLenum face = GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f);
        const DecodedImage& image = faces[f];
        if (source.compare) {
            std::vector<float> depth(std::size_t(image.width) * std::size_t(image.height));
            for (std::size_t i = 0; i < depth.size(); ++i) depth[i] = float(image.bytes[4 * i]) * float(1.0 / 255.0);
            glTexImage2D(face, 0, GL_DEPTH_COMPONENT32F, image.width, image.height, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                         depth.data());
        } else {
            const GLenum type = image.sixteen_bits ? GL_UNSIGNED_SHORT : GL_UNSIGNED_BYTE;
            glTexImage2D(face, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, type, image.bytes.data());
        }
    }
    if (source.compare) {
        glTexParameteri(t.target, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glTexParameteri(t.target, GL_TEXTURE_COMPARE_FUNC, GLint(*source.compare));  // GL's values
    }
    const Sampler& s = source.sampler;
    glTexParameteri(t.target, GL_TEXTURE_MIN_FILTER, gl_enum(s.min_filter));
    glTexParameteri(t.target, GL_TEXTURE_MAG_FILTER, gl_enum(s.mag_filter));
    glTexParameteri(t.target, GL_TEXTURE_WRAP_S, gl_enum(s.wrap_s));
    glTexParameteri(t.target, GL_TEXTURE_WRAP_T, gl_enum(s.wrap_t));
    if (uses_mipmaps(s.min_filter)) glGenerateMipmap(t.target);
    if (GLenum e = glGetError(); e != GL_NO_ERROR) {
        throw std::runtime_error(scene_.file.string() + ": " + source.field + ": OpenGL error " + std::to_string(e) +
                                 " uploading the cube map");
    }
    return t;
}

const GlSceneRenderer::Texture& GlSceneRenderer::white(int dims) {
    Texture& t = white_[dims == 3 ? 1 : dims == kCubeMap ? 2 : 0];
    if (t.id) return t;
    const GLubyte texel[4] = {255, 255, 255, 255};
    t.target = dims == 3 ? GL_TEXTURE_3D : dims == kCubeMap ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
    t.width = t.height = 1;
    glGenTextures(1, &t.id);
    glBindTexture(t.target, t.id);
    if (dims == 3) {
        glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    } else if (dims == kCubeMap) {
        for (int f = 0; f < 6; ++f) {
            glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
        }
    } else {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    }
    glTexParameteri(t.target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(t.target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
}

GlSceneRenderer::~GlSceneRenderer() {
    for (const Texture& t : textures_) {
        if (t.id) glDeleteTextures(1, &t.id);
    }
    for (const Texture& t : white_) {
        if (t.id) glDeleteTextures(1, &t.id);
    }
}

// Culling and blending for object i, as glTF asks.
void GlSceneRenderer::set_state(std::size_t i, const Pose& pose) {
    const Object& o = scene_.objects[i];
    // glTF: a material that is not doubleSided culls back faces; a mirroring node turns its
    // front faces clockwise. An atlas bake draws every triangle, in texture space.
    if (o.double_sided || request_.atlas) {
        glDisable(GL_CULL_FACE);
    } else {
        glEnable(GL_CULL_FACE);
        glFrontFace(mirrors(pose, i) ? GL_CW : GL_CCW);
    }
    // glTF's alphaMode BLEND, for the default material: blended over what is drawn, no depth writes.
    const bool blend =
        o.look.alpha_mode == AlphaMode::Blend && shaders_[i] == kDefaultMaterialShader && !request_.atlas;
    if (blend) {
        glEnable(GL_BLEND);
    } else {
        glDisable(GL_BLEND);
    }
    glDepthMask(blend ? GL_FALSE : GL_TRUE);
}

// Object i's uniforms in its program p: the scene's transforms, time and frame size, the
// material's and --uniform's values, its textures' units.
void GlSceneRenderer::set_uniforms(std::size_t i, const Pose& pose, double time, double aspect) {
    const Object& o = scene_.objects[i];
    const GLuint p = programs_[i];
    const int width = context_.width(), height = context_.height();
    if (GLint loc = glGetUniformLocation(p, "time"); loc >= 0) glUniform1f(loc, float(time));
    const ObjectTransforms transforms = object_transforms(scene_, pose, i, aspect);
    for (const MatrixBinding& m : matrices_[i]) {
        switch (m.matrix) {
            case SceneMatrix::ModelViewProjection:
                glUniformMatrix4fv(m.location, 1, GL_FALSE, glm::value_ptr(transforms.model_view_projection));
                break;
            case SceneMatrix::Model: glUniformMatrix4fv(m.location, 1, GL_FALSE, glm::value_ptr(transforms.model)); break;
            case SceneMatrix::View: glUniformMatrix4fv(m.location, 1, GL_FALSE, glm::value_ptr(transforms.view)); break;
            case SceneMatrix::Projection:
                glUniformMatrix4fv(m.location, 1, GL_FALSE, glm::value_ptr(transforms.projection));
                break;
            case SceneMatrix::Normal: glUniformMatrix3fv(m.location, 1, GL_FALSE, glm::value_ptr(transforms.normal)); break;
        }
    }
    if (GLint loc = glGetUniformLocation(p, std::string(kResolutionUniform).c_str()); loc >= 0) {
        glUniform2f(loc, float(width), float(height));
    }
    // The scene's values where the program has the uniform, then the material's and --uniform's.
    const std::vector<std::pair<std::string, GLenum>> active = active_uniforms(p);
    for (const UniformSetting& s : object_uniforms(scene_, i, pose, aspect)) {
        for (const auto& [name, type] : active) {
            if (name == s.name && gl_uniform_type(type).components == int(s.values.size())) {
                set_uniform(glGetUniformLocation(p, name.c_str()), type, s.values);
            }
        }
    }
    for (const UniformValue& u : uniforms_[i]) set_uniform(u.location, u.type, u.values);
    for (const Binding& b : bound_[i]) {
        glActiveTexture(GLenum(GL_TEXTURE0 + b.unit));
        glBindTexture(b.texture->target, b.texture->id);
        glUniform1i(b.location, b.unit);
    }
    if (GLint loc = glGetUniformLocation(p, "dims"); loc >= 0) {
        const int teximage = o.texture_for("teximage");
        const Texture& t = teximage < 0 ? white(2) : textures_[std::size_t(teximage)];
        if (!t.id) throw std::runtime_error(o.material + ": dims without teximage");
        glUniform2f(loc, float(t.width), float(t.height));
    }
}

// Object i's mesh through its program's vertex inputs.
void GlSceneRenderer::draw_mesh(std::size_t i) {
    const Object& o = scene_.objects[i];
    const Mesh& mesh = scene_.meshes[o.mesh];
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, sizeof(Vertex), &mesh.vertices[0].position);
    glNormalPointer(GL_FLOAT, sizeof(Vertex), &mesh.vertices[0].normal);
    glColorPointer(4, GL_FLOAT, sizeof(Vertex), &mesh.vertices[0].color);
    for (const GLenum unit : {GL_TEXTURE0, GL_TEXTURE1}) {  // gl_MultiTexCoord0, gl_MultiTexCoord1
        glClientActiveTexture(unit);
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glTexCoordPointer(2, GL_FLOAT, sizeof(Vertex),
                          unit == GL_TEXTURE0 ? &mesh.vertices[0].texcoord : &mesh.vertices[0].texcoord1);
    }
    glClientActiveTexture(GL_TEXTURE0);
    const std::string& shader = shaders_[i];
    for (const AttributeBinding& a : attributes_[i]) {
        const AttributeArray array = attribute_array(mesh, a.attribute, shader, "");
        glEnableVertexAttribArray(GLuint(a.location));
        glVertexAttribPointer(GLuint(a.location), array.components, GL_FLOAT, GL_FALSE, sizeof(Vertex), array.first);
    }
    glDrawElements(GL_TRIANGLES, GLsizei(mesh.indices.size()), GL_UNSIGNED_INT, mesh.indices.data());
    for (const AttributeBinding& a : attributes_[i]) glDisableVertexAttribArray(GLuint(a.location));
}

void GlSceneRenderer::draw() {
    context_.make_current();
    const int width = context_.width(), height = context_.height();
    const double aspect = double(width) / double(height);
    const double time = request_.time.value_or(double(scene_.time));
    const Pose pose = scene_.pose(time);
    glViewport(0, 0, width, height);
    glClearColor(scene_.clear_color.r, scene_.clear_color.g, scene_.clear_color.b, scene_.clear_color.a);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glCullFace(GL_BACK);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    for (const std::size_t i : scene_.draw_order(pose)) {
        glUseProgram(programs_[i]);
        // The scene model's MVP, as the projection; gl_ModelViewProjectionMatrix = P * I.
        const glm::mat4 mvp = scene_.clip_from_object(pose, i, aspect);
        glMatrixMode(GL_PROJECTION);
        glLoadMatrixf(glm::value_ptr(mvp));
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        set_state(i, pose);
        set_uniforms(i, pose, time, aspect);
        draw_mesh(i);
    }
    glDepthMask(GL_TRUE);
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
