#include "shading/glsl_export.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "scenes/output_file.h"
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

}  // namespace

std::string glsl_source(const Program& program, bool vertex_stage) {
    if (const std::string* text = compiled_glsl(program, vertex_stage)) return *text;  // a user's GLSL, as written
    const ShaderInfo& info = program.info();
    const std::filesystem::path folder = glsl_folder(program);
    // ShaderInfo::glsl_version; from 1.50 on the compatibility profile (gl_Vertex, gl_FragColor).
    std::string src = "#version " + std::to_string(info.glsl_version) + (info.glsl_version >= 150 ? " compatibility\n" : "\n");
    src += info.glsl_defines;
    for (std::string_view file : vertex_stage ? info.glsl_vertex : info.glsl_fragment) {
        if (file.empty()) continue;
        src += "#line 1\n";
        src += read_file(folder / file);
    }
    return src;
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
