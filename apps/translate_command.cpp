#include "apps/translate_command.h"

#include <cstdio>
#include <filesystem>

#include "files/temporary_file.h"
#include "frontend/cpp_writer.h"

namespace qs::app {

namespace fs = std::filesystem;

namespace {

// The translation's name from the fragment shader's file name: its stem, with every character
// a C identifier cannot hold made an underscore.
std::string name_from(const fs::path& fragment) {
    std::string n;
    for (char c : fragment.stem().string()) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
        if (ok) n += c;
        else if (!n.empty() && n.back() != '_') n += '_';
    }
    while (!n.empty() && n.back() == '_') n.pop_back();
    if (n.empty() || (n[0] >= '0' && n[0] <= '9')) n = "shader_" + n;
    return n;
}

}  // namespace

void add_translate_options(CLI::App& cmd, TranslateArgs& a) {
    cmd.add_option("fragment", a.fragment, "the fragment shader")->required()->option_text("FRAG");
    cmd.add_option("--vert", a.vertex, "its vertex shader (default: the one quadshade writes for it, docs/glsl.md)")
        ->option_text("VERT");
    cmd.add_option("-o,--output", a.output, "the folder to write NAME.h, NAME.cpp, NAME.frag, NAME.vert and "
                                            "CMakeLists.txt into (created if missing)")
        ->required()
        ->option_text("DIR");
    cmd.add_option("--name", a.name, "the shader's name (default: the fragment shader's file name)")->option_text("NAME");
}

int cmd_translate(const TranslateArgs& a) {
    const frontend::GlslSource fragment = frontend::read_glsl_file(a.fragment);
    std::optional<frontend::GlslSource> vertex;
    if (!a.vertex.empty()) vertex = frontend::read_glsl_file(a.vertex);
    const std::string name = a.name.empty() ? name_from(a.fragment) : a.name;
    const frontend::Translation t = frontend::translate_glsl(fragment, vertex, name);
    const fs::path dir(a.output);
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw std::runtime_error(a.output + ": cannot create the folder: " + ec.message());
    // Written together: a reader of the folder never sees one file of the translation without the others.
    OutputSet out(dir / "CMakeLists.txt");
    const std::pair<std::string, const std::string*> files[] = {
        {name + ".h", &t.header}, {name + ".cpp", &t.source}, {name + ".frag", &t.fragment_glsl},
        {name + ".vert", &t.vertex_glsl}, {"CMakeLists.txt", &t.cmake}};
    for (const auto& [file, text] : files) {
        std::FILE* f = std::fopen(out.staged(file).c_str(), "wb");
        if (!f) throw std::runtime_error((dir / file).string() + ": cannot write");
        const bool ok = std::fwrite(text->data(), 1, text->size(), f) == text->size();
        if (std::fclose(f) != 0 || !ok) throw std::runtime_error((dir / file).string() + ": cannot write");
    }
    out.commit("CMakeLists.txt");
    std::printf("wrote %s: %s.h, %s.cpp, %s.frag, %s.vert, CMakeLists.txt (shader %s)\n", dir.string().c_str(),
                name.c_str(), name.c_str(), name.c_str(), name.c_str(), name.c_str());
    return 0;
}

}  // namespace qs::app
