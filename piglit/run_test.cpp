#include "piglit/run_test.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "core/framebuffer.h"
#include "frontend/compile.h"
#include "interpreter/glsl_program.h"
#include "piglit/numbers.h"
#include "piglit/requirements.h"
#include "piglit/shader_test.h"
#include "piglit/test_commands.h"
#include "piglit/vertex_data.h"
#include "piglit/skip_reason.h"
#include "raster/rasterizer.h"
#include "shading/glsl/texture.h"
#ifdef QUADSHADE_HAS_RAYCAST
#include "raycast/ray_caster.h"
#endif

namespace qs::piglit {

namespace {

// shader_runner's [vertex shader passthrough].
constexpr const char* kPassthroughVertexShader =
    "#if __VERSION__ >= 130\n"
    "in vec4 piglit_vertex;\n"
    "#else\n"
    "attribute vec4 piglit_vertex;\n"
    "#endif\n"
    "void main() { gl_Position = piglit_vertex; }\n";

// GL's fixed-function stages, as GLSL, for a test that has no shader of one stage: the vertex
// transformed by the matrices, the current colour and texture coordinates passed on (no
// lighting, no texture matrices); the fragment's colour.
constexpr const char* kFixedFunctionVertexShader =
    "#version 110\n"
    "void main() {\n"
    "    gl_Position = ftransform();\n"
    "    gl_FrontColor = gl_Color;\n"
    "    gl_BackColor = gl_Color;\n"
    "    gl_TexCoord[0] = gl_MultiTexCoord0;\n"
    "    gl_TexCoord[1] = gl_MultiTexCoord1;\n"
    "}\n";
constexpr const char* kFixedFunctionFragmentShader = "#version 110\nvoid main() { gl_FragColor = gl_Color; }\n";

// piglit binds these before linking (shader_runner.c, PIGLIT_ATTRIB_POS and _TEX).
const std::map<std::string, int> kBoundAttributes = {{"piglit_vertex", 0}, {"piglit_texcoord", 1}};

// Thrown to end the run: piglit_report_result's exits, and skips found while running.
struct Outcome {
    Status status;
    std::string reason, message;
};

// The GL state that decides how the program is compiled (compile_options.h).
struct ColorState {
    bool two_sided = false, flat = false;
    bool operator<(const ColorState& o) const { return std::pair(two_sided, flat) < std::pair(o.two_sided, o.flat); }
};

struct Variant {
    std::unique_ptr<interpreter::GlslProgram> program;
};

// A texture the script made (texture rgbw, texture miptree), its levels as given and its
// parameters as texparameter left them, built for sampling when a draw first reads it.
struct ScriptTexture {
    int width = 0, height = 0;
    std::vector<std::vector<std::uint8_t>> levels;  // RGBA8, rows from t = 0; level 0 first
    glsl::SamplerState sampler;
    std::unique_ptr<glsl::sampler2D> built;

    // GL samples a texture whose minification filter reads mipmaps only when every level is given.
    bool complete() const {
        if (sampler.mip == glsl::MipFilter::None) return true;
        std::size_t needed = 1;
        for (int w = width, h = height; w > 1 || h > 1; w = std::max(w / 2, 1), h = std::max(h / 2, 1)) ++needed;
        return levels.size() >= needed;
    }
    const glsl::sampler2D& get() {
        if (!built) {
            built = std::make_unique<glsl::sampler2D>(width, height, levels[0].data(), sampler);
            for (std::size_t l = 1; l < built->levels.size() && l < levels.size(); ++l) {
                const glsl::Texture::Level& level = built->levels[l];
                for (std::size_t i = 0; i < std::size_t(level.width) * std::size_t(level.height); ++i) {
                    const std::uint8_t* t = &levels[l][4 * i];
                    built->texels[std::size_t(level.offset) + i] = std::uint32_t(t[0]) | std::uint32_t(t[1]) << 8 |
                                                                   std::uint32_t(t[2]) << 16 | std::uint32_t(t[3]) << 24;
                }
            }
        }
        return *built;
    }
};

class ScriptRun {
public:
    ScriptRun(ShaderTest test, const RunOptions& options) : test_(std::move(test)), options_(options) {}

    TestResult run() {
        TestResult r;
        r.file = test_.file;
        try {
            prepare();
            execute();
            r.status = status_;
            r.message = message_;
        } catch (const Outcome& o) {
            r.status = o.status, r.reason = o.reason, r.message = o.message;
        }
        r.probes = std::move(probes_);
        if (r.status == Status::Pass || r.status == Status::Warn) {
            // Probes that warned are kept; a passing test has no mismatches to report otherwise.
        }
        return r;
    }

private:
    [[noreturn]] static void skip(const std::string& reason, const std::string& message = {}) {
        throw Outcome{Status::Skip, reason, message.empty() ? reason : message};
    }
    [[noreturn]] void fail(const std::string& message) const { throw Outcome{Status::Fail, {}, message}; }
    std::string at_line(int line) const { return test_.file + ":" + std::to_string(line) + ": "; }

    // ---- before the script -------------------------------------------------------------------

