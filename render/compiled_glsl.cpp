#include "render/compiled_glsl.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <vector>

#include "frontend/cpp_writer.h"
#include "render/glsl_shaders.h"
#include "render/plugin_compiler.h"
#include "render/plugins.h"
#include "shading/catalogue.h"

extern char** environ;

namespace qs {

namespace fs = std::filesystem;

namespace {

// FNV-1a, 64 bits: a cache key, not a defence (the cache is the user's own folder).
struct Hash {
    std::uint64_t h = 0xcbf29ce484222325ull;
    void add(const std::string& s) {
        for (unsigned char c : s) h = (h ^ c) * 0x100000001b3ull;
        h = (h ^ 0xFF) * 0x100000001b3ull;  // ends each part, so that parts cannot slide
    }
    std::string hex() const {
        char b[17];
        std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(h));
        return b;
    }
};

// Where the shading headers are: an installation's include/quadshade beside bin/, else the
// source tree this build came from.
fs::path include_dir() {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path installed = exe.parent_path().parent_path() / "include" / "quadshade";
        if (fs::exists(installed / "shading" / "glsl.h", ec)) return installed;
    }
    return plugin_compiler::kSourceDir;
}

// The shading headers' paths and contents: a plugin compiled against other headers is another plugin.
void add_headers(Hash& h, const fs::path& include) {
    std::vector<fs::path> files;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(include / "shading", ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec)) {
        if (it->is_regular_file(ec) && it->path().extension() == ".h") files.push_back(it->path());
    }
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) {
        std::ifstream in(f, std::ios::binary);
        std::ostringstream s;
        s << in.rdbuf();
        h.add(f.lexically_relative(include).string());
        h.add(s.str());
    }
}

// Runs the compiler (no shell: arguments as they are); its messages go to `log`.
int run_compiler(const std::vector<std::string>& args, const fs::path& log) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    pid_t pid = 0;
    const int rc = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) return -1;
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) return -1;
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void write_file(const fs::path& p, const std::string& text) {
    std::ofstream out(p, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw std::runtime_error(p.string() + ": cannot write");
}

// The translation's C identifier from the shader's name (a file name).
std::string identifier_from(const std::string& name) {
    std::string n;
    for (char c : name) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
        if (ok) n += c;
        else if (!n.empty() && n.back() != '_') n += '_';
    }
    while (!n.empty() && n.back() == '_') n.pop_back();
    return n.empty() || (n[0] >= '0' && n[0] <= '9') ? "shader_" + n : n;
}

// The plugin's registration of the translation, in the GLSL collection (quadshade gallery --glsl
// draws it with the GLSL the interpreter runs), holding the instantiations of `modes` only.
std::string registration_source(const frontend::Translation& t, ShadeModes modes) {
    std::string s = "#include \"" + t.name + ".h\"\n\nnamespace " + t.name + " {\n\n";
    std::string registered = t.struct_name;
    if (modes.bits != ShadeModes{}.bits) {
        char bits[16];
        std::snprintf(bits, sizeof bits, "0x%08xu", unsigned(modes.bits));
        s += "// Compiled for the ways of shading one run needs (shading/shade_choice.h): no others.\n"
             "struct ForThisRun : " + t.struct_name + " {\n"
             "    static constexpr ShadeModes compiled_modes{" + bits + "};\n"
             "};\n\n";
        registered = "ForThisRun";
    }
    return s + "QUADSHADE_SHADERS_IN(\"" + kGlslCollection + "\", " + registered + ")\n\n}  // namespace " + t.name + "\n";
}

