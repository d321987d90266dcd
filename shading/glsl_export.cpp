#include "shading/glsl_export.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

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

void write_file(const std::filesystem::path& p, const std::string& text) {
    std::ofstream out(p, std::ios::binary);
    out << text;
    if (!out.flush()) throw std::runtime_error(p.string() + ": cannot write GLSL");
}

}  // namespace

std::string glsl_source(const Program& program, bool vertex_stage) {
    const ShaderInfo& info = program.info();
    const std::filesystem::path folder = glsl_folder(program, vertex_stage);
    // ShaderInfo::glsl_version (0: 120); from 1.50 on the compatibility profile (gl_Vertex, gl_FragColor).
    const int version = info.glsl_version ? info.glsl_version : 120;
    std::string src = "#version " + std::to_string(version) + (version >= 150 ? " compatibility\n" : "\n");
    src += info.glsl_defines;
    for (std::string_view file : vertex_stage ? info.glsl_vertex : info.glsl_fragment) {
        if (file.empty()) continue;
        src += "#line 1\n";
        src += read_file(folder / file);
    }
    return src;
}

int export_glsl(const std::filesystem::path& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw std::runtime_error(dir.string() + ": cannot create folder: " + ec.message());
    int n = 0;
    for (const Program* p : catalogue()) {
        const std::string name(p->info().name);
        write_file(dir / (name + ".vert"), glsl_source(*p, true));
        write_file(dir / (name + ".frag"), glsl_source(*p, false));
        ++n;
    }
    return n;
}

}  // namespace qs
