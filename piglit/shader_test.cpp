#include "piglit/shader_test.h"

#include <fstream>
#include <sstream>

namespace qs::piglit {

namespace {

enum class Section {
    None,
    Require,
    Shader,       // GLSL of ShaderTest::shaders.back()
    Passthrough,  // [vertex shader passthrough]: no text of its own
    VertexData,
    Test,
    Ignored,      // read by piglit only in SPIR-V mode, or not read at all
    Unsupported,
};

struct Header {
    const char* name;
    Section section;
    Stage stage = Stage::Vertex;
};

// piglit's section names, matched as prefixes of the line in this order (as shader_runner.c
// matches them).
constexpr Header kHeaders[] = {
    {"[require]", Section::Require},
    {"[vertex shader passthrough]", Section::Passthrough},
    {"[vertex shader specializations]", Section::Ignored},
    {"[vertex shader spirv]", Section::Ignored},
    {"[vertex shader]", Section::Shader, Stage::Vertex},
    {"[vertex program]", Section::Unsupported},
    {"[tessellation control shader specializations]", Section::Ignored},
    {"[tessellation control shader spirv]", Section::Ignored},
    {"[tessellation control shader]", Section::Shader, Stage::TessControl},
    {"[tessellation evaluation shader specializations]", Section::Ignored},
    {"[tessellation evaluation shader spirv]", Section::Ignored},
    {"[tessellation evaluation shader]", Section::Shader, Stage::TessEvaluation},
    {"[geometry shader specializations]", Section::Ignored},
    {"[geometry shader spirv]", Section::Ignored},
    {"[geometry shader]", Section::Shader, Stage::Geometry},
    {"[geometry layout]", Section::Unsupported},
    {"[fragment shader specializations]", Section::Ignored},
    {"[fragment shader spirv]", Section::Ignored},
    {"[fragment shader]", Section::Shader, Stage::Fragment},
    {"[fragment program]", Section::Unsupported},
    {"[compute shader specializations]", Section::Ignored},
    {"[compute shader spirv]", Section::Ignored},
    {"[compute shader]", Section::Shader, Stage::Compute},
    {"[vertex data]", Section::VertexData},
    {"[shader include paths]", Section::Unsupported},
    {"[shader include]", Section::Unsupported},
    {"[test]", Section::Test},
};

}  // namespace

const char* stage_name(Stage s) {
    switch (s) {
        case Stage::Vertex: return "vertex";
        case Stage::TessControl: return "tessellation control";
        case Stage::TessEvaluation: return "tessellation evaluation";
        case Stage::Geometry: return "geometry";
        case Stage::Fragment: return "fragment";
        case Stage::Compute: return "compute";
    }
    return "?";
}

ShaderTest parse_shader_test(const std::string& file, const std::string& text) {
    ShaderTest t;
    t.file = file;
    Section section = Section::None;
    bool required = false;
    std::size_t at = 0;
    for (int number = 1; at < text.size(); ++number) {
        std::size_t end = text.find('\n', at);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(at, end - at);
        at = end + 1;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (!line.empty() && line[0] == '[') {
            const Header* header = nullptr;
            for (const Header& h : kHeaders) {
                if (line.compare(0, std::string(h.name).size(), h.name) == 0) {
                    header = &h;
                    break;
                }
            }
            if (!header) {
                throw ShaderTestError(file + ":" + std::to_string(number) + ": unknown section '" + line +
                                      "' (perhaps a missing ']')");
            }
            section = header->section;
            switch (section) {
                case Section::Require: required = true; break;
                case Section::Shader: t.shaders.push_back({header->stage, number + 1, {}}); break;
                case Section::Passthrough: t.vertex_passthrough = true; break;
                case Section::VertexData: t.has_vertex_data = true, t.vertex_data.clear(); break;
                case Section::Test: t.has_test = true; break;
                case Section::Unsupported: t.unsupported.push_back({number, header->name}); break;
                case Section::None: case Section::Ignored: break;
            }
            // piglit reads nothing after [test] as a section: the rest of the file is its script.
            if (section == Section::Test) {
                for (int n = number + 1; at < text.size(); ++n) {
                    std::size_t e = text.find('\n', at);
                    if (e == std::string::npos) e = text.size();
                    std::string l = text.substr(at, e - at);
                    at = e + 1;
                    if (!l.empty() && l.back() == '\r') l.pop_back();
                    t.test.push_back({n, std::move(l)});
                }
                break;
            }
            continue;
        }
        switch (section) {
            case Section::Require: t.require.push_back({number, std::move(line)}); break;
            case Section::Shader: t.shaders.back().text += line + "\n"; break;
            case Section::VertexData: t.vertex_data.push_back({number, std::move(line)}); break;
            default: break;
        }
    }
    if (!required) throw ShaderTestError(file + ": no [require] section");
    return t;
}

ShaderTest read_shader_test(const std::filesystem::path& path) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) throw ShaderTestError(path.string() + ": cannot read: " + ec.message());
    if (size > kMaxShaderTestBytes) {
        throw ShaderTestError(path.string() + ": " + std::to_string(size) + " bytes: larger than a shader_test can be here (" +
                              std::to_string(kMaxShaderTestBytes) + ")");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ShaderTestError(path.string() + ": cannot read");
    std::ostringstream s;
    s << in.rdbuf();
    const std::string text = s.str();
    if (text.find('\0') != std::string::npos) throw ShaderTestError(path.string() + ": not a text file (it holds a NUL byte)");
    return parse_shader_test(path.string(), text);
}

}  // namespace qs::piglit
