#include "shading/glsl_export.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "files/output_file.h"
#include "shading/catalogue.h"

namespace qs {

namespace {

std::string read_file(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    if (!in) throw std::runtime_error(p.string() + ": cannot read GLSL source");
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// A file's #version directive: the first thing in it but comments and white space.
struct VersionDirective {
    bool found = false;
    std::size_t begin = 0, end = 0;  // the line, without its newline
    int line = 0;                    // counted from 1
    int version = 0;
};

VersionDirective version_directive(const std::string& text) {
    VersionDirective d;
    std::size_t i = 0;
    int line = 1;
    while (i < text.size()) {
        const char c = text[i];
        if (c == '\n') {
            ++line, ++i;
        } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
            ++i;
        } else if (text.compare(i, 2, "//") == 0) {
            i = text.find('\n', i);
            if (i == std::string::npos) return d;
        } else if (text.compare(i, 2, "/*") == 0) {
            const std::size_t close = text.find("*/", i + 2);
            if (close == std::string::npos) return d;
            for (std::size_t k = i; k < close; ++k) line += text[k] == '\n';
            i = close + 2;
        } else {
            break;
        }
    }
    if (i >= text.size() || text[i] != '#') return d;
    std::size_t k = i + 1;
    while (k < text.size() && (text[k] == ' ' || text[k] == '\t')) ++k;
    if (text.compare(k, 7, "version") != 0) return d;
    d.found = true;
    d.begin = i;
    d.end = std::min(text.find('\n', i), text.size());
    d.line = line;
    k += 7;
    while (k < d.end && (text[k] == ' ' || text[k] == '\t')) ++k;
    while (k < d.end && text[k] >= '0' && text[k] <= '9') d.version = d.version * 10 + (text[k++] - '0');
    return d;
}

}  // namespace

std::string stage_source(const std::vector<GlslText>& files, int glsl_version, std::string_view defines) {
    std::string version_line, body;
    for (std::size_t f = 0; f < files.size(); ++f) {
        std::string text = files[f].text;
        const VersionDirective v = version_directive(text);
        if (v.found) {
            const std::string where = files[f].name + ":" + std::to_string(v.line);
            if (f > 0) throw std::runtime_error(where + ": #version in a stage's second or later file (only its first file's comes first)");
            if (glsl_version != 0 && glsl_version != v.version) {
                throw std::runtime_error(where + ": #version " + std::to_string(v.version) +
                                         ", but the shader's ShaderInfo::glsl_version is " + std::to_string(glsl_version));
            }
            version_line = text.substr(v.begin, v.end - v.begin) + "\n";
            text.replace(v.begin, v.end - v.begin, "");  // the line stays, empty: the file's line numbers hold
        }
        body += "#line 1\n" + text;
    }
    if (version_line.empty()) {
        // ShaderInfo::glsl_version (0: 120); from 1.50 on the compatibility profile (gl_Vertex, gl_FragColor).
        const int version = glsl_version ? glsl_version : 120;
        version_line = "#version " + std::to_string(version) + (version >= 150 ? " compatibility\n" : "\n");
    }
    return version_line + std::string(defines) + body;
}

std::string glsl_source(const Program& program, bool vertex_stage) {
    if (const std::string* text = compiled_glsl(program, vertex_stage)) return *text;  // a user's GLSL, as written
    const ShaderInfo& info = program.info();
    const std::filesystem::path folder = glsl_folder(program, vertex_stage);
    std::vector<GlslText> files;
    for (std::string_view name : vertex_stage ? info.glsl_vertex : info.glsl_fragment) {
        if (!name.empty()) files.push_back({(folder / name).string(), read_file(folder / name)});
    }
    return stage_source(files, info.glsl_version, info.glsl_defines);
}

int export_glsl(const std::filesystem::path& dir) {
    make_output_folder(dir, FolderLink::Followed);
    int n = 0;
    for (const Program* p : catalogue()) {
        // A shader's name is an identifier (the catalogue refuses any other): a file name in DIR.
        const std::string name(p->info().name);
        write_output(dir / (name + ".vert"), glsl_source(*p, true));
        write_output(dir / (name + ".frag"), glsl_source(*p, false));
        ++n;
    }
    return n;
}

}  // namespace qs
