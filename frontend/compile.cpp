#include "frontend/compile.h"

#include <atomic>
#include <fstream>
#include <mutex>
#include <sstream>

#include <glslang/Include/ResourceLimits.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include "frontend/binding_names.h"
#include "frontend/bounded_preprocess.h"
#include "frontend/derivative_control.h"
#include "frontend/derivative_probe.h"
#include "frontend/float_literals.h"
#include "frontend/glsl_types.h"
#include "frontend/ir_operands.h"
#include "frontend/lowering.h"
#include "frontend/parse_stage.h"

namespace qs::frontend {

namespace {

void initialise_glslang() {
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

// Line continuations removed as Mesa's preprocessor removes them, in every GLSL version (glslang
// takes them from 4.20 on only), with the lines they joined kept as empty lines after the
// joined one, so that messages name the lines of the file.
std::string join_continued_lines(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    int pending = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\\' && i + 1 < text.size() && (text[i + 1] == '\n' || (text[i + 1] == '\r' && i + 2 < text.size() && text[i + 2] == '\n'))) {
            i += text[i + 1] == '\r' ? 2 : 1;
            ++pending;
            continue;
        }
        out += text[i];
        if (text[i] == '\n') {
            out.append(std::size_t(pending), '\n');
            pending = 0;
        }
    }
    out.append(std::size_t(pending), '\n');
    return out;
}

// Where a glslang message's "NAME:LINE: " place ends (at its last colon), or npos without one.
std::size_t located(const std::string& message) {
    const std::size_t name_end = message.find(':');
    if (name_end == std::string::npos) return std::string::npos;
    std::size_t k = name_end + 1;
    while (k < message.size() && message[k] >= '0' && message[k] <= '9') ++k;
    return k > name_end + 1 && message.compare(k, 2, ": ") == 0 ? k : std::string::npos;
}

// glslang's "ERROR: FILE:LINE: message" lines as FILE:LINE: error: message; a line glslang
// gives no place (an unsupported #version) as FILE: error: message.
std::string reword(const std::string& file, const std::string& log, std::vector<std::string>* warnings) {
    std::istringstream in(log);
    std::string line, errors;
    while (std::getline(in, line)) {
        for (const char* kind : {"ERROR: ", "WARNING: "}) {
            if (line.rfind(kind, 0) != 0) continue;
            std::string rest = line.substr(std::string(kind).size());
            if (rest.find("compilation errors.") != std::string::npos || rest.find("compilation terminated") != std::string::npos) break;
            // "FILE:LINE: 'token' : message" -> "FILE:LINE: error: 'token': message"
            const std::size_t colon = located(rest);
            std::string where = colon == std::string::npos ? file + ": " : rest.substr(0, colon + 2);
            std::string what = colon == std::string::npos ? rest : rest.substr(colon + 2);
            for (std::size_t at; (at = what.find(" : ")) != std::string::npos;) what.replace(at, 3, ": ");
            const bool error = kind[0] == 'E';
            const std::string message = where + (error ? "error: " : "warning: ") + what;
            if (error) {
                errors += (errors.empty() ? "" : "\n") + message;
            } else if (warnings) {
                warnings->push_back(message);
            }
        }
    }
    return errors;
}

// `text` as glslang's preprocessor writes it: comments gone, macros expanded, lines kept.
std::string preprocessed(const std::string& file, const std::string& text, EShLanguage stage) {
    Preprocessed p = preprocess(file, text, stage == EShLangFragment);
    if (!p.ok) {
        const std::string errors = reword(file, p.log, nullptr);
        throw GlslError(errors.empty() ? file + ": error: the shader does not preprocess" : errors);
    }
    return std::move(p.text);
}

}  // namespace