    void prepare() {
        requirements_ = check_requirements(test_, Implementation::quadshade());
        if (requirements_.error) fail(*requirements_.error);
        if (requirements_.unmet) skip("requires " + *requirements_.unmet);
        for (const Line& l : test_.unsupported) skip("section " + l.text, at_line(l.number) + "section " + l.text);
        const ShaderSection* vertex = nullptr;
        const ShaderSection* fragment = nullptr;
        for (const ShaderSection& s : test_.shaders) {
            if (s.stage != Stage::Vertex && s.stage != Stage::Fragment) {
                skip(std::string(stage_name(s.stage)) + " shader", at_line(s.first_line - 1) + stage_name(s.stage) +
                                                                       " shaders are not run");
            }
            const ShaderSection*& slot = s.stage == Stage::Vertex ? vertex : fragment;
            if (slot) {
                skip("several shaders of one stage", at_line(s.first_line - 1) + "a second " + stage_name(s.stage) +
                                                          " shader: quadshade links one per stage");
            }
            slot = &s;
        }
        if (vertex && test_.vertex_passthrough) skip("several shaders of one stage");
        commands_ = parse_test_commands(test_.test);
        check_commands();
        if (test_.has_vertex_data) {
            try {
                vertex_data_ = parse_vertex_data(test_.file, test_.vertex_data);
            } catch (const ShaderTestError& e) {
                fail(e.what());
            }
        }
        width_ = requirements_.width, height_ = requirements_.height;
        fb_.hold(width_, height_, {0, height_}, false, false);
        std::fill(fb_.rgba.begin(), fb_.rgba.end(), 0.0f);
        if (!vertex && !fragment && !test_.vertex_passthrough) return;  // no program: piglit fails its draws
        if (requirements_.glsl_version == 0) fail(test_.file + ": GLSL version requirement missing");
        fragment_ = fragment ? source_of(*fragment) : frontend::GlslSource{test_.file + " (fixed-function fragment stage)",
                                                                            kFixedFunctionFragmentShader};
        if (vertex) {
            vertex_ = source_of(*vertex);
        } else if (test_.vertex_passthrough) {
            vertex_ = passthrough_source();
        } else {
            vertex_ = frontend::GlslSource{test_.file + " (fixed-function vertex stage)", kFixedFunctionVertexShader};
        }
        compile_variants();
    }

    // The GLSL of a section as shader_runner hands it to GL: with a #version from [require] when it
    // has none, and padded so that the compiler's line numbers are the file's.
    frontend::GlslSource source_of(const ShaderSection& s) const {
        std::string text;
        if (s.text.find("#version ") == std::string::npos) {
            text = "#version " + std::to_string(requirements_.glsl_version) + "\n";
            text.append(std::size_t(std::max(s.first_line - 2, 0)), '\n');
        } else {
            text.append(std::size_t(std::max(s.first_line - 1, 0)), '\n');
        }
        return {test_.file, text + s.text};
    }
    frontend::GlslSource passthrough_source() const {
        return {test_.file + " (passthrough vertex shader)",
                "#version " + std::to_string(requirements_.glsl_version) + "\n" + kPassthroughVertexShader};
    }

    // Skips for what the script asks that quadshade does not do, before anything is drawn.
    void check_commands() {
        for (const TestCommand& c : commands_) {
            const std::string where = at_line(c.line) + c.text;
            if (const auto* u = std::get_if<Unsupported>(&c.command)) skip("command '" + u->name + "'", where);
            if (const auto* e = std::get_if<Enable>(&c.command)) {
                if (e->on && (e->what == "GL_DEPTH_TEST" || e->what == "GL_DEPTH_CLAMP")) skip("enable " + e->what, where);
            }
            if (const auto* p = std::get_if<ClipPlane>(&c.command); p && (p->index < 0 || p->index >= kMaxClipDistances)) {
                fail(where + ": clip plane id " + std::to_string(p->index) + " out of range");
            }
            if (const auto* t = std::get_if<TextureRgbw>(&c.command)) {
                if (!t->format.empty() && t->format != "GL_RGBA" && t->format != "GL_RGBA8") skip("texture format " + t->format, where);
            }
            // Its GL_CLAMP_TO_BORDER has no counterpart in quadshade's samplers.
            if (std::holds_alternative<TextureCheckerboard>(c.command)) skip("command 'texture checkerboard'", where);
            if (const auto* t = std::get_if<TexParameter>(&c.command)) {
                if (t->target != "2D") skip("texparameter " + t->target, where);
                if (!sampler_parameter(t->parameter, t->value, nullptr)) skip("texparameter " + t->parameter + " " + t->value, where);
            }
            if (const auto* d = std::get_if<DrawArrays>(&c.command)) {
                if (d->mode != "GL_TRIANGLES" && d->mode != "GL_TRIANGLE_STRIP" && d->mode != "GL_TRIANGLE_FAN" &&
                    d->mode != "GL_QUADS" && d->mode != "GL_POLYGON") {
                    skip("primitive " + d->mode, where);
                }
            }
            if (const auto* u = std::get_if<SetUniform>(&c.command)) {
                for (const char* t : {"double", "dvec", "dmat", "int64_t", "uint64_t", "i64vec", "u64vec", "handle"}) {
                    if (u->type.rfind(t, 0) == 0) skip("uniform " + std::string(t), where);
                }
            }
        }
    }

