#include "shading/catalogue.h"

#include <map>
#include <stdexcept>

namespace qs {

namespace {

struct Entry {
    const Program* program;
    std::filesystem::path plugin;  // empty: built in
    std::string collection;        // empty: none
    // A program compiled at run time: owned here, with its stages' GLSL.
    std::shared_ptr<const Program> owned;
    std::string vertex_glsl, fragment_glsl;
};

// Filled by static constructors (the built-in shaders' before main, a plugin's inside dlopen),
// so it lives in a function: it must exist before the first of them runs.
struct Registry {
    std::vector<Entry> entries;
    ProgramList programs;
    std::filesystem::path loading;       // the plugin whose constructors are running
    std::vector<std::string> problems;  // the loading plugin's
    std::vector<std::string> builtin_problems;
    int added = 0;
    bool unoptimised = false;  // the loading plugin's
};

Registry& registry() {
    static Registry r;
    return r;
}

std::string origin_name(const std::filesystem::path& plugin) {
    return plugin.empty() ? std::string("quadshade") : plugin.string();
}

// The built-in shaders' GLSL: share/quadshade/shading beside the executable's bin/ folder.
std::filesystem::path builtin_glsl_folder() {
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) throw std::runtime_error("cannot find the quadshade executable (/proc/self/exe): " + ec.message());
    return exe.parent_path().parent_path() / "share" / "quadshade" / "shading";
}

// A shader's name names files (--export-glsl writes NAME.vert and NAME.frag) and is what scenes
// and command lines ask for: an identifier, so that no name can lead out of a folder.
bool is_shader_name(std::string_view name) {
    auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
    if (name.empty() || name.size() > 128 || !letter(name[0])) return false;
    for (const char c : name) {
        if (!letter(c) && !(c >= '0' && c <= '9')) return false;
    }
    return true;
}

// `name` as a message shows it: what is not printable ASCII as '?'.
std::string shown(std::string_view name) {
    std::string s(name.substr(0, 128));
    for (char& c : s) c = c >= 0x20 && c < 0x7f ? c : '?';
    return s;
}

const Entry& entry_of(const Program& program) {
    for (const Entry& e : registry().entries) {
        if (e.program == &program) return e;
    }
    throw std::logic_error(std::string(program.info().name) + ": not in the catalogue");
}

}  // namespace

namespace registration {

void add(const Program& program, const ShaderAbi& abi, std::string_view collection, bool optimised) {
    Registry& r = registry();
    if (!r.loading.empty() && !optimised) r.unoptimised = true;
    std::vector<std::string>& problems = r.loading.empty() ? r.builtin_problems : r.problems;
    const std::string name(program.info().name);
    if (!(abi == ShaderAbi{})) {
        problems.push_back("shader '" + name + "' was built against other quadshade headers (batch of " +
                             std::to_string(abi.batch_lanes) + " lanes, " + std::to_string(abi.fragment_batch) +
                             "-byte fragment batches; this quadshade: " + std::to_string(kBatchLanes) + ", " +
                             std::to_string(sizeof(FragmentBatch)) + "): rebuild it against this installation");
        return;
    }
    if (!is_shader_name(name)) {
        problems.push_back("shader '" + shown(name) +
                           "': a shader's name is letters, digits and '_', not starting with a "
                           "digit (it names the files --export-glsl writes)");
        return;
    }
    if (const Program* taken = find_program(name)) {
        problems.push_back("shader '" + name + "' is already defined by " + origin_name(entry_of(*taken).plugin));
        return;
    }
    r.entries.push_back({&program, r.loading, std::string(collection), nullptr, {}, {}});
    r.programs.push_back(&program);
    ++r.added;
}

void begin_plugin(const std::filesystem::path& plugin) {
    Registry& r = registry();
    r.loading = plugin;
    r.problems.clear();
    r.added = 0;
    r.unoptimised = false;
}

PluginResult end_plugin() {
    Registry& r = registry();
    PluginResult result{r.added, std::move(r.problems), r.unoptimised};
    r.loading.clear();
    r.problems.clear();
    r.added = 0;
    r.unoptimised = false;
    return result;
}

}  // namespace registration

const ProgramList& catalogue() {
    Registry& r = registry();
    // Two built-in shaders of one name are a bug of this build, found by its first test.
    if (!r.builtin_problems.empty()) throw std::logic_error(r.builtin_problems.front());
    return r.programs;
}

const Program* find_program(std::string_view name) {
    for (const Program* p : registry().programs) {
        if (p->info().name == name) return p;
    }
    return nullptr;
}

const std::filesystem::path& plugin_of(const Program& program) { return entry_of(program).plugin; }

std::string collection_of(const Program& program) {
    const Entry& e = entry_of(program);
    if (!e.collection.empty()) return e.collection;
    return e.plugin.empty() ? std::string("other") : e.plugin.filename().string();
}

std::vector<std::pair<std::string, ProgramList>> catalogue_by_collection() {
    std::map<std::string, ProgramList> groups;
    for (const Program* p : catalogue()) groups[collection_of(*p)].push_back(p);
    return {groups.begin(), groups.end()};
}

const Program& add_compiled_program(std::unique_ptr<Program> program, std::string collection, std::string vertex_glsl,
                                    std::string fragment_glsl) {
    Registry& r = registry();
    const std::string name(program->info().name);
    if (find_program(name)) throw std::invalid_argument("a shader named '" + name + "' is in the catalogue already");
    const Program& p = *program;
    r.entries.push_back({&p, {}, std::move(collection), std::shared_ptr<const Program>(std::move(program)),
                         std::move(vertex_glsl), std::move(fragment_glsl)});
    r.programs.push_back(&p);
    return p;
}

const std::string* compiled_glsl(const Program& program, bool vertex_stage) {
    const Entry& e = entry_of(program);
    if (!e.owned) return nullptr;
    return vertex_stage ? &e.vertex_glsl : &e.fragment_glsl;
}

std::filesystem::path glsl_folder(const Program& program, bool vertex_stage) {
    const std::filesystem::path& plugin = plugin_of(program);
    const bool builtin = plugin.empty() || (vertex_stage && program.info().stock_vertex_glsl);
    return builtin ? builtin_glsl_folder() : plugin.parent_path();
}

}  // namespace qs