ParsedStage parse(const GlslSource& source, EShLanguage stage, std::vector<std::string>& warnings,
                  const DerivativeProbe* probe) {
    initialise_glslang();
    ParsedStage p;
    const std::string text = float_literals_as_float(join_continued_lines(source.text));
    check_macro_expansion(source.file, text, stage == EShLangFragment);
    if (probe) {
        ProbedSource s = probed_source(source.file, preprocessed(source.file, text, stage), *probe);
        s.strings[kProbeString] = float_literals_as_float(s.strings[kProbeString]);
        p.strings = std::move(s.strings), p.names = std::move(s.names);
    } else {
        p.strings = {text}, p.names = {source.file};
    }
    std::vector<const char*> texts, names;
    std::vector<int> lengths;
    for (std::size_t i = 0; i < p.strings.size(); ++i) {
        texts.push_back(p.strings[i].c_str()), names.push_back(p.names[i].c_str());
        lengths.push_back(int(p.strings[i].size()));
    }
    const auto parse_with = [&](const char* preamble) {
        p.shader = std::make_unique<glslang::TShader>(stage);
        p.shader->setStringsWithLengthsAndNames(texts.data(), lengths.data(), names.data(), int(texts.size()));
        p.shader->setPreamble(preamble);
        p.shader->setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientNone, 100);
        p.shader->setEnvClient(glslang::EShClientNone, glslang::EShTargetClientVersion(0));
        p.shader->setEnvTarget(glslang::EShTargetNone, glslang::EShTargetLanguageVersion(0));
        const auto messages = EShMessages(EShMsgDefault | EShMsgEnhanced);
        return p.shader->parse(GetDefaultResources(), 110, ENoProfile, false, false, messages);
    };
    bool ok = parse_with("");
    if (!ok && wants_derivative_control(*p.shader->getIntermediate())) {
        ok = parse_with(derivative_control_declarations());
        if (ok) call_derivative_control_builtins(*p.shader->getIntermediate());
    }
    const std::string log = std::string(p.shader->getInfoLog()) + p.shader->getInfoDebugLog();
    std::vector<std::string> said;
    std::string errors = reword(source.file, log, &said);
    if (probe) {
        errors = probe_messages(errors, *probe);
        for (std::string& w : said) w = probe_messages(w, *probe);
    }
    warnings.insert(warnings.end(), said.begin(), said.end());
    if (!ok) throw GlslError(errors.empty() ? source.file + ": error: the shader does not compile" : errors);
    if (glslang::TIntermediate* ast = p.shader->getIntermediate()) p.version = ast->getVersion();
    return p;
}

namespace {

// The GLSL type of a varying, for the vertex shader written for a fragment shader.
std::string glsl_type(int components) { return components == 1 ? "float" : "vec" + std::to_string(components); }

}  // namespace

GlslSource read_glsl_file(const std::filesystem::path& path) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) throw GlslError(path.string() + ": cannot read: " + ec.message());
    if (size > kMaxGlslBytes) {
        throw GlslError(path.string() + ": " + std::to_string(size) + " bytes: larger than a GLSL shader can be here (" +
                        std::to_string(kMaxGlslBytes) + ")");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw GlslError(path.string() + ": cannot read");
    std::ostringstream s;
    s << in.rdbuf();
    GlslSource src{path.string(), s.str()};
    if (src.text.find('\0') != std::string::npos) throw GlslError(path.string() + ": not a text file (it holds a NUL byte)");
    return src;
}