    // The program under each colour state the script draws with (two-sided colour, shade model),
    // compiled before the script runs, as GL links before drawing.
    void compile_variants() {
        std::set<ColorState> states{{}};
        ColorState s;
        for (const TestCommand& c : commands_) {
            if (const auto* e = std::get_if<Enable>(&c.command); e && e->what == "GL_VERTEX_PROGRAM_TWO_SIDE") s.two_sided = e->on;
            if (const auto* m = std::get_if<ShadeModel>(&c.command)) s.flat = m->flat;
            if (std::holds_alternative<DrawRect>(c.command) || std::holds_alternative<DrawArrays>(c.command)) states.insert(s);
        }
        for (const ColorState& state : states) {
            frontend::CompileOptions o;
            o.attribute_locations = kBoundAttributes;
            o.two_sided_color = state.two_sided;
            o.flat_colors = state.flat;
            try {
                frontend::CompiledProgram compiled = frontend::compile_glsl(fragment_, vertex_, o);
                auto program = std::make_unique<interpreter::GlslProgram>(test_.file, std::move(compiled));
                variants_.emplace(state, Variant{std::move(program)});
            } catch (const frontend::GlslUnsupported& e) {
                skip(skip_reason_of(e.what(), test_.file), e.what());
            } catch (const frontend::GlslLinkError& e) {
                linked_ = false;
                link_log_ = e.what();
                return;
            } catch (const frontend::GlslError& e) {
                fail(std::string("compile error:\n") + e.what());
            }
        }
        linked_ = true;
        const ir::Program& p = variants_.begin()->second.program->program();
        for (const auto& [state, v] : variants_) {
            if (v.program->program().uniforms.size() != p.uniforms.size()) {
                throw std::logic_error("the program's variants declare different uniforms");
            }
        }
        uniform_words_.assign(p.uniforms.size() * kUniformWords, 0u);
        for (std::size_t u = 0; u < p.uniforms.size(); ++u) {
            std::copy_n(p.uniforms[u].initial.begin(), p.uniforms[u].components, &uniform_words_[u * kUniformWords]);
        }
    }

    // ---- the script -------------------------------------------------------------------------

    void execute() {
        bool link_error_expected = false;
        for (const TestCommand& c : commands_) {
            line_ = c.line;
            text_ = c.text;
            Status result = Status::Pass;
            std::visit([&](const auto& command) { result = apply(command); }, c.command);
            if (std::holds_alternative<LinkError>(c.command)) link_error_expected = true;
            // As shader_runner: the last line that did not pass decides.
            if (result != Status::Pass) status_ = result;
        }
        if (!linked_ && !link_error_expected) {
            status_ = Status::Fail;
            add_message("the program did not link" + (link_log_.empty() ? std::string() : ":\n" + link_log_));
        }
    }

    void add_message(const std::string& m) { message_ += (message_.empty() ? "" : "\n") + m; }
    Status failed_line(const std::string& why) {
        add_message(at_line(line_) + text_ + (why.empty() ? "" : ": " + why));
        return Status::Fail;
    }
    Status program_in_use() {
        if (linked_) return Status::Pass;
        return failed_line("the program did not link" + (link_log_.empty() ? std::string() : ":\n" + link_log_));
    }

    Status apply(const ClearColor& c) {
        clear_color_ = glm::vec4(c.rgba[0], c.rgba[1], c.rgba[2], c.rgba[3]);
        clear_bits_color_ = true;
        return Status::Pass;
    }
    Status apply(const ClearDepth&) { return Status::Pass; }  // no depth test runs
    Status apply(const Clear&) {
        if (clear_bits_color_) {
            for (std::size_t i = 0; i < fb_.rgba.size(); i += 4) {
                for (int k = 0; k < 4; ++k) fb_.rgba[i + std::size_t(k)] = clear_color_[k];
            }
        }
        return Status::Pass;
    }
    Status apply(const Tolerance& t) {
        tolerance_ = t.values;
        return Status::Pass;
    }
    Status apply(const Ortho& o) {
        // piglit_ortho_projection / piglit_gen_ortho_projection: the projection, model-view identity.
        if (o.box) {
            projection_ = ortho((*o.box)[0], (*o.box)[1], (*o.box)[2], (*o.box)[3], -1.0f, 1.0f);
        } else {
            projection_ = ortho(0.0f, float(width_), 0.0f, float(height_), -1.0f, 1.0f);
        }
        return Status::Pass;
    }
    Status apply(const Frustum& f) {
        const auto& p = f.planes;
        // piglit_frustum_projection: glFrustum's matrix.
        glm::mat4 m(0.0f);
        m[0][0] = 2.0f * p[4] / (p[1] - p[0]);
        m[1][1] = 2.0f * p[4] / (p[3] - p[2]);
        m[2][0] = (p[1] + p[0]) / (p[1] - p[0]);
        m[2][1] = (p[3] + p[2]) / (p[3] - p[2]);
        m[2][2] = -(p[5] + p[4]) / (p[5] - p[4]);
        m[2][3] = -1.0f;
        m[3][2] = -2.0f * p[5] * p[4] / (p[5] - p[4]);
        projection_ = m;
        return Status::Pass;
    }
    static glm::mat4 ortho(float l, float r, float b, float t, float n, float f) {
        glm::mat4 m(1.0f);
        m[0][0] = 2.0f / (r - l);
        m[1][1] = 2.0f / (t - b);
        m[2][2] = -2.0f / (f - n);
        m[3][0] = -(r + l) / (r - l);
        m[3][1] = -(t + b) / (t - b);
        m[3][2] = -(f + n) / (f - n);
        return m;
    }
    Status apply(const CurrentColor& c) {
        color_ = c.rgba;
        return Status::Pass;
    }
    Status apply(const CurrentTexcoord& t) {
        if (t.unit < 0 || t.unit > 1) skip("texture coordinates of unit 2 and above");
        if (t.stpq[2] != 0.0f || t.stpq[3] != 1.0f) skip("texture coordinates r and q");
        texcoord_[std::size_t(t.unit)] = t.stpq;
        return Status::Pass;
    }
    Status apply(const ShadeModel& m) {
        color_state_.flat = m.flat;
        return Status::Pass;
    }
    Status apply(const Enable& e) {
        if (e.what == "GL_VERTEX_PROGRAM_TWO_SIDE") color_state_.two_sided = e.on;
        if (e.what.rfind("GL_CLIP_PLANE", 0) == 0) {
            const unsigned bit = 1u << (e.what.back() - '0');
            clip_enabled_ = e.on ? clip_enabled_ | bit : clip_enabled_ & ~bit;
        }
        return Status::Pass;
    }
    Status apply(const ClipPlane& p) {
        // glClipPlane keeps the plane in eye space: times the inverse model-view matrix (the
        // identity here: scripts change only the projection).
        clip_planes_[std::size_t(p.index)] = glm::vec4(glm::dvec4(p.plane[0], p.plane[1], p.plane[2], p.plane[3]));
        return Status::Pass;
    }
    // ---- textures ---------------------------------------------------------------------------