// The folder of a cached plugin that shades in `modes`: `stem`-MODES, MODES those it holds, in hex.
std::optional<fs::path> cached_folder(const fs::path& cache, const std::string& stem, const std::string& library,
                                      ShadeModes modes) {
    std::error_code ec;
    std::vector<fs::path> found;
    for (auto it = fs::directory_iterator(cache, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
        const std::string n = it->path().filename().string();
        if (n.size() != stem.size() + 9 || n.compare(0, stem.size() + 1, stem + "-") != 0) continue;
        const std::string hex = n.substr(stem.size() + 1);
        if (hex.find_first_not_of("0123456789abcdef") != std::string::npos) continue;
        const ShadeModes held{std::uint32_t(std::stoul(hex, nullptr, 16))};
        if (held.covers(modes) && fs::exists(it->path() / library, ec)) found.push_back(it->path());
    }
    if (found.empty()) return std::nullopt;
    std::sort(found.begin(), found.end());
    return found.front();
}

// One warning per process: the cache is one place, and one cause usually stops every use of it.
void warn_once(const std::string& what) {
    static std::once_flag once;
    std::call_once(once, [&] {
        std::fprintf(stderr, "quadshade: warning: %s; running the GLSL in the interpreter instead\n", what.c_str());
    });
}

// What a cached plugin is made from, hashed: the compiler and its flags, quadshade's headers, the
// translation's files.
std::string translation_hash(const frontend::Translation& t, const fs::path& include) {
    Hash h;
    h.add(plugin_compiler::kVersion);
    h.add(plugin_compiler::kCompiler);
    for (const char* f : plugin_compiler::kFlags) h.add(f);
    h.add(include.string());
    add_headers(h, include);
    for (const std::string* s : {&t.header, &t.source, &t.vertex_glsl, &t.fragment_glsl}) h.add(*s);
    return h.hex();
}

// The translation compiled into `folder` of the plugin cache, through a staging folder of its
// own; false, with a warning, where that failed.
bool compile_plugin(const frontend::Translation& t, const fs::path& include, const std::string& cache,
                    const fs::path& folder, const std::string& name) {
    std::error_code ec;
    fs::create_directories(cache, ec);
    std::string staging = (fs::path(cache) / ".compiling-XXXXXX").string();
    if (ec || !mkdtemp(staging.data())) {
        warn_once("the plugin cache " + cache + " is not writable");
        return false;
    }
    const fs::path work(staging);
    try {
        write_file(work / (t.name + ".h"), t.header);
        write_file(work / (t.name + ".cpp"), t.source);
        write_file(work / (t.name + ".vert"), t.vertex_glsl);
        write_file(work / (t.name + ".frag"), t.fragment_glsl);
        std::vector<std::string> args{plugin_compiler::kCompiler};
        for (const char* f : plugin_compiler::kFlags) args.push_back(f);
        args.push_back("-I" + include.string());
        args.push_back("-I" + work.string());
        args.push_back("-o");
        args.push_back((work / ("lib" + t.name + ".so")).string());
        args.push_back((work / (t.name + ".cpp")).string());
        std::fprintf(stderr, "quadshade: compiling %s's C++ translation into %s ...\n", name.c_str(), folder.c_str());
        const auto start = std::chrono::steady_clock::now();
        const int rc = run_compiler(args, work / "compiler.log");
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (rc != 0) {
            warn_once("compiling " + name + "'s translation failed (" + (work / "compiler.log").string() + ")");
            return false;  // the staging folder is kept for its log
        }
        std::fprintf(stderr, "quadshade: compiled %s in %.1f s\n", name.c_str(), seconds);
        // Whole or not at all: the folder appears with its plugin complete. Where another run
        // put it there first, its plugin is the same and this one goes.
        if (::rename(work.c_str(), folder.c_str()) != 0) fs::remove_all(work, ec);
    } catch (const std::exception& e) {
        fs::remove_all(work, ec);
        warn_once(std::string("the plugin cache is unusable: ") + e.what());
        return false;
    }
    return true;
}

}  // namespace

std::optional<std::string> plugin_cache_dir() {
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x && fs::path(x).is_absolute()) {
        return (fs::path(x) / "quadshade" / "plugins").string();
    }
    if (const char* home = std::getenv("HOME"); home && *home) return (fs::path(home) / ".cache" / "quadshade" / "plugins").string();
    return std::nullopt;
}

const Program* compiled_glsl_program(const frontend::GlslSource& fragment, const std::optional<frontend::GlslSource>& vertex,
                                     const std::string& name, GlslWay way, ShadeModes modes) {
    if (way == GlslWay::Interpret) return nullptr;
    // A plugin's shader is named as a catalogue shader is: "marble.frag" is "marble_frag".
    const std::string shader_name = identifier_from(name);
    frontend::Translation t;
    try {
        t = frontend::translate_glsl(fragment, vertex, identifier_from(fs::path(fragment.file).stem().string()), shader_name);
    } catch (const frontend::GlslError& e) {
        // The interpreter runs what the writer does not write yet.
        if (way == GlslWay::Compile) std::fprintf(stderr, "quadshade: not compiled: %s\n", e.what());
        return nullptr;
    }
    if (!t.unbounded_loop.empty()) {
        if (way == GlslWay::Compile) {
            std::fprintf(stderr, "quadshade: not compiled: %s, where llvmpipe leaves a shader's loops and C++ does not\n",
                         t.unbounded_loop.c_str());
        }
        return nullptr;
    }
    t.source = registration_source(t, ShadeModes{});  // hashed without the modes: the folder's name ends with them
    const std::optional<std::string> cache = plugin_cache_dir();
    if (!cache) {
        if (way == GlslWay::Compile) warn_once("no plugin cache: neither XDG_CACHE_HOME nor HOME is set");
        return nullptr;
    }
    const fs::path include = include_dir();
    const std::string stem = t.name + "-" + translation_hash(t, include), library_name = "lib" + t.name + ".so";
    char bits[16];
    std::snprintf(bits, sizeof bits, "%08x", unsigned(modes.bits));
    fs::path folder = fs::path(*cache) / (stem + "-" + bits);
    std::error_code ec;
    if (const std::optional<fs::path> cached = cached_folder(*cache, stem, library_name, modes)) folder = *cached;
    const fs::path library = folder / library_name;
    if (!fs::exists(library, ec)) {
        if (way != GlslWay::Compile) return nullptr;
        t.source = registration_source(t, modes);
        if (!compile_plugin(t, include, *cache, folder, name)) return nullptr;
    }
    try {
        load_plugin(library);
    } catch (const std::exception& e) {
        warn_once(std::string("a cached plugin does not load (") + e.what() + ")");
        return nullptr;
    }
    return find_program(shader_name);
}

}  // namespace qs