GlslSource default_vertex_shader(const GlslSource& fragment, const CompileOptions& options) {
    std::vector<std::string> warnings;
    const DerivativeProbe* probe = options.derivative_probe ? &*options.derivative_probe : nullptr;
    ParsedStage f = parse(fragment, EShLangFragment, warnings, probe);
    // The fragment stage's inputs, in the order the code reads them.
    ir::Program scratch;
    ProgramInterface interface{scratch, {}, {}, {}};
    StageLowering lowering(StageKind::Fragment, fragment.file, *f.shader->getIntermediate(), interface);
    (void)lowering.run();
    const int version = f.version;
    const bool modern = version >= 130;
    std::string text = "#version " + std::to_string(version) + (version >= 150 ? " compatibility\n" : "\n");
    text += "// Written by quadshade for " + std::filesystem::path(fragment.file).filename().string() +
            ": each varying from the vertex attribute of its name.\n";
    std::string body;
    for (const VaryingSlot& v : interface.varyings) {
        const std::string& n = v.name;
        if (n.rfind("gl_", 0) == 0) {
            if (n == "gl_Color") body += "    gl_FrontColor = gl_Color;\n";
            else if (n.rfind("gl_TexCoord[", 0) == 0) body += "    " + n + " = gl_MultiTexCoord" + n.substr(12, n.size() - 13) + ";\n";
            else throw GlslError(v.where + "'" + n + "' has no vertex shader to write it: pass one with --vert");
            continue;
        }
        if (v.bank != ir::Bank::Float || v.components > 4) {
            throw GlslError(v.where + "varying '" + n + "' has no vertex shader to write it: pass one with --vert");
        }
        std::string value;
        const std::string swizzle = std::string("xyzw").substr(0, std::size_t(v.components));
        if (n == "st" || n == "uv" || n == "texcoord" || n == "texcoord0" || n == "texCoord") {
            value = "gl_MultiTexCoord0";
        } else if (n == "texcoord1" || n == "uv1") {
            value = "gl_MultiTexCoord1";
        } else if (n == "normal" || n == "N") {
            value = "vec4(gl_Normal, 0.0)";
        } else if (n == "color") {
            value = "gl_Color";
        } else if (n == "position" || n == "P") {
            value = "gl_Vertex";
        } else {
            throw GlslError(v.where + "varying '" + n + "' has no vertex shader to write it: pass one with --vert, or name it "
                            "st, uv or texcoord (texture coordinates), texcoord1, normal, color, or position or P (the "
                            "object-space position)");
        }
        text += std::string(modern ? (v.flat ? "flat out " : v.noperspective ? "noperspective out " : "out ") : "varying ") + glsl_type(v.components) + " " + n + ";\n";
        body += "    " + n + " = " + value + (v.components == 4 ? "" : "." + swizzle) + ";\n";
    }
    text += "void main() {\n" + body + "    gl_Position = ftransform();\n}\n";
    const std::filesystem::path f_path(fragment.file);
    return {(f_path.parent_path() / (f_path.stem().string() + ".default.vert")).string(), text};
}

CompiledProgram compile_glsl(const GlslSource& fragment, const std::optional<GlslSource>& vertex,
                             const CompileOptions& options) {
    CompiledProgram out;
    out.vertex = vertex ? *vertex : default_vertex_shader(fragment, options);
    const DerivativeProbe* probe = options.derivative_probe ? &*options.derivative_probe : nullptr;
    ParsedStage f = parse(fragment, EShLangFragment, out.warnings, probe);
    ParsedStage v = parse(out.vertex, EShLangVertex, out.warnings);
    ir::Program& program = out.program;
    program.version = f.version;
    ProgramInterface interface{program, {}, options, {}};
    program.fragment = StageLowering(StageKind::Fragment, fragment.file, *f.shader->getIntermediate(), interface).run();
    program.vertex = StageLowering(StageKind::Vertex, out.vertex.file, *v.shader->getIntermediate(), interface).run();
    out.probe_components = interface.probe_components;
    for (const VaryingSlot& s : interface.varyings) {
        if (!s.written) {
            throw GlslLinkError(s.where + "error: varying '" + s.name + "' is read here but the vertex shader (" + out.vertex.file +
                            ") does not write it");
        }
    }
    bool position = false;
    for (const ir::Binding& b : program.vertex.outputs) position = position || b.source == ir::Source::Position;
    if (!position) throw GlslLinkError(out.vertex.file + ": error: the vertex shader does not write gl_Position");
    static std::atomic<std::uint64_t> serials{0};
    program.vertex.serial = ++serials;
    program.fragment.serial = ++serials;
    ir::validate(program.vertex, int(program.samplers.size()));
    ir::validate(program.fragment, int(program.samplers.size()));
    return out;
}

}  // namespace qs::frontend