    static std::array<std::uint8_t, 4> rgba8(const std::array<float, 4>& c) {
        return {unorm8(c[0]), unorm8(c[1]), unorm8(c[2]), unorm8(c[3])};
    }
    Status apply(const TextureRgbw& t) {
        // piglit_rgbw_texture: red, green, blue and white quadrants (red at s, t < 1/2), one
        // level, nearest filters, clamped to the edge.
        if (t.width < 1 || t.height < 1 || t.width > 16384 || t.height > 16384) fail(at_line(line_) + "invalid texture size");
        ScriptTexture tex;
        tex.width = t.width, tex.height = t.height;
        tex.sampler.min = tex.sampler.mag = glsl::Filter::Nearest;
        std::vector<std::uint8_t>& level = tex.levels.emplace_back(std::size_t(t.width) * std::size_t(t.height) * 4);
        for (int y = 0; y < t.height; ++y) {
            for (int x = 0; x < t.width; ++x) {
                const bool left = x < t.width / 2, bottom = y < t.height / 2;
                const std::array<float, 4> c = bottom ? (left ? std::array<float, 4>{1, 0, 0, 1} : std::array<float, 4>{0, 1, 0, 1})
                                                      : (left ? std::array<float, 4>{0, 0, 1, 1} : std::array<float, 4>{1, 1, 1, 1});
                std::copy_n(rgba8(c).begin(), 4, &level[(std::size_t(y) * std::size_t(t.width) + std::size_t(x)) * 4]);
            }
        }
        bind(t.unit, std::move(tex));
        return Status::Pass;
    }
    Status apply(const TextureMiptree& t) {
        // piglit_miptree_texture: 8x8, four levels of red, green, blue and white, nearest filters
        // reading the nearest level.
        ScriptTexture tex;
        tex.width = tex.height = 8;
        tex.sampler.min = tex.sampler.mag = glsl::Filter::Nearest;
        tex.sampler.mip = glsl::MipFilter::Nearest;
        constexpr std::array<std::array<float, 4>, 4> kWheel = {{{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 1}}};
        for (int l = 0; l < 4; ++l) {
            const int size = 8 >> l;
            std::vector<std::uint8_t>& level = tex.levels.emplace_back();
            for (int i = 0; i < size * size; ++i) {
                const std::array<std::uint8_t, 4> c = rgba8(kWheel[std::size_t(l)]);
                level.insert(level.end(), c.begin(), c.end());
            }
        }
        bind(t.unit, std::move(tex));
        return Status::Pass;
    }
    void bind(int unit, ScriptTexture tex) {
        if (unit < 0 || unit > 31) fail(at_line(line_) + "texture unit " + std::to_string(unit) + " out of range");
        textures_[unit] = std::move(tex);
        active_unit_ = unit;  // glActiveTexture
    }
    Status apply(const TextureCheckerboard&) { return Status::Pass; }  // skipped before the script runs
    Status apply(const TexParameter& t) {
        const auto it = textures_.find(active_unit_);
        if (it == textures_.end()) return Status::Pass;  // no texture bound: GL's default texture, never sampled here
        sampler_parameter(t.parameter, t.value, &it->second.sampler);
        it->second.built.reset();
        return Status::Pass;
    }
    // texparameter PARAMETER VALUE into `s` (when given); false for one quadshade's samplers lack.
    static bool sampler_parameter(const std::string& parameter, const std::string& value, glsl::SamplerState* s) {
        glsl::SamplerState ignored;
        glsl::SamplerState& out = s ? *s : ignored;
        if (parameter == "min" || parameter == "mag") {
            struct Filter {
                const char* name;
                glsl::Filter filter;
                glsl::MipFilter mip;
            };
            static constexpr Filter kFilters[] = {
                {"nearest", glsl::Filter::Nearest, glsl::MipFilter::None},
                {"linear", glsl::Filter::Linear, glsl::MipFilter::None},
                {"nearest_mipmap_nearest", glsl::Filter::Nearest, glsl::MipFilter::Nearest},
                {"linear_mipmap_nearest", glsl::Filter::Linear, glsl::MipFilter::Nearest},
                {"nearest_mipmap_linear", glsl::Filter::Nearest, glsl::MipFilter::Linear},
                {"linear_mipmap_linear", glsl::Filter::Linear, glsl::MipFilter::Linear},
            };
            for (const Filter& f : kFilters) {
                if (value != f.name) continue;
                if (parameter == "mag") {
                    if (f.mip != glsl::MipFilter::None) return false;
                    out.mag = f.filter;
                } else {
                    out.min = f.filter, out.mip = f.mip;
                }
                return true;
            }
            return false;
        }
        if (parameter == "wrap_s" || parameter == "wrap_t") {
            glsl::Wrap w;
            if (value == "repeat") w = glsl::Wrap::Repeat;
            else if (value == "clamp_to_edge") w = glsl::Wrap::ClampToEdge;
            else if (value == "mirrored_repeat") w = glsl::Wrap::MirroredRepeat;
            else return false;
            (parameter == "wrap_s" ? out.wrap_s : out.wrap_t) = w;
            return true;
        }
        return false;  // lod_bias, compare_func, depth_mode, levels, border colour, swizzles
    }
    Status apply(const NoEffect&) { return Status::Pass; }
    Status apply(const Unsupported&) { return Status::Pass; }  // skipped before the script runs
    Status apply(const Invalid& i) { fail(at_line(line_) + text_ + ": " + i.message); }
    Status apply(const LinkError&) {
        if (linked_) fail(at_line(line_) + "shader link error expected, but it was successful");
        return Status::Pass;
    }
    Status apply(const LinkSuccess&) { return program_in_use(); }

    // ---- uniforms ---------------------------------------------------------------------------

    Status apply(const SetUniform& u) {
        if (program_in_use() != Status::Pass) return Status::Fail;
        const ir::Program& p = variants_.begin()->second.program->program();
        std::optional<std::size_t> slot;
        for (const std::string& name : {u.name, u.name + "[0]"}) {
            for (std::size_t i = 0; i < p.uniforms.size() && !slot; ++i) {
                if (p.uniforms[i].name == name) slot = i;
            }
            if (slot) break;
        }
        if (!slot) {
            for (const ir::Sampler& s : p.samplers) {
                if (s.name != u.name) continue;
                // glUniform1i on a sampler: the texture unit it reads.
                const std::vector<std::int32_t> unit = parse_ints(u.values.c_str(), 1);
                if (u.type == "int" && unit.size() == 1) sampler_units_[u.name] = unit[0];
                return Status::Pass;
            }
            fail(at_line(line_) + "cannot get location of uniform \"" + u.name + "\"");
        }
        const ir::Uniform& decl = p.uniforms[*slot];
        // The command's type: its scalar kind and how many values it sets.
        const std::string& t = u.type;
        ir::Bank kind;
        int count = 0;
        if (t.rfind("float", 0) == 0) {
            kind = ir::Bank::Float, count = 1;
        } else if (t.rfind("int", 0) == 0) {
            kind = ir::Bank::Int, count = 1;
        } else if (t.rfind("uint", 0) == 0) {
            kind = ir::Bank::Uint, count = 1;
        } else if (t.rfind("vec", 0) == 0 && t.size() >= 4 && t[3] >= '2' && t[3] <= '4') {
            kind = ir::Bank::Float, count = t[3] - '0';
        } else if (t.rfind("ivec", 0) == 0 && t.size() >= 5 && t[4] >= '2' && t[4] <= '4') {
            kind = ir::Bank::Int, count = t[4] - '0';
        } else if (t.rfind("uvec", 0) == 0 && t.size() >= 5 && t[4] >= '2' && t[4] <= '4') {
            kind = ir::Bank::Uint, count = t[4] - '0';
        } else if (t.rfind("mat", 0) == 0 && t.size() >= 4 && t[3] >= '2' && t[3] <= '4') {
            const int columns = t[3] - '0';
            const int rows = t.size() >= 6 && t[4] == 'x' ? t[5] - '0' : columns;
            if (rows < 2 || rows > 4) fail(at_line(line_) + "unknown uniform type \"" + t + "\"");
            kind = ir::Bank::Float, count = columns * rows;
            if (decl.columns != columns) return mismatched(u, decl);
        } else {
            fail(at_line(line_) + "unknown uniform type \"" + t + "\"");
        }
        std::array<std::uint32_t, 16> words{};
        const char* values = u.values.c_str();
        switch (kind) {
            case ir::Bank::Float: {
                const std::vector<float> v = parse_floats(values, std::size_t(count));
                for (std::size_t i = 0; i < v.size(); ++i) words[i] = std::bit_cast<std::uint32_t>(v[i]);
                break;
            }
            case ir::Bank::Int: {
                const std::vector<std::int32_t> v = parse_ints(values, std::size_t(count));
                for (std::size_t i = 0; i < v.size(); ++i) words[i] = std::uint32_t(v[i]);
                break;
            }
            default: {
                const std::vector<std::uint32_t> v = parse_uints(values, std::size_t(count));
                for (std::size_t i = 0; i < v.size(); ++i) words[i] = v[i];
                break;
            }
        }
        if (decl.components != count) return mismatched(u, decl);
        std::uint32_t* out = &uniform_words_[*slot * kUniformWords];
        if (decl.bank == ir::Bank::Bool) {
            // glUniform*{f,i,ui} set a bool to whether the value is not zero.
            for (int i = 0; i < count; ++i) {
                const bool set = kind == ir::Bank::Float ? std::bit_cast<float>(words[std::size_t(i)]) != 0.0f : words[std::size_t(i)] != 0;
                out[i] = set ? 1u : 0u;
            }
            return Status::Pass;
        }
        if (decl.bank != kind) return mismatched(u, decl);
        std::copy_n(words.begin(), count, out);
        return Status::Pass;
    }
    // GL refuses a glUniform call of another type (GL_INVALID_OPERATION) and the uniform keeps
    // its value; shader_runner does not check, and the test goes on.
    Status mismatched(const SetUniform&, const ir::Uniform&) { return Status::Pass; }

    // ---- drawing ----------------------------------------------------------------------------

    const interpreter::GlslProgram& program() const { return *variants_.at(color_state_).program; }

    Status apply(const DrawRect& d) {
        if (program_in_use() != Status::Pass) return Status::Fail;
        float x = d.rect[0], y = d.rect[1], w = d.rect[2], h = d.rect[3];
        if (d.ortho) {
            // shader_runner's conversion from window pixels, in its arithmetic (float / int,
            // promoted to double by 2.0, rounded to float as an argument).
            x = float(-1.0 + 2.0 * (d.rect[0] / float(width_)));
            y = float(-1.0 + 2.0 * (d.rect[1] / float(height_)));
            w = float(2.0 * (d.rect[2] / float(width_)));
            h = float(2.0 * (d.rect[3] / float(height_)));
        }
        // piglit_draw_rect_custom: a strip of (x, y), (x + w, y), (x, y + h), (x + w, y + h).
        const float px[4] = {x, x + w, x, x + w}, py[4] = {y, y, y + h, y + h};
        std::vector<VertexIn> vertices(4);
        std::array<std::vector<AttributeValue>, kMaxGenericAttributes> arrays;
        for (int i = 0; i < 4; ++i) {
            VertexIn& v = vertices[std::size_t(i)];
            v.position = glm::vec3(px[i], py[i], 0.0f);
            v.id = std::uint32_t(i);
            current_values(v);
            if (d.tex) {
                const auto& t = *d.tex;
                v.texcoord = glm::vec2(i % 2 ? t[0] + t[2] : t[0], i >= 2 ? t[1] + t[3] : t[1]);
            }
        }
        arrays[0].resize(4);  // piglit_vertex
        for (int i = 0; i < 4; ++i) arrays[0][std::size_t(i)] = words(px[i], py[i], 0.0f, 1.0f);
        if (d.tex) {
            arrays[1].resize(4);  // piglit_texcoord
            for (int i = 0; i < 4; ++i) {
                const VertexIn& v = vertices[std::size_t(i)];
                arrays[1][std::size_t(i)] = words(v.texcoord.x, v.texcoord.y, 0.0f, 1.0f);
            }
        }
        draw(vertices, strip_indices(4), arrays);
        return Status::Pass;
    }

    Status apply(const DrawArrays& d) {
        if (program_in_use() != Status::Pass) return Status::Fail;
        const int rows = test_.has_vertex_data ? vertex_data_.vertices : 0;
        if (d.first < 0) fail(at_line(line_) + "draw arrays 'first' must be >= 0");
        if (d.count <= 0) fail(at_line(line_) + "draw arrays 'count' must be > 0");
        if (test_.has_vertex_data && (d.first >= rows || d.count > rows - d.first)) {
            fail(at_line(line_) + "draw arrays beyond the " + std::to_string(rows) + " rows of [vertex data]");
        }
        const std::size_t n = std::size_t(std::max(rows, d.first + d.count));
        std::vector<VertexIn> vertices(n);
        for (std::size_t i = 0; i < n; ++i) {
            vertices[i].id = std::uint32_t(i);
            current_values(vertices[i]);
        }
        std::array<std::vector<AttributeValue>, kMaxGenericAttributes> arrays;
        const ir::Program& p = program().program();
        for (std::size_t c = 0; c < vertex_data_.columns.size(); ++c) {
            const VertexColumn& col = vertex_data_.columns[c];
            if (col.kind == AttributeKind::Double) skip("double attributes");
            int location = -1;
            if (!col.name.empty() && std::all_of(col.name.begin(), col.name.end(), [](char ch) { return ch >= '0' && ch <= '9'; })) {
                location = std::atoi(col.name.c_str());
            } else {
                for (const ir::GenericAttribute& g : p.generic_attributes) {
                    if (g.name == col.name) location = g.location;
                }
            }
            if (location < 0) fail(at_line(col.line) + "unexpected vbo column name '" + col.name + "'");
            const int actual = location + col.matrix_column + col.array_index * col.columns;
            if (actual >= kMaxGenericAttributes) fail(at_line(col.line) + "attribute location " + std::to_string(actual) + " out of range");
            std::vector<AttributeValue>& a = arrays[std::size_t(actual)];
            a.assign(n, AttributeValue{});
            for (std::size_t i = 0; i < std::size_t(rows); ++i) a[i] = vertex_data_.values[c][i];
        }
        std::vector<std::uint32_t> indices;
        const std::uint32_t f = std::uint32_t(d.first), count = std::uint32_t(d.count);
        if (d.mode == "GL_TRIANGLES") {
            for (std::uint32_t i = 0; i + 3 <= count; i += 3) {
                indices.insert(indices.end(), {f + i, f + i + 1, f + i + 2});
            }
        } else if (d.mode == "GL_TRIANGLE_STRIP") {
            for (std::uint32_t i : strip_indices(int(count))) indices.push_back(f + i);
        } else if (d.mode == "GL_TRIANGLE_FAN" || d.mode == "GL_POLYGON") {
            // Fans and polygons as Mesa's draw module decomposes them, provoking vertex last.
            for (std::uint32_t i = 1; i + 1 < count; ++i) indices.insert(indices.end(), {f, f + i, f + i + 1});
        } else if (d.mode == "GL_QUADS") {
            for (std::uint32_t q = 0; q + 4 <= count; q += 4) {
                indices.insert(indices.end(), {f + q, f + q + 1, f + q + 3, f + q + 1, f + q + 2, f + q + 3});
            }
        }
        draw(vertices, indices, arrays);
        return Status::Pass;
    }

    // GL's current attribute values: colour and texture coordinates, where a draw gives none.
    void current_values(VertexIn& v) const {
        v.color = glm::vec4(color_[0], color_[1], color_[2], color_[3]);
        v.texcoord = glm::vec2(texcoord_[0][0], texcoord_[0][1]);
        v.texcoord1 = glm::vec2(texcoord_[1][0], texcoord_[1][1]);
    }
    static AttributeValue words(float x, float y, float z, float w) {
        return {std::bit_cast<std::uint32_t>(x), std::bit_cast<std::uint32_t>(y), std::bit_cast<std::uint32_t>(z),
                std::bit_cast<std::uint32_t>(w)};
    }
    // A triangle strip's triangles, each turning as the first (GL: odd ones with their first two
    // vertices swapped), the provoking vertex last.
    static std::vector<std::uint32_t> strip_indices(int count) {
        std::vector<std::uint32_t> out;
        for (int i = 0; i + 2 < count; ++i) {
            const std::uint32_t a = std::uint32_t(i), b = a + 1, c = a + 2;
            if (i % 2 == 0) {
                out.insert(out.end(), {a, b, c});
            } else {
                out.insert(out.end(), {b, a, c});
            }
        }
        return out;
    }

    void draw(const std::vector<VertexIn>& vertices, const std::vector<std::uint32_t>& indices,
              const std::array<std::vector<AttributeValue>, kMaxGenericAttributes>& arrays) {
        DrawCall call;
        call.vertices = vertices;
        call.indices = indices;
        call.program = &program();
        call.uniforms.model_view_projection = projection_ * model_view_;
        call.uniforms.user = uniform_words_.data();
        call.uniforms.clip_planes = clip_planes_;
        call.clip_distances = clip_enabled_;
        // The textures of the units the samplers read, in the order GlslProgram binds them.
        int other = 0;
        for (const ir::Sampler& s : program().program().samplers) {
            if (s.dims != 2) skip(s.dims == 3 ? "sampler3D textures" : "samplerCube textures");
            const auto unit = sampler_units_.find(s.name);
            const auto tex = textures_.find(unit == sampler_units_.end() ? 0 : unit->second);
            if (tex == textures_.end()) skip("a sampler reading no texture", at_line(line_) + "sampler '" + s.name + "' reads no texture");
            if (!tex->second.complete()) skip("an incomplete texture", at_line(line_) + "sampler '" + s.name + "' reads an incomplete texture");
            const glsl::sampler2D& t = tex->second.get();
            call.texture_lod = call.texture_lod || t.needs_lod();
            if (s.name == "teximage") {
                call.uniforms.teximage = &t;
            } else if (other < kMaxSamplers) {
                call.uniforms.samplers[std::size_t(other++)] = &t;
            }
        }
        for (int i = 0; i < kMaxGenericAttributes; ++i) {
            if (!arrays[std::size_t(i)].empty()) call.uniforms.attributes[std::size_t(i)] = arrays[std::size_t(i)].data();
        }
        RasterOptions o;
        o.derivatives = options_.derivatives;
        o.pairing = QuadPairing::BottomUp;  // a framebuffer object's rows count up
        if (options_.backend == Backend::RayCaster) {
            if (call.clip_distances) skip("user clip planes with the ray caster");
            if (call.program->info().needs.noperspective_varyings) skip("noperspective varyings with the ray caster");
            draw_ray_cast(call, o);
        } else {
            rasterize_over(fb_, std::span<const DrawCall>(&call, 1), o);
        }
    }

    // The ray caster draws a frame of its own; its pixels the draw reached replace the
    // framebuffer's (the frame is cast twice with different clear colours: a pixel no ray hit
    // shows the two, one a ray hit shows the same fragment's colour in both).
    void draw_ray_cast([[maybe_unused]] const DrawCall& call, [[maybe_unused]] const RasterOptions& o) {
#ifdef QUADSHADE_HAS_RAYCAST
        RayCaster caster(std::span<const DrawCall>(&call, 1), call.uniforms.model_view_projection);
        Framebuffer a, b;
        caster.render_into(a, width_, height_, glm::vec4(0.0f), std::span<const DrawCall>(&call, 1), o);
        caster.render_into(b, width_, height_, glm::vec4(1.0f), std::span<const DrawCall>(&call, 1), o);
        for (std::size_t p = 0; p < fb_.rgba.size(); p += 4) {
            if (std::memcmp(&a.rgba[p], &b.rgba[p], 4 * sizeof(float)) == 0) std::copy_n(&a.rgba[p], 4, &fb_.rgba[p]);
        }
#else
        skip("the ray caster (not built)");
#endif
    }

    // ---- probes -----------------------------------------------------------------------------

    // The framebuffer as glReadPixels reads an RGBA8 buffer: the 8-bit value of pixel (x, y)
    // (window coordinates, y up).
    std::array<std::uint8_t, 4> read(int x, int y) const {
        const float* p = fb_.pixel(x, height_ - 1 - y);
        return {unorm8(p[0]), unorm8(p[1]), unorm8(p[2]), unorm8(p[3])};
    }

    Status apply(const Probe& p) {
        int x = 0, y = 0, w = 1, h = 1;
        switch (p.area) {
            case Probe::Area::Pixel:
                if (p.relative) {
                    // shader_runner: c * read_width as an int, clamped to the last pixel.
                    x = std::min(int(p.at[0] * float(width_)), width_ - 1);
                    y = std::min(int(p.at[1] * float(height_)), height_ - 1);
                } else {
                    x = int(p.at[0]), y = int(p.at[1]);
                }
                break;
            case Probe::Area::Rect:
                if (p.relative) {
                    x = int(p.at[0] * float(width_)), y = int(p.at[1] * float(height_));
                    w = int(p.at[2] * float(width_)), h = int(p.at[3] * float(height_));
                } else {
                    x = int(p.at[0]), y = int(p.at[1]), w = int(p.at[2]), h = int(p.at[3]);
                }
                break;
            case Probe::Area::All: w = width_, h = height_; break;
        }
        if (x < 0 || y < 0 || w < 0 || h < 0 || x + w > width_ || y + h > height_) {
            return failed_line("the probe reaches outside the " + std::to_string(width_) + "x" + std::to_string(height_) +
                               " framebuffer");
        }
        ProbeMismatch m;
        m.line = line_, m.command = text_, m.components = p.components, m.expected = p.expected, m.pixels = 0;
        m.warn = p.warn;
        if (p.area == Probe::Area::Pixel) {
            // piglit_probe_pixel_rgb[a]: float readback, |observed - expected| > tolerance fails.
            const std::array<std::uint8_t, 4> v = read(x, y);
            bool ok = true;
            for (int c = 0; c < p.components; ++c) {
                const float observed = float(v[std::size_t(c)]) / 255.0f;
                ok = ok && !(std::fabs(observed - p.expected[std::size_t(c)]) > tolerance_[std::size_t(c)]);
            }
            if (ok) return Status::Pass;
            m.x = x, m.y = y, m.pixels = 1;
            for (int c = 0; c < 4; ++c) m.observed[std::size_t(c)] = float(v[std::size_t(c)]) / 255.0f;
        } else {
            // probe_rect_ubyte: the expected value and the tolerance as 8-bit numbers (truncated
            // and rounded up), compared pixel by pixel.
            std::array<int, 4> expected{}, tolerance{};
            for (int c = 0; c < p.components; ++c) {
                expected[std::size_t(c)] = std::uint8_t(int(p.expected[std::size_t(c)] * 255.0f));
                tolerance[std::size_t(c)] = std::uint8_t(int(std::ceil(tolerance_[std::size_t(c)] * 255.0f)));
            }
            for (int j = 0; j < h; ++j) {
                for (int i = 0; i < w; ++i) {
                    const std::array<std::uint8_t, 4> v = read(x + i, y + j);
                    bool ok = true;
                    for (int c = 0; c < p.components; ++c) {
                        ok = ok && std::abs(int(v[std::size_t(c)]) - expected[std::size_t(c)]) <= tolerance[std::size_t(c)];
                    }
                    if (ok) continue;
                    if (m.pixels++ == 0) {
                        m.x = x + i, m.y = y + j;
                        for (int c = 0; c < 4; ++c) m.observed[std::size_t(c)] = float(v[std::size_t(c)]) / 255.0f;
                        for (int c = 0; c < p.components; ++c) m.expected[std::size_t(c)] = float(expected[std::size_t(c)]) / 255.0f;
                    }
                }
            }
            if (m.pixels == 0) return Status::Pass;
        }
        probes_.push_back(m);
        return p.warn ? Status::Warn : Status::Fail;
    }

    ShaderTest test_;
    RunOptions options_;
    Requirements requirements_;
    std::vector<TestCommand> commands_;
    VertexData vertex_data_;
    frontend::GlslSource fragment_, vertex_;
    std::map<ColorState, Variant> variants_;
    bool linked_ = false;
    std::string link_log_;
    std::vector<std::uint32_t> uniform_words_;

    int width_ = 250, height_ = 250;
    Framebuffer fb_;
    glm::vec4 clear_color_{0.0f};
    bool clear_bits_color_ = false;  // glClear clears colour once a clear colour was set
    std::array<float, 4> tolerance_{0.01f, 0.01f, 0.01f, 0.01f};
    glm::mat4 projection_{1.0f}, model_view_{1.0f};
    std::array<float, 4> color_{1.0f, 1.0f, 1.0f, 1.0f};
    std::array<std::array<float, 4>, 2> texcoord_{{{0.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f, 1.0f}}};
    ColorState color_state_;
    std::map<int, ScriptTexture> textures_;           // by texture unit
    int active_unit_ = 0;
    std::map<std::string, int> sampler_units_;        // sampler uniform -> unit (0 unless set)
    std::array<glm::vec4, kMaxClipDistances> clip_planes_{};
    unsigned clip_enabled_ = 0;  // bit i: GL_CLIP_PLANEi

    int line_ = 0;
    std::string text_;
    Status status_ = Status::Pass;
    std::string message_;
    std::vector<ProbeMismatch> probes_;
};

}  // namespace

const char* status_word(Status s) {
    switch (s) {
        case Status::Pass: return "pass";
        case Status::Warn: return "warn";
        case Status::Fail: return "fail";
        case Status::Crash: return "crash";
        case Status::Skip: return "skip";
    }
    return "?";
}

TestResult run_shader_test(const std::filesystem::path& file, const RunOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    TestResult r;
    try {
        r = ScriptRun(read_shader_test(file), options).run();
    } catch (const ShaderTestError& e) {
        r.status = Status::Fail;
        r.message = e.what();
    } catch (const std::exception& e) {
        r.status = Status::Crash;
        r.message = e.what();
    }
    r.file = file.string();
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

}  // namespace qs::piglit
